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
//! [`sensitivity`] are what a firmware calls every tick. To simulate, any
//! `rodyn::sim` integrator advances the joints and the activations together
//! ([`RobotState`], the activations as auxiliary states) under
//! [`RobotLoads`], the muscles driven by an excitation pattern such as
//! [`example_excitation`].

use crate::two_link_muscles::{self as file, M1_F32, M1_F64, M2_F32, M2_F64, M3_F32, M3_F64};
use crate::two_link_muscles::{M4_F32, M4_F64};
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::drive::{drive_forces, forward_dynamics_with_drives, DriveForces, ThelenMuscle};
use rodyn::planar::Planar;
use rodyn::sensitivity::forward_dynamics_and_sensitivity;
use rodyn::sim::{AuxiliaryLoads, State};
use rodyn::space::Geometry;
use rodyn::{Data, Model, Result, Scalar};

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
///
/// # Errors
/// The first muscle's error from
/// [`ThelenParameters::activation_rate`](rodyn::drive::ThelenParameters::activation_rate)
/// (a non-finite excitation or activation).
pub fn activation_rates<S: Scalar>(
    muscles: &RobotMuscles<S>,
    excitation: &[S; NU],
    activation: &[S; NU],
) -> Result<[S; NU]> {
    let mut rates = [S::ZERO; NU];
    for (k, rate) in rates.iter_mut().enumerate() {
        *rate = muscles[k].activation_rate(excitation[k], activation[k])?;
    }
    Ok(rates)
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

/// The robot's simulation state: the joints `(t, q, v)` and the four muscle
/// activations as its auxiliary states `z` (Thelen's first-order
/// activation dynamics, `ȧ = (u − a) / τ(u, a)`), in input order, in
/// `[0, 1]`. Any `rodyn::sim` integrator advances it under
/// [`RobotLoads`].
pub type RobotState<S> = State<S, NV, NV, NU>;

/// Hanging straight down at rest, every muscle at `activation`, at `t = 0`.
#[must_use]
pub fn rest_state<S: Scalar>(activation: S) -> RobotState<S> {
    State::with_auxiliary([S::ZERO; NV], [S::ZERO; NV], [activation; NU])
}

/// The muscles under an excitation pattern, as loads with auxiliary states
/// for `rodyn::sim`'s integrators: the muscle forces at the activations
/// `z`, and the activation rates `ż` for the excitations `excitation(t)`.
///
/// ```
/// use rodyn::algorithm::forward_dynamics::Aba;
/// use rodyn::sim::{Integrator, Rk4};
/// use rodyn_scenarios::muscle_robot::{self as robot, example_excitation, RobotLoads};
/// let mut loads = RobotLoads::new(&robot::MUSCLES_F64, example_excitation::<f64>);
/// let mut state = robot::rest_state(robot::INITIAL_ACTIVATION);
/// let mut data = rodyn::Data::new();
/// Rk4::default().step(Aba, &robot::MODEL_F64, &mut data, &mut state, 1e-3, &mut loads)?;
/// assert!(state.z[0] > robot::INITIAL_ACTIVATION); // m1 is excited above its start
/// # Ok::<(), rodyn::Error>(())
/// ```
pub struct RobotLoads<'m, S: Scalar, E> {
    /// The four muscles, in input order.
    pub muscles: &'m RobotMuscles<S>,
    /// Excitations in `[0, 1]` as a function of time (s).
    pub excitation: E,
    /// Muscle forces of the last evaluation (at a trial state when the
    /// integrator has stages).
    pub forces: RobotForces<S>,
}

impl<'m, S: Scalar, E: FnMut(S) -> [S; NU]> RobotLoads<'m, S, E> {
    /// `muscles` driven by `excitation`.
    pub fn new(muscles: &'m RobotMuscles<S>, excitation: E) -> Self {
        Self {
            muscles,
            excitation,
            forces: DriveForces::new(),
        }
    }
}

impl<S: Scalar, E: FnMut(S) -> [S; NU]> AuxiliaryLoads<S, NB, NV, NV, NU, Planar>
    for RobotLoads<'_, S, E>
{
    fn loads_and_rates(
        &mut self,
        model: &RobotModel<S>,
        data: &mut RobotData<S>,
        t: S,
        q: &[S; NV],
        v: &[S; NV],
        activation: &[S; NU],
        tau: &mut [S; NV],
        f_ext: &mut [<Planar as Geometry>::Force<S>; NB],
        activation_rate: &mut [S; NU],
    ) -> Result<()> {
        drive_forces(
            model,
            data,
            q,
            v,
            self.muscles,
            activation,
            &mut self.forces,
        )?;
        for (total, muscle) in tau.iter_mut().zip(&self.forces.tau) {
            *total += *muscle;
        }
        for (total, muscle) in f_ext.iter_mut().zip(&self.forces.f_ext) {
            *total += *muscle;
        }
        *activation_rate = activation_rates(self.muscles, &(self.excitation)(t), activation)?;
        Ok(())
    }
}
