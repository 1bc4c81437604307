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
//!   up the supporting bodies by `n ← n + d × f`, giving `H_λᵢ = S̄_λᵀ F`;
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
use crate::data::Data;
use crate::error::Result;
use crate::model::Model;
use crate::space::{BodyInertia, MotionVector, RigidTransform, Space, VectorOps};
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
    let t = model.topology();
    // Per coordinate: its subspace column in its body's aligned frame, and
    // the step from it to its λ: when it is its body's first coordinate,
    // the offset of its body's origin from that of the nearest supporting
    // body with coordinates (the parent's `dᵢ`, plus the offsets of any
    // fixed bodies between); none otherwise.
    let zero = <G::Transform<S> as RigidTransform<S>>::IDENTITY.translation();
    let mut s_bar = [G::Motion::<S>::ZERO; NV];
    let mut steps = [None; NV];
    // For a body without coordinates, its offset from that nearest body.
    let mut reach = [zero; NB];
    let frames = &mut data.o_m_i;
    for i in 0..NB {
        let li_m_i = match q {
            Some(q) => body_transform(model, i, q),
            None => data.li_m_i[i],
        };
        let joint = model.joint(i);
        // A root body's frame is its own: its axes are the aligned ones.
        let frame = match t.parents[i] {
            None => <G::Transform<S> as RigidTransform<S>>::IDENTITY,
            Some(p) => match t.parents[p] {
                None => li_m_i,
                Some(_) => G::rotate_transform(&frames[p], &li_m_i),
            },
        };
        data.ic[i] = G::rotate_inertia(model.inertia(i), &frame);
        let iv = t.idx_v[i];
        for k in 0..t.nv[i] {
            s_bar[iv + k] = G::rotate_subspace_column(joint, k, &frame);
        }
        let d = match t.parents[i] {
            Some(p) if t.nv[p] == 0 => frame.translation() + reach[p],
            _ => frame.translation(),
        };
        if t.nv[i] > 0 {
            steps[iv] = Some(d);
        } else {
            reach[i] = d;
        }
        frames[i] = frame;
        data.li_m_i[i] = li_m_i;
    }
    let (frames, ic, mass_matrix) = (&data.o_m_i, &mut data.ic, &mut data.mass_matrix);
    for i in (0..NB).rev() {
        for c in t.idx_v[i]..t.idx_v[i] + t.nv[i] {
            let row = &mut mass_matrix[c];
            let mut f = ic[i].mul_motion(&s_bar[c]);
            row[c] = s_bar[c].dot(&f);
            // Down λ from c: F about each coordinate's body origin, projected
            // on its column. λ runs in unbroken stretches (a chain is one),
            // each walked as slices; the coordinates between two stretches
            // do not support c, and their entries are zero.
            let mut m = c;
            loop {
                let start = t.chain_start_v[m];
                let stretch = s_bar[start..m].iter().zip(&steps[start + 1..=m]);
                for ((s, step), h) in stretch.zip(&mut row[start..m]).rev() {
                    if let Some(step) = step {
                        f = G::translate_force(&f, step);
                    }
                    *h = s.dot(&f);
                }
                match t.lambda_v[start] {
                    Some(p) => {
                        row[p + 1..start].fill(S::ZERO);
                        if let Some(step) = &steps[start] {
                            f = G::translate_force(&f, step);
                        }
                        row[p] = s_bar[p].dot(&f);
                        m = p;
                    }
                    None => {
                        row[..start].fill(S::ZERO);
                        break;
                    }
                }
            }
        }
        if let Some(p) = t.parents[i] {
            let ic_i = ic[i];
            G::add_translated_inertia(&mut ic[p], &ic_i, &frames[i]);
        }
    }
    // Rotor (armature) inertias sit on the diagonal only.
    for (k, armature) in model.armature().iter().enumerate() {
        mass_matrix[k][k] += *armature;
    }
}
