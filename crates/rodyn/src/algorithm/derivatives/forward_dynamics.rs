//! `∂q̈/∂q`, `∂q̈/∂v` and `∂q̈/∂τ = M⁻¹` of forward dynamics.
//!
//! Forward dynamics solves `τ = ID(q, v, q̈)` for q̈, so differentiating
//! that identity gives `∂q̈/∂x = −M⁻¹ ∂ID/∂x` at `q̈ = FD(q, v, τ)`
//! (Carpentier & Mansard 2018, §IV). [`aba_derivatives`] takes `q̈` itself
//! from the same passes and factorisation (inverse dynamics is affine in
//! `q̈`, see `inverse_dynamics::forward_dynamics_passes`) instead of an
//! articulated-body pass; [`aba_derivatives_by_solves`] is the plain form,
//! ABA then RNEA's derivatives at its result, kept as its oracle. `M⁻¹`
//! and the two products come from the branch-aware `Lᵀ D L` factorisation
//! (`M⁻¹` on deep trees through articulated-body sweeps over its factors).

use super::inverse_dynamics::forward_dynamics_passes;
use super::{rnea_derivatives, DerivativeData, DerivativeSpace};
use crate::algorithm::aba::aba;
use crate::algorithm::ltdl::{ltdl_factor, ltdl_solve_columns, solve_columns_by_rows};
use crate::data::Data;
use crate::error::{Quantity, Result};
use crate::model::{check_matrix_result, check_result, Model};
use crate::space::{MotionVector, VectorOps};
use crate::topology::Topology;
use crate::tuning::HOST_ORDER;
use crate::Scalar;

/// Forward dynamics and its derivatives at `(q, v, τ)`: `q̈` in
/// `data.ddq`, `∂q̈/∂q` in `deriv.ddq_dq`, `∂q̈/∂v` in `deriv.ddq_dv` and
/// `∂q̈/∂τ = M⁻¹` in `deriv.minv` (both triangles).
///
/// External forces as for [`aba`]. Runs the passes of
/// [`rnea_derivatives`] once, at `q̈ = 0`, takes `q̈ = M⁻¹ (τ − ID(q, v, 0))`
/// from the factors of the `M` they give, and brings what depends on the
/// acceleration to it: leaves valid `deriv.dtau_dq` and `deriv.dtau_dv` at
/// `(q, v, q̈)`, `data.tau` (`τ`), `data.mass_matrix` and `data.ltdl`
/// (`data.pa` is used as workspace).
///
/// # Errors
/// As [`aba`] (with a `τ` that overflows the bias forces as a non-finite
/// result) and [`rnea_derivatives`];
/// [`Error::MassMatrixNotPositiveDefinite`](crate::Error::MassMatrixNotPositiveDefinite)
/// from the factorisation.
///
/// # Example
///
/// ```
/// use rodyn::algorithm::derivatives::{aba_derivatives, DerivativeData};
/// use rodyn::prelude::*;
/// // The pendulum of `rnea_derivatives`: q̈ = τ - g cos q, so
/// // ∂q̈/∂q = g sin q and ∂q̈/∂τ = 1.
/// const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
///     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
///     [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
///     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// );
/// let (mut data, mut deriv) = (Data::new(), DerivativeData::new());
/// let q = 0.3;
/// aba_derivatives(&PENDULUM, &mut data, &mut deriv, &[q], &[2.0], &[4.0], None)?;
/// assert!((deriv.ddq_dq[0][0] - 9.81 * f64::sin(q)).abs() < 1e-12);
/// assert!((deriv.minv[0][0] - 1.0).abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
#[allow(clippy::too_many_arguments)]
pub fn aba_derivatives<
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
    forward_dynamics_passes(model, data, deriv, q, v, tau, f_ext)?;
    minv_and_products(model, data, deriv)
}

/// `M⁻¹` and `∂q̈/∂x = −M⁻¹ ∂τ/∂x` from the factors in `data.ltdl`: three
/// solves of NV columns, each row formed once in registers
/// ([`solve_columns_by_rows`]), reading `∂τ/∂x` in place.
fn minv_and_products<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: DerivativeSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
) -> Result<()> {
    let minv_sum = if articulated_sweeps_pay(model.topology()) {
        minv_by_articulated_sweeps(model, data, deriv);
        None
    } else {
        solve_columns_by_rows(model, data, None, &mut deriv.minv)
    };
    let minus = -S::ONE;
    let dq_sum = solve_columns_by_rows(
        model,
        data,
        Some((minus, &deriv.dtau_dq)),
        &mut deriv.ddq_dq,
    );
    let dv_sum = solve_columns_by_rows(
        model,
        data,
        Some((minus, &deriv.dtau_dv)),
        &mut deriv.ddq_dv,
    );
    check_by_sum(dq_sum, &deriv.ddq_dq)?;
    check_by_sum(dv_sum, &deriv.ddq_dv)?;
    check_by_sum(minv_sum, &deriv.minv)
}

/// [`check_matrix_result`] of a derivative matrix, given the sum of its
/// entries when the solve that formed it gave one: a finite sum proves
/// every entry finite; otherwise the entries are searched.
#[inline]
fn check_by_sum<S: Scalar, const NV: usize>(sum: Option<S>, x: &[[S; NV]; NV]) -> Result<()> {
    match sum {
        Some(sum) if sum.is_finite() => Ok(()),
        Some(_) => check_result(x.as_flattened(), Quantity::Derivative),
        None => check_matrix_result(x.as_flattened(), Quantity::Derivative),
    }
}

