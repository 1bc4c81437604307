//! The articulated-body algorithm for forward dynamics (Featherstone Table 7.1).
//!
//! | symbol   | field       | meaning                                            |
//! |----------|-------------|----------------------------------------------------|
//! | `Iᴬᵢ`    | `ia`        | articulated-body inertia of the subtree at i       |
//! | `pᴬᵢ`    | `pa`        | its bias force                                     |
//! | `U`      | `u_cols`    | `Iᴬᵢ S`                                            |
//! | `D`      | `d_inv`     | `Sᵀ U` (stored inverted)                           |
//! | `u`      | `u`         | `τᵢ - Sᵀ pᴬᵢ`                                      |
//! | `a'`     |             | `ⁱX_λ a_λ + cᵢ`                                    |
//!
//! Pass 1 (root to leaves): velocities, `cᵢ`, `Iᴬᵢ = Iᵢ`,
//! `pᴬᵢ = vᵢ ×* Iᵢ vᵢ - fᵉˣᵗᵢ`. Pass 2 (leaves to root): `U`, `D`, `u`, and
//! `Iᵃ = Iᴬ - U D⁻¹ Uᵀ`, `pᵃ = pᴬ + Iᵃ c + U D⁻¹ u` carried to the parent.
//! Pass 3 (root to leaves): `q̈ᵢ = D⁻¹ (u - Uᵀ a')`, `aᵢ = a' + S q̈ᵢ`, with
//! `a₀ = -g`.

use crate::algorithm::common::{
    body_transform_with, check_external, check_state, joint_rates, JointSinCos,
};
use crate::data::Data;
use crate::error::{Error, Quantity, Result};
use crate::joint::{JointModel, MAX_JOINT_NV};
use crate::model::{check_finite, check_result, Model};
use crate::space::{
    ArticulatedInertia, BodyInertia, MotionVector, RigidTransform, Space, VectorOps,
};
use crate::Scalar;

/// `D` below this fraction of `trace(Iᴬ)`, in units of the scalar's epsilon,
/// is treated as singular: the subtree is (nearly) massless along the joint.
pub const SINGULAR_PIVOT_EPS: f64 = 64.0;

/// Joint accelerations `q̈ = M⁻¹ (τ - h)` in O(n).
///
/// Inputs: `q` (NQ), `v` and `tau` (NV), optional external forces per body
/// (body frame). Returns `data.ddq`. Leaves valid: `li_m_i`, `v`, `c`,
/// `ia` (each body's `Iᵃ`, the inertia handed to its parent, or `Iᴬ` at a
/// root), `pa` (`pᴬ`, before projection), `u_cols`, `d_inv`, `u`, `a_gf`
/// (acceleration minus gravity), `ddq`. `o_m_i` is not written (run
/// [`forward_kinematics`](crate::algorithm::kinematics::forward_kinematics)
/// for body poses).
///
/// # Errors
/// Non-finite inputs, invalid configurations, and
/// [`Error::SingularArticulatedInertia`] for a joint that moves a (nearly)
/// massless subtree.
///
/// # Example
///
/// ```
/// use rodyn::algorithm::aba::aba;
/// use rodyn::prelude::*;
/// // A 1 kg point mass on a massless 1 m link, pivot about z, gravity -y.
/// const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
///     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
///     [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
///     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// );
/// let mut data = Data::new();
/// // No torque: the pendulum falls with q̈ = -(g / l) cos q.
/// let q = 0.3;
/// let ddq = aba(&PENDULUM, &mut data, &[q], &[2.0], &[0.0], None)?;
/// assert!((ddq[0] + 9.81 * f64::cos(q)).abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
pub fn aba<'d, S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    tau: &[S; NV],
    f_ext: Option<&[G::Force<S>; NB]>,
) -> Result<&'d [S; NV]> {
    check_state(model, q, Some(v))?;
    check_external(f_ext.map(|f| &f[..]))?;
    velocity_and_bias_pass(model, data, q, v, f_ext);
    backward_pass(model, data, tau)?;
    forward_acceleration_pass(model, data);
    if let Err(overflow) = check_result(&data.ddq, Quantity::Acceleration) {
        return Err(name_non_finite_result(tau, overflow));
    }
    Ok(&data.ddq)
}

