//! The first seed's two-link robot driven by four muscles (its figure 3),
//! from [`two_link_muscles`](crate::two_link_muscles)
//! (`models/two_link_muscles.toml`): forward dynamics with its muscles and
//! the sensitivity of the joint accelerations to the activations.
//!
//! Two uniform rods of 0.4 m (2 kg and 1 kg) hang from a revolute shoulder
//! at the world origin and are joined by a revolute elbow; gravity is `-y`;
//! at `q = 0` both links point straight down and positive angles swing the
//! arm forward (`+x`). Four Thelen (2003) muscles with rigid tendons, each a
//! path origin → via point → insertion, move it:
//!
//! | input | muscle | crosses            | action               |
//! |-------|--------|--------------------|----------------------|
//! | 0     | m1     | shoulder           | flexes the shoulder  |
//! | 1     | m2     | shoulder           | extends the shoulder |
//! | 2     | m3     | elbow              | flexes the elbow     |
//! | 3     | m4     | shoulder and elbow | extends both         |
//!
//! The drive inputs `w` are the four activations. [`forward_dynamics`] and
//! [`sensitivity`] are what a firmware calls every tick. [`step`] advances
//! the joints and the activations together ([`RobotState`]) under an
//! excitation pattern such as [`example_excitation`].

use crate::two_link_muscles::{self as file, M1_F32, M1_F64, M2_F32, M2_F64, M3_F32, M3_F64};
use crate::two_link_muscles::{M4_F32, M4_F64};
use rodyn::algorithm::forward_dynamics::{Aba, ForwardDynamics};
use rodyn::drive::{forward_dynamics_with_drives, DriveForces, ThelenMuscle};
use rodyn::error::Quantity;
use rodyn::planar::Planar;
use rodyn::sensitivity::forward_dynamics_and_sensitivity;
use rodyn::{Data, Error, Model, Result, Scalar};

pub use file::{NB, NU, NV};

/// The robot's multibody model.
pub type RobotModel<S> = Model<S, NB, NV, NV, Planar>;
/// Its workspace.
pub type RobotData<S> = Data<S, NB, NV, Planar>;
/// Its four muscles, in input order.
pub type RobotMuscles<S> = [ThelenMuscle<S, Planar, 3>; NU];
/// Its drive forces.
pub type RobotForces<S> = DriveForces<S, Planar, NB, NV>;

/// The model in `f32`, as the firmware uses it.
pub const MODEL_F32: RobotModel<f32> = file::MODEL_F32;
/// The model in `f64`.
pub const MODEL_F64: RobotModel<f64> = file::MODEL_F64;
/// The muscles in `f32`.
pub const MUSCLES_F32: RobotMuscles<f32> = [M1_F32, M2_F32, M3_F32, M4_F32];
/// The muscles in `f64`.
pub const MUSCLES_F64: RobotMuscles<f64> = [M1_F64, M2_F64, M3_F64, M4_F64];

/// The model in any scalar type (e.g. a dual number, for parameter
/// derivatives).
///
/// # Errors
/// None for this model (planar revolute joints always cast); the `Result`
/// is that of [`Model::cast`].
pub fn model<S: Scalar>() -> Result<RobotModel<S>> {
    MODEL_F64.cast()
}

/// The four muscles in any scalar type.
#[must_use]
pub fn muscles<S: Scalar>() -> RobotMuscles<S> {
    MUSCLES_F64.map(|m| m.cast())
}

/// Joint accelerations (rad/s²) at `(q, v)` under activations `a`, by ABA.
/// `forces` receives the muscle forces.
///
/// # Errors
/// Non-finite state or activations.
pub fn forward_dynamics<'d, S: Scalar>(
    model: &RobotModel<S>,
    muscles: &RobotMuscles<S>,
    data: &'d mut RobotData<S>,
    q: &[S; NV],
    v: &[S; NV],
    activation: &[S; NU],
    forces: &mut RobotForces<S>,
) -> Result<&'d [S; NV]> {
    forward_dynamics_with_drives::<Aba, _, _, _, NB, NV, NV>(
        model,
        data,
        q,
        v,
        &[S::ZERO; NV],
        muscles,
        activation,
        forces,
    )
}

/// Joint accelerations and the full sensitivity matrix `∂q̈/∂a` (2 × 4,
/// rad/s² per unit activation), one extra articulated-body pass per muscle.
///
/// # Errors
/// As [`forward_dynamics`].
#[allow(clippy::too_many_arguments)]
pub fn sensitivity<'d, S: Scalar>(
    model: &RobotModel<S>,
    muscles: &RobotMuscles<S>,
    data: &'d mut RobotData<S>,
    q: &[S; NV],
    v: &[S; NV],
    activation: &[S; NU],
    forces: &mut RobotForces<S>,
    d_ddq_d_activation: &mut [[S; NU]; NV],
) -> Result<&'d [S; NV]> {
    forward_dynamics_and_sensitivity(
        model,
        data,
        q,
        v,
        &[S::ZERO; NV],
        muscles,
        activation,
        forces,
        d_ddq_d_activation,
    )
}

