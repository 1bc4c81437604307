//! The composite-rigid-body algorithm for the mass matrix (Featherstone Table 6.2).
//!
//! Everything stays in body coordinates: each body's composite inertia
//! `Iᶜᵢ` and each column `F = Iᶜᵢ Sₖ` of its joint are formed in its own
//! frame, and move to the parent's frame through the joint transform
//! `ˡⁱXᵢ`. Lever arms are a link long, so `f32` keeps its accuracy.
//!
//! The backward pass takes the bodies from the leaves to the root, and at
//! body i:
//! - its columns `F = Iᶜᵢ Sₖ` join those of its subtree, which its children
//!   have already brought into its frame;
//! - the column `F_d` of each coordinate d of the subtree gives row d's
//!   entries against body i's coordinates, `M[d][k] = Sₖᵀ F_d` (for a joint
//!   about a coordinate axis, one component of `F_d`);
//! - the subtree's columns and `Iᶜᵢ` move to the parent's frame, one joint
//!   transform applied to all of them at once (as Pinocchio does).
//!
//! A revolute joint about a coordinate axis whose placement does not rotate
//! (or turns about the same axis) moves vectors by mixing two of their
//! components ([`Space::joint_step`]): a Solo12 leg's joints or a chain's
//! cost about half of a general transform's arithmetic per column and a
//! third per inertia, and their sine and cosine are all the transform that
//! is formed. The columns moved at one body are independent of each other,
//! so an out-of-order core overlaps them.
//!
//! Two cases take the whole step as one fused pass of the geometry's
//! ([`Space::crba_axis_body`], [`Space::crba_free_root`]): a body whose
//! revolute joint's step turns about its own coordinate axis (its column,
//! projections, moves and inertia with that axis known at compile time),
//! and a free-flying root, whose block of `M` is its composite inertia
//! and whose entries are its subtree's columns reordered. Against the
//! same steps one operation at a time: Solo12 CRBA 17 % fewer
//! instructions, the Panda 12 %, the 20-link chain 18 %.
//!
//! With the bodies numbered depth first (URDF order), a body's subtree
//! holds a contiguous range of coordinates; any other tree takes the same
//! steps with a test of support per coordinate. Cost O(n·depth); branches
//! are never coupled. The backward pass fills the lower triangle; for
//! [`crba`] on a host it writes each entry's mirror above the diagonal as
//! it goes, and with subtrees numbered depth first it writes the zeros
//! between unrelated limbs itself.
//!
//! Bodies behind quarter-turn placements (a URDF arm's) are expressed in
//! frames turned by the quarter turns above them
//! ([`TurnedFrame`](crate::spatial::TurnedFrame)), where
//! their joints turn about coordinate axes again: their inertias come
//! turned from the model, each step reads `Q_λ p` from
//! [`Model::turned_placement`], and a turned joint's subspace column is a
//! coordinate axis, possibly reversed. `M` does not depend on the frames.
//! On the Panda this takes a fifth of CRBA's instructions away.
//!
//! Long chains in `f64` take a second form of the backward pass,
//! `about_root`: columns and subspace columns moved once from the turned
//! frames into the root frame, each entry a dot product (Pinocchio's world
//! convention); for [`crba`] on a host it writes each entry's mirror too.

use crate::algorithm::kinematics::{
    body_transform_with, check_state, joint_configuration, JointSinCos, ANGLES_FIRST,
};
use crate::algorithm::ltdl::supporting_ranges;
use crate::algorithm::rnea;
use crate::data::Data;
use crate::error::Result;
use crate::joint::{JointModel, MAX_JOINT_NV};
use crate::model::Model;
use crate::space::{RigidTransform, Space, VectorOps};
use crate::topology::Topology;
use crate::Scalar;

/// Whether the local backward pass writes `M`'s zeros (those between
/// unrelated limbs) and, for [`crba`], its entries above the diagonal
/// itself, as it meets each entry, on hosts (the root-frame pass, for
/// [`crba`], the entries above the diagonal): the separate clear and mirror
/// passes are stores to scattered rows that an out-of-order core
/// otherwise waits on, where the stores in the pass hide among its
/// arithmetic (x86-64 CRBA time: Solo12 -12 %, the UR5 -7 %, the Panda
/// -4 %, for 9 % more instructions). The Cortex-M4, which pays for every
/// instruction, keeps the separate passes (the in-pass form measured
/// there: Panda CRBA +10 %, quadruped +17 %).
const ENTRIES_IN_PASS: bool = cfg!(not(target_arch = "arm"));

