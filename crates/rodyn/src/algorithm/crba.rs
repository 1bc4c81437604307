//! The composite-rigid-body algorithm for the mass matrix (Featherstone Table 6.2).
//!
//! It runs in aligned frames: frame ī of body i has its origin at body i's
//! origin and the axes of its tree's root body. The lever arms stay local
//! (a body's own size, not its distance from some common origin, which
//! would cancel badly in `f32`), the root body's quantities are never
//! rotated (a floating base's block stays exact), and every move between
//! two frames is a translation, with no rotation:
//!
//! - forward pass: `ʳRᵢ = ʳR_λ ˡⁱRᵢ` and the offset `dᵢ = ʳR_λ ˡⁱpᵢ` of
//!   body i's origin from its parent's, then each body's inertia and its
//!   joint's subspace columns rotated into frame ī (`S̄ = ʳRᵢ S`); a root
//!   body's frame is its own;
//! - backward pass: each column `F = Iᶜᵢ S̄ₖ` gives `Hᵢᵢ = S̄ᵀ F`, then travels
//!   up the supporting bodies by `n ← n + d × f`, giving `H_λᵢ = S̄_λᵀ F`
//!   (a column and its λ, as along a chain, go up together);
//!   the composite inertia moves to the parent by the parallel-axis
//!   theorem (`Iᶜ_λ += Iᶜᵢ` shifted by `dᵢ`).
//!
//! The composite inertias are kept about each body's origin in the linear
//! parametrisation (mass, first moment `h = m c`, rotational inertia `Ī`):
//! adding a child's is a sum with a parallel-axis term, with no division
//! by the combined mass on the pass's critical path.
//!
//! Cost O(n·depth); only ancestors are visited, so branches are never
//! coupled. The backward pass fills the lower triangle only.

use crate::algorithm::kinematics::{body_transform, check_state};
use crate::algorithm::rnea;
use crate::data::Data;
use crate::error::Result;
use crate::model::Model;
use crate::space::{BodyInertia, MotionVector, RigidTransform, Space, VectorOps};
use crate::topology::Topology;
use crate::Scalar;

/// The joint-space mass matrix `M(q)` (symmetric, NV x NV).
///
/// Inputs: `q` (NQ). Returns `data.mass_matrix` with both triangles filled.
/// Leaves valid: `li_m_i`, `mass_matrix`, and `ic`, the composite inertias
/// in the aligned frames described in the [module](self) documentation
/// (origin at the body's origin, axes of its tree's root body). `o_m_i` is
/// used as scratch: it holds `(ʳRᵢ, dᵢ)`, not body poses.
///
/// # Errors
/// An invalid configuration.
pub fn crba<'d, S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
) -> Result<&'d [[S; NV]; NV]> {
    check_state(model, q, None)?;
    crba_lower(model, data, Some(q));
    let m = &mut data.mass_matrix;
    for r in 1..NV {
        for c in 0..r {
            m[c][r] = m[r][c];
        }
    }
    Ok(&data.mass_matrix)
}

/// Whether the forward pass rotates the body inertias in a loop of their
/// own after the frames instead of beside each frame. The frames form one
/// dependency chain (each is its parent's times the joint's); the
/// rotations depend only on their own frame, and an out-of-order core
/// overlaps them once they no longer sit between two links of that chain
/// (x86-64: 3 to 7 % less time with about as many instructions). The
/// in-order Cortex-M4 gains nothing and pays for reading the frames back.
const ROTATE_AFTER_FRAMES: bool = cfg!(not(target_arch = "arm"));

/// [`crba`] without the check of `q` and without mirroring: leaves `M`'s
/// lower triangle (diagonal included) in `data.mass_matrix`; the entries
/// above the diagonal are not written. With `q` `None` it takes the joint
/// transforms from `data.li_m_i`, which must hold them for the
/// configuration (as RNEA leaves them) instead of computing them again.
#[inline]
pub(crate) fn crba_lower<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: Option<&[S; NQ]>,
) {
    let mut columns = Columns::new();
    for i in 0..NB {
        let li_m_i = match q {
            Some(q) => body_transform(model, i, q),
            None => data.li_m_i[i],
        };
        columns.body(model, data, i, &li_m_i);
        data.li_m_i[i] = li_m_i;
    }
    columns.rotate_inertias(model, data);
    let mut pending = None;
    for i in (0..NB).rev() {
        columns.backward_body(model, data, i, &mut pending);
    }
    columns.finish(model, data);
}

