//! Forward kinematics: body poses, velocities and accelerations.
//!
//! One forward pass over the bodies (Featherstone §3.4 / Table 5.1, first
//! loop). Symbols: `ˡⁱMᵢ` (`li_m_i`) is the parent frame from body i at `q`,
//! `ᵒMᵢ` (`o_m_i`) the world frame from body i, `v_J = S qd` the joint
//! velocity and `c = v × v_J` the velocity-product acceleration.

use crate::data::Data;
use crate::error::{Quantity, Result};
use crate::joint::JointModel;
use crate::model::{check_finite, Model};
use crate::space::{RigidTransform, Space, VectorOps};
use crate::Scalar;

/// Joint transform and placement of body `i`: `ˡⁱMᵢ = placement · jMi(q)`.
///
/// Inlined into each algorithm: with the firmware at opt-level 3 that saves
/// the Panda about 10 instructions a body (its bounds checks fold into the
/// algorithm's loop) for 420 bytes of the pendulum's flash. (At opt-level
/// "s" one shared out-of-line copy is the better trade: 800 bytes for two
/// instructions a body.)
#[inline]
pub(crate) fn body_transform<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    i: usize,
    q: &[S; NQ],
) -> G::Transform<S> {
    model
        .joint(i)
        .placed_transform(model.placement(i), joint_configuration(model, i, q))
}

/// Body `i`'s joint configuration: its slice of `q`.
#[inline(always)]
pub(crate) fn joint_configuration<
    'q,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    i: usize,
    q: &'q [S; NQ],
) -> &'q [S] {
    let t = model.topology();
    let iq = t.idx_q[i];
    &q[iq..iq + t.nq[i]]
}

/// Body `i`'s joint rates: its slice of `v` (which holds every joint's
/// rates, or accelerations).
#[inline(always)]
pub(crate) fn joint_rates<
    'v,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    i: usize,
    v: &'v [S; NV],
) -> &'v [S] {
    let t = model.topology();
    let iv = t.idx_v[i];
    &v[iv..iv + t.nv[i]]
}

/// Checks `q` (finite, unit quaternions) and `v` (finite).
pub(crate) fn check_state<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
    v: Option<&[S; NV]>,
) -> Result<()> {
    model.check_configuration(q)?;
    if let Some(v) = v {
        check_finite(v, Quantity::Velocity)?;
    }
    Ok(())
}

/// Body poses at configuration `q`.
///
/// Inputs: `q` (NQ). Leaves valid: `data.li_m_i`, `data.o_m_i`.
///
/// # Errors
/// [`Error::InvalidConfiguration`](crate::Error::InvalidConfiguration) for a
/// non-finite `q` or a quaternion that is not of unit length.
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

/// `ᵒMᵢ = ᵒM_λ ˡⁱMᵢ` from the parent transforms already in `data.li_m_i`.
#[inline]
fn pose_pass<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
) {
    for i in 0..NB {
        data.o_m_i[i] = match model.parent(i) {
            Some(p) => data.o_m_i[p].compose(&data.li_m_i[i]),
            None => data.li_m_i[i],
        };
    }
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
/// As [`forward_kinematics_velocity`], and for a non-finite `a`.
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
    for i in 0..NB {
        let a_parent = match model.parent(i) {
            Some(p) => data.li_m_i[i].act_inv_motion(&data.a[p]),
            None => G::Motion::<S>::ZERO,
        };
        data.a[i] = model
            .joint(i)
            .add_motion(&(a_parent + data.c[i]), joint_rates(model, i, a));
    }
    Ok(())
}

/// The forward pass shared by the dynamics algorithms: `ˡⁱMᵢ`,
/// `vᵢ = ⁱX_λ v_λ + v_J` and `cᵢ = vᵢ × v_J`. Inputs must already be checked.
///
/// It leaves the world poses `ᵒMᵢ` alone: RNEA and ABA work in body frames
/// and never read them, and composing them costs a 3x3 product per body
/// (about a tenth of RNEA on the Cortex-M4). Callers that need poses run
/// [`forward_kinematics`] or [`forward_kinematics_velocity`].
#[inline]
pub(crate) fn velocity_pass<
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
) {
    for i in 0..NB {
        let (li_m_i, v_i) = body_velocity(model, data, i, q, v);
        data.c[i] = model.joint(i).cross_motion(&v_i, joint_rates(model, i, v));
        data.v[i] = v_i;
        data.li_m_i[i] = li_m_i;
    }
}

/// Body `i`'s transform `ˡⁱMᵢ` and velocity `vᵢ = ⁱX_λ v_λ + S q̇ᵢ`, given
/// its parent's velocity in `data.v` (the step every root-to-leaves pass
/// starts a body with).
#[inline(always)]
pub(crate) fn body_velocity<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    i: usize,
    q: &[S; NQ],
    v: &[S; NV],
) -> (G::Transform<S>, G::Motion<S>) {
    let li_m_i = body_transform(model, i, q);
    let v_parent = match model.parent(i) {
        Some(p) => li_m_i.act_inv_motion(&data.v[p]),
        None => G::Motion::<S>::ZERO,
    };
    let v_i = model
        .joint(i)
        .add_motion(&v_parent, joint_rates(model, i, v));
    (li_m_i, v_i)
}
