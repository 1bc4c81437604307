//! The Newton-Euler body steps that RNEA runs and that CRBA forward
//! dynamics fuses with CRBA's backward pass (one sweep over the bodies
//! gives both the bias forces and the mass matrix). Here rather than in
//! `rnea.rs` so that neither algorithm reaches into the other's passes.

use super::joint_rates;
use crate::data::Data;
use crate::joint::JointModel;
use crate::model::Model;
use crate::space::{BodyInertia, RigidTransform, Space, VectorOps};
use crate::Scalar;

/// One body of RNEA's forward pass, given its joint transform `li_m_i`
/// and `minus_g = -g`: stores `ˡⁱMᵢ`, `vᵢ`, `aᵢ - g` (`a: None` is a zero
/// joint acceleration) and `fᵢ`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn forward_body<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    i: usize,
    li_m_i: G::Transform<S>,
    v: &[S; NV],
    a: Option<&[S; NV]>,
    f_ext: Option<&[G::Force<S>; NB]>,
    minus_g: &G::Motion<S>,
) {
    let (v_parent, a_parent) = match model.parent(i) {
        Some(p) => (li_m_i.act_inv_motion(&data.v[p]), data.a_gf[p]),
        None => (G::Motion::<S>::ZERO, *minus_g),
    };
    let joint = model.joint(i);
    let q_dot = joint_rates(model, i, v);
    let v_i = joint.add_motion(&v_parent, q_dot);
    let c_i = joint.cross_motion(&v_i, q_dot);
    let a_i = li_m_i.act_inv_motion(&a_parent) + c_i;
    let a_i = match a {
        Some(a) => joint.add_motion(&a_i, joint_rates(model, i, a)),
        None => a_i,
    };
    let inertia = model.inertia(i);
    let mut f_i = inertia.net_force(&v_i, &a_i);
    if let Some(f_ext) = f_ext {
        f_i -= f_ext[i];
    }
    data.li_m_i[i] = li_m_i;
    data.v[i] = v_i;
    data.a_gf[i] = a_i;
    data.f[i] = f_i;
}

/// RNEA's backward pass, `τᵢ = Sᵀ fᵢ + armatureᵢ q̈ᵢ` and `f_λ += ˡⁱXᵢ* fᵢ`
/// from the leaves to the root (`a: None`: no armature term), running
/// `also(data, i)` after body i's step (CRBA's backward pass, fused in by
/// [`Crba`](crate::algorithm::forward_dynamics::Crba)).
#[cfg_attr(rodyn_tuning = "in_order", inline(always))]
#[cfg_attr(rodyn_tuning = "out_of_order", inline)]
pub(crate) fn backward_force_pass_with<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    a: Option<&[S; NV]>,
    mut also: impl FnMut(&mut Data<S, NB, NV, G>, usize),
) {
    let t = model.topology();
    let armature = model.armature();
    // Out of order, the force handed to the body just before (a chain's
    // parent) stays in registers (see `crate::tuning::CARRY`; the figures:
    // the performance notebook, "RNEA").
    const CARRY: bool = crate::tuning::CARRY;
    let mut carry = G::Force::<S>::ZERO;
    for i in (0..NB).rev() {
        let (iv, nv) = t.velocity_range(i);
        let f_i = if CARRY {
            let f_i = data.f[i] + carry;
            carry = G::Force::<S>::ZERO;
            data.f[i] = f_i;
            f_i
        } else {
            data.f[i]
        };
        // A valid topology keeps the joint's coordinates in range
        // (`Topology::try_new`); one that does not stops the pass.
        let Some(tau) = data.tau.get_mut(iv..iv + nv) else {
            return;
        };
        model.joint(i).project_force(&f_i, tau);
        // Rotor inertias act on the joint coordinates alone.
        if let Some(a) = a {
            if let ([tau], Some(armature), Some(a)) = (&mut *tau, armature.get(iv), a.get(iv)) {
                *tau += *armature * *a;
            } else {
                for ((tau, armature), a) in tau.iter_mut().zip(&armature[iv..]).zip(&a[iv..]) {
                    *tau += *armature * *a;
                }
            }
        }
        if let Some(p) = model.parent(i) {
            let f_p = data.li_m_i[i].act_force(&f_i);
            if CARRY && p + 1 == i {
                carry = f_p;
            } else if let Some(f) = data.f.get_mut(p) {
                // (A valid topology's parent is a body: `p < i`.)
                *f += f_p;
            }
        }
        also(data, i);
    }
}
