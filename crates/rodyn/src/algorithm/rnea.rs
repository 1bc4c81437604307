//! Recursive Newton-Euler inverse dynamics (Featherstone Table 5.1).
//!
//! Forward pass: `vᵢ = ⁱX_λ v_λ + S q̇ᵢ`, `aᵢ = ⁱX_λ a_λ + S q̈ᵢ + cᵢ`
//! with `a₀ = -g` (gravity as a fictitious base acceleration), and the body
//! force `fᵢ = Iᵢ aᵢ + vᵢ ×* Iᵢ vᵢ - fᵢᵉˣᵗ`. Backward pass: `τᵢ = Sᵀ fᵢ`,
//! `f_λ += ᵏX_ᵢ* fᵢ`.

use crate::algorithm::common::{
    body_transform_with, check_external, check_state, joint_rates, JointSinCos,
};
use crate::data::Data;
use crate::error::{Quantity, Result};
use crate::joint::JointModel;
use crate::model::{check_finite, check_result, Model};
use crate::space::{BodyInertia, RigidTransform, Space, VectorOps};
use crate::Scalar;

/// Joint forces `τ = M(q) a + h(q, v) - Σ Jᵀ f_ext` that produce the
/// acceleration `a`.
///
/// Inputs: `q` (NQ), `v` and `a` (NV), and optionally one external force per
/// body, acting on that body and expressed in its own frame (Pinocchio's
/// `fext` convention). Returns `data.tau`. Leaves valid: `li_m_i`, `v`,
/// `a_gf` (acceleration minus gravity), `f`, `tau`. `c` and `o_m_i` are not
/// written
/// (run [`forward_kinematics`](crate::algorithm::kinematics::forward_kinematics)
/// for body poses).
///
/// # Errors
/// Non-finite inputs and invalid configurations, naming the entry.
///
/// # Example
///
/// ```
/// use rodyn::algorithm::rnea::rnea;
/// use rodyn::prelude::*;
/// // A 1 kg point mass on a massless 1 m link, pivot about z, gravity -y.
/// const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
///     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
///     [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
///     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// );
/// let mut data = Data::new();
/// let (q, v, a) = (0.3, 2.0, 1.5);
/// let tau = rnea(&PENDULUM, &mut data, &[q], &[v], &[a], None)?;
/// // τ = m l² q̈ + m g l cos q: the centripetal force does no work on the joint.
/// assert!((tau[0] - (a + 9.81 * f64::cos(q))).abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
pub fn rnea<'d, S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    a: &[S; NV],
    f_ext: Option<&[G::Force<S>; NB]>,
) -> Result<&'d [S; NV]> {
    check_state(model, q, Some(v))?;
    check_finite(a, Quantity::Acceleration)?;
    check_external(f_ext.map(|f| &f[..]))?;
    forward_pass(model, data, q, v, Some(a), f_ext);
    backward_force_pass(model, data, Some(a));
    check_result(&data.tau, Quantity::Torque)?;
    Ok(&data.tau)
}

/// The forward pass: `ˡⁱMᵢ`, `vᵢ`, `aᵢ - g` and `fᵢ` for every body;
/// `a: None` is a zero joint acceleration, with its `S q̈` terms left out.
///
/// One loop rather than the shared [`velocity_pass`](crate::algorithm::kinematics)
/// and a second one for forces: each body's transform, velocity and `c`
/// stay in registers instead of being stored and read back (fewer
/// instructions a body on the Cortex-M4).
// Inlined into each caller in the in-order profile (`crate::tuning`), so
// that `a: None` folds away (the Cortex-M4's pendulum RNEA is slower with
// plain `#[inline]`). Out of order it and the backward pass stay out of
// line, shared by `rnea` and `nonlinear_effects`: inlined into `rnea` alone
// (as once `Crba` no longer called `nonlinear_effects`), Solo12's RNEA ran
// more instructions and more time on hosts. Figures: docs/sections/performance_notebook.md, "RNEA".
#[cfg_attr(rodyn_tuning = "in_order", inline(always))]
#[cfg_attr(rodyn_tuning = "out_of_order", inline(never))]
fn forward_pass<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    a: Option<&[S; NV]>,
    f_ext: Option<&[G::Force<S>; NB]>,
) {
    let minus_g = -*model.gravity();
    let sin_cos = JointSinCos::at(model, q);
    for i in 0..NB {
        let li_m_i = body_transform_with(model, i, q, sin_cos.as_ref());
        forward_body(model, data, i, li_m_i, v, a, f_ext, &minus_g);
    }
}