/// Activation rates `ȧ` (1/s) of the four muscles for excitations `u`.
#[must_use]
pub fn activation_rates<S: Scalar>(
    muscles: &RobotMuscles<S>,
    excitation: &[S; NU],
    activation: &[S; NU],
) -> [S; NU] {
    core::array::from_fn(|k| muscles[k].activation_rate(excitation[k], activation[k]))
}

/// Excitations in `[0, 1]` at time `t` (s): the pattern that the example,
/// the drive figures and the `rodyn-sim` scenario all drive the robot with.
/// m1 and m2 alternate at the shoulder (0.5 Hz), m3 pulses the elbow (1 Hz),
/// m4 holds a steady tone.
#[must_use]
pub fn example_excitation<S: Scalar>(t: S) -> [S; NU] {
    let c = S::from_f64;
    let shoulder = (c(core::f64::consts::PI) * t).sin();
    let elbow = (c(2.0 * core::f64::consts::PI) * t).sin();
    [
        c(0.35) + c(0.3) * shoulder,
        c(0.35) - c(0.3) * shoulder,
        c(0.1) + c(0.06) * elbow,
        c(0.12),
    ]
}

/// The activation every muscle starts from in the example runs.
pub const INITIAL_ACTIVATION: f64 = 0.05;

/// The robot's full simulation state: the multibody state `(t, q, v)` and
/// the four muscle activations, which are states of their own (Thelen's
/// first-order activation dynamics, `ȧ = (u − a) / τ(u, a)`).
///
/// `rodyn::sim::State` holds `(t, q, v)` only, and `rodyn::sim::Loads` must
/// be a function of `(t, q, v)`, so activations cannot ride through the core
/// integrators without changing their trait (which every firmware image
/// links). [`step`] therefore integrates `(q, v, a)` together with the same
/// four schemes. The robot is planar with revolute joints only (`q` and `v`
/// share coordinates), so none of them needs the manifold update.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RobotState<S> {
    /// Time (s).
    pub t: S,
    /// Joint angles (rad): shoulder, elbow.
    pub q: [S; NV],
    /// Joint rates (rad/s).
    pub v: [S; NV],
    /// Muscle activations in input order, in `[0, 1]`.
    pub activation: [S; NU],
}

impl<S: Scalar> RobotState<S> {
    /// Hanging straight down at rest, every muscle at `activation`, at `t = 0`.
    #[must_use]
    pub fn at_rest(activation: S) -> Self {
        Self {
            t: S::ZERO,
            q: [S::ZERO; NV],
            v: [S::ZERO; NV],
            activation: [activation; NU],
        }
    }
}

/// How [`step`] advances the state; the same schemes as `rodyn::sim`'s
/// integrators, applied to `(q, v, a)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scheme {
    /// Explicit Euler: every component from the rates at the start.
    ExplicitEuler,
    /// Semi-implicit Euler: `v` and `a` explicit, then `q` with the new `v`.
    SemiImplicitEuler,
    /// Classical RK4 on `(q, v, a)`: four dynamics calls.
    Rk4,
    /// Linearly implicit Euler (one Newton step, finite-difference
    /// Jacobian): `2 NV + NU + 1` = 9 dynamics calls and a 2 × 2 solve.
    ImplicitEuler,
}

/// The buffers a simulation of the robot needs: the dynamics workspace and
/// the drive forces.
pub struct RobotWorkspace<S: Scalar> {
    /// Multibody workspace.
    pub data: RobotData<S>,
    /// Muscle forces of the last evaluation.
    pub forces: RobotForces<S>,
}

impl<S: Scalar> RobotWorkspace<S> {
    /// Fresh buffers.
    #[must_use]
    pub fn new() -> Self {
        Self {
            data: Data::new(),
            forces: DriveForces::new(),
        }
    }
}

impl<S: Scalar> Default for RobotWorkspace<S> {
    fn default() -> Self {
        Self::new()
    }
}

/// Time derivative of a [`RobotState`] (without the time itself).
#[derive(Clone, Copy)]
struct Rates<S> {
    q: [S; NV],
    v: [S; NV],
    activation: [S; NU],
}

/// `q̈` at `(q, v, a)` by the forward-dynamics method `M`.
fn joint_accelerations<M: ForwardDynamics, S: Scalar>(
    model: &RobotModel<S>,
    muscles: &RobotMuscles<S>,
    work: &mut RobotWorkspace<S>,
    q: &[S; NV],
    v: &[S; NV],
    activation: &[S; NU],
) -> Result<[S; NV]> {
    Ok(*forward_dynamics_with_drives::<M, _, _, _, NB, NV, NV>(
        model,
        &mut work.data,
        q,
        v,
        &[S::ZERO; NV],
        muscles,
        activation,
        &mut work.forces,
    )?)
}