/// The joint-space mass matrix `M(q)` (symmetric, NV x NV).
///
/// Inputs: `q` (NQ). Returns `data.mass_matrix` with both triangles filled.
/// Leaves valid: `mass_matrix`, and `ic`, each body's composite inertia
/// (its own and its subtree's) in its turned frame (see the module
/// documentation; the body's own frame at a root and in a model without
/// declared quarter turns).
/// Reads and writes nothing else of `data`.
///
/// # Errors
/// An invalid configuration.
pub fn crba<'d, S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
) -> Result<&'d [[S; NV]; NV]> {
    check_state(model, q, None)?;
    let upper_written = if ENTRIES_IN_PASS {
        mass_matrix_pass::<S, NB, NQ, NV, G, true>(model, data, Some(q))
    } else {
        crba_lower(model, data, Some(q));
        false
    };
    if !upper_written {
        mirror_lower(&mut data.mass_matrix);
    }
    Ok(&data.mass_matrix)
}

/// Copies the lower triangle of `m` onto the upper. On hosts two rows by
/// two columns at a time, so that each row above takes its entries in
/// adjacent pairs (60-link chain CRBA time -3 %); the Cortex-M4, which
/// pays per instruction, one entry at a time (the blocked form measured
/// there: quadruped CRBA +470 instructions).
#[inline]
fn mirror_lower<S: Scalar, const NV: usize>(m: &mut [[S; NV]; NV]) {
    if cfg!(target_arch = "arm") {
        for r in 1..NV {
            for c in 0..r {
                m[c][r] = m[r][c];
            }
        }
        return;
    }
    let mut r = 1;
    while r + 1 < NV {
        // Rows r and r + 1, their common columns in 2 x 2 blocks.
        let mut c = 0;
        while c + 1 < r {
            let (a0, a1, b0, b1) = (m[r][c], m[r][c + 1], m[r + 1][c], m[r + 1][c + 1]);
            m[c][r] = a0;
            m[c][r + 1] = b0;
            m[c + 1][r] = a1;
            m[c + 1][r + 1] = b1;
            c += 2;
        }
        // The rest: at most one column of row r, two of row r + 1.
        for k in c..=r {
            if k < r {
                m[k][r] = m[r][k];
            }
            m[k][r + 1] = m[r + 1][k];
        }
        r += 2;
    }
    if r < NV {
        for k in 0..r {
            m[k][r] = m[r][k];
        }
    }
}

/// [`crba`] without the check of `q` and without mirroring: leaves `M`'s
/// lower triangle (diagonal included) in `data.mass_matrix`; the entries
/// above the diagonal are not written. With `q` `None` it takes the joint
/// transforms from `data.li_m_i`, which must hold them for the
/// configuration (as RNEA leaves them) instead of computing them again.
#[inline(always)]
pub(crate) fn crba_lower<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: Option<&[S; NQ]>,
) {
    mass_matrix_pass::<S, NB, NQ, NV, G, false>(model, data, q);
}

/// [`crba_lower`], which with `UPPER` writes the entries above the
/// diagonal too where it can: the root-frame pass, and the local pass on a
/// tree whose subtrees hold contiguous coordinates; each meets each entry
/// once while it is in a register. Returns whether it did.
#[inline]
fn mass_matrix_pass<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
    const UPPER: bool,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: Option<&[S; NQ]>,
) -> bool {
    let t = model.topology();
    for (i, ic) in data.ic.iter_mut().enumerate() {
        *ic = *model.turned_inertia(i);
    }
    let upper_written = if about_root_pays::<S, NB, NV>(t) {
        clear_lower(t, &mut data.mass_matrix, UPPER);
        // Its steps are formed in a pass of their own already.
        about_root::<S, NB, NQ, NV, G, UPPER>(model, data, |li_m_i, i| {
            joint_step(model, li_m_i, q, None, i)
        });
        UPPER
    } else {
        // Other trees take `clear_lower` (and `crba` the mirror afterwards).
        if !(ENTRIES_IN_PASS && t.subtrees_contiguous) {
            clear_lower(t, &mut data.mass_matrix, false);
        }
        let angles = q.filter(|_| ANGLES_FIRST).map(|q| step_sin_cos(model, q));
        let mut columns = [G::Force::<S>::ZERO; NV];
        for i in (0..NB).rev() {
            let sin_cos = angles.as_ref().map(|a| a.get(i));
            let step = joint_step(model, &data.li_m_i, q, sin_cos, i);
            backward_body(model, data, i, step.as_ref(), &mut columns, UPPER);
        }
        UPPER && ENTRIES_IN_PASS && t.subtrees_contiguous
    };
    add_armature(model, data);
    upper_written
}

