//! `∂τ/∂q`, `∂τ/∂v` and `M` of inverse dynamics (Carpentier & Mansard 2018).
//!
//! All quantities are in the world frame (RNEA itself runs there too),
//! body i's written `vᵢ`, `aᵢ`
//! (gravity included as a base acceleration `−g`), `Yᵢ`, `Ẏᵢ`, and its
//! subtree's composites `Yᶜᵢ`, `Ẏᶜᵢ`, `Fᶜᵢ` (the force across joint i);
//! `S_c` is coordinate c's column and λ its body's parent. Per coordinate:
//!
//! ```text
//! ∂v/∂q_c = v_λ × S_c                        (dv_dq)
//! ∂a/∂q_c = a_λ × S_c + v_λ × (v_λ × S_c)    (da_dq)
//! ∂a/∂v_c = vᵢ × S_c + v_λ × S_c             (da_dv)
//! ∂F/∂q_c = Yᶜᵢ da_dq + Ẏᶜᵢ dv_dq            (df_dq)
//! ∂F/∂v_c = Yᶜᵢ da_dv + Ẏᶜᵢ S_c              (df_dv)
//! ```
//!
//! which every body of i's subtree shares, beyond the rigid turn of the
//! subtree about `S_c` (which leaves `S_rᵀ Fᶜ` unchanged for any row r in
//! the subtree, and adds `S_c ×* Fᶜᵢ` to the force seen by the rows above
//! i). With rows r of joint j: for c in j's subtree (j's own columns
//! included) `∂τ_r/∂q_c = S_rᵀ (df_dq_c + [c not j's] S_c ×* Fᶜᵢ)`; for c
//! above j, `∂τ_r/∂q_c = S_rᵀ (Yᶜⱼ da_dq_c + Ẏᶜⱼ dv_dq_c)`; and likewise
//! for v without the turn term. Other entries are zero.

use super::{DerivativeData, DerivativeSpace, VariationMap};
use crate::algorithm::common::{check_external, check_state, pose_step, JointSinCos};
use crate::algorithm::ltdl::{ltdl_factor, ltdl_solve};
use crate::data::Data;
use crate::error::{Quantity, Result};
use crate::model::{check_finite, check_matrix_result, check_result, Model};
use crate::space::{BodyInertia, MotionVector, RigidTransform, VectorOps};
use crate::Scalar;

/// Inverse dynamics and its derivatives at `(q, v, a)`: `τ` in `data.tau`,
/// `∂τ/∂q` in `deriv.dtau_dq`, `∂τ/∂v` in `deriv.dtau_dv`, and
/// `∂τ/∂a = M(q)` in `data.mass_matrix` (both triangles, rotor inertias
/// included).
///
/// External forces, one per body in its own frame as for
/// [`rnea`](crate::algorithm::rnea::rnea), enter `τ` and, since they turn
/// with their bodies, `∂τ/∂q`. RNEA runs inside, in the world frame; leaves
/// valid `data.li_m_i`, `data.o_m_i`, `data.tau` and `data.mass_matrix`.
/// The joints' motion subspaces must be constant in their own frames, as
/// every built-in joint's is.
///
/// # Errors
/// As [`rnea`](crate::algorithm::rnea::rnea), and
/// [`Error::NonFiniteResult`](crate::Error::NonFiniteResult) with
/// [`Quantity::Derivative`] (index `row · NV + column`) when a derivative
/// overflows.
///
/// # Example
///
/// ```
/// use rodyn::algorithm::derivatives::{rnea_derivatives, DerivativeData};
/// use rodyn::prelude::*;
/// // A 1 kg point mass on a massless 1 m link, pivot about z, gravity -y:
/// // τ = q̈ + g cos q, so ∂τ/∂q = -g sin q and ∂τ/∂v = 0.
/// const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
///     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
///     [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
///     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// );
/// let (mut data, mut deriv) = (Data::new(), DerivativeData::new());
/// let q = 0.3;
/// rnea_derivatives(&PENDULUM, &mut data, &mut deriv, &[q], &[2.0], &[1.5], None)?;
/// assert!((deriv.dtau_dq[0][0] + 9.81 * f64::sin(q)).abs() < 1e-12);
/// assert!(deriv.dtau_dv[0][0].abs() < 1e-12);
/// assert!((data.mass_matrix[0][0] - 1.0).abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
#[allow(clippy::too_many_arguments)]
pub fn rnea_derivatives<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: DerivativeSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    a: &[S; NV],
    f_ext: Option<&[G::Force<S>; NB]>,
) -> Result<()> {
    check_state(model, q, Some(v))?;
    check_finite(a, Quantity::Acceleration)?;
    check_external(f_ext.map(|f| &f[..]))?;
    world_pass(model, data, deriv, q, v, a, f_ext);
    for row in deriv.dtau_dq.iter_mut().chain(deriv.dtau_dv.iter_mut()) {
        *row = [S::ZERO; NV];
    }
    data.mass_matrix = [[S::ZERO; NV]; NV];
    backward_pass::<S, NB, NQ, NV, G, true>(model, data, deriv, &[S::ZERO; NV]);
    subtree_pass::<S, NB, NQ, NV, G, true>(model, data, deriv);
    // Rotor inertias act on the joint coordinates alone.
    for (k, armature) in model.armature().iter().enumerate() {
        data.mass_matrix[k][k] += *armature;
        data.tau[k] += *armature * a[k];
    }
    check_result(&data.tau, Quantity::Torque)?;
    check_matrix_result(deriv.dtau_dq.as_flattened(), Quantity::Derivative)?;
    check_matrix_result(deriv.dtau_dv.as_flattened(), Quantity::Derivative)?;
    check_matrix_result(data.mass_matrix.as_flattened(), Quantity::MassMatrix)
}