#[allow(clippy::too_many_arguments)]
fn rates<M: ForwardDynamics, S: Scalar>(
    model: &RobotModel<S>,
    muscles: &RobotMuscles<S>,
    work: &mut RobotWorkspace<S>,
    excitation: &impl Fn(S) -> [S; NU],
    t: S,
    q: &[S; NV],
    v: &[S; NV],
    activation: &[S; NU],
) -> Result<Rates<S>> {
    Ok(Rates {
        q: *v,
        v: joint_accelerations::<M, S>(model, muscles, work, q, v, activation)?,
        activation: activation_rates(muscles, &excitation(t), activation),
    })
}

fn add_scaled<S: Scalar, const N: usize>(x: &[S; N], h: S, d: &[S; N]) -> [S; N] {
    core::array::from_fn(|k| x[k] + h * d[k])
}

/// Advances `state` by `dt` seconds under the excitations `excitation(t)`,
/// with forward dynamics by `M` (`Aba` or `Crba`) and the scheme `scheme`.
///
/// # Errors
/// The dynamics' errors at any evaluation, or [`Error::NonFinite`] when the
/// new state would not be finite (an implicit step whose 2 × 2 system is
/// singular reports the acceleration coordinate). On error `state` is
/// unchanged.
#[allow(clippy::too_many_arguments)]
pub fn step<M: ForwardDynamics, S: Scalar>(
    scheme: Scheme,
    model: &RobotModel<S>,
    muscles: &RobotMuscles<S>,
    work: &mut RobotWorkspace<S>,
    state: &mut RobotState<S>,
    dt: S,
    excitation: &impl Fn(S) -> [S; NU],
) -> Result<()> {
    let RobotState {
        t,
        q,
        v,
        activation: a,
    } = *state;
    let mut f = |t: S, q: &[S; NV], v: &[S; NV], a: &[S; NU]| {
        rates::<M, S>(model, muscles, work, excitation, t, q, v, a)
    };
    let next = match scheme {
        Scheme::ExplicitEuler => {
            let d = f(t, &q, &v, &a)?;
            RobotState {
                t: t + dt,
                q: add_scaled(&q, dt, &v),
                v: add_scaled(&v, dt, &d.v),
                activation: add_scaled(&a, dt, &d.activation),
            }
        }
        Scheme::SemiImplicitEuler => {
            let d = f(t, &q, &v, &a)?;
            let v_next = add_scaled(&v, dt, &d.v);
            RobotState {
                t: t + dt,
                q: add_scaled(&q, dt, &v_next),
                v: v_next,
                activation: add_scaled(&a, dt, &d.activation),
            }
        }
        Scheme::Rk4 => {
            let half = dt * S::from_f64(0.5);
            let k1 = f(t, &q, &v, &a)?;
            let k2 = f(
                t + half,
                &add_scaled(&q, half, &k1.q),
                &add_scaled(&v, half, &k1.v),
                &add_scaled(&a, half, &k1.activation),
            )?;
            let k3 = f(
                t + half,
                &add_scaled(&q, half, &k2.q),
                &add_scaled(&v, half, &k2.v),
                &add_scaled(&a, half, &k2.activation),
            )?;
            let k4 = f(
                t + dt,
                &add_scaled(&q, dt, &k3.q),
                &add_scaled(&v, dt, &k3.v),
                &add_scaled(&a, dt, &k3.activation),
            )?;
            let two = S::from_f64(2.0);
            let sixth = dt / S::from_f64(6.0);
            let combine =
                |x: S, d1: S, d2: S, d3: S, d4: S| x + sixth * (d1 + two * (d2 + d3) + d4);
            RobotState {
                t: t + dt,
                q: core::array::from_fn(|k| combine(q[k], k1.q[k], k2.q[k], k3.q[k], k4.q[k])),
                v: core::array::from_fn(|k| combine(v[k], k1.v[k], k2.v[k], k3.v[k], k4.v[k])),
                activation: core::array::from_fn(|k| {
                    combine(
                        a[k],
                        k1.activation[k],
                        k2.activation[k],
                        k3.activation[k],
                        k4.activation[k],
                    )
                }),
            }
        }
        Scheme::ImplicitEuler => {
            implicit_euler_step::<M, S>(model, muscles, work, excitation, state, dt)?
        }
    };
    check_finite(&next)?;
    *state = next;
    Ok(())
}

