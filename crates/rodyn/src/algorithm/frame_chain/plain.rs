//! The [frame chain](super)'s functions in the book's form, one body and
//! one column at a time: `ᵒMᵢ = ᵒM_λ ˡⁱMᵢ`, `ᵒJₖ = ᵒXᵢ Sₖ` moved by
//! `express_world_motion`, and the velocity pass with `J̇ v` from the
//! frame's motion as [`frame_velocity`](crate::algorithm::frames::frame_velocity)
//! and [`frame_classical_acceleration`](crate::algorithm::frames::frame_classical_acceleration)
//! form it. For reading and for the tests, which hold the tuned forms to
//! these.

use super::{FrameChain, FrameMotion};
use crate::algorithm::common::{body_transform, check_state, joint_rates};
use crate::algorithm::frames::{express_world_motion, zero_motion, FrameSpace, ReferenceFrame};
use crate::error::Result;
use crate::joint::JointModel;
use crate::model::Model;
use crate::space::{MotionVector, RigidTransform};
use crate::Scalar;

/// [`chain_jacobian`](super::chain_jacobian) in the book's form.
///
/// # Errors
/// As [`Model::check_configuration`].
pub fn chain_jacobian<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
    chain: &FrameChain<S, NB, G>,
    reference: ReferenceFrame,
    jacobian: &mut [G::Motion<S>; NV],
) -> Result<G::Transform<S>> {
    model.check_configuration(q)?;
    let (o_m_b, world) = world_columns(model, q, chain);
    let o_m_f = o_m_b.compose(&chain.frame().placement);
    *jacobian = [zero_motion::<S, G>(); NV];
    for i in chain.path().iter() {
        for k in model.topology().velocity_coordinates(i) {
            jacobian[k] = express_world_motion::<S, G>(&o_m_f, &world[k], reference);
        }
    }
    Ok(o_m_f)
}

/// [`chain_kinematics`](super::chain_kinematics) in the book's form.
///
/// # Errors
/// As [`Model::check_configuration`], or a non-finite `v`.
pub fn chain_kinematics<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    chain: &FrameChain<S, NB, G>,
    reference: ReferenceFrame,
    jacobian: &mut [G::Motion<S>; NV],
) -> Result<FrameMotion<S, G>> {
    check_state(model, q, Some(v))?;
    let placement = chain_jacobian(model, q, chain, reference, jacobian)?;
    // vᵢ = ⁱX_λ v_λ + Sᵢ q̇ᵢ, aᵢ = ⁱX_λ a_λ + vᵢ × Sᵢ q̇ᵢ (q̈ = 0), body
    // frames, root to the frame's body.
    let (mut v_b, mut a_b) = (zero_motion::<S, G>(), zero_motion::<S, G>());
    for i in chain.path().iter() {
        let li_m_i = body_transform(model, i, q);
        let joint = model.joint(i);
        let s_qd = joint.motion(joint_rates(model, i, v));
        v_b = li_m_i.act_inv_motion(&v_b) + s_qd;
        a_b = li_m_i.act_inv_motion(&a_b) + v_b.cross_motion(&s_qd);
    }
    // The body's motion at the frame, in its own axes, then in `reference`.
    let frame = &chain.frame().placement;
    let o_m_b = placement.compose(&frame.inverse());
    let world = |m: &G::Motion<S>| o_m_b.act_motion(m);
    let velocity = express_world_motion::<S, G>(&placement, &world(&v_b), reference);
    let a = express_world_motion::<S, G>(&placement, &world(&a_b), reference);
    let dj_v = match reference {
        // `ᶠX_o ᵒJ̇ v − v_f × ᶠJ v` with the reference frame's own velocity
        // `v_f = (0, ṗ)`: `a − (0, ṗ) × (ω, ṗ) = a + (0, ω × ṗ)`.
        ReferenceFrame::LocalWorldAligned => a - G::linear_part(&velocity).cross_motion(&velocity),
        // `v_f` is the frame's velocity itself (`v_f × v_f = 0`), or zero.
        ReferenceFrame::Local | ReferenceFrame::World => a,
    };
    Ok(FrameMotion {
        placement,
        velocity,
        dj_v,
    })
}

/// Every world column of the chain's path (the others zero) and the pose
/// of its body.
fn world_columns<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: FrameSpace>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
    chain: &FrameChain<S, NB, G>,
) -> (G::Transform<S>, [G::Motion<S>; NV]) {
    let mut world = [zero_motion::<S, G>(); NV];
    let mut o_m_i = <G::Transform<S> as RigidTransform<S>>::IDENTITY;
    for i in chain.path().iter() {
        // The path starts at a root, whose parent is the world (the
        // identity), and each body's parent is the one before it.
        o_m_i = o_m_i.compose(&body_transform(model, i, q));
        let joint = model.joint(i);
        let (iv, nv) = model.topology().velocity_range(i);
        for c in 0..nv {
            world[iv + c] = o_m_i.act_motion(&joint.subspace_column(c));
        }
    }
    (o_m_i, world)
}