/// The passes of [`rnea_derivatives`] solved for the acceleration, for
/// [`aba_derivatives`](super::aba_derivatives): `q̈ = FD(q, v, τ)` in
/// `data.ddq` and, at `(q, v, q̈)`, `deriv.dtau_dq`, `deriv.dtau_dv`, `M`
/// (both triangles) and its factors in `data.ltdl`; `data.tau = τ`.
///
/// Inverse dynamics is affine in the acceleration, `ID(q, v, q̈) = τ₀ + M
/// q̈`, and so is everything the derivative passes read (Carpentier &
/// Mansard 2018, §IV: forward dynamics' derivatives are inverse dynamics'
/// at `q̈ = FD(q, v, τ)`). So the world pass runs once, at `q̈ = 0`; the
/// composites give `τ₀ = ID(q, v, 0)` and `M`, whose `Lᵀ D L` factors
/// (needed for `M⁻¹` anyway) give `q̈ = M⁻¹ (τ − τ₀)`; then what depends
/// on the acceleration is brought to `q̈`: each body's acceleration by
/// `Δaᵢ = Δa_λ + Σ S_c q̈_c`, `∂a/∂q_c` by `Δa_λ × S_c`, and each
/// composite force by `Σ Y_b Δa_b` over its subtree, which is `Yᶜᵢ Δaᵢ`
/// plus `Yᶜ_b S_b q̈_b` over the bodies b below i. No articulated-body
/// pass, and the kinematics are formed once.
///
/// # Errors
/// As [`rnea_derivatives`] (`τ` checked as a torque) and the
/// factorisation's [`Error::MassMatrixNotPositiveDefinite`](crate::Error::MassMatrixNotPositiveDefinite).
#[allow(clippy::too_many_arguments)]
pub(super) fn forward_dynamics_passes<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: DerivativeSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    tau: &[S; NV],
    f_ext: Option<&[G::Force<S>; NB]>,
) -> Result<()> {
    check_state(model, q, Some(v))?;
    check_finite(tau, Quantity::Torque)?;
    check_external(f_ext.map(|f| &f[..]))?;
    world_pass(model, data, deriv, q, v, &[S::ZERO; NV], f_ext);
    data.mass_matrix = [[S::ZERO; NV]; NV];
    composite_pass(model, data, deriv);
    check_result(&data.tau, Quantity::Torque)?;
    for (k, armature) in model.armature().iter().enumerate() {
        data.mass_matrix[k][k] += *armature;
    }
    // A non-finite entry of `M` (an overflow) fails a pivot, so `M` is
    // searched for one only when the factorisation fails, to report it.
    if let Err(error) = ltdl_factor(model, data) {
        check_matrix_result(data.mass_matrix.as_flattened(), Quantity::MassMatrix)?;
        return Err(error);
    }
    let mut ddq: [S; NV] = core::array::from_fn(|k| tau[k] - data.tau[k]);
    ltdl_solve(model, data, &mut ddq)?;
    acceleration_pass(model, data, deriv, &ddq);
    for row in deriv.dtau_dq.iter_mut().chain(deriv.dtau_dv.iter_mut()) {
        *row = [S::ZERO; NV];
    }
    backward_pass::<S, NB, NQ, NV, G, false>(model, data, deriv, &ddq);
    subtree_pass::<S, NB, NQ, NV, G, false>(model, data, deriv);
    data.ddq = ddq;
    data.tau = *tau;
    // `∂τ/∂(q, v)` are not checked here: a non-finite entry would make the
    // products `M⁻¹ ∂τ/∂x` that the caller checks non-finite too.
    Ok(())
}