/// The error of a non-finite q̈: a non-finite torque when there is one,
/// else the overflow. A non-finite torque always makes its own
/// coordinate's q̈ non-finite (q̈ = D⁻¹ (τ − Sᵀ pᴬ − Uᵀ a′) has no other
/// path), so the torques are looked at only here, to name the cause, and
/// not on every call.
#[cold]
#[inline(never)]
fn name_non_finite_result<S: Scalar>(tau: &[S], overflow: Error) -> Error {
    match check_finite(tau, Quantity::Torque) {
        Err(torque) => torque,
        Ok(()) => overflow,
    }
}

/// Pass 1: `ˡⁱMᵢ`, `vᵢ`, `cᵢ`, `Iᴬᵢ = Iᵢ` and `pᴬᵢ = vᵢ ×* Iᵢ vᵢ - fᵉˣᵗᵢ`.
///
/// One loop, as in RNEA's forward pass: each body's velocity stays in
/// registers for its bias force. The joint transform goes to `data.li_m_i`
/// at once and the velocity is formed from there (not through
/// `body_velocity`, whose returned pair was merged on the stack and copied
/// into `data` afterwards: fewer instructions and less time on x86-64,
/// about even on the Cortex-M4). Giving `body_velocity` itself this form,
/// for both callers, grew the pendulum image past its size guard, so the
/// step is written here. Figures: docs/sections/performance_notebook.md,
/// "ABA".
#[inline]
fn velocity_and_bias_pass<
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
    let sin_cos = JointSinCos::at(model, q);
    for i in 0..NB {
        data.li_m_i[i] = body_transform_with(model, i, q, sin_cos.formed());
        let v_parent = match model.parent(i) {
            Some(p) => data.li_m_i[i].act_inv_motion(&data.v[p]),
            None => G::Motion::<S>::ZERO,
        };
        let joint = model.joint(i);
        let qd = joint_rates(model, i, v);
        let (v_i, c_i) = joint.velocity_and_bias(&v_parent, qd);
        data.v[i] = v_i;
        data.c[i] = c_i;
        let inertia = model.inertia(i);
        data.ia[i] = G::Articulated::<S>::from_rigid(inertia);
        let mut p_a = inertia.velocity_product_force(&v_i);
        if let Some(f_ext) = f_ext {
            p_a -= f_ext[i];
        }
        data.pa[i] = p_a;
    }
}

/// Pass 2: articulated inertias and bias forces, leaves to root.
///
/// Each body's `Iᴬ` is projected in place (`data.ia[i]` ends as `Iᵃ`, the
/// inertia its parent receives; a root keeps `Iᴬ`) and added to the
/// parent's through one fused transform.
pub(crate) fn backward_pass<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    tau: &[S; NV],
) -> Result<()> {
    let t = model.topology();
    let mut st_pa = [S::ZERO; MAX_JOINT_NV];
    for i in (0..NB).rev() {
        let (iv, nv) = t.joint_velocity_range(i);
        let joint = model.joint(i);
        let (ancestors, rest) = data.ia.split_at_mut(i);
        let i_a = &mut rest[0];
        let mut p_a = data.pa[i];
        if nv == 1 {
            // The common case, without the loops over the joint's columns.
            // On hosts into a local first: the column is read at once, and
            // a copy read back from `data` waits on store-to-load
            // forwarding. (On the Cortex-M4 the local only costs
            // instructions: see `joint_column`.)
            let u_col = joint_column(joint, i_a, &mut data.u_cols[iv]);
            let mut s_t = [S::ZERO];
            joint.project_force(&u_col, &mut s_t);
            // The armature adds to D = Sᵀ I^A S (Pinocchio's convention).
            let d = s_t[0] + model.armature()[iv];
            check_pivot(i, d, i_a.trace())?;
            let d_inv = S::ONE / d;
            joint.project_force(&p_a, &mut s_t);
            let u = tau[iv] - s_t[0];
            data.d_inv[iv][0] = d_inv;
            data.u[iv] = u;
            if let Some(p) = t.parent(i) {
                let ancestor = &mut ancestors[p];
                // Without armature, Iᵃ S = 0: a coordinate-axis revolute
                // joint's row and column of Iᵃ are zero and skipped.
                let axis = if model.armature()[iv] == S::ZERO {
                    joint.revolute_axis_index()
                } else {
                    None
                };
                // I^a = I^A - U D⁻¹ Uᵀ, p^a = p^A + I^a c + U D⁻¹ u.
                let ia_c = i_a.project_mul_motion(&u_col, d_inv, &data.c[i], axis);
                p_a += u_col * (d_inv * u) + ia_c;
                ancestor.add_act_projected(i_a, &data.li_m_i[i], axis);
                data.pa[p] += data.li_m_i[i].act_force(&p_a);
            }
            continue;
        }
        joint.articulated_columns(i_a, &mut data.u_cols[iv..iv + nv]);
        joint.project_force(&p_a, &mut st_pa[..nv]);
        // The joint's stretch of each vector, sliced once: `k < nv` then
        // indexes it without a check (`iv + k` alone the optimiser cannot
        // bound).
        let (u, tau_i) = (&mut data.u[iv..iv + nv], &tau[iv..iv + nv]);
        for k in 0..nv {
            u[k] = tau_i[k] - st_pa[k];
        }
        if nv > 1 {
            invert_joint_d(model, i, &data.u_cols, i_a.trace(), &mut data.d_inv)?;
        }
        if let Some(p) = t.parent(i) {
            let (u_cols, d_inv) = (&data.u_cols[iv..iv + nv], &data.d_inv[iv..iv + nv]);
            for k in 0..nv {
                let mut dinv_u = S::ZERO;
                for l in 0..nv {
                    dinv_u += d_inv[k][l] * u[l];
                }
                p_a += u_cols[k] * dinv_u;
                i_a.sub_outer(&u_cols[k], d_inv[k][k]);
                for l in 0..k {
                    i_a.sub_outer_sym(&u_cols[k], &u_cols[l], d_inv[k][l]);
                }
            }
            p_a += i_a.mul_motion(&data.c[i]);
            ancestors[p].add_act(i_a, &data.li_m_i[i]);
            data.pa[p] += data.li_m_i[i].act_force(&p_a);
        }
    }
    Ok(())
}

