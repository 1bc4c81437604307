//! The root-frame backward pass: every column moved once into its tree's
//! root frame, each entry of `M` a dot product there.
//!
//! Why it exists: the local pass moves a subtree's columns one joint per
//! body, O(n·depth) column moves, which on a long chain dominate; here each
//! column is moved once and each entry is a contiguous dot product
//! (Pinocchio's world convention, about the root body so that a floating
//! base's position does not enter). The two terms of each product grow
//! with the distance from the root and cancel, so only `f64` takes it
//! ([`CrbaPass::RootFrame`](super::CrbaPass::RootFrame)).

use super::plan::BodyFrames;
use crate::algorithm::ltdl::supporting_ranges;
use crate::data::Data;
use crate::joint::MAX_JOINT_NV;
use crate::model::Model;
use crate::space::{RigidTransform, Space, VectorOps};
use crate::Scalar;

/// The backward pass for long chains: every column and every subspace
/// column moved once from its body's turned frame into its tree's root
/// frame, each entry below the diagonal then a dot product, 11 operations
/// where moving a column one body up takes 24 (Pinocchio's world
/// convention, about the root body instead of the world so that a
/// floating base's position does not enter). The root frames compose the
/// same steps as the local pass, so a turned joint's rotation mixes two
/// columns of its parent's. The two terms of each product grow with the
/// bodies' distance from the root and cancel to the offset between them,
/// which `f32` could not afford. `step(li_m_i, i)` gives body i's step
/// ([`joint_step`](super::joint_step)); leaves what [`crba_lower`](super::crba_lower) leaves, and with `MIRROR`
/// the upper triangle too.
#[inline(never)]
pub(super) fn about_root<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
    const MIRROR: bool,
>(
    model: &Model<S, NB, NQ, NV, G>,
    frames: &impl BodyFrames<S, NB, G>,
    data: &mut Data<S, NB, NV, G>,
    step: impl Fn(&[G::Transform<S>; NB], usize) -> Option<G::Step<S>>,
) {
    let t = model.topology();
    let identity = <G::Transform<S> as RigidTransform<S>>::IDENTITY;
    // Each body's step to its parent, the root frame from each body's
    // turned frame, and each subspace column in it, stored by components
    // so that a row's dot products run along contiguous arrays, two
    // entries per SIMD instruction on a host.
    let mut steps = [None; NB];
    let mut to_root = [identity; NB];
    let mut s_root = [[S::ZERO; NV]; 6];
    for i in 0..NB {
        steps[i] = step(&data.li_m_i, i);
        if let (Some(p), Some(step)) = (t.parent(i), &steps[i]) {
            to_root[i] = G::then_step(&to_root[p], step);
        }
        let (joint, frame) = (model.joint(i), frames.frame(i));
        for k in 0..t.nv[i] {
            let s = G::act_turned_subspace_column(&to_root[i], frame, joint, k);
            for (d, s_d) in s_root.iter_mut().take(G::DIM).enumerate() {
                s_d[t.idx_v[i] + k] = s.component(d);
            }
        }
    }
    // Each body's columns in the root frame, filled up to its own number
    // of coordinates (cleared once, not per body: a `memset` call each).
    let mut f_root = [[S::ZERO; 6]; MAX_JOINT_NV];
    for i in (0..NB).rev() {
        let (joint, frame) = (model.joint(i), frames.frame(i));
        let iv = t.idx_v[i];
        for (k, f_k) in f_root.iter_mut().enumerate().take(t.nv[i]) {
            let f = G::turned_inertia_column(frame, &data.ic[i], joint, k);
            let f = to_root[i].act_force(&f);
            *f_k = core::array::from_fn(|d| if d < G::DIM { f.component(d) } else { S::ZERO });
        }
        // The composite inertias form one chain of dependent steps: the
        // parent's is stepped before this body's rows, so that it overlaps
        // their dot products (faster on the 60-link chain; see the
        // performance notebook, "CRBA").
        if let (Some(p), Some(step)) = (t.parent(i), &steps[i]) {
            let ic_i = data.ic[i];
            G::add_stepped_inertia(&mut data.ic[p], step, &ic_i);
        }
        for (k, f) in f_root.iter().enumerate().take(t.nv[i]) {
            let c = iv + k;
            let (above, below) = data.mass_matrix.split_at_mut(c);
            let row = &mut below[0];
            // Every supporting coordinate, the joint's own up to c included.
            for (first, last) in supporting_ranges(t, Some(c)) {
                if MIRROR {
                    // The diagonal, which ends the first range, has no mirror.
                    let end = if last == c { c } else { last + 1 };
                    let (row, above) = (&mut row[first..end], &mut above[first..end]);
                    dot_columns_mirrored::<S, NV, G>(row, above, c, &s_root, first, f);
                } else {
                    dot_columns::<S, NV, G>(&mut row[first..=last], &s_root, first, f);
                }
            }
            if MIRROR {
                row[c] = column_dot::<S, NV, G>(&s_root, c, f);
            }
        }
    }
}

/// `row[j] = s_j · f` for the subspace columns `s_j` stored by components
/// in `s`, from column `first` on.
#[inline(always)]
pub(super) fn dot_columns<S: Scalar, const NV: usize, G: Space>(
    row: &mut [S],
    s: &[[S; NV]; 6],
    first: usize,
    f: &[S; 6],
) {
    let n = row.len();
    let s: [&[S]; 6] = core::array::from_fn(|d| &s[d][first..first + n]);
    for j in 0..n {
        row[j] = dot_components::<S, G>(&s, j, f);
    }
}

/// [`dot_columns`] that also writes each entry's mirror, `above[j][c]`
/// (`above` starting at row `first`), while the entry is in a register:
/// cheaper than copying the triangle afterwards, which loads it again
/// (measured on the 60-link chain's CRBA: the performance notebook,
/// "CRBA").
#[inline(always)]
pub(super) fn dot_columns_mirrored<S: Scalar, const NV: usize, G: Space>(
    row: &mut [S],
    above: &mut [[S; NV]],
    c: usize,
    s: &[[S; NV]; 6],
    first: usize,
    f: &[S; 6],
) {
    let n = row.len();
    let above = &mut above[..n];
    let s: [&[S]; 6] = core::array::from_fn(|d| &s[d][first..first + n]);
    for j in 0..n {
        let m = dot_components::<S, G>(&s, j, f);
        row[j] = m;
        above[j][c] = m;
    }
}

/// `s_c · f` for one subspace column, stored by components in `s`.
#[inline(always)]
pub(super) fn column_dot<S: Scalar, const NV: usize, G: Space>(
    s: &[[S; NV]; 6],
    c: usize,
    f: &[S; 6],
) -> S {
    let s: [&[S]; 6] = core::array::from_fn(|d| &s[d][c..=c]);
    dot_components::<S, G>(&s, 0, f)
}

/// `s_j · f` over the space's components, `s` holding them by component.
#[inline(always)]
pub(super) fn dot_components<S: Scalar, G: Space>(s: &[&[S]; 6], j: usize, f: &[S; 6]) -> S {
    let mut acc = s[0][j] * f[0];
    for d in 1..G::DIM {
        acc += s[d][j] * f[d];
    }
    acc
}