/// Root to leaves, RNEA's forward pass in the world frame: body poses
/// `ᵒMᵢ`, velocities `vᵢ = v_λ + S q̇ᵢ`, accelerations minus gravity
/// `aᵢ = a_λ + S q̈ᵢ + vᵢ × S q̇ᵢ`, each body's force `fᵢ = Yᵢ aᵢ + vᵢ ×* Yᵢ vᵢ
/// − f_extᵢ` (the composites' starting values, with `Yᵢ` and `Ẏᵢ`), and
/// per coordinate `S_c`, `dv_dq`, `da_dq`, `da_dv`.
#[allow(clippy::too_many_arguments)]
fn world_pass<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: DerivativeSpace>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    a: &[S; NV],
    f_ext: Option<&[G::Force<S>; NB]>,
) {
    let t = model.topology();
    let minus_g = -*model.gravity();
    let sin_cos = JointSinCos::at(model, q);
    for i in 0..NB {
        let o_m_i = pose_step(model, data, i, q, sin_cos.formed(), None);
        let (v_parent, a_parent) = match model.parent(i) {
            Some(p) => (deriv.o_v[p], deriv.o_a[p]),
            None => (<G::Motion<S> as VectorOps<S>>::ZERO, minus_g),
        };
        let joint = model.joint(i);
        let (mut joint_velocity, mut joint_acceleration) = (
            <G::Motion<S> as VectorOps<S>>::ZERO,
            <G::Motion<S> as VectorOps<S>>::ZERO,
        );
        for (k, c) in t.velocity_coordinates(i).enumerate() {
            let s = G::act_subspace_column(&o_m_i, joint, k);
            deriv.s[c] = s;
            joint_velocity += s * v[c];
            joint_acceleration += s * a[c];
        }
        let v_i = v_parent + joint_velocity;
        let a_i = a_parent + joint_acceleration + v_i.cross_motion(&joint_velocity);
        let y_i = model.inertia(i).act(&o_m_i);
        let mut f_i = y_i.net_force(&v_i, &a_i);
        if let Some(f_ext) = f_ext {
            f_i -= o_m_i.act_force(&f_ext[i]);
        }
        deriv.o_v[i] = v_i;
        deriv.o_a[i] = a_i;
        deriv.o_yc[i] = y_i;
        deriv.o_dyc[i] = G::Variation::<S>::of_body(&y_i, &v_i);
        deriv.o_fc[i] = f_i;
        // `vᵢ × S_c = v_λ × S_c + v_J × S_c`, and a joint's velocity crosses
        // only its other columns (a column crossed with itself is zero): so
        // `da_dv = 2 dv_dq` for a joint of one column, and at a root, where
        // `v_λ` is zero, only the terms in `a_λ` and `v_J` are left.
        let columns = t.velocity_coordinates(i);
        let own_turn = columns.len() > 1;
        let zero = <G::Motion<S> as VectorOps<S>>::ZERO;
        if model.parent(i).is_none() {
            for c in columns {
                let s = deriv.s[c];
                deriv.dv_dq[c] = zero;
                deriv.da_dq[c] = a_parent.cross_motion(&s);
                deriv.da_dv[c] = if own_turn {
                    joint_velocity.cross_motion(&s)
                } else {
                    zero
                };
            }
        } else {
            for c in columns {
                let s = deriv.s[c];
                let dv_dq = v_parent.cross_motion(&s);
                deriv.dv_dq[c] = dv_dq;
                deriv.da_dq[c] = a_parent.cross_motion(&s) + v_parent.cross_motion(&dv_dq);
                let twice = dv_dq + dv_dq;
                deriv.da_dv[c] = if own_turn {
                    twice + joint_velocity.cross_motion(&s)
                } else {
                    twice
                };
            }
        }
    }
}