/// Backward Euler linearised once about the current state, as
/// `rodyn::sim::ImplicitEuler` does, with the loads at `t + dt`.
///
/// The Jacobian is block triangular: `ȧ_k` depends on `a_k` alone (and on
/// the excitation), `q̈` on `q`, `v` and `a`. So the activations are solved
/// first, each a scalar equation `(1 − dt ∂ȧ_k/∂a_k) Δa_k = dt ȧ_k`, and
/// then the joints, `(I − dt A_v − dt² A_q) Δv = dt (q̈ + dt A_q v + A_a Δa)`.
fn implicit_euler_step<M: ForwardDynamics, S: Scalar>(
    model: &RobotModel<S>,
    muscles: &RobotMuscles<S>,
    work: &mut RobotWorkspace<S>,
    excitation: &impl Fn(S) -> [S; NU],
    state: &RobotState<S>,
    dt: S,
) -> Result<RobotState<S>> {
    let RobotState {
        t,
        q,
        v,
        activation: a,
    } = *state;
    let t1 = t + dt;
    let h = S::from_f64(S::EPSILON).sqrt();
    let u = excitation(t1);
    let mut a_next = a;
    for k in 0..NU {
        let rate = muscles[k].activation_rate(u[k], a[k]);
        let slope = (muscles[k].activation_rate(u[k], a[k] + h) - rate) / h;
        a_next[k] = a[k] + dt * rate / (S::ONE - dt * slope);
    }
    let ddq = joint_accelerations::<M, S>(model, muscles, work, &q, &v, &a)?;
    let dt2 = dt * dt;
    // K = I − dt A_v − dt² A_q and rhs = dt (q̈ + dt A_q v + A_a Δa), column
    // by column of the finite-difference Jacobian.
    let mut k_mat = [[S::ZERO; NV]; NV];
    let mut rhs: [S; NV] = core::array::from_fn(|r| dt * ddq[r]);
    for col in 0..NV {
        let mut q_pert = q;
        q_pert[col] += h;
        let ddq_q = joint_accelerations::<M, S>(model, muscles, work, &q_pert, &v, &a)?;
        let h_v = h * S::ONE.max(v[col].abs());
        let mut v_pert = v;
        v_pert[col] += h_v;
        let ddq_v = joint_accelerations::<M, S>(model, muscles, work, &q, &v_pert, &a)?;
        for r in 0..NV {
            let d_aq = (ddq_q[r] - ddq[r]) / h;
            let d_av = (ddq_v[r] - ddq[r]) / h_v;
            k_mat[r][col] = -(dt * d_av + dt2 * d_aq);
            rhs[r] += dt2 * d_aq * v[col];
        }
        k_mat[col][col] += S::ONE;
    }
    for k in 0..NU {
        let mut a_pert = a;
        a_pert[k] += h;
        let ddq_a = joint_accelerations::<M, S>(model, muscles, work, &q, &v, &a_pert)?;
        for r in 0..NV {
            rhs[r] += dt * (ddq_a[r] - ddq[r]) / h * (a_next[k] - a[k]);
        }
    }
    let dv = solve_2x2(&k_mat, &rhs)?;
    let v_next = core::array::from_fn(|k| v[k] + dv[k]);
    Ok(RobotState {
        t: t1,
        q: add_scaled(&q, dt, &v_next),
        v: v_next,
        activation: a_next,
    })
}

/// Solves the 2 × 2 system `K x = b` by Cramer's rule.
fn solve_2x2<S: Scalar>(k: &[[S; NV]; NV], b: &[S; NV]) -> Result<[S; NV]> {
    let det = k[0][0] * k[1][1] - k[0][1] * k[1][0];
    let scale = k[0][0]
        .abs()
        .max(k[1][1].abs())
        .max(k[0][1].abs())
        .max(k[1][0].abs());
    if !det.is_finite() || det.abs() <= scale * scale * S::from_f64(S::EPSILON) {
        return Err(Error::NonFinite {
            quantity: Quantity::Acceleration,
            index: 0,
        });
    }
    Ok([
        (b[0] * k[1][1] - k[0][1] * b[1]) / det,
        (k[0][0] * b[1] - b[0] * k[1][0]) / det,
    ])
}

/// Every entry finite, or the first bad one named (an activation counts as
/// a configuration coordinate after the joints: index `NV + k`).
fn check_finite<S: Scalar>(state: &RobotState<S>) -> Result<()> {
    if let Some(index) = state
        .q
        .iter()
        .chain(&state.activation)
        .position(|x| !x.is_finite())
    {
        return Err(Error::NonFinite {
            quantity: Quantity::Configuration,
            index,
        });
    }
    if let Some(index) = state.v.iter().position(|x| !x.is_finite()) {
        return Err(Error::NonFinite {
            quantity: Quantity::Velocity,
            index,
        });
    }
    Ok(())
}