/// Whether [`minv_by_articulated_sweeps`] forms `M⁻¹`: on hosts, in
/// depth-first trees whose coordinates sit below at least `MIN_DEPTH`
/// moving bodies on average (chains of 31 links or more). Its sweeps cost
/// a fixed twelve products per entry of `M⁻¹` where the row sweeps cost
/// one per supporting coordinate, so it pays only on deep trees (counts
/// per chain length in the performance notebook, "Derivatives: sparse
/// solves"). The condition on `NV` is known at compile time, so small
/// models carry no second copy.
#[inline(always)]
fn articulated_sweeps_pay<const NB: usize, const NV: usize>(t: &Topology<NB, NV>) -> bool {
    const MIN_DEPTH: usize = 15;
    HOST_ORDER && NV > 2 * MIN_DEPTH && t.depth_first && t.mean_support_depth >= MIN_DEPTH
}

/// `M⁻¹` by articulated-body sweeps (Carpentier & Mansard 2018, as Pinocchio's
/// `computeMinverse`), in a [`depth_first`](crate::topology::Topology::depth_first)
/// tree, from the factors and the passes' world-frame `S_c` and `Yᶜ S_c`.
///
/// The factors are ABA's: `L[d][c] = U_d · S_c / D_d` for c supporting d,
/// with `U_d = Iᴬ S_d` the articulated inertia's column, so
/// `U_c = Yᶜ S_c − Σ L[d][c] U_d` over the d that c supports. The sums over
/// a coordinate's subtree or path that the row sweeps form with rows of `L`
/// are then formed through six-dimensional accumulators per column: leaves
/// to root, `F_j = Σ U_d Y[d][j] / D_d` gives `Y[c][j] / D_c = −S_c · F_j / D_c`
/// (`Y = L⁻ᵀ`, j below c); root to leaves, `A_k = Σ S_m M⁻¹[m][j]` over
/// k's path gives the upper triangle `M⁻¹[i][j] = Y[i][j] / D_i − (U_i / D_i) · A_λ(i)`.
fn minv_by_articulated_sweeps<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: DerivativeSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
) {
    let t = model.topology();
    let h = &data.ltdl;
    let zero_f = <G::Force<S> as VectorOps<S>>::ZERO;
    let zero_m = <G::Motion<S> as VectorOps<S>>::ZERO;
    let s = &deriv.s;
    // U_c, leaves to root.
    let mut u = [zero_f; NV];
    for c in (0..NV).rev() {
        let end = t.last_supported_v[c] + 1;
        let mut u_c = deriv.df_da[c];
        for d in c + 1..end {
            u_c -= u[d] * h[c][d];
        }
        u[c] = u_c;
    }
    // Y / D in the upper triangle, leaves to root.
    let minv = &mut deriv.minv;
    let mut f = [zero_f; NV];
    for c in (0..NV).rev() {
        let end = t.last_supported_v[c] + 1;
        let d_inv = S::ONE / h[c][c];
        minv[c][c] = d_inv;
        f[c] += u[c] * d_inv;
        for j in c + 1..end {
            let m = -s[c].dot(&f[j]) * d_inv;
            minv[c][j] = m;
            f[j] += u[c] * m;
        }
    }
    // M⁻¹'s upper triangle, a column at a time, root to leaves.
    let w: [G::Force<S>; NV] = core::array::from_fn(|i| u[i] * (S::ONE / h[i][i]));
    let mut a = [zero_m; NV];
    for j in 0..NV {
        for i in 0..=j {
            let a_parent = t.lambda_v[i].map_or(zero_m, |k| a[k]);
            let y = if j <= t.last_supported_v[i] {
                minv[i][j]
            } else {
                S::ZERO
            };
            let m = y - a_parent.dot(&w[i]);
            minv[i][j] = m;
            a[i] = a_parent + s[i] * m;
        }
    }
    for r in 0..NV {
        for c in 0..r {
            minv[r][c] = minv[c][r];
        }
    }
}

/// `M⁻¹` and the two products as three plain solves of NV columns
/// ([`ltdl_solve_columns`]), for [`aba_derivatives_by_solves`].
fn minv_and_products_by_solves<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: DerivativeSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
) -> Result<()> {
    for (r, row) in deriv.minv.iter_mut().enumerate() {
        *row = [S::ZERO; NV];
        row[r] = S::ONE;
    }
    ltdl_solve_columns(model, data, &mut deriv.minv)?;
    for (out, dtau) in [
        (&mut deriv.ddq_dq, &deriv.dtau_dq),
        (&mut deriv.ddq_dv, &deriv.dtau_dv),
    ] {
        for (out_row, row) in out.iter_mut().zip(dtau) {
            *out_row = row.map(|x| -x);
        }
        ltdl_solve_columns(model, data, out)?;
    }
    check_matrix_result(deriv.ddq_dq.as_flattened(), Quantity::Derivative)?;
    check_matrix_result(deriv.ddq_dv.as_flattened(), Quantity::Derivative)?;
    check_matrix_result(deriv.minv.as_flattened(), Quantity::Derivative)
}

/// [`aba_derivatives`] in its plain form, the oracle of the tuned one:
/// [`aba`] for `q̈`, [`rnea_derivatives`] at its result, the factors of
/// its `M`, then `M⁻¹` and the two products by three `Lᵀ D L` solves of
/// NV columns ([`ltdl_solve_columns`]). Same results as [`aba_derivatives`] up to rounding; leaves what
/// [`aba`] and [`rnea_derivatives`] leave.
///
/// # Errors
/// As [`aba_derivatives`].
#[allow(clippy::too_many_arguments)]
pub fn aba_derivatives_by_solves<
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
    let ddq = *aba(model, data, q, v, tau, f_ext)?;
    rnea_derivatives(model, data, deriv, q, v, &ddq, f_ext)?;
    ltdl_factor(model, data)?;
    data.ddq = ddq;
    minv_and_products_by_solves(model, data, deriv)
}