/// Leaves to root, the composites alone: `Yᶜ`, `Ẏᶜ`, `Fᶜ` (at the
/// acceleration of the world pass), `τ` of each body's rows in `data.tau`,
/// `df_da = Yᶜ S_c` of its columns, and `M`'s entries in those columns
/// and the rows of the body and the joints above it, in both triangles
/// (`M` zero beforehand).
fn composite_pass<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: DerivativeSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
) {
    let t = model.topology();
    for j in (0..NB).rev() {
        let (y, f) = (deriv.o_yc[j], deriv.o_fc[j]);
        // Through `get`: no bounds checks in firmware images.
        for c in t.velocity_coordinates(j) {
            let (Some(s_c), Some(tau_c), Some(df_da_c)) =
                (deriv.s.get(c), data.tau.get_mut(c), deriv.df_da.get_mut(c))
            else {
                continue;
            };
            *tau_c = s_c.dot(&f);
            let df_da = y.mul_motion(s_c);
            *df_da_c = df_da;
            let mut row_body = Some(j);
            while let Some(i) = row_body {
                // The walk's bodies are in range (`p < i`), which the optimiser
                // does not carry from step to step; a test, not a panic path.
                if i >= NB {
                    break;
                }
                let first = t.idx_v.get(i).copied().unwrap_or(0);
                for r in first..first + t.nv.get(i).copied().unwrap_or(0) {
                    let m = deriv.s.get(r).map_or(S::ZERO, |s_r| s_r.dot(&df_da));
                    let mass = &mut data.mass_matrix;
                    if let Some(m_rc) = mass.get_mut(r).and_then(|row| row.get_mut(c)) {
                        *m_rc = m;
                    }
                    if let Some(m_cr) = mass.get_mut(c).and_then(|row| row.get_mut(r)) {
                        *m_cr = m;
                    }
                }
                row_body = model.parent(i);
            }
        }
        if let Some(p) = model.parent(j) {
            let dy = deriv.o_dyc[j];
            if let (Some(y_p), Some(dy_p), Some(f_p)) = (
                deriv.o_yc.get_mut(p),
                deriv.o_dyc.get_mut(p),
                deriv.o_fc.get_mut(p),
            ) {
                *y_p = y_p.combine(&y);
                dy_p.add_assign(&dy);
                *f_p += f;
            }
        }
    }
}

/// Root to leaves, the world pass's accelerations brought from `q̈ = 0` to
/// `q̈`: `Δaᵢ = Δa_λ + Σ S_c q̈_c` (kept in `deriv.o_a`, which no later
/// pass reads as an acceleration) and `∂a/∂q_c += Δa_λ × S_c`; clears
/// `data.pa`, where [`backward_pass`] gathers each subtree's
/// `Σ Yᶜ_b S_b q̈_b`.
fn acceleration_pass<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: DerivativeSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
    ddq: &[S; NV],
) {
    let t = model.topology();
    let zero = <G::Motion<S> as VectorOps<S>>::ZERO;
    for i in 0..NB {
        let da_parent = model
            .parent(i)
            .and_then(|p| deriv.o_a.get(p))
            .map_or(zero, |a| *a);
        let mut da = da_parent;
        // Through `get`: no bounds checks in firmware images.
        let columns = t.velocity_coordinates(i);
        let da_dq = deriv.da_dq.get_mut(columns.clone()).unwrap_or_default();
        let s = deriv.s.get(columns.clone()).unwrap_or_default();
        let ddq = ddq.get(columns).unwrap_or_default();
        for ((da_dq, s), ddq) in da_dq.iter_mut().zip(s).zip(ddq) {
            *da_dq += da_parent.cross_motion(s);
            da += *s * *ddq;
        }
        deriv.o_a[i] = da;
        data.pa[i] = <G::Force<S> as VectorOps<S>>::ZERO;
    }
}