/// `U = Iᴬ S` of a one-coordinate joint, also stored in `u_col`.
///
/// Out of order formed in a local first: the column is read at once, and a
/// copy read back from `data` (stored piecewise, read whole) waits on
/// store-to-load forwarding. In order (the Cortex-M4), with no such stall,
/// the local costs instructions (`crate::tuning::COLUMN_IN_LOCAL`; the
/// performance notebook, "ABA").
#[inline(always)]
fn joint_column<S: Scalar, G: Space, J: JointModel<S, G>>(
    joint: &J,
    i_a: &G::Articulated<S>,
    u_col: &mut G::Force<S>,
) -> G::Force<S> {
    if !crate::tuning::COLUMN_IN_LOCAL {
        joint.articulated_columns(i_a, core::slice::from_mut(u_col));
        *u_col
    } else {
        let mut local = [G::Force::<S>::ZERO];
        joint.articulated_columns(i_a, &mut local);
        let [column] = local;
        *u_col = column;
        column
    }
}

/// Pass 3: joint and body accelerations, root to leaves.
pub(crate) fn forward_acceleration_pass<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
) {
    let t = model.topology();
    let minus_g = -*model.gravity();
    let mut ut_a = [S::ZERO; MAX_JOINT_NV];
    for i in 0..NB {
        let (iv, nv) = t.joint_velocity_range(i);
        let a_parent = match t.parent(i) {
            Some(p) => data.a_gf[p],
            None => minus_g,
        };
        let a_prime = data.li_m_i[i].act_inv_motion(&a_parent) + data.c[i];
        let joint = model.joint(i);
        if nv == 1 {
            let ddq = data.d_inv[iv][0] * (data.u[iv] - a_prime.dot(&data.u_cols[iv]));
            data.ddq[iv] = ddq;
            data.a_gf[i] = joint.add_motion(&a_prime, &[ddq]);
            continue;
        }
        // Sliced once, as in `backward_pass`.
        let (u, u_cols, d_inv) = (
            &data.u[iv..iv + nv],
            &data.u_cols[iv..iv + nv],
            &data.d_inv[iv..iv + nv],
        );
        for k in 0..nv {
            ut_a[k] = u[k] - a_prime.dot(&u_cols[k]);
        }
        let ddq = &mut data.ddq[iv..iv + nv];
        for k in 0..nv {
            let mut sum = S::ZERO;
            for l in 0..nv {
                sum += d_inv[k][l] * ut_a[l];
            }
            ddq[k] = sum;
        }
        data.a_gf[i] = a_prime + joint.motion(ddq);
    }
}

