//! CRBA's work at one body, fused for the two commonest joints of a tree.
//!
//! The backward pass visits each body once: it forms the body's column
//! `Iᶜ S`, reads the body's entries of `M` off the columns of its subtree,
//! moves those columns and `Iᶜ` into the parent's frame. Done one
//! operation at a time behind the joint type, a leg or an arm body spends
//! as many instructions on dispatch and loop control as on arithmetic.
//! Here each case is one pass with everything known at compile time:
//! - a revolute joint about coordinate axis `K` of the columns' frame
//!   whose step turns about the same axis (every joint of a Solo12 leg,
//!   of the chains, of a turned-frame URDF arm): the projection reads
//!   component `K`, and the move mixes two components of each vector;
//! - a free-flying root: `S` is the identity, so the body's block of `M` is
//!   its composite inertia and its entries against the subtree are the
//!   columns themselves, reordered; nothing moves.

use super::spatial::{add_shifted_inertia, revolute_inertia_column};
use super::step::{rotate_about, rotate_inertia_about, TransformStep};
use crate::spatial::{Force, Inertia, Vec3};
use crate::Scalar;

/// [`CrbaSpace::crba_axis_body`](super::CrbaSpace::crba_axis_body) for
/// [`Spatial`](super::Spatial).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) fn axis_body<S: Scalar, const NV: usize>(
    step: &TransformStep<S>,
    (axis, reversed): (usize, bool),
    ic: &Inertia<S>,
    parent_ic: &mut Inertia<S>,
    columns: &mut [Force<S>],
    rows: &mut [[S; NV]],
    iv: usize,
    upper: bool,
) -> bool {
    let TransformStep::Axis {
        axis: step_axis,
        cos,
        sin,
        trans,
    } = *step
    else {
        return false;
    };
    if step_axis != axis {
        return false;
    }
    let turn = AxisTurn {
        cos,
        sin,
        trans,
        sign: if reversed { -S::ONE } else { S::ONE },
    };
    match axis {
        0 => turn.body::<0, NV>(ic, parent_ic, columns, rows, iv, upper),
        1 => turn.body::<1, NV>(ic, parent_ic, columns, rows, iv, upper),
        _ => turn.body::<2, NV>(ic, parent_ic, columns, rows, iv, upper),
    }
    true
}

/// A step that turns about the joint's own coordinate axis.
struct AxisTurn<S> {
    cos: S,
    sin: S,
    trans: Vec3<S>,
    /// -1 when the joint turns about the axis reversed.
    sign: S,
}