/// Leaves to root, with body j's composites complete: `τ` of j's rows, the
/// force derivatives of j's own columns, and the entries of j's rows in
/// the columns of the joints above it.
///
/// `COMPOSE`: the composites are summed here (inverse dynamics). Without
/// it ([`forward_dynamics_passes`]) [`composite_pass`] has summed them at
/// `q̈ = 0` and formed `τ` and `df_da`; here each composite force gains
/// `Yᶜⱼ Δaⱼ` and its children's `Σ Yᶜ_b S_b q̈_b` (gathered in `data.pa`),
/// which are then passed up with j's own.
fn backward_pass<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: DerivativeSpace,
    const COMPOSE: bool,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
    ddq: &[S; NV],
) {
    let t = model.topology();
    for j in (0..NB).rev() {
        let (y, dy) = (deriv.o_yc[j], deriv.o_dyc[j]);
        let columns = t.velocity_coordinates(j);
        if COMPOSE {
            let f = deriv.o_fc[j];
            for r in columns.clone() {
                data.tau[r] = deriv.s[r].dot(&f);
            }
        } else {
            let mut below = data.pa[j];
            deriv.o_fc[j] += y.mul_motion(&deriv.o_a[j]) + below;
            let df_da = deriv.df_da.get(columns.clone()).unwrap_or_default();
            let ddq = ddq.get(columns.clone()).unwrap_or_default();
            for (df_da, ddq) in df_da.iter().zip(ddq) {
                below += *df_da * *ddq;
            }
            if let Some(pa) = model.parent(j).and_then(|p| data.pa.get_mut(p)) {
                *pa += below;
            }
        }
        for c in columns.clone() {
            deriv.df_dq[c] = y.mul_motion(&deriv.da_dq[c]) + dy.mul_motion(&deriv.dv_dq[c]);
            deriv.df_dv[c] = y.mul_motion(&deriv.da_dv[c]) + dy.mul_motion(&deriv.s[c]);
            if COMPOSE {
                deriv.df_da[c] = y.mul_motion(&deriv.s[c]);
            }
        }
        for r in columns {
            // `Yᶜ` is symmetric, so `S_rᵀ Yᶜ x = (Yᶜ S_r) · x`.
            let y_s = deriv.df_da[r];
            let dy_row = dy.row(&deriv.s[r]);
            let mut above = model.parent(j);
            while let Some(i) = above {
                // The walk's bodies are in range (`p < i`), which the optimiser
                // does not carry from step to step; a test, not a panic path.
                if i >= NB {
                    break;
                }
                for c in t.velocity_coordinates(i) {
                    deriv.dtau_dq[r][c] = deriv.da_dq[c].dot(&y_s)
                        + G::Variation::<S>::dot_row(&dy_row, &deriv.dv_dq[c]);
                    deriv.dtau_dv[r][c] =
                        deriv.da_dv[c].dot(&y_s) + G::Variation::<S>::dot_row(&dy_row, &deriv.s[c]);
                }
                above = model.parent(i);
            }
        }
        // In the world frame the composites add without transforms.
        if let (true, Some(p)) = (COMPOSE, model.parent(j)) {
            let f = deriv.o_fc[j];
            deriv.o_yc[p] = deriv.o_yc[p].combine(&y);
            deriv.o_dyc[p].add_assign(&dy);
            deriv.o_fc[p] += f;
        }
    }
}

