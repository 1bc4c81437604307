//! Sparse `Lᵀ D L` factorisation of the mass matrix (Featherstone §6.5, Table 6.3).
//!
//! `M = Lᵀ D L` with `L` unit lower triangular. Because `M[k][i]` is zero
//! unless coordinate i supports coordinate k, `L` has the same sparsity and
//! both the factorisation and the solves only walk the λ chain of each
//! coordinate: branches cost nothing, and no fill-in is created.

use crate::data::Data;
use crate::error::{Error, Result};
use crate::model::Model;
use crate::space::Space;
use crate::topology::Topology;
use crate::Scalar;

/// A pivot below this fraction of the largest diagonal entry, in units of
/// the scalar's epsilon, means `M` is not numerically positive definite.
const PIVOT_TOLERANCE_EPS: f64 = 64.0;

/// The ranges of coordinates that support coordinate `k` (`k` included),
/// from `k` towards the root: `(first, last)` pairs, each one unbroken
/// stretch of the λ chain (see [`Topology::chain_start_v`]).
///
/// [`Topology::chain_start_v`]: crate::topology::Topology::chain_start_v
#[inline]
fn supporting_ranges<const NB: usize, const NV: usize>(
    topology: &Topology<NB, NV>,
    k: Option<usize>,
) -> impl Iterator<Item = (usize, usize)> + '_ {
    let mut last = k;
    core::iter::from_fn(move || {
        let end = last?;
        let first = topology.chain_start_v[end];
        last = topology.lambda_v[first];
        Some((first, end))
    })
}

/// `y -= a x`, element by element. Slices of equal length, so the loop
/// carries no bounds checks and vectorises.
#[inline]
fn sub_scaled<S: Scalar>(y: &mut [S], a: S, x: &[S]) {
    let x = &x[..y.len()];
    for j in 0..y.len() {
        y[j] -= a * x[j];
    }
}

/// `x · y` over slices of equal length.
#[inline]
fn dot<S: Scalar>(x: &[S], y: &[S]) -> S {
    let mut sum = S::ZERO;
    for (x, y) in x.iter().zip(y) {
        sum += *x * *y;
    }
    sum
}

/// Factors `data.mass_matrix` into `data.ltdl` (D on the diagonal, L below).
///
/// Inputs: the lower triangle of `data.mass_matrix` (diagonal included), as
/// [`crba`](crate::algorithm::crba::crba) leaves it. Leaves valid: the lower
/// triangle of `ltdl` (`D` on the diagonal, `L` below; the entries above
/// the diagonal are not written).
///
/// Only the supporting coordinates of each row are touched, and they are
/// walked as contiguous ranges rather than one λ link at a time: on a chain
/// every update is one slice operation over a row.
///
/// # Errors
/// [`Error::MassMatrixNotPositiveDefinite`] when a pivot is not safely positive.
pub fn ltdl_factor<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
) -> Result<()> {
    let topology = model.topology();
    let h = &mut data.ltdl;
    // The lower triangle is all the factorisation reads and writes.
    for (k, (row, m)) in h.iter_mut().zip(&data.mass_matrix).enumerate() {
        row[..=k].copy_from_slice(&m[..=k]);
    }
    // Compared in S, like ABA's pivots: no f64 on the hot path.
    let mut scale = S::ZERO;
    for (k, row) in h.iter().enumerate() {
        scale = scale.max(row[k].abs());
    }
    let tolerance = S::from_f64(PIVOT_TOLERANCE_EPS * S::EPSILON) * scale;
    for k in (0..NV).rev() {
        let (rows_above, rows_from_k) = h.split_at_mut(k);
        let row_k = &mut rows_from_k[0];
        let d = row_k[k];
        if !(d.is_finite() && d > tolerance) {
            let scale = scale.to_f64();
            return Err(Error::MassMatrixNotPositiveDefinite {
                dof: k,
                relative_pivot: if scale > 0.0 { d.to_f64() / scale } else { 0.0 },
            });
        }
        // Every supporting coordinate i of k, nearest first:
        // H[i][j] -= (H[k][i] / d) H[k][j] over the coordinates j supporting
        // i, then H[k][i] becomes L[k][i]. Entries H[k][j] with j < i are
        // still unscaled when row i uses them.
        for (first, last) in supporting_ranges(topology, topology.lambda_v[k]) {
            for i in (first..=last).rev() {
                let a = row_k[i] / d;
                let row_i = &mut rows_above[i];
                sub_scaled(&mut row_i[first..=i], a, &row_k[first..=i]);
                for (f, l) in supporting_ranges(topology, topology.lambda_v[first]) {
                    sub_scaled(&mut row_i[f..=l], a, &row_k[f..=l]);
                }
                row_k[i] = a;
            }
        }
    }
    Ok(())
}

/// Solves `M x = b` in place with the factors from [`ltdl_factor`].
///
/// Inputs: `b` (NV); `data.ltdl` valid. On return `b` holds `x`.
pub fn ltdl_solve<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    b: &mut [S; NV],
) {
    let topology = model.topology();
    let h = &data.ltdl;
    // Lᵀ y = b, leaves to root: b[j] -= L[i][j] b[i] over j supporting i.
    for i in (0..NV).rev() {
        let (b_above, b_from_i) = b.split_at_mut(i);
        let b_i = b_from_i[0];
        for (first, last) in supporting_ranges(topology, topology.lambda_v[i]) {
            sub_scaled(&mut b_above[first..=last], b_i, &h[i][first..=last]);
        }
    }
    // D z = y.
    for (i, bi) in b.iter_mut().enumerate() {
        *bi /= h[i][i];
    }
    // L x = z, root to leaves: b[i] -= Σ L[i][j] b[j] over j supporting i.
    for i in 0..NV {
        let mut sum = S::ZERO;
        for (first, last) in supporting_ranges(topology, topology.lambda_v[i]) {
            sum += dot(&h[i][first..=last], &b[first..=last]);
        }
        b[i] -= sum;
    }
}