/// Bias forces and `M`'s lower triangle in one pass over the bodies, for
/// [`Crba`](crate::algorithm::forward_dynamics::Crba): each joint
/// transform is computed once and used at once by RNEA's forward pass
/// (`a = 0`) and CRBA's. Leaves `h` in `data.tau` and what
/// [`nonlinear_effects`](crate::algorithm::rnea::nonlinear_effects) and
/// [`crba_lower`] leave; checks nothing.
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
    let minus_g = -*model.gravity();
    let mut columns = Columns::new();
    for i in 0..NB {
        let li_m_i = body_transform(model, i, q);
        columns.body(model, data, i, &li_m_i);
        rnea::forward_body(model, data, i, li_m_i, v, None, f_ext, &minus_g);
    }
    columns.rotate_inertias(model, data);
    let mut pending = None;
    rnea::backward_force_pass_with(model, data, None, |data, i| {
        columns.backward_body(model, data, i, &mut pending);
    });
    columns.finish(model, data);
}

/// CRBA's passes a body at a time, so that [`crba_lower`] runs them in its
/// own loops and [`bias_and_mass_lower`] beside RNEA's.
///
/// The forward pass's products that the backward pass reads besides the
/// frames (`o_m_i`) and the rotated inertias (`ic`). Per coordinate: its
/// subspace column in its body's aligned frame, and the step from it to
/// its λ: when it is its body's first coordinate, the offset of its body's
/// origin from that of the nearest supporting body with coordinates (the
/// parent's `dᵢ`, plus the offsets of any fixed bodies between); none
/// otherwise.
pub(crate) struct Columns<S: Scalar, const NB: usize, const NV: usize, G: Space> {
    s_bar: [G::Motion<S>; NV],
    steps: [Option<G::Point<S>>; NV],
    /// For a body without coordinates, its offset from that nearest body.
    reach: [G::Point<S>; NB],
}

impl<S: Scalar, const NB: usize, const NV: usize, G: Space> Columns<S, NB, NV, G> {
    #[inline(always)]
    pub(crate) fn new() -> Self {
        let zero = <G::Transform<S> as RigidTransform<S>>::IDENTITY.translation();
        Self {
            s_bar: [G::Motion::<S>::ZERO; NV],
            steps: [None; NV],
            reach: [zero; NB],
        }
    }

    /// Body i's step of the forward pass, given its joint
    /// transform (its parent's frame must be in `data.o_m_i` already): its
    /// frame, and on the Cortex-M4 its rotated inertia (hosts rotate them
    /// all afterwards, [`Self::rotate_inertias`]).
    #[inline(always)]
    pub(crate) fn body<const NQ: usize>(
        &mut self,
        model: &Model<S, NB, NQ, NV, G>,
        data: &mut Data<S, NB, NV, G>,
        i: usize,
        li_m_i: &G::Transform<S>,
    ) {
        let t = model.topology();
        let frames = &mut data.o_m_i;
        let joint = model.joint(i);
        // A root body's frame is its own: its axes are the aligned ones.
        let frame = match t.parents[i] {
            None => <G::Transform<S> as RigidTransform<S>>::IDENTITY,
            Some(p) => match t.parents[p] {
                None => *li_m_i,
                Some(_) => G::rotate_transform(&frames[p], li_m_i),
            },
        };
        if !ROTATE_AFTER_FRAMES {
            data.ic[i] = G::rotate_inertia(model.inertia(i), &frame);
        }
        let iv = t.idx_v[i];
        for k in 0..t.nv[i] {
            self.s_bar[iv + k] = G::rotate_subspace_column(joint, k, &frame);
        }
        let d = match t.parents[i] {
            Some(p) if t.nv[p] == 0 => frame.translation() + self.reach[p],
            _ => frame.translation(),
        };
        if t.nv[i] > 0 {
            self.steps[iv] = Some(d);
        } else {
            self.reach[i] = d;
        }
        frames[i] = frame;
    }

    /// On hosts, every body's inertia rotated into its frame.
    #[inline(always)]
    pub(crate) fn rotate_inertias<const NQ: usize>(
        &self,
        model: &Model<S, NB, NQ, NV, G>,
        data: &mut Data<S, NB, NV, G>,
    ) {
        if ROTATE_AFTER_FRAMES {
            for (i, (ic, frame)) in data.ic.iter_mut().zip(&data.o_m_i).enumerate() {
                *ic = G::rotate_inertia(model.inertia(i), frame);
            }
        }
    }