/// The entries of `∂τ/∂q`, `∂τ/∂v` (and with `MASS` of `M`) in the rows of
/// each body and the columns of its subtree: [`subtree_rows_pass`] where
/// subtrees hold contiguous coordinates, [`subtree_columns_pass`] (its
/// plain form) otherwise. Leaves `deriv.df_dq` undefined.
#[inline(always)]
fn subtree_pass<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: DerivativeSpace,
    const MASS: bool,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
) {
    if model.topology().subtrees_contiguous {
        subtree_rows_pass::<S, NB, NQ, NV, G, MASS>(model, data, deriv);
    } else {
        subtree_columns_pass::<S, NB, NQ, NV, G, MASS>(model, data, deriv);
    }
}

/// [`subtree_columns_pass`] a row at a time, in a tree whose subtrees hold
/// contiguous coordinates: leaves to root, each row r of body j takes the
/// columns of j's subtree as one stretch, `S_r` held while the stretch is
/// swept (where a column's pass set up each column and walked its rows).
/// A column's rows above its body see the turn `S_c ×* Fᶜ`, which is added
/// to `df_dq_c` in place once the body's own rows are done (the bodies
/// above come later), so `deriv.df_dq` holds the turned forces afterwards.
fn subtree_rows_pass<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: DerivativeSpace,
    const MASS: bool,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
) {
    let t = model.topology();
    for j in (0..NB).rev() {
        let own = t.velocity_coordinates(j);
        let subtree = own.start..t.subtree_end(j);
        // Through `get`: no bounds checks in firmware images.
        let (Some(dq), Some(dv), Some(da)) = (
            deriv.df_dq.get(subtree.clone()),
            deriv.df_dv.get(subtree.clone()),
            deriv.df_da.get(subtree.clone()),
        ) else {
            continue;
        };
        for r in own.clone() {
            let Some(s_r) = deriv.s.get(r).copied() else {
                continue;
            };
            let (Some(row_q), Some(row_v)) = (
                deriv
                    .dtau_dq
                    .get_mut(r)
                    .and_then(|row| row.get_mut(subtree.clone())),
                deriv
                    .dtau_dv
                    .get_mut(r)
                    .and_then(|row| row.get_mut(subtree.clone())),
            ) else {
                continue;
            };
            for (((x_q, x_v), f_q), f_v) in row_q.iter_mut().zip(row_v).zip(dq).zip(dv) {
                *x_q = s_r.dot(f_q);
                *x_v = s_r.dot(f_v);
            }
            if MASS {
                let row_m = data
                    .mass_matrix
                    .get_mut(r)
                    .and_then(|row| row.get_mut(subtree.clone()));
                for (x, f) in row_m.unwrap_or_default().iter_mut().zip(da) {
                    *x = s_r.dot(f);
                }
            }
        }
        let f_j = deriv.o_fc[j];
        for c in own {
            if let (Some(df_dq), Some(s_c)) = (deriv.df_dq.get_mut(c), deriv.s.get(c)) {
                *df_dq += s_c.cross_force(&f_j);
            }
        }
    }
    // M's other triangle, in one sequential sweep.
    if MASS {
        for r in 0..NV {
            for c in 0..r {
                data.mass_matrix[r][c] = data.mass_matrix[c][r];
            }
        }
    }
}

