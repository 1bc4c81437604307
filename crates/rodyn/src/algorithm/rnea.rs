//! Recursive Newton-Euler inverse dynamics (Featherstone Table 5.1).
//!
//! Forward pass: `vᵢ = ⁱX_λ v_λ + S q̇ᵢ`, `aᵢ = ⁱX_λ a_λ + S q̈ᵢ + cᵢ`
//! with `a₀ = -g` (gravity as a fictitious base acceleration), and the body
//! force `fᵢ = Iᵢ aᵢ + vᵢ ×* Iᵢ vᵢ - fᵢᵉˣᵗ`. Backward pass: `τᵢ = Sᵀ fᵢ`,
//! `f_λ += ᵏX_ᵢ* fᵢ`.

use crate::algorithm::common::{
    backward_force_pass_with, body_transform_with, check_external, check_state, forward_body,
    JointSinCos,
};
use crate::data::Data;
use crate::error::{Quantity, Result};
use crate::model::{check_finite, check_result, Model};
use crate::space::Space;
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
        let li_m_i = body_transform_with(model, i, q, sin_cos.formed());
        forward_body(model, data, i, li_m_i, v, a, f_ext, &minus_g);
    }
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
