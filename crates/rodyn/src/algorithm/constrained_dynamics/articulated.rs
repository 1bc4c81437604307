//! The articulated-body method for contacts: the Delassus matrix from test
//! forces propagated through ABA's factorisation, never forming `M` (after
//! Kokkevis 2004, the method of RBDL's `ForwardDynamicsContactsKokkevis`).
//!
//! 1. ABA gives the unconstrained `q̈₀` and leaves, per joint, `U = Iᴬ S`
//!    and `D⁻¹ = (Sᵀ Iᴬ S)⁻¹`: the factorisation of `M` in articulated
//!    form.
//! 2. For each constrained row, a unit test force at the contact (`J_rᵀ`)
//!    is propagated with zero velocity, gravity and torque: a backward
//!    sweep along the path from the contact's body to the root (only those
//!    bodies' bias forces are non-zero), then a forward sweep over every
//!    body. Its joint accelerations are `M⁻¹ J_rᵀ`, and the contacts'
//!    accelerations under it are column `r` of `G = J_c M⁻¹ J_cᵀ` (with
//!    zero velocity, spatial and classical accelerations agree).
//! 3. `(G + μ I) λ = a_c* − a_c(q̈₀)` and `q̈ = q̈₀ + M⁻¹ J_cᵀ λ`, as the KKT
//!    method.
//!
//! Cost: one ABA, one kinematics pass, and per row a sweep along one path
//! and one over the tree: `O(n m)` for `m` rows, against the KKT method's
//! CRBA (`O(n d)` for depth `d`), factorisation and `m` sparse solves. Its
//! numbers are the KKT method's to rounding (both are held to Pinocchio's).

use super::{baumgarte_less_drift, constrained_rows, weighted_rows, ConstraintData, Contact};
use crate::algorithm::aba::aba;
use crate::algorithm::kinematics::forward_kinematics_acceleration;
use crate::data::Data;
use crate::error::Result;
use crate::joint::{JointModel, MAX_JOINT_NV};
use crate::model::Model;
use crate::space::{MotionVector, RigidTransform, VectorOps};
use crate::spatial::{Force, Motion, Spatial, Vec3};
use crate::Scalar;

/// `q̈₀`, the right-hand side `a_c* − a_c(q̈₀)` (in `cdata.lambda`), the
/// responses `M⁻¹ J_rᵀ` (in `cdata.responses`) and `G` (in
/// `cdata.delassus`, without the damping), leaving `data` as ABA and
/// `forward_kinematics_acceleration` at `q̈₀` leave it. Returns `q̈₀`.
#[allow(clippy::too_many_arguments)]
pub(super) fn form_delassus<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NC: usize,
>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    cdata: &mut ConstraintData<S, NV, NC>,
    q: &[S; NQ],
    v: &[S; NV],
    tau: &[S; NV],
    contacts: &[Contact<S>],
    settings: &super::ConstraintSettings<S>,
) -> Result<[S; NV]> {
    let ddq0 = *aba(model, data, q, v, tau, None)?;
    // The contacts' accelerations at q̈₀ (and the poses for their axes).
    forward_kinematics_acceleration(model, data, q, v, &ddq0)?;
    // `check_input` refused more rows than `NC`; the clamp, which changes
    // nothing then, lets the optimiser see it.
    let rows = constrained_rows(contacts).min(NC);
    cdata.rows = rows;
    let mut row = 0;
    for contact in contacts {
        let n = contact.rows();
        // Within `NC` (`check_input`); `get` says so without a panic path.
        let Some(lambda) = cdata.lambda.get_mut(row..row + n) else {
            break;
        };
        baumgarte_less_drift(data, contact, settings, lambda)?;
        row += n;
    }

    let mut accel = [Motion::ZERO; NB];
    let mut column = 0;
    for contact in contacts {
        for r in 0..contact.rows() {
            let force = test_force(data, contact, r);
            // Columns and rows within `NC` (`check_input`): `get`.
            let Some(response) = cdata.responses.get_mut(column) else {
                break;
            };
            unit_response(
                model,
                data,
                contact.held_frame().body,
                &force,
                response,
                &mut accel,
            );
            let mut row = 0;
            for other in contacts {
                let acceleration = contact_acceleration(data, other, &accel);
                for (k, a) in acceleration.iter().take(other.rows()).enumerate() {
                    if let Some(entry) = cdata
                        .delassus
                        .get_mut(row + k)
                        .and_then(|d| d.get_mut(column))
                    {
                        *entry = *a;
                    }
                }
                row += other.rows();
            }
            column += 1;
        }
    }
    // G is symmetric in exact arithmetic; average away the rounding.
    let half = S::from_f64(0.5);
    for r in 0..rows {
        for s in 0..r {
            let g = (cdata.delassus[r][s] + cdata.delassus[s][r]) * half;
            cdata.delassus[r][s] = g;
            cdata.delassus[s][r] = g;
        }
    }
    Ok(ddq0)
}

/// `q̈ = q̈₀ + M⁻¹ J_cᵀ λ` into `cdata.ddq`.
pub(super) fn accelerations<S: Scalar, const NV: usize, const NC: usize>(
    cdata: &mut ConstraintData<S, NV, NC>,
    ddq0: &[S; NV],
) {
    let mut ddq = *ddq0;
    weighted_rows(
        &cdata.responses,
        &cdata.lambda,
        cdata.rows.min(NC),
        &mut ddq,
    );
    cdata.ddq = ddq;
}

