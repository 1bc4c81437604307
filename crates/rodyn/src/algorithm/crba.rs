//! The composite-rigid-body algorithm for the mass matrix (Featherstone Table 6.2).
//!
//! Backward pass: the composite inertia `Iᶜᵢ = Iᵢ + Σ children` is carried to
//! the parent (`Iᶜ_λ += ˡⁱXᵢ* Iᶜᵢ ⁱX_λ`); each column `F = Iᶜᵢ S` gives
//! `Hᵢᵢ = Sᵢᵀ F`, then travels up the supporting bodies, `F ← ˡʲXⱼ* F`,
//! giving `H_jᵢ = Sⱼᵀ F`. Cost O(n·depth); only ancestors are visited, so
//! branches are never coupled.

use crate::algorithm::kinematics::{body_transform, check_state};
use crate::data::Data;
use crate::error::Result;
use crate::joint::{JointModel, MAX_JOINT_NV};
use crate::model::Model;
use crate::space::{BodyInertia, RigidTransform, Space};
use crate::Scalar;

/// The joint-space mass matrix `M(q)` (symmetric, NV x NV).
///
/// Inputs: `q` (NQ). Returns `data.mass_matrix` with both triangles filled.
/// Leaves valid: `li_m_i`, `ic` (composite inertias, body frames),
/// `mass_matrix`. `o_m_i` is stale.
///
/// # Errors
/// An invalid configuration.
pub fn crba<'d, S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
) -> Result<&'d [[S; NV]; NV]> {
    check_state(model, q, None)?;
    for i in 0..NB {
        data.li_m_i[i] = body_transform(model, i, q);
        data.ic[i] = *model.inertia(i);
    }
    // The passes below write every entry between a coordinate and its
    // supporting coordinates; entries between unrelated branches are
    // structurally zero. Clearing the matrix once (O(n²)) sets them far more
    // cheaply than testing every pair for support (O(n² · depth)).
    data.mass_matrix = [[S::ZERO; NV]; NV];
    let t = model.topology();
    let mut column = [S::ZERO; MAX_JOINT_NV];
    for i in (0..NB).rev() {
        let (iv, nv) = (t.idx_v[i], t.nv[i]);
        let joint = model.joint(i);
        for k in 0..nv {
            let mut f = data.ic[i].mul_motion(&joint.subspace_column(k));
            joint.project_force(&f, &mut column[..nv]);
            // The joint's own block: lower triangle computed, mirrored exactly.
            for (r, value) in column[..nv].iter().enumerate().skip(k) {
                data.mass_matrix[iv + r][iv + k] = *value;
                data.mass_matrix[iv + k][iv + r] = *value;
            }
            let mut j = i;
            while let Some(p) = t.parents[j] {
                f = data.li_m_i[j].act_force(&f);
                let (jv, jn) = (t.idx_v[p], t.nv[p]);
                model.joint(p).project_force(&f, &mut column[..jn]);
                for (r, value) in column[..jn].iter().enumerate() {
                    data.mass_matrix[jv + r][iv + k] = *value;
                    data.mass_matrix[iv + k][jv + r] = *value;
                }
                j = p;
            }
        }
        if let Some(p) = t.parents[i] {
            let ic_in_parent = data.ic[i].act(&data.li_m_i[i]);
            data.ic[p] = data.ic[p].combine(&ic_in_parent);
        }
    }
    // Rotor (armature) inertias sit on the diagonal only.
    for (k, armature) in model.armature().iter().enumerate() {
        data.mass_matrix[k][k] += *armature;
    }
    Ok(&data.mass_matrix)
}
