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
//!   joint's subspace columns rotated into frame ī (`S̄ = ʳRᵢ S`);
//! - backward pass: each column `F = Iᶜᵢ S̄ₖ` gives `Hᵢᵢ = S̄ᵀ F`, then travels
//!   up the supporting bodies by `n ← n + d × f`, giving `H_λᵢ = S̄_λᵀ F`;
//!   the composite inertia moves to the parent by shifting its centre of
//!   mass by `dᵢ` (`Iᶜ_λ += Iᶜᵢ`).
//!
//! Cost O(n·depth); only ancestors are visited, so branches are never
//! coupled. The backward pass fills the lower triangle only.

use crate::algorithm::kinematics::{body_transform, check_state};
use crate::data::Data;
use crate::error::Result;
use crate::joint::JointModel;
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
    crba_lower(model, data, q);
    let m = &mut data.mass_matrix;
    for r in 1..NV {
        for c in 0..r {
            m[c][r] = m[r][c];
        }
    }
    Ok(&data.mass_matrix)
}

/// [`crba`] without the check of `q` and without mirroring: leaves `M`'s
/// lower triangle (diagonal included) in `data.mass_matrix` and zeros above.
#[inline]
pub(crate) fn crba_lower<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
) {
    let t = model.topology();
    // The subspace columns in the aligned frames, one per coordinate.
    let mut s_bar = [G::Motion::<S>::ZERO; NV];
    let frames = &mut data.o_m_i;
    for i in 0..NB {
        let li_m_i = body_transform(model, i, q);
        let joint = model.joint(i);
        let columns = &mut s_bar[t.idx_v[i]..t.idx_v[i] + t.nv[i]];
        let inertia = model.inertia(i);
        frames[i] = match t.parents[i] {
            // A root body's frame is its own: nothing to rotate.
            None => {
                data.ic[i] = *inertia;
                for (k, s) in columns.iter_mut().enumerate() {
                    *s = joint.subspace_column(k);
                }
                <G::Transform<S> as RigidTransform<S>>::IDENTITY
            }
            Some(p) => {
                let frame = match t.parents[p] {
                    None => li_m_i,
                    Some(_) => G::rotate_transform(&frames[p], &li_m_i),
                };
                data.ic[i] = G::rotate_inertia(inertia, &frame);
                for (k, s) in columns.iter_mut().enumerate() {
                    *s = G::rotate_subspace_column(joint, k, &frame);
                }
                frame
            }
        };
        data.li_m_i[i] = li_m_i;
    }
    // The pass below writes every entry between a coordinate and its
    // supporting coordinates; entries between unrelated branches are
    // structurally zero. Clearing the matrix once (O(n²)) sets them far more
    // cheaply than testing every pair for support (O(n² · depth)).
    data.mass_matrix = [[S::ZERO; NV]; NV];
    let (frames, ic, mass_matrix) = (&data.o_m_i, &mut data.ic, &mut data.mass_matrix);
    for i in (0..NB).rev() {
        let (iv, nv) = (t.idx_v[i], t.nv[i]);
        for k in 0..nv {
            let row = &mut mass_matrix[iv + k];
            let mut f = ic[i].mul_motion(&s_bar[iv + k]);
            for r in 0..=k {
                row[iv + r] = s_bar[iv + r].dot(&f);
            }
            let mut j = i;
            while let Some(p) = t.parents[j] {
                f = G::translate_force(&f, &frames[j]);
                let (jv, jn) = (t.idx_v[p], t.nv[p]);
                if t.parents[p].is_some() {
                    for r in jv..jv + jn {
                        row[r] = s_bar[r].dot(&f);
                    }
                } else {
                    // A root's frame is its body frame: its joint projects
                    // directly (a free flyer copies the six components).
                    model.joint(p).project_force(&f, &mut row[jv..jv + jn]);
                }
                j = p;
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