    /// Body i's step of the backward pass (bodies from the last to the
    /// first): its columns of `M` and its composite inertia added to its
    /// parent's. `pending` carries a column that waits for the next one
    /// down; `None` before the first body.
    #[inline(always)]
    pub(crate) fn backward_body<const NQ: usize>(
        &self,
        model: &Model<S, NB, NQ, NV, G>,
        data: &mut Data<S, NB, NV, G>,
        i: usize,
        pending: &mut Option<(usize, G::Force<S>)>,
    ) {
        let t = model.topology();
        let (s_bar, steps) = (&self.s_bar, &self.steps);
        let (frames, ic, mass_matrix) = (&data.o_m_i, &mut data.ic, &mut data.mass_matrix);
        // A column whose λ is the next column down waits for it, and the
        // two then walk λ together: they share every step and every `S̄`,
        // loaded once for both.
        for c in (t.idx_v[i]..t.idx_v[i] + t.nv[i]).rev() {
            let f = ic[i].mul_motion(&s_bar[c]);
            mass_matrix[c][c] = s_bar[c].dot(&f);
            match pending.take() {
                // `a = c + 1`, and `c` is its λ.
                Some((a, mut f_a)) => {
                    if let Some(step) = &steps[a] {
                        f_a = G::translate_force(&f_a, step);
                    }
                    let (below, above) = mass_matrix.split_at_mut(a);
                    if let (Some(row_c), Some(row_a)) = (below.last_mut(), above.first_mut()) {
                        row_a[c] = s_bar[c].dot(&f_a);
                        walk_lambda::<S, NB, NV, G, _, 2>(
                            t,
                            s_bar,
                            steps,
                            c,
                            [row_a, row_c],
                            [f_a, f],
                            |f, d| f.map(|f| G::translate_force(&f, d)),
                            |s, f| f.map(|f| s.dot(&f)),
                        );
                    }
                }
                None if c > 0 && t.lambda_v[c] == Some(c - 1) => *pending = Some((c, f)),
                None => walk_lambda::<S, NB, NV, G, _, 1>(
                    t,
                    s_bar,
                    steps,
                    c,
                    [&mut mass_matrix[c]],
                    f,
                    G::translate_force,
                    |s, f| [s.dot(f)],
                ),
            }
        }
        if let Some(p) = t.parents[i] {
            let ic_i = ic[i];
            G::add_translated_inertia(&mut ic[p], &ic_i, &frames[i]);
        }
    }

    /// Rotor (armature) inertias, on the diagonal only.
    #[inline(always)]
    pub(crate) fn finish<const NQ: usize>(
        &self,
        model: &Model<S, NB, NQ, NV, G>,
        data: &mut Data<S, NB, NV, G>,
    ) {
        for (k, armature) in model.armature().iter().enumerate() {
            data.mass_matrix[k][k] += *armature;
        }
    }
}

/// Fills `K` rows of `M` below column `m`, given their forces `f` about
/// the origin of `m`'s body: down λ from `m`, the forces about each
/// coordinate's body origin (`step`), projected on its column (`dot`). λ
/// runs in unbroken stretches (a chain is one), each walked as slices; the
/// coordinates between two stretches do not support `m`, and their entries
/// are zero.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn walk_lambda<S: Scalar, const NB: usize, const NV: usize, G: Space, F: Copy, const K: usize>(
    t: &Topology<NB, NV>,
    s_bar: &[G::Motion<S>; NV],
    steps: &[Option<G::Point<S>>; NV],
    mut m: usize,
    mut rows: [&mut [S; NV]; K],
    mut f: F,
    step: impl Fn(&F, &G::Point<S>) -> F,
    dot: impl Fn(&G::Motion<S>, &F) -> [S; K],
) {
    loop {
        let start = t.chain_start_v[m];
        let stretch = s_bar[start..m].iter().zip(&steps[start + 1..=m]);
        let mut h = rows.each_mut().map(|row| &mut row[start..m]);
        for (j, (s, d)) in stretch.enumerate().rev() {
            if let Some(d) = d {
                f = step(&f, d);
            }
            for (h, value) in h.iter_mut().zip(dot(s, &f)) {
                h[j] = value;
            }
        }
        match t.lambda_v[start] {
            Some(p) => {
                if let Some(d) = &steps[start] {
                    f = step(&f, d);
                }
                for (row, value) in rows.iter_mut().zip(dot(&s_bar[p], &f)) {
                    row[p + 1..start].fill(S::ZERO);
                    row[p] = value;
                }
                m = p;
            }
            None => {
                for row in &mut rows {
                    row[..start].fill(S::ZERO);
                }
                break;
            }
        }
    }
}
