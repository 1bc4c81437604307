//! Forward kinematics: body poses, velocities and accelerations.
//!
//! One forward pass over the bodies (Featherstone §3.4 / Table 5.1, first
//! loop). Symbols: `ˡⁱMᵢ` (`li_m_i`) is the parent frame from body i at `q`,
//! `ᵒMᵢ` (`o_m_i`) the world frame from body i, `v_J = S qd` the joint
//! velocity and `c = v × v_J` the velocity-product acceleration.

use crate::data::Data;
use crate::error::{Quantity, Result};
use crate::joint::JointModel;
use crate::model::{check_finite, check_vectors_result, Model};
use crate::space::{RigidTransform, Space, VectorOps};
use crate::Scalar;

use super::common::{body_transform, check_state, pose_pass};
use super::common::{joint_rates, velocity_pass};

/// Body poses at configuration `q`.
///
/// Inputs: `q` (NQ). Leaves valid: `data.li_m_i`, `data.o_m_i`.
///
/// # Errors
/// [`Error::InvalidConfiguration`](crate::Error::InvalidConfiguration) for a
/// non-finite `q` or a quaternion that is not of unit length.
///
/// # Example
///
/// ```
/// use rodyn::algorithm::kinematics::forward_kinematics;
/// # use rodyn::prelude::*;
/// # // Two 1 m links about z, 1 kg point masses at the tips, gravity -y.
/// # const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
/// # const DOUBLE: Model<f64, 2, 2, 2> = Model::new(
/// #     [None, Some(0)], [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
/// #     [Transform::IDENTITY, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))],
/// #     [LINK, LINK], Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// # );
/// let mut data = Data::new();
/// let (q1, q2) = (0.4, -0.7);
/// forward_kinematics(&DOUBLE, &mut data, &[q1, q2])?;
/// // The elbow body's origin sits at the end of the first link.
/// let elbow = data.o_m_i[1].trans;
/// assert!((elbow.x - f64::cos(q1)).abs() < 1e-12 && (elbow.y - f64::sin(q1)).abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
pub fn forward_kinematics<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
) -> Result<()> {
    check_state(model, q, None)?;
    for i in 0..NB {
        data.li_m_i[i] = body_transform(model, i, q);
    }
    pose_pass(model, data);
    Ok(())
}

/// Body poses and velocities at `(q, v)`.
///
/// Inputs: `q` (NQ), `v` (NV). Leaves valid: `li_m_i`, `o_m_i`, `v` (body
/// frames), `c`.
///
/// # Errors
/// As [`forward_kinematics`], and [`Error::NonFinite`](crate::Error::NonFinite) for `v`.
pub fn forward_kinematics_velocity<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
) -> Result<()> {
    check_state(model, q, Some(v))?;
    velocity_pass(model, data, q, v);
    pose_pass(model, data);
    Ok(())
}

/// Body poses, velocities and accelerations at `(q, v, a)` (gravity excluded).
///
/// Inputs: `q` (NQ), `v` (NV), `a` (NV). Leaves valid: `li_m_i`, `o_m_i`,
/// `v`, `c`, `a` (body frames).
///
/// # Errors
/// As [`forward_kinematics_velocity`], [`Error::NonFinite`](crate::Error::NonFinite)
/// for a non-finite `a`, and
/// [`Error::NonFiniteResult`](crate::Error::NonFiniteResult)
/// (`Quantity::BodyAcceleration`, naming the body) when the products of
/// the velocities overflow (a velocity of 1e154 in f64).
pub fn forward_kinematics_acceleration<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    a: &[S; NV],
) -> Result<()> {
    check_state(model, q, Some(v))?;
    check_finite(a, Quantity::Acceleration)?;
    velocity_pass(model, data, q, v);
    pose_pass(model, data);
    // Summed as they are formed, for one finiteness test of them all (a
    // test of the leaves' alone, with its branch per body, cost the
    // Cortex-M4 more than the additions).
    let mut sum = G::Motion::<S>::ZERO;
    for i in 0..NB {
        let a_parent = match model.parent(i) {
            Some(p) => data.li_m_i[i].act_inv_motion(&data.a[p]),
            None => G::Motion::<S>::ZERO,
        };
        data.a[i] = model
            .joint(i)
            .add_motion(&(a_parent + data.c[i]), joint_rates(model, i, a));
        sum += data.a[i];
    }
    if sum.is_finite() {
        return Ok(());
    }
    check_vectors_result(&data.a, Quantity::BodyAcceleration)
}