impl<S: Scalar> AxisTurn<S> {
    /// The fused step about axis `K`: `columns[0]` (the body's own) is
    /// written first, then every column projected and moved, then `ic`
    /// added to the parent's. With `upper`, each entry also goes to its
    /// mirror in the body's own row, `rows[0]`.
    #[inline(always)]
    fn body<const K: usize, const NV: usize>(
        &self,
        ic: &Inertia<S>,
        parent_ic: &mut Inertia<S>,
        columns: &mut [Force<S>],
        rows: &mut [[S; NV]],
        iv: usize,
        upper: bool,
    ) {
        let (c, s, sign) = (self.cos, self.sin, self.sign);
        let turned = |f: &Force<S>| {
            let lin = rotate_about::<S, K>(c, s, &f.lin);
            let ang = rotate_about::<S, K>(c, s, &f.ang) + self.trans.cross(&lin);
            Force::new(ang, lin)
        };
        let own = revolute_inertia_column::<S, K>(ic);
        let own = Force::new(own.ang * sign, own.lin * sign);
        // Index loops over equal lengths: no bounds checks, and no
        // vectorised copy with its set-up and remainder for the one to
        // three columns a limb body moves (fewer instructions than zipped
        // iterators on Solo12's CRBA; see the performance notebook, "CRBA").
        if upper {
            // The body's own column and row apart: the mirrors are then
            // stores the compiler knows to be distinct from the column's
            // entries (on Solo12's CRBA faster than mirroring after the
            // pass, though more instructions; see the notebook, "CRBA").
            let (Some((column, columns)), Some((own_row, rows))) =
                (columns.split_first_mut(), rows.split_first_mut())
            else {
                return;
            };
            own_row[iv] = sign * own.ang.get(K);
            *column = turned(&own);
            // The last bound never binds (`rows` ends at row NV at most);
            // it tells the compiler that the mirror's slice fits.
            let n = columns.len().min(rows.len()).min(NV.saturating_sub(iv + 1));
            let (columns, rows) = (&mut columns[..n], &mut rows[..n]);
            let mirror = &mut own_row[iv + 1..iv + 1 + n];
            for d in 0..n {
                let entry = sign * columns[d].ang.get(K);
                rows[d][iv] = entry;
                mirror[d] = entry;
                columns[d] = turned(&columns[d]);
            }
        } else {
            // Through `first_mut`, without a panic path (the caller always
            // passes the body's own column); the loop below projects and
            // moves it with the others.
            if let Some(column) = columns.first_mut() {
                *column = own;
            }
            let n = columns.len().min(rows.len());
            let (columns, rows) = (&mut columns[..n], &mut rows[..n]);
            for d in 0..n {
                rows[d][iv] = sign * columns[d].ang.get(K);
                columns[d] = turned(&columns[d]);
            }
        }
        add_shifted_inertia(
            parent_ic,
            &rotate_inertia_about::<S, K>(c, s, ic),
            &self.trans,
        );
    }
}

/// [`CrbaSpace::crba_free_root`](super::CrbaSpace::crba_free_root) for
/// [`Spatial`](super::Spatial), once the joint is known to be a free flyer.
#[inline(always)]
pub(super) fn free_flyer_root<S: Scalar, const NV: usize>(
    ic: &Inertia<S>,
    columns: &[Force<S>],
    rows: &mut [[S; NV]],
    iv: usize,
    upper: bool,
) {
    let (own, subtree) = rows.split_at_mut(6.min(rows.len()));
    free_flyer_block(ic, own, iv, upper);
    for (d, (row, f)) in subtree.iter_mut().zip(columns).enumerate() {
        let entries = f.to_linear_first();
        row[iv..iv + 6].copy_from_slice(&entries);
        if upper {
            for (own_row, entry) in own.iter_mut().zip(entries) {
                own_row[iv + 6 + d] = entry;
            }
        }
    }
}

/// The lower triangle of a free flyer's block of `M` (with `upper`, the
/// whole block): its inertia as a 6x6 matrix, linear coordinates first,
/// `[[m 1, ·], [m [c×], Ī]]` with `Ī = I_c + m [c×][c×]ᵀ` about the origin.
#[inline(always)]
fn free_flyer_block<S: Scalar, const NV: usize>(
    i: &Inertia<S>,
    rows: &mut [[S; NV]],
    iv: usize,
    upper: bool,
) {
    let (m, z) = (i.mass, S::ZERO);
    let mc = i.com * m;
    let about_origin = i.rot_inertia_at_origin();
    let b = |r: usize, c: usize| about_origin.get(r, c);
    let block: [&[S]; 6] = [
        &[m],
        &[z, m],
        &[z, z, m],
        &[z, -mc.z, mc.y, b(0, 0)],
        &[mc.z, z, -mc.x, b(1, 0), b(1, 1)],
        &[-mc.y, mc.x, z, b(2, 0), b(2, 1), b(2, 2)],
    ];
    for (r, entries) in block.into_iter().enumerate().take(rows.len()) {
        // The caller's rows hold the joint's six coordinates from `iv`.
        let Some(row) = rows[r].get_mut(iv..iv + entries.len()) else {
            return;
        };
        row.copy_from_slice(entries);
        if upper {
            for (c, &entry) in entries.iter().enumerate() {
                rows[c][iv + r] = entry;
            }
        }
    }
}