/// Rejects a pivot that is not safely positive relative to `scale`.
#[inline]
fn check_pivot<S: Scalar>(joint: usize, d: S, scale: S) -> Result<()> {
    // Compared in S: on an FPU without double precision (Cortex-M4F) every
    // f32-to-f64 conversion is a software call; only the error path pays it.
    let tolerance = S::from_f64(SINGULAR_PIVOT_EPS * S::EPSILON) * scale;
    if d.is_finite() && scale.is_finite() && d > tolerance {
        Ok(())
    } else {
        // Divided in S too: an f64 division is a software routine there.
        Err(Error::SingularArticulatedInertia {
            joint,
            relative_pivot: if scale > S::ZERO {
                (d / scale).to_f64()
            } else {
                0.0
            },
        })
    }
}

/// `D = Sᵀ U` of a multi-degree-of-freedom joint, inverted through its
/// `L Δ Lᵀ` factor, with every pivot checked.
///
/// `L` unit lower triangular, then `L⁻¹` and `D⁻¹ = L⁻ᵀ Δ⁻¹ L⁻¹`, its lower
/// triangle mirrored: one division per pivot and no square root (a free
/// flyer's pivots are one dependency chain, on which a square root before
/// each division doubled the latency). `D` is padded with the identity to
/// `MAX_JOINT_NV` so that every loop has a constant trip count and the
/// optimiser unrolls it (on a host; at opt-level "s" they stay loops).
// Out of line: inlined, its 6 x 6 work arrays grew the stack of every
// caller of ABA, also of models without a multi-coordinate joint.
#[inline(never)]
fn invert_joint_d<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    i: usize,
    u_cols: &[G::Force<S>; NV],
    scale: S,
    d_inv: &mut [[S; MAX_JOINT_NV]; NV],
) -> Result<()> {
    const N: usize = MAX_JOINT_NV;
    // Never taken (the caller passes a body of its loop), but out of line
    // the optimiser does not know `i < NB`.
    if i >= NB {
        return Ok(());
    }
    let (iv, n) = model.topology().joint_velocity_range(i);
    let joint = model.joint(i);
    let (u_cols, armature) = (&u_cols[iv..iv + n], &model.armature()[iv..iv + n]);
    let d_inv = &mut d_inv[iv..iv + n];
    let mut l = [[S::ZERO; N]; N];
    for k in n..N {
        l[k][k] = S::ONE;
    }
    let mut column = [S::ZERO; N];
    for k in 0..n {
        joint.project_force(&u_cols[k], &mut column[..n]);
        for r in 0..n {
            l[r][k] = column[r];
        }
        l[k][k] += armature[k];
    }
    // In place: below the diagonal l becomes L Δ (column k of L times the
    // pivot Δₖ), and `inv_d` holds 1 / Δₖ.
    let mut inv_d = [S::ZERO; N];
    for k in 0..N {
        let mut d = l[k][k];
        for m in 0..k {
            d -= l[k][m] * l[k][m] * inv_d[m];
        }
        if k < n {
            check_pivot(i, d, scale)?;
        }
        inv_d[k] = S::ONE / d;
        for r in k + 1..N {
            let mut s = l[r][k];
            for m in 0..k {
                s -= l[r][m] * l[k][m] * inv_d[m];
            }
            l[r][k] = s;
        }
    }
    // L⁻¹ = X, unit lower triangular, column by column: L x = eₖ with
    // L[r][m] = l[r][m] / Δₘ.
    let mut x = [[S::ZERO; N]; N];
    for c in 0..N {
        x[c][c] = S::ONE;
        for r in c + 1..N {
            let mut s = S::ZERO;
            for m in c..r {
                s -= l[r][m] * inv_d[m] * x[m][c];
            }
            x[r][c] = s;
        }
    }
    // D⁻¹[r][c] = Σₘ X[m][r] X[m][c] / Δₘ over m ≥ r ≥ c.
    // Over `0..N` with an exit at `n`, so that `r < N` bounds the columns
    // (`n <= N` alone the optimiser does not carry this far).
    for r in 0..N {
        if r >= n {
            break;
        }
        for c in 0..=r {
            let mut s = S::ZERO;
            for m in r..N {
                s += x[m][r] * inv_d[m] * x[m][c];
            }
            d_inv[r][c] = s;
            d_inv[c][r] = s;
        }
    }
    Ok(())
}