/// One body of the [`forward_pass`], given its joint transform `li_m_i`
/// and `minus_g = -g`: stores `ˡⁱMᵢ`, `vᵢ`, `aᵢ - g` and `fᵢ`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn forward_body<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    i: usize,
    li_m_i: G::Transform<S>,
    v: &[S; NV],
    a: Option<&[S; NV]>,
    f_ext: Option<&[G::Force<S>; NB]>,
    minus_g: &G::Motion<S>,
) {
    let (v_parent, a_parent) = match model.parent(i) {
        Some(p) => (li_m_i.act_inv_motion(&data.v[p]), data.a_gf[p]),
        None => (G::Motion::<S>::ZERO, *minus_g),
    };
    let joint = model.joint(i);
    let q_dot = joint_rates(model, i, v);
    let v_i = joint.add_motion(&v_parent, q_dot);
    let c_i = joint.cross_motion(&v_i, q_dot);
    let a_i = li_m_i.act_inv_motion(&a_parent) + c_i;
    let a_i = match a {
        Some(a) => joint.add_motion(&a_i, joint_rates(model, i, a)),
        None => a_i,
    };
    let inertia = model.inertia(i);
    let mut f_i = inertia.net_force(&v_i, &a_i);
    if let Some(f_ext) = f_ext {
        f_i -= f_ext[i];
    }
    data.li_m_i[i] = li_m_i;
    data.v[i] = v_i;
    data.a_gf[i] = a_i;
    data.f[i] = f_i;
}

/// `τᵢ = Sᵀ fᵢ + armatureᵢ q̈ᵢ` and `f_λ += ˡⁱXᵢ* fᵢ`, leaves to root
/// (`a: None`: no armature term).
#[cfg_attr(rodyn_tuning = "in_order", inline(always))]
#[cfg_attr(rodyn_tuning = "out_of_order", inline(never))]
fn backward_force_pass<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    a: Option<&[S; NV]>,
) {
    backward_force_pass_with(model, data, a, |_, _| {});
}

/// [`backward_force_pass`], running `also(data, i)` after body i's step
/// (CRBA's backward pass, fused in by
/// [`Crba`](crate::algorithm::forward_dynamics::Crba)).
#[cfg_attr(rodyn_tuning = "in_order", inline(always))]
#[cfg_attr(rodyn_tuning = "out_of_order", inline)]
pub(crate) fn backward_force_pass_with<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    a: Option<&[S; NV]>,
    mut also: impl FnMut(&mut Data<S, NB, NV, G>, usize),
) {
    let t = model.topology();
    let armature = model.armature();
    // Out of order, the force handed to the body just before (a chain's
    // parent) stays in registers (see `crate::tuning::CARRY`; the figures:
    // the performance notebook, "RNEA").
    const CARRY: bool = crate::tuning::CARRY;
    let mut carry = G::Force::<S>::ZERO;
    for i in (0..NB).rev() {
        let (iv, nv) = t.velocity_range(i);
        let f_i = if CARRY {
            let f_i = data.f[i] + carry;
            carry = G::Force::<S>::ZERO;
            data.f[i] = f_i;
            f_i
        } else {
            data.f[i]
        };
        // A valid topology keeps the joint's coordinates in range
        // (`Topology::try_new`); one that does not stops the pass.
        let Some(tau) = data.tau.get_mut(iv..iv + nv) else {
            return;
        };
        model.joint(i).project_force(&f_i, tau);
        // Rotor inertias act on the joint coordinates alone.
        if let Some(a) = a {
            if let ([tau], Some(armature), Some(a)) = (&mut *tau, armature.get(iv), a.get(iv)) {
                *tau += *armature * *a;
            } else {
                for ((tau, armature), a) in tau.iter_mut().zip(&armature[iv..]).zip(&a[iv..]) {
                    *tau += *armature * *a;
                }
            }
        }
        if let Some(p) = model.parent(i) {
            let f_p = data.li_m_i[i].act_force(&f_i);
            if CARRY && p + 1 == i {
                carry = f_p;
            } else if let Some(f) = data.f.get_mut(p) {
                // (A valid topology's parent is a body: `p < i`.)
                *f += f_p;
            }
        }
        also(data, i);
    }
}

