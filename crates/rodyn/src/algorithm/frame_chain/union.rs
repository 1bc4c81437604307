//! The world columns of several frames' support paths taken together (a
//! quadruped's stance feet, a humanoid's soles), each body of the union
//! once, and one frame's columns moved out of them: the pieces
//! [`chains_jacobians`](super::chains_jacobians) and the contact Jacobians
//! of the constrained dynamics share. A body off every path (a leg in
//! swing, an arm) costs nothing.

use super::FrameChain;
use crate::algorithm::common::{body_transform_with, JointSinCos};
use crate::algorithm::frames::{FrameSpace, ReferenceFrame};
use crate::data::Data;
use crate::model::Model;
use crate::space::RigidTransform;
use crate::Scalar;

/// The bodies on any of `chains`' paths.
#[inline]
pub(crate) fn bodies_on_paths<'c, S: Scalar, const NB: usize, G: FrameSpace + 'c>(
    chains: impl IntoIterator<Item = &'c FrameChain<S, NB, G>>,
) -> [bool; NB] {
    let mut on_paths = [false; NB];
    for chain in chains {
        for i in chain.path.iter() {
            on_paths[i] = true;
        }
    }
    on_paths
}

/// At `q` (checked by the caller): the poses `ᵒMᵢ = ᵒM_λ ˡⁱMᵢ` of the
/// bodies marked in `on_paths` into `data.o_m_i`, and their world columns
/// `ᵒXᵢ Sₖ` into `columns` (the other bodies' entries untouched). A
/// body's parent is on the union when the body is: the union of support
/// paths is closed under λ.
#[inline(always)]
pub(crate) fn union_world_columns<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    on_paths: &[bool; NB],
    columns: &mut [G::Motion<S>; NV],
) {
    let t = model.topology();
    let sin_cos = JointSinCos::at(model, q);
    for i in 0..NB {
        if !on_paths[i] {
            continue;
        }
        let li_m_i = body_transform_with(model, i, q, sin_cos.formed());
        let o_m_i = match t.parent(i) {
            Some(p) => G::then_joint(&data.o_m_i[p], &li_m_i, model.joint(i)),
            None => li_m_i,
        };
        data.o_m_i[i] = o_m_i;
        write_columns(model, i, &o_m_i, columns);
    }
}

/// [`union_world_columns`] from the poses already in `data.o_m_i` (left by
/// a forward-kinematics pass at `q`): the world columns only.
#[inline(always)]
pub(crate) fn union_world_columns_from_poses<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    on_paths: &[bool; NB],
    columns: &mut [G::Motion<S>; NV],
) {
    for (i, o_m_i) in data.o_m_i.iter().enumerate() {
        if on_paths[i] {
            write_columns(model, i, o_m_i, columns);
        }
    }
}

/// Body i's world columns at its pose `o_m_i`.
#[inline(always)]
fn write_columns<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: FrameSpace>(
    model: &Model<S, NB, NQ, NV, G>,
    i: usize,
    o_m_i: &G::Transform<S>,
    columns: &mut [G::Motion<S>; NV],
) {
    let joint = model.joint(i);
    let (iv, nv) = model.topology().velocity_range(i);
    for (k, column) in columns[iv..iv + nv].iter_mut().enumerate() {
        *column = G::act_subspace_column(o_m_i, joint, k);
    }
}

/// `f(k, column)` for each velocity coordinate k of the support path of
/// `body` (the body and its ancestors, walked up from the body: no path
/// to store), with its world column `world[k]` moved into `reference` at
/// the frame whose pose is `o_m_f`. The coordinates off the path are not
/// visited: their columns are zero. A body past the model's ends the walk.
#[inline(always)]
pub(crate) fn for_each_path_column<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    body: usize,
    o_m_f: &G::Transform<S>,
    reference: ReferenceFrame,
    world: &[G::Motion<S>; NV],
    mut f: impl FnMut(usize, &G::Motion<S>),
) {
    let t = model.topology();
    let p = o_m_f.translation();
    let mut b = Some(body).filter(|&i| i < NB);
    while let Some(i) = b {
        for k in t.velocity_coordinates(i) {
            let c = &world[k];
            let column = match reference {
                ReferenceFrame::World => *c,
                ReferenceFrame::Local => o_m_f.act_inv_motion(c),
                ReferenceFrame::LocalWorldAligned => G::shift_motion(c, &p),
            };
            f(k, &column);
        }
        b = t.parent(i);
    }
}