/// The sines and cosines of each body's [`Space::step_angle`].
#[inline(always)]
fn step_sin_cos<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
) -> JointSinCos<S, NB> {
    JointSinCos::from_angles(|i| {
        let q = joint_configuration(model, i, q);
        G::step_angle(model.turned_frame(i), model.joint(i), q)
    })
}

/// Body i's step from its turned frame to its parent's, from `q` or, with
/// `q` `None`, from the joint transforms `li_m_i`; `None` at a root, whose
/// transform moves nothing. `sin_cos`: body i's entry of
/// [`step_sin_cos`], when formed.
#[inline(always)]
fn joint_step<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    li_m_i: &[G::Transform<S>; NB],
    q: Option<&[S; NQ]>,
    sin_cos: Option<(S, S)>,
    i: usize,
) -> Option<G::Step<S>> {
    let frame = model.turned_frame(i);
    model.parent(i).map(|_| match q {
        Some(q) => G::turned_joint_step(
            frame,
            model.joint(i),
            model.turned_placement(i),
            joint_configuration(model, i, q),
            sin_cos,
        ),
        None => G::turned_step(frame, &li_m_i[i], model.turned_placement(i)),
    })
}

/// Bias forces and `M`'s lower triangle in one pass over the bodies, for
/// [`Crba`](crate::algorithm::forward_dynamics::Crba): RNEA's forward pass
/// (`a = 0`), then its backward pass with CRBA's step for each body beside
/// its own, which reuse its joint transforms. Leaves `h` in `data.tau` and
/// what [`nonlinear_effects`](crate::algorithm::rnea::nonlinear_effects)
/// and [`crba_lower`] leave; checks nothing.
#[inline]
pub(crate) fn bias_and_mass_lower<
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
    f_ext: Option<&[G::Force<S>; NB]>,
) {
    let t = model.topology();
    let minus_g = -*model.gravity();
    let sin_cos = JointSinCos::at(model, q);
    for i in 0..NB {
        let li_m_i = body_transform_with(model, i, q, sin_cos.as_ref());
        data.ic[i] = *model.turned_inertia(i);
        rnea::forward_body(model, data, i, li_m_i, v, None, f_ext, &minus_g);
    }
    if about_root_pays::<S, NB, NV>(t) {
        clear_lower(t, &mut data.mass_matrix, false);
        rnea::backward_force_pass_with(model, data, None, |_, _| {});
        about_root::<S, NB, NQ, NV, G, false>(model, data, |li_m_i, i| {
            joint_step(model, li_m_i, None, None, i)
        });
    } else {
        if !(ENTRIES_IN_PASS && t.subtrees_contiguous) {
            clear_lower(t, &mut data.mass_matrix, false);
        }
        let mut columns = [G::Force::<S>::ZERO; NV];
        rnea::backward_force_pass_with(model, data, None, |data, i| {
            let step = joint_step(model, &data.li_m_i, None, None, i);
            backward_body(model, data, i, step.as_ref(), &mut columns, false);
        });
    }
    add_armature(model, data);
}

/// Whether [`about_root`] pays: in double precision, on trees whose
/// columns walk past at least `MIN_DEPTH` moving bodies on average (a
/// chain of 51 links or more; an arm or a legged robot never). x86-64,
/// f64, the root-frame pass against the local one (`profile` binary,
/// fastest of alternating runs), CRBA time: 20-link chain +32 %, 30-link
/// +20 %, 40-link +8 %, 50-link +2 %, 60-link -3.5 %; CRBA forward
/// dynamics: 40-link +4 %, 50-link -1 %, 60-link -2.5 %; planar algebra,
/// CRBA: 40-link +16 %, 50-link +4 %, 60-link -12 %. The root frames
/// and the root-frame columns cost two general transforms per body, which
/// only long chains repay. The condition on `NV` is implied by the depth
/// and known at compile time, so smaller models carry no second copy of
/// the pass.
#[inline(always)]
fn about_root_pays<S: Scalar, const NB: usize, const NV: usize>(t: &Topology<NB, NV>) -> bool {
    const MIN_DEPTH: usize = 25;
    NV > 2 * MIN_DEPTH && S::EPSILON < 1.0e-10 && t.mean_support_depth >= MIN_DEPTH
}

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
/// ([`joint_step`]); leaves what [`crba_lower`] leaves, and with `MIRROR`
/// the upper triangle too.
#[inline(never)]
fn about_root<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
    const MIRROR: bool,