/// Bias forces `h(q, v) = C(q, v) q̇ + g(q)` (minus external forces): RNEA
/// with zero acceleration, its `S q̈` and armature terms left out.
///
/// Returns `data.tau`; leaves valid the same fields as [`rnea`].
///
/// # Errors
/// As [`rnea`].
///
/// # Example
///
/// ```
/// use rodyn::algorithm::rnea::nonlinear_effects;
/// # use rodyn::prelude::*;
/// # // Two 1 m links about z, 1 kg point masses at the tips, gravity -y.
/// # const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
/// # const DOUBLE: Model<f64, 2, 2, 2> = Model::new(
/// #     [None, Some(0)], [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
/// #     [Transform::IDENTITY, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))],
/// #     [LINK, LINK], Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// # );
/// let mut data = Data::new();
/// // Upper link at rest and level, elbow bent 90° and turning at 2 rad/s: the
/// // elbow needs no torque but gravity's, the shoulder also carries the
/// // centrifugal force m l₁ l₂ sin(q₂) q̇₂² of the tip.
/// let h = nonlinear_effects(&DOUBLE, &mut data, &[0.0, core::f64::consts::FRAC_PI_2], &[0.0, 2.0], None)?;
/// assert!((h[1] - 0.0).abs() < 1e-12);
/// assert!((h[0] - (2.0 * 9.81 - 4.0)).abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
pub fn nonlinear_effects<
    'd,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    f_ext: Option<&[G::Force<S>; NB]>,
) -> Result<&'d [S; NV]> {
    check_state(model, q, Some(v))?;
    check_external(f_ext.map(|f| &f[..]))?;
    forward_pass(model, data, q, v, None, f_ext);
    backward_force_pass(model, data, None);
    check_result(&data.tau, Quantity::Torque)?;
    Ok(&data.tau)
}

/// Gravity torques `g(q)`: RNEA with zero velocity and acceleration.
///
/// Returns `data.tau`; leaves valid the same fields as [`rnea`].
///
/// # Errors
/// As [`rnea`].
///
/// # Example
///
/// ```
/// use rodyn::algorithm::rnea::gravity_torques;
/// # use rodyn::prelude::*;
/// # // Two 1 m links about z, 1 kg point masses at the tips, gravity -y.
/// # const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
/// # const DOUBLE: Model<f64, 2, 2, 2> = Model::new(
/// #     [None, Some(0)], [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
/// #     [Transform::IDENTITY, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))],
/// #     [LINK, LINK], Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// # );
/// let mut data = Data::new();
/// // Both links level: the shoulder holds 1 kg at 1 m and 1 kg at 2 m.
/// let g = gravity_torques(&DOUBLE, &mut data, &[0.0, 0.0])?;
/// assert!((g[0] - 3.0 * 9.81).abs() < 1e-12 && (g[1] - 9.81).abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
pub fn gravity_torques<
    'd,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
) -> Result<&'d [S; NV]> {
    let zero = [S::ZERO; NV];
    rnea(model, data, q, &zero, &zero, None)
}