/// For every column c (of body i), the rows of i and of the joints above
/// it, which see the subtree's force change `df_dq_c` (and, above i, the
/// turn `S_c ×* Fᶜᵢ`); and `M`'s entries there (rows above columns), then
/// its other triangle.
fn subtree_columns_pass<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: DerivativeSpace,
    const MASS: bool,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
) {
    let t = model.topology();
    for i in 0..NB {
        for c in t.velocity_coordinates(i) {
            // Through `get`: no bounds checks in firmware images.
            let (Some(df_dq), Some(df_dv), Some(df_da)) =
                (deriv.df_dq.get(c), deriv.df_dv.get(c), deriv.df_da.get(c))
            else {
                continue;
            };
            let (df_dq, df_dv, df_da) = (*df_dq, *df_dv, *df_da);
            let df_dq_above = df_dq + deriv.s[c].cross_force(&deriv.o_fc[i]);
            let mut row_body = Some(i);
            while let Some(j) = row_body {
                // The walk's bodies are in range (`p < i`), which the optimiser
                // does not carry from step to step; a test, not a panic path.
                if j >= NB {
                    break;
                }
                let df_dq = if j == i { df_dq } else { df_dq_above };
                for r in t.velocity_coordinates(j) {
                    let s_r = &deriv.s[r];
                    deriv.dtau_dq[r][c] = s_r.dot(&df_dq);
                    deriv.dtau_dv[r][c] = s_r.dot(&df_dv);
                    if MASS {
                        data.mass_matrix[r][c] = s_r.dot(&df_da);
                    }
                }
                row_body = model.parent(j);
            }
        }
    }
    // M's other triangle, in one sequential sweep.
    if MASS {
        for r in 0..NV {
            for c in 0..r {
                data.mass_matrix[r][c] = data.mass_matrix[c][r];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::joint::{Axis, Joint};
    use crate::spatial::{Force, Inertia, Motion, Spatial, Sym3, Transform, Vec3};
    use crate::topology::Topology;

    /// A free-flyer carrying three limbs of two links, numbered depth first.
    fn limbs() -> Model<f64, 7, 13, 12> {
        let parents = core::array::from_fn(|i| match i {
            0 => None,
            1 | 3 | 5 => Some(0),
            _ => Some(i - 1),
        });
        let axes = [Axis::X, Axis::Y, Axis::Z];
        Model::from_parts(
            Topology::new(
                parents,
                core::array::from_fn(|i| if i == 0 { 7 } else { 1 }),
                core::array::from_fn(|i| if i == 0 { 6 } else { 1 }),
                13,
            ),
            core::array::from_fn(|i| match i {
                0 => Joint::free_flyer(),
                _ => Joint::revolute(axes[i % 3]),
            }),
            core::array::from_fn(|i| {
                let k = i as f64;
                Transform::from_translation(Vec3::new(0.1 + 0.05 * k, -0.2 + 0.03 * k, 0.3))
            }),
            core::array::from_fn(|i| {
                let k = i as f64;
                Inertia::new(
                    1.0 + 0.3 * k,
                    Vec3::new(0.05 * k, 0.1, -0.02 * k),
                    Sym3::new(0.2 + 0.01 * k, 0.01, -0.02, 0.3, 0.015, 0.25 + 0.02 * k),
                )
            }),
            Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
        )
    }

    /// The rows pass against the plain columns pass on the state the
    /// backward pass leaves: the same entries of `∂τ/∂q`, `∂τ/∂v` and `M`.
    #[test]
    fn the_rows_pass_matches_the_columns_pass() {
        let model = limbs();
        assert!(model.topology().subtrees_contiguous);
        let mut q: [f64; 13] = core::array::from_fn(|k| 0.3 * (k as f64).sin() + 0.1);
        model.normalize_unvalidated(&mut q);
        let v: [f64; 12] = core::array::from_fn(|k| 0.5 * (k as f64 + 1.0).cos());
        let a: [f64; 12] = core::array::from_fn(|k| 0.7 * (2.0 * k as f64).sin());
        let f_ext: [Force<f64>; 7] = core::array::from_fn(|i| {
            let k = i as f64;
            Force::new(Vec3::new(0.1 * k, -0.2, 0.3), Vec3::new(1.0, 0.5 * k, -0.4))
        });
        let mut data = Data::<f64, 7, 12>::new();
        let mut deriv = DerivativeData::<f64, 7, 12>::new();
        world_pass(&model, &mut data, &mut deriv, &q, &v, &a, Some(&f_ext));
        backward_pass::<f64, 7, 13, 12, Spatial, true>(&model, &mut data, &mut deriv, &[0.0; 12]);
        let (mut data_rows, mut deriv_rows) = (data.clone(), deriv.clone());
        subtree_rows_pass::<f64, 7, 13, 12, Spatial, true>(&model, &mut data_rows, &mut deriv_rows);
        subtree_columns_pass::<f64, 7, 13, 12, Spatial, true>(&model, &mut data, &mut deriv);
        assert_eq!(deriv_rows.dtau_dq, deriv.dtau_dq);
        assert_eq!(deriv_rows.dtau_dv, deriv.dtau_dv);
        assert_eq!(data_rows.mass_matrix, data.mass_matrix);
        assert!(deriv.dtau_dq.iter().flatten().any(|x| *x != 0.0));
    }
}
