//! The local backward pass: CRBA's recursion in each body's own (turned) frame.
//!
//! Why it exists: it is the book's backward pass (Table 6.2) with the
//! columns `F = Iᶜᵢ Sₖ` of a whole subtree carried up together, so one step
//! per body moves them all, and a joint about a coordinate axis reads one
//! component of each column instead of a dot product. Every vector stays a
//! link long from the frame it is in, which keeps `f32` accurate; it is the
//! default pass ([`CrbaPass::Local`](super::CrbaPass::Local)) for every
//! model but long `f64` chains.

use super::TurnedFrame;
use super::ENTRIES_IN_PASS;
use crate::data::Data;
use crate::joint::{JointModel, MAX_JOINT_NV};
use crate::model::Model;
use crate::space::{Space, VectorOps};
use crate::Scalar;

/// Body i's step of the backward pass, in its `frame`: its columns `Iᶜᵢ Sₖ`, its entries
/// of `M` against every coordinate of its subtree (whose columns
/// `columns` hold in body i's frame), then the subtree's columns and `Iᶜᵢ`
/// moved through `step` (`ˡⁱXᵢ`; `None` at a root) to the parent's frame.
/// With `upper`, on trees whose subtrees hold contiguous coordinates, each
/// entry's mirror above the diagonal too.
///
/// Where subtrees hold contiguous coordinates, it also zeroes the entries
/// of its coordinates' columns below its subtree (and with `upper` their
/// mirrors): no other body writes them, and a few stores here cost less
/// than clearing row stretches that the pass then partly overwrites
/// ([`clear_lower`], which trees numbered otherwise take).
#[inline(always)]
pub(super) fn backward_body<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    frame: &TurnedFrame,
    data: &mut Data<S, NB, NV, G>,
    i: usize,
    step: Option<&G::Step<S>>,
    columns: &mut [G::Force<S>; NV],
    upper: bool,
) {
    let t = model.topology();
    let joint = model.joint(i);
    let (iv, nv) = t.velocity_range(i);
    let end = t.subtree_end(i);
    if ENTRIES_IN_PASS && t.subtrees_contiguous && end < NV {
        let m = &mut data.mass_matrix;
        // Bounds known to the compiler: no checks inside.
        for k in iv..(iv + nv).min(NV) {
            for d in end..NV {
                m[d][k] = S::ZERO;
                if upper {
                    m[k][d] = S::ZERO;
                }
            }
        }
    }
    // A revolute joint's coordinate axis in the frame of the columns.
    let axis = match frame.axis() {
        Some(a) => Some((a.turned, a.reversed)),
        None => joint.revolute_axis_index().map(|k| (k, false)),
    };
    // The geometry's fused steps where they apply: a revolute joint whose
    // step turns about its own coordinate axis, a free-flying root.
    if let (true, 1, Some(axis), Some(p), Some(step)) = (
        G::FUSES_CRBA_STEPS && t.subtrees_contiguous,
        nv,
        axis,
        t.parent(i),
        step,
    ) {
        let end = t.subtree_end(i);
        let (ancestors, rest) = data.ic.split_at_mut(i);
        // A valid topology has `p < i` and its subtree's coordinates in
        // range; one that does not is left to the general step below.
        if let (Some(ic_i), Some(ancestor), Some(subtree), Some(rows)) = (
            rest.first(),
            ancestors.get_mut(p),
            columns.get_mut(iv..end),
            data.mass_matrix.get_mut(iv..end),
        ) {
            if G::crba_axis_body(step, axis, ic_i, ancestor, subtree, rows, iv, upper) {
                return;
            }
        }
    }
    if G::FUSES_CRBA_STEPS && t.subtrees_contiguous && t.parent(i).is_none() && nv == 6 {
        let end = t.subtree_end(i);
        if let (Some(ic_i), Some(subtree), Some(rows)) = (
            data.ic.get(i),
            columns.get(iv + 6..end),
            data.mass_matrix.get_mut(iv..end),
        ) {
            if G::crba_free_root(joint, ic_i, subtree, rows, iv, upper) {
                return;
            }
        }
    }
    let Some(ic_i) = data.ic.get(i) else { return };
    for (k, column) in columns[iv..iv + nv].iter_mut().enumerate() {
        *column = G::turned_inertia_column(frame, ic_i, joint, k);
    }
    if t.subtrees_contiguous {
        let end = t.subtree_end(i);
        let rows = iv..end;
        project_rows(
            joint,
            axis,
            iv,
            nv,
            rows,
            &mut data.mass_matrix,
            columns,
            upper,
        );
        if let (Some(step), Some(subtree)) = (step, columns.get_mut(iv..end)) {
            G::step_forces(step, subtree);
        }
    } else {
        // The subtree's coordinates all follow body i's first.
        for d in iv..NV {
            if d < iv + nv || t.supports(i, t.body_of_v[d]) {
                project_rows(
                    joint,
                    axis,
                    iv,
                    nv,
                    d..d + 1,
                    &mut data.mass_matrix,
                    columns,
                    false,
                );
                if let Some(step) = step {
                    G::step_forces(step, core::slice::from_mut(&mut columns[d]));
                }
            }
        }
    }
    if let (Some(p), Some(step)) = (t.parent(i), step) {
        let ic_i = *ic_i;
        if let Some(ic_p) = data.ic.get_mut(p) {
            G::add_stepped_inertia(ic_p, step, &ic_i);
        }
    }
}

