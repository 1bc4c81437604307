//! One extra articulated-body pass: accelerations caused by a force alone.

use crate::data::Data;
use crate::joint::{JointModel, MAX_JOINT_NV};
use crate::model::Model;
use crate::space::{MotionVector, RigidTransform, Space, VectorOps};
use crate::Scalar;

/// `δq̈ = M⁻¹ (δτ + Jᵀ δf)`: the joint accelerations the generalised forces
/// `tau` and body forces `f_ext` (body frames) cause on their own, at zero
/// velocity and without gravity, written to `ddq`.
///
/// It reuses the articulated quantities that
/// [`aba`](crate::algorithm::aba::aba) left in `data` (`li_m_i`, `u_cols`,
/// `d_inv`; they depend on `q` only), so it costs two O(n) sweeps and reads
/// `data` without changing it. Call it after `aba` at the same `q`; results
/// for another `q` are meaningless.
///
/// Symbols (Featherstone Table 7.1 with `v = 0`, `g = 0`): backward,
/// `pᴬᵢ = -δfᵢ`, `uᵢ = δτᵢ - Sᵀ pᴬᵢ`, `pᴬ_λ += ˡⁱXᵢ* (pᴬᵢ + U D⁻¹ uᵢ)`;
/// forward, `a'ᵢ = ⁱX_λ a_λ`, `q̈ᵢ = D⁻¹ (uᵢ - Uᵀ a'ᵢ)`, `aᵢ = a'ᵢ + S q̈ᵢ`.
pub(crate) fn aba_response<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    tau: &[S; NV],
    f_ext: Option<&[G::Force<S>; NB]>,
    ddq: &mut [S; NV],
) {
    let t = model.topology();
    let mut p_a = [G::Force::<S>::ZERO; NB];
    if let Some(f_ext) = f_ext {
        for (p, f) in p_a.iter_mut().zip(f_ext) {
            *p = -*f;
        }
    }
    let mut u = [S::ZERO; NV];
    let mut st_pa = [S::ZERO; MAX_JOINT_NV];
    for i in (0..NB).rev() {
        let (iv, nv) = t.joint_velocity_range(i);
        model.joint(i).project_force(&p_a[i], &mut st_pa[..nv]);
        // The joint's stretch of each vector, sliced once (as in ABA).
        let (u_i, tau_i) = (&mut u[iv..iv + nv], &tau[iv..iv + nv]);
        for k in 0..nv {
            u_i[k] = tau_i[k] - st_pa[k];
        }
        if let Some(parent) = t.parent(i) {
            let mut p_i = p_a[i];
            let (d_inv, u_cols) = (&data.d_inv[iv..iv + nv], &data.u_cols[iv..iv + nv]);
            for k in 0..nv {
                let mut dinv_u = S::ZERO;
                for l in 0..nv {
                    dinv_u += d_inv[k][l] * u_i[l];
                }
                p_i += u_cols[k] * dinv_u;
            }
            let p_parent = data.li_m_i[i].act_force(&p_i);
            p_a[parent] += p_parent;
        }
    }
    let mut a = [G::Motion::<S>::ZERO; NB];
    let mut ut_a = [S::ZERO; MAX_JOINT_NV];
    for i in 0..NB {
        let (iv, nv) = t.joint_velocity_range(i);
        let a_prime = match t.parent(i) {
            Some(parent) => data.li_m_i[i].act_inv_motion(&a[parent]),
            None => G::Motion::<S>::ZERO,
        };
        let (u_i, u_cols, d_inv) = (
            &u[iv..iv + nv],
            &data.u_cols[iv..iv + nv],
            &data.d_inv[iv..iv + nv],
        );
        for k in 0..nv {
            ut_a[k] = u_i[k] - a_prime.dot(&u_cols[k]);
        }
        let ddq_i = &mut ddq[iv..iv + nv];
        for k in 0..nv {
            let mut x = S::ZERO;
            for l in 0..nv {
                x += d_inv[k][l] * ut_a[l];
            }
            ddq_i[k] = x;
        }
        a[i] = a_prime + model.joint(i).motion(ddq_i);
    }
}