/// The force (body frame, about the body's origin) whose generalised
/// force is row `r` of the contact's Jacobian transposed: a unit force
/// along world axis `r` at a point; along the frame's axis `r` at its
/// origin, or a unit moment about axis `r − 3`, for a frame.
fn test_force<S: Scalar, const NB: usize, const NV: usize>(
    data: &Data<S, NB, NV, Spatial>,
    contact: &Contact<S>,
    r: usize,
) -> Force<S> {
    let frame = contact.held_frame();
    match contact {
        Contact::Point { .. } => {
            // A body in range (`check_input`): `get`, no panic path.
            let Some(o_m_i) = data.o_m_i.get(frame.body) else {
                return Force::ZERO;
            };
            let axis = o_m_i.rot.row(r);
            Force::at_point(axis, &frame.placement.trans)
        }
        Contact::Frame { .. } => {
            let unit = if r < 3 {
                Force::new(Vec3::ZERO, Vec3::unit(r))
            } else {
                Force::new(Vec3::unit(r - 3), Vec3::ZERO)
            };
            frame.placement.act_force(&unit)
        }
    }
}

/// The contact's rows of acceleration for body accelerations `accel` at
/// zero velocity (linear before angular; a point's three in world axes, a
/// frame's six in its own).
fn contact_acceleration<S: Scalar, const NB: usize, const NV: usize>(
    data: &Data<S, NB, NV, Spatial>,
    contact: &Contact<S>,
    accel: &[Motion<S>; NB],
) -> [S; 6] {
    let frame = contact.held_frame();
    // A body in range (`check_input`): `get`, no panic path.
    let (Some(accel), Some(o_m_i)) = (accel.get(frame.body), data.o_m_i.get(frame.body)) else {
        return [S::ZERO; 6];
    };
    let a = frame.placement.act_inv_motion(accel);
    let mut out = [S::ZERO; 6];
    match contact {
        Contact::Point { .. } => {
            let frame_axes = o_m_i.rot.mul_mat(&frame.placement.rot);
            out[..3].copy_from_slice(&frame_axes.mul_vec(&a.lin).to_array());
        }
        Contact::Frame { .. } => {
            out[..3].copy_from_slice(&a.lin.to_array());
            out[3..].copy_from_slice(&a.ang.to_array());
        }
    }
    out
}

/// The joint accelerations `ddq = M⁻¹ Jᵀ f` and body accelerations `accel`
/// (body frames) of the tree at rest, without gravity or torques, under
/// the force `f` on `body` (body frame), from the `U` and `D⁻¹` ABA left
/// in `data`.
fn unit_response<S: Scalar, const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &Data<S, NB, NV, Spatial>,
    body: usize,
    force: &Force<S>,
    ddq: &mut [S; NV],
    accel: &mut [Motion<S>; NB],
) {
    let t = model.topology();
    let mut u = [S::ZERO; NV];
    let mut st = [S::ZERO; MAX_JOINT_NV];
    // Backward along the path: pᴬ = −f at `body`; u = −Sᵀ pᴬ; the parent
    // receives pᵃ = pᴬ + U D⁻¹ u (no velocity: no c term).
    let mut p_a = -*force;
    let mut i = body;
    // `body` is the caller's; the parents are in range.
    while i < NB {
        let (iv, nv) = t.joint_velocity_range(i);
        let joint = model.joint(i);
        // One coordinate without the loops, as in ABA: with the joint's
        // range known, the loops over it unroll and cost the common case
        // instructions on the Cortex-M4.
        if nv == 1 {
            let mut s = [S::ZERO];
            joint.project_force(&p_a, &mut s);
            let u_k = -s[0];
            u[iv] = u_k;
            let Some(parent) = t.parent(i) else { break };
            p_a += data.u_cols[iv] * (data.d_inv[iv][0] * u_k);
            p_a = data.li_m_i[i].act_force(&p_a);
            i = parent;
            continue;
        }
        joint.project_force(&p_a, &mut st[..nv]);
        // The joint's stretch of each vector, sliced once (see ABA's
        // `backward_pass`).
        let u_i = &mut u[iv..iv + nv];
        for k in 0..nv {
            u_i[k] = -st[k];
        }
        let Some(parent) = t.parent(i) else { break };
        let (d_inv, u_cols) = (&data.d_inv[iv..iv + nv], &data.u_cols[iv..iv + nv]);
        for k in 0..nv {
            let dinv_u = (0..nv).fold(S::ZERO, |acc, l| acc + d_inv[k][l] * u_i[l]);
            p_a += u_cols[k] * dinv_u;
        }
        p_a = data.li_m_i[i].act_force(&p_a);
        i = parent;
    }
    // Forward over the tree: a' = ⁱXₚ aₚ, q̈ = D⁻¹ (u − Uᵀ a'), a = a' + S q̈.
    for i in 0..NB {
        let (iv, nv) = t.joint_velocity_range(i);
        let a_parent = t.parent(i).map_or(Motion::ZERO, |p| accel[p]);
        let a_prime = data.li_m_i[i].act_inv_motion(&a_parent);
        let joint = model.joint(i);
        if nv == 1 {
            let x = data.d_inv[iv][0] * (u[iv] - a_prime.dot(&data.u_cols[iv]));
            ddq[iv] = x;
            accel[i] = joint.add_motion(&a_prime, &[x]);
            continue;
        }
        let (u_i, d_inv, u_cols) = (
            &u[iv..iv + nv],
            &data.d_inv[iv..iv + nv],
            &data.u_cols[iv..iv + nv],
        );
        for k in 0..nv {
            st[k] = u_i[k] - a_prime.dot(&u_cols[k]);
        }
        let ddq_i = &mut ddq[iv..iv + nv];
        for k in 0..nv {
            ddq_i[k] = (0..nv).fold(S::ZERO, |acc, l| acc + d_inv[k][l] * st[l]);
        }
        accel[i] = a_prime + joint.motion(ddq_i);
    }
}