/// `M[d][iv + k] = Sₖᵀ F_d` for the rows d of `rows`, with `F_d =
/// columns[d]`; rows of the joint's own coordinates fill the lower
/// triangle of its block only. With `upper`, each entry's mirror
/// `M[iv + k][d]` too. `axis`: a revolute joint's coordinate axis in the
/// columns' frame, and whether it is reversed there.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn project_rows<S: Scalar, J: JointModel<S, G>, G: Space, const NV: usize>(
    joint: &J,
    axis: Option<(usize, bool)>,
    iv: usize,
    nv: usize,
    rows: core::ops::Range<usize>,
    m: &mut [[S; NV]; NV],
    columns: &[G::Force<S>; NV],
    upper: bool,
) {
    // Index loops over slices as long as the range: no bounds checks
    // inside, and no slice lengths to divide out of byte counts (a body's
    // subtree here is one to 30 rows; longer chains in `f64` take
    // `about_root`). On the Panda and Solo12, fewer instructions than
    // zipped slice iterators (the performance notebook, "CRBA").
    let (Some(m), Some(columns)) = (m.get_mut(..rows.end), columns.get(..rows.end)) else {
        return;
    };
    // The rows start at the joint's first coordinate or after it, so a
    // range with rows has `iv < rows.end`; stated, it puts every `[iv]`
    // below in range.
    if iv >= rows.end || nv > MAX_JOINT_NV {
        return;
    }
    match (nv, axis) {
        (0, _) => {}
        // A coordinate axis reads one component of each column.
        (1, Some((0, false))) => column(m, iv, rows.clone(), upper, |d| columns[d].component(0)),
        (1, Some((1, false))) => column(m, iv, rows.clone(), upper, |d| columns[d].component(1)),
        (1, Some((_, false))) => column(m, iv, rows.clone(), upper, |d| columns[d].component(2)),
        (1, Some((0, true))) => column(m, iv, rows.clone(), upper, |d| -columns[d].component(0)),
        (1, Some((1, true))) => column(m, iv, rows.clone(), upper, |d| -columns[d].component(1)),
        (1, Some((_, true))) => column(m, iv, rows.clone(), upper, |d| -columns[d].component(2)),
        // One coordinate: its own row is the diagonal alone.
        (1, None) => {
            for d in rows {
                joint.project_force(&columns[d], core::slice::from_mut(&mut m[d][iv]));
                if upper {
                    m[iv][d] = m[d][iv];
                }
            }
        }
        _ => {
            for d in rows {
                if d < iv + nv {
                    // The joint's own row: its block's lower triangle only.
                    let mut projected = [S::ZERO; MAX_JOINT_NV];
                    joint.project_force(&columns[d], &mut projected[..nv]);
                    for (e, p) in m[d].iter_mut().take(d + 1).skip(iv).zip(projected) {
                        *e = p;
                    }
                } else if let Some(entries) = m[d].get_mut(iv..iv + nv) {
                    joint.project_force(&columns[d], entries);
                }
                if upper {
                    for k in iv..(iv + nv).min(d + 1) {
                        m[k][d] = m[d][k];
                    }
                }
            }
        }
    }
}

/// `M[d][iv] = entry(d)` for the rows d of `rows` (with `upper`, its
/// mirror `M[iv][d]` too): a one-coordinate joint's column.
#[inline(always)]
fn column<S: Scalar, const NV: usize>(
    m: &mut [[S; NV]],
    iv: usize,
    rows: core::ops::Range<usize>,
    upper: bool,
    entry: impl Fn(usize) -> S,
) {
    for d in rows {
        let e = entry(d);
        m[d][iv] = e;
        if upper {
            m[iv][d] = e;
        }
    }
}
