//! The composite-rigid-body algorithm as the book writes it
//! (Featherstone 2008, Table 6.2), the oracle for the tuned passes.
//!
//! Why it exists: the tuned passes ([`super::crba`]) carry turned frames,
//! fused steps, column blocks and two backward passes; this file is the
//! algorithm they must agree with, in the book's symbols and order, short
//! enough to check by eye. Each body's composite inertia `Iᶜᵢ` is formed in
//! its own frame and moved to its parent's by `ˡⁱXᵢ*`; each column
//! `F = Iᶜᵢ Sᵢ` walks up its support, giving `H_ij = Fᵀ S_j` at each
//! ancestor j. No step is skipped or fused, no quarter turn recognised, no
//! entry written twice. It is O(n·depth) like the tuned passes but with
//! general transforms throughout: use it to check, not to run a robot.

use crate::algorithm::common::{body_transform, check_state};
use crate::error::Result;
use crate::joint::JointModel;
use crate::model::Model;
use crate::space::{BodyInertia, MotionVector, RigidTransform, Space};
use crate::Scalar;

/// The joint-space mass matrix `H(q)` (NV x NV, both triangles, rotor
/// inertias `model.armature()` added on the diagonal), by Table 6.2.
///
/// Inputs: `q` (NQ). Uses no `Data`: the composite inertias and the joint
/// transforms live on the stack (`NB` of each), and `H` is returned by
/// value. Units: kg·m² for rotational, kg for translational coordinates.
///
/// # Errors
/// An invalid configuration.
pub fn crba<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
) -> Result<[[S; NV]; NV]> {
    check_state(model, q, None)?;
    let t = model.topology();
    // ˡⁱXᵢ: body i's coordinates to its parent's (ˡⁱMᵢ = placement · X_J(q)).
    let x_up: [G::Transform<S>; NB] = core::array::from_fn(|i| body_transform(model, i, q));
    // Iᶜᵢ = Iᵢ.
    let mut ic: [G::Inertia<S>; NB] = core::array::from_fn(|i| *model.inertia(i));
    let mut h = [[S::ZERO; NV]; NV];
    for i in (0..NB).rev() {
        // Iᶜ_λ(i) = Iᶜ_λ(i) + ˡⁱXᵢ* Iᶜᵢ ⁱX_λ(i)
        if let Some(lambda) = t.parent(i) {
            ic[lambda] = ic[lambda].combine(&ic[i].act(&x_up[i]));
        }
        let joint_i = model.joint(i);
        for k in 0..t.nv[i] {
            let row = t.idx_v[i] + k;
            // F = Iᶜᵢ Sᵢ (column k of the joint's subspace).
            let mut f = ic[i].mul_motion(&joint_i.subspace_column(k));
            // H_ii = Sᵢᵀ F
            for c in 0..t.nv[i] {
                h[row][t.idx_v[i] + c] = joint_i.subspace_column(c).dot(&f);
            }
            // j = i; while λ(j) ≠ 0: F = ˡʲXⱼ* F; j = λ(j); H_ij = Fᵀ S_j; H_ji = H_ijᵀ
            let mut j = i;
            while let Some(lambda) = t.parent(j) {
                f = x_up[j].act_force(&f);
                j = lambda;
                let joint_j = model.joint(j);
                for c in 0..t.nv[j] {
                    let col = t.idx_v[j] + c;
                    h[row][col] = joint_j.subspace_column(c).dot(&f);
                    h[col][row] = h[row][col];
                }
            }
        }
    }
    for (k, armature) in model.armature().iter().enumerate() {
        h[k][k] += *armature;
    }
    Ok(h)
}

#[cfg(test)]
mod tests {
    use super::crba;
    use crate::joint::{Axis, Joint};
    use crate::spatial::{Inertia, Motion, Spatial, Sym3, Transform, Vec3};
    use crate::Model;

    #[test]
    fn a_single_revolute_body_has_its_inertia_about_the_axis() {
        // H = I_zz + m (cx² + cy²) about the joint's z axis, for any q.
        let (m, c) = (2.0, Vec3::new(0.3, -0.1, 0.2));
        let inertia = Inertia::new(m, c, Sym3::new(0.1, 0.0, 0.0, 0.2, 0.0, 0.3));
        let model: Model<f64, 1, 1, 1, Spatial> = Model::new(
            [None],
            [Joint::revolute(Axis::Z)],
            [Transform::IDENTITY],
            [inertia],
            Motion::new(Vec3::ZERO, Vec3::ZERO),
        );
        let h = crba(&model, &[0.7]).unwrap();
        let expected = 0.3 + m * (0.3f64 * 0.3 + 0.1 * 0.1);
        assert!(
            (h[0][0] - expected).abs() < 1e-14,
            "{} against {expected}",
            h[0][0]
        );
    }
}