>(
    model: &Model<S, NB, NQ, NV, G>,
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
        if let (Some(p), Some(step)) = (t.parents[i], &steps[i]) {
            to_root[i] = G::then_step(&to_root[p], step);
        }
        let (joint, frame) = (model.joint(i), model.turned_frame(i));
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
        let (joint, frame) = (model.joint(i), model.turned_frame(i));
        let iv = t.idx_v[i];
        for (k, f_k) in f_root.iter_mut().enumerate().take(t.nv[i]) {
            let f = G::turned_inertia_column(frame, &data.ic[i], joint, k);
            let f = to_root[i].act_force(&f);
            *f_k = core::array::from_fn(|d| if d < G::DIM { f.component(d) } else { S::ZERO });
        }
        // The composite inertias form one chain of dependent steps: the
        // parent's is stepped before this body's rows, so that it overlaps
        // their dot products (60-link chain CRBA time -6 %).
        if let (Some(p), Some(step)) = (t.parents[i], &steps[i]) {
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
fn dot_columns<S: Scalar, const NV: usize, G: Space>(
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
/// (60-link chain CRBA time -8 %).
#[inline(always)]
fn dot_columns_mirrored<S: Scalar, const NV: usize, G: Space>(
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
fn column_dot<S: Scalar, const NV: usize, G: Space>(s: &[[S; NV]; 6], c: usize, f: &[S; 6]) -> S {
    let s: [&[S]; 6] = core::array::from_fn(|d| &s[d][c..=c]);
    dot_components::<S, G>(&s, 0, f)
}

/// `s_j · f` over the space's components, `s` holding them by component.
#[inline(always)]
fn dot_components<S: Scalar, G: Space>(s: &[&[S]; 6], j: usize, f: &[S; 6]) -> S {
    let mut acc = s[0][j] * f[0];
    for d in 1..G::DIM {
        acc += s[d][j] * f[d];
    }
    acc
}

/// Zeroes the entries below the diagonal that no column reaches: those
/// left of each coordinate's unbroken stretch of supporting coordinates
/// (see [`Topology::chain_start_v`]) that do not support it. A chain has
/// none. With `mirrored`, their mirrors above the diagonal too. The local
/// pass on a tree with contiguous subtrees writes its zeros itself
/// ([`backward_body`]).
#[inline]
fn clear_lower<S: Scalar, const NB: usize, const NV: usize>(
    t: &Topology<NB, NV>,
    m: &mut [[S; NV]; NV],
    mirrored: bool,
) {
    for (k, row) in m.iter_mut().enumerate() {
        // Most rows have nothing to clear (every row of a chain): they
        // skip the fill, which can become a call into `memset` (M4, Panda
        // CRBA 20 instructions fewer).
        let start = t.chain_start_v[k];
        if start > 0 {
            row[..start].fill(S::ZERO);
        }
    }
    if mirrored {
        for (k, &start) in t.chain_start_v.iter().enumerate() {
            for row in &mut m[..start] {
                row[k] = S::ZERO;
            }
        }
    }
}

/// Rotor (armature) inertias, on the diagonal only.
#[inline]
fn add_armature<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
) {
    for (k, armature) in model.armature().iter().enumerate() {
        data.mass_matrix[k][k] += *armature;
    }
}

/// Body i's step of the backward pass: its columns `Iᶜᵢ Sₖ`, its entries
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
fn backward_body<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    i: usize,
    step: Option<&G::Step<S>>,
    columns: &mut [G::Force<S>; NV],
    upper: bool,
) {
    let t = model.topology();
    let joint = model.joint(i);
    let frame = model.turned_frame(i);
    let (iv, nv) = (t.idx_v[i], t.nv[i]);
    let end = t.subtree_end_v[i];
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
        t.parents[i],
        step,
    ) {
        let end = t.subtree_end_v[i];
        let (ancestors, rest) = data.ic.split_at_mut(i);
        if G::crba_axis_body(
            step,
            axis,
            &rest[0],
            &mut ancestors[p],
            &mut columns[iv..end],
            &mut data.mass_matrix[iv..end],
            iv,
            upper,
        ) {
            return;
        }
    }
    if G::FUSES_CRBA_STEPS && t.subtrees_contiguous && t.parents[i].is_none() && nv == 6 {
        let end = t.subtree_end_v[i];
        if G::crba_free_root(
            joint,
            &data.ic[i],
            &columns[iv + 6..end],
            &mut data.mass_matrix[iv..end],
            iv,
            upper,
        ) {
            return;
        }
    }
    for k in 0..nv {
        columns[iv + k] = G::turned_inertia_column(frame, &data.ic[i], joint, k);
    }
    if t.subtrees_contiguous {
        let end = t.subtree_end_v[i];
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
        if let Some(step) = step {
            G::step_forces(step, &mut columns[iv..end]);
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
                    G::step_forces(step, &mut columns[d..=d]);
                }
            }
        }
    }
    if let (Some(p), Some(step)) = (t.parents[i], step) {
        let ic_i = data.ic[i];
        G::add_stepped_inertia(&mut data.ic[p], step, &ic_i);
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
    // `about_root`). On the Panda and Solo12, 4-5 % fewer instructions
    // than zipped slice iterators.
    let (m, columns) = (&mut m[..rows.end], &columns[..rows.end]);
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
                joint.project_force(&columns[d], &mut m[d][iv..=iv]);
                if upper {
                    m[iv][d] = m[d][iv];
                }
            }
        }
        _ => {
            for d in rows {
                if d < iv + nv {
                    let mut projected = [S::ZERO; MAX_JOINT_NV];
                    joint.project_force(&columns[d], &mut projected[..nv]);
                    m[d][iv..=d].copy_from_slice(&projected[..=d - iv]);
                } else {
                    joint.project_force(&columns[d], &mut m[d][iv..iv + nv]);
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

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::{bias_and_mass_lower, crba, crba_lower};
    use crate::algorithm::kinematics::body_transform;
    use crate::joint::{Axis, Joint};
    use crate::spatial::{AxisPermutation, Inertia, Mat3, Motion, Spatial, Sym3, Transform, Vec3};
    use crate::{Data, Model};

    const QUARTER_X: AxisPermutation =
        AxisPermutation::from_rows([[1, 0, 0], [0, 0, -1], [0, 1, 0]]);
    const QUARTER_Y: AxisPermutation =
        AxisPermutation::from_rows([[0, 0, 1], [0, 1, 0], [-1, 0, 0]]);
    const HALF_Z_THEN_X: AxisPermutation =
        AxisPermutation::from_rows([[-1, 0, 0], [0, 0, 1], [0, 1, 0]]);
    const CYCLE: AxisPermutation = AxisPermutation::from_rows([[0, 1, 0], [0, 0, 1], [1, 0, 0]]);

    /// A branched tree with joints about every coordinate axis behind
    /// quarter turns (reversing axes too), a tilted placement under a
    /// turned parent, a prismatic joint and a general axis.
    fn model() -> Model<f64, 7, 7, 7, Spatial> {
        let turned =
            |p: AxisPermutation, t: [f64; 3]| Transform::new(p.matrix(), Vec3::from_array(t));
        let tilted = Mat3::from_axis_angle(&Vec3::new(0.6, 0.0, 0.8), 0.4);
        let inertia = |k: f64| {
            Inertia::new(
                1.0 + k,
                Vec3::new(0.1 * k, -0.05, 0.02 * k),
                Sym3::new(0.3, 0.01 * k, -0.02, 0.4, 0.03, 0.5 + 0.1 * k),
            )
        };
        Model::new(
            [None, Some(0), Some(1), Some(2), Some(1), Some(4), Some(5)],
            [
                Joint::revolute(Axis::Z),
                Joint::revolute(Axis::Z),
                Joint::revolute(Axis::X),
                Joint::revolute(Axis::Y),
                Joint::revolute(Axis::Y),
                Joint::prismatic(Axis::X),
                Joint::revolute(Axis::Unit(Vec3::new(0.0, 0.6, 0.8))),
            ],
            [
                turned(QUARTER_Y, [0.0, 0.0, 0.3]),
                turned(QUARTER_X, [0.1, -0.2, 0.0]),
                turned(HALF_Z_THEN_X, [0.0, 0.3, 0.05]),
                turned(CYCLE, [0.2, 0.0, -0.1]),
                Transform::new(tilted, Vec3::new(0.0, 0.1, 0.2)),
                turned(QUARTER_X, [0.05, 0.0, 0.1]),
                turned(CYCLE, [0.0, 0.0, 0.15]),
            ],
            core::array::from_fn(|k| inertia(k as f64)),
            Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
        )
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-13 * (1.0 + a.abs().max(b.abs()))
    }

    #[test]
    fn turned_frames_give_the_unturned_mass_matrix_on_every_path() {
        let plain = model();
        let declared = plain.with_placement_turns([
            Some(QUARTER_Y),
            Some(QUARTER_X),
            Some(HALF_Z_THEN_X),
            Some(CYCLE),
            None,
            Some(QUARTER_X),
            Some(CYCLE),
        ]);
        let recognised = plain.with_recognised_turns();
        assert_eq!(declared.turned_frame(3), recognised.turned_frame(3));
        // Bodies 1-3 turn; 4 (tilted), 5 (prismatic) and 6 (general axis) keep their frames.
        for (i, turned) in [
            (1, true),
            (2, true),
            (3, true),
            (4, false),
            (5, false),
            (6, false),
        ] {
            assert_eq!(
                recognised.turned_frame(i).axis().is_some(),
                turned,
                "body {i}"
            );
        }
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut random = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 6.0 - 3.0
        };
        let mut reference = Data::new();
        let mut data = Data::new();
        for _ in 0..20 {
            let q: [f64; 7] = core::array::from_fn(|_| random());
            let v: [f64; 7] = core::array::from_fn(|_| random());
            let expected = *crba(&plain, &mut reference, &q).unwrap();
            for model in [&declared, &recognised] {
                let lower = |m: &[[f64; 7]; 7], what: &str| {
                    for r in 0..7 {
                        for c in 0..=r {
                            let (a, b) = (m[r][c], expected[r][c]);
                            assert!(close(a, b), "{what}: M[{r}][{c}] {a} against {b}");
                        }
                    }
                };
                lower(crba(model, &mut data, &q).unwrap(), "crba");
                // From the joint transforms RNEA leaves (the Cortex-M's path).
                for i in 0..7 {
                    data.li_m_i[i] = body_transform(model, i, &q);
                }
                crba_lower(model, &mut data, None);
                lower(&data.mass_matrix, "from transforms");
                bias_and_mass_lower(model, &mut data, &q, &v, None);
                lower(&data.mass_matrix, "fused with the bias forces");
            }
        }
    }

    /// A 52-link chain, long enough in `f64` for the root-frame pass.
    fn long_chain() -> Model<f64, 52, 52, 52, Spatial> {
        long_tree(
            core::array::from_fn(|i| i.checked_sub(1)),
            Joint::revolute(Axis::X),
        )
    }

    /// A tree on `parents`, body 0 on `root`, the others on
    /// single-coordinate joints: about every axis behind quarter turns,
    /// tilted placements, a prismatic joint and a general axis.
    fn long_tree<const NB: usize, const NQ: usize, const NV: usize>(
        parents: [Option<usize>; NB],
        root: Joint<f64>,
    ) -> Model<f64, NB, NQ, NV, Spatial> {
        let turns = [QUARTER_X, QUARTER_Y, HALF_Z_THEN_X, CYCLE];
        let tilted = Mat3::from_axis_angle(&Vec3::new(0.6, 0.0, 0.8), 0.4);
        Model::new(
            parents,
            core::array::from_fn(|i| match i % 7 {
                _ if i == 0 => root,
                3 => Joint::prismatic(Axis::Y),
                5 => Joint::revolute(Axis::Unit(Vec3::new(0.0, 0.6, 0.8))),
                k => Joint::revolute([Axis::X, Axis::Y, Axis::Z][k % 3]),
            }),
            core::array::from_fn(|i| {
                let rot = match i % 5 {
                    4 => tilted,
                    0 => Mat3::IDENTITY,
                    k => turns[(i + k) % 4].matrix(),
                };
                let k = i as f64;
                Transform::new(rot, Vec3::new(0.1 + 0.01 * k, -0.02 * (k % 3.0), 0.05))
            }),
            core::array::from_fn(|i| {
                let k = (i % 4) as f64;
                Inertia::new(
                    0.5 + k,
                    Vec3::new(0.05 * k, -0.02, 0.01 * k),
                    Sym3::new(0.03, 0.001 * k, -0.002, 0.04, 0.003, 0.05 + 0.01 * k),
                )
            }),
            Motion::new(Vec3::ZERO, Vec3::ZERO),
        )
    }

    #[test]
    fn the_root_frame_pass_gives_rneas_columns_with_and_without_turns() {
        let plain = long_chain();
        assert!(super::about_root_pays::<f64, 52, 52>(plain.topology()));
        let turned = plain.with_recognised_turns();
        let turned_bodies = (0..52)
            .filter(|&i| turned.turned_frame(i).axis().is_some())
            .count();
        assert!(turned_bodies >= 8, "{turned_bodies} turned bodies");
        let q: [f64; 52] = core::array::from_fn(|k| (0.7 * k as f64).sin() * 1.5);
        for model in [&plain, &turned] {
            assert_rneas_columns(model, &q);
        }
    }

    #[test]
    fn the_root_frame_pass_fills_the_zeros_between_branches() {
        // A 40-link trunk; a 10-link branch from its tip and another from
        // its 31st link, whose coordinates and the first's share zeros.
        let parents = core::array::from_fn(|i| match i {
            0 => None,
            50 => Some(30),
            i => Some(i - 1),
        });
        let model = long_tree::<60, 60, 60>(parents, Joint::revolute(Axis::X));
        assert!(super::about_root_pays::<f64, 60, 60>(model.topology()));
        let q: [f64; 60] = core::array::from_fn(|k| (0.9 * k as f64).cos() * 1.2);
        assert_rneas_columns(&model, &q);
        let m = *crba(&model, &mut Data::new(), &q).unwrap();
        assert_eq!((m[55][45], m[45][55]), (0.0, 0.0));
    }

    #[test]
    fn the_root_frame_pass_takes_a_free_flying_root() {
        // A 60-link chain on a free flyer: the root's six coordinates form
        // a block whose entries below its diagonal are dot products too.
        let parents = core::array::from_fn(|i: usize| i.checked_sub(1));
        let model = long_tree::<61, 67, 66>(parents, Joint::free_flyer());
        assert!(super::about_root_pays::<f64, 61, 66>(model.topology()));
        let norm = (0.01f64 + 0.04 + 0.09 + 0.86).sqrt();
        let q: [f64; 67] = core::array::from_fn(|k| match k {
            0..3 => 0.3 * k as f64 - 0.2,
            3..7 => [0.1, -0.2, 0.3, 0.86f64.sqrt()][k - 3] / norm,
            k => (0.9 * k as f64).cos() * 1.2,
        });
        assert_rneas_columns(&model, &q);
    }

    /// Holds `M` from [`crba`], from the joint transforms and fused with
    /// the bias forces to RNEA's columns (column k is the torque for the
    /// unit acceleration of coordinate k, without velocities), to 1e-12.
    /// The model has no gravity.
    fn assert_rneas_columns<const NB: usize, const NQ: usize, const NV: usize>(
        model: &Model<f64, NB, NQ, NV, Spatial>,
        q: &[f64; NQ],
    ) {
        use crate::algorithm::rnea::rnea;
        let v = [0.0; NV];
        let mut data = Data::new();
        let mut expected = [[0.0; NV]; NV];
        for k in 0..NV {
            let mut a = [0.0; NV];
            a[k] = 1.0;
            let tau = *rnea(model, &mut data, q, &v, &a, None).unwrap();
            for r in 0..NV {
                expected[r][k] = tau[r];
            }
        }
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + a.abs().max(b.abs()));
        // Every entry written, the zeros of unrelated limbs included.
        data.mass_matrix = [[f64::NAN; NV]; NV];
        let m = *crba(model, &mut data, q).unwrap();
        for i in 0..NB {
            data.li_m_i[i] = body_transform(model, i, q);
        }
        data.mass_matrix = [[f64::NAN; NV]; NV];
        crba_lower(model, &mut data, None);
        let from_transforms = data.mass_matrix;
        data.mass_matrix = [[f64::NAN; NV]; NV];
        bias_and_mass_lower(model, &mut data, q, &v, None);
        for r in 0..NV {
            for c in 0..NV {
                let e = expected[r][c];
                assert!(
                    close(m[r][c], e),
                    "crba: M[{r}][{c}] {} against {e}",
                    m[r][c]
                );
                if c > r {
                    continue;
                }
                for (what, got) in [
                    ("from transforms", from_transforms[r][c]),
                    ("fused", data.mass_matrix[r][c]),
                ] {
                    assert!(close(got, e), "{what}: M[{r}][{c}] {got} against {e}");
                }
            }
        }
    }

    /// A free-flying base with two limbs (`parents`): joints about every
    /// axis behind quarter turns, behind placements that turn about the
    /// joint's own axis or not at all, a prismatic joint and a general
    /// axis; no gravity.
    fn floating_tree(parents: [Option<usize>; 8]) -> Model<f64, 8, 14, 13, Spatial> {
        let turned =
            |p: AxisPermutation, t: [f64; 3]| Transform::new(p.matrix(), Vec3::from_array(t));
        let (s, c) = 0.3f64.sin_cos();
        Model::new(
            parents,
            [
                Joint::free_flyer(),
                Joint::revolute(Axis::X),
                Joint::revolute(Axis::Z),
                Joint::revolute(Axis::Y),
                Joint::revolute(Axis::Z),
                Joint::revolute(Axis::Y),
                Joint::prismatic(Axis::X),
                Joint::revolute(Axis::Unit(Vec3::new(0.0, 0.6, 0.8))),
            ],
            [
                Transform::IDENTITY,
                turned(QUARTER_Y, [0.1, 0.2, 0.0]),
                turned(QUARTER_X, [0.0, 0.0, 0.3]),
                turned(HALF_Z_THEN_X, [0.05, 0.3, 0.0]),
                Transform::new(Mat3::from_axis_index(2, s, c), Vec3::new(-0.1, 0.2, 0.0)),
                Transform::new(Mat3::IDENTITY, Vec3::new(0.0, 0.25, 0.1)),
                turned(CYCLE, [0.2, 0.0, -0.1]),
                Transform::new(Mat3::IDENTITY, Vec3::new(0.0, 0.1, 0.15)),
            ],
            core::array::from_fn(|i| {
                let k = i as f64;
                Inertia::new(
                    0.7 + k,
                    Vec3::new(0.04 * k, -0.03, 0.02 * k),
                    Sym3::new(0.3, 0.01 * k, -0.02, 0.4, 0.03, 0.5 + 0.1 * k),
                )
            }),
            Motion::new(Vec3::ZERO, Vec3::ZERO),
        )
        .with_recognised_turns()
    }

    #[test]
    fn a_floating_tree_gives_rneas_columns_in_either_body_order() {
        // Limbs {1, 2, 3} and {4, 5, 6, 7} (5 branching), each subtree's
        // coordinates contiguous; then the same joints with the limbs'
        // bodies interleaved, which the pass walks with a test of support.
        let contiguous = floating_tree([
            None,
            Some(0),
            Some(1),
            Some(2),
            Some(0),
            Some(4),
            Some(5),
            Some(5),
        ]);
        assert!(contiguous.topology().subtrees_contiguous);
        let interleaved = floating_tree([
            None,
            Some(0),
            Some(1),
            Some(2),
            Some(0),
            Some(4),
            Some(5),
            Some(3),
        ]);
        assert!(!interleaved.topology().subtrees_contiguous);
        for model in [&contiguous, &interleaved] {
            let turned = (1..8)
                .filter(|&i| model.turned_frame(i).axis().is_some())
                .count();
            assert!(turned >= 3, "{turned} turned bodies");
        }
        let mut q: [f64; 14] = core::array::from_fn(|k| (0.9 * k as f64 + 0.4).sin() * 1.3);
        let norm = q[3..7].iter().map(|x| x * x).sum::<f64>().sqrt();
        q[3..7].iter_mut().for_each(|x| *x /= norm);
        assert_rneas_columns(&contiguous, &q);
        assert_rneas_columns(&interleaved, &q);
    }

    /// Every entry above the diagonal is its mirror's, at every parity of
    /// the size (the host's copy goes by 2 x 2 blocks).
    fn assert_mirrors<const N: usize>() {
        let mut m = [[f64::NAN; N]; N];
        for (r, row) in m.iter_mut().enumerate() {
            for (c, e) in row.iter_mut().enumerate().take(r + 1) {
                *e = (10 * r + c) as f64;
            }
        }
        super::mirror_lower(&mut m);
        for r in 0..N {
            for c in 0..N {
                let e = (10 * r.max(c) + r.min(c)) as f64;
                assert_eq!(m[r][c], e, "N = {N}: M[{r}][{c}]");
            }
        }
    }

    #[test]
    fn the_mirror_fills_the_upper_triangle_at_every_size() {
        assert_mirrors::<1>();
        assert_mirrors::<2>();
        assert_mirrors::<3>();
        assert_mirrors::<4>();
        assert_mirrors::<5>();
        assert_mirrors::<8>();
        assert_mirrors::<13>();
    }

    #[test]
    fn a_placement_set_at_run_time_is_recognised_or_not() {
        let plain = model();
        let mut turned = plain.with_recognised_turns();
        let tilted = Transform::new(
            Mat3::from_axis_angle(&Vec3::new(1.0, 0.0, 0.0), 0.3),
            Vec3::new(0.1, -0.2, 0.0),
        );
        turned.set_placement(1, tilted).unwrap();
        assert!(turned.turned_frame(1).axis().is_none());
        // Its child's frame no longer includes the parent's turn.
        assert_eq!(
            turned.turned_frame(2).parent_turn(),
            AxisPermutation::IDENTITY
        );
        let mut reference_model = plain;
        reference_model.set_placement(1, tilted).unwrap();
        let q = [0.3, -1.1, 0.7, 2.0, -0.4, 0.1, 0.9];
        let (mut a, mut b) = (Data::new(), Data::new());
        let expected = *crba(&reference_model, &mut a, &q).unwrap();
        let got = *crba(&turned, &mut b, &q).unwrap();
        for r in 0..7 {
            for c in 0..7 {
                assert!(close(got[r][c], expected[r][c]), "M[{r}][{c}]");
            }
        }
        // Back to a quarter turn: recognised again.
        turned
            .set_placement(1, Transform::new(QUARTER_Y.matrix(), Vec3::ZERO))
            .unwrap();
        assert!(turned.turned_frame(1).axis().is_some());
        let inertia = Inertia::new(2.5, Vec3::new(0.0, 0.1, 0.0), Sym3::diagonal(0.2, 0.3, 0.4));
        turned.set_inertia(2, inertia).unwrap();
        assert_eq!(
            *turned.turned_inertia(2),
            turned.turned_frame(2).turn().apply_inertia(&inertia)
        );
    }
}
