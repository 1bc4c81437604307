//! Sparse `Lᵀ D L` factorisation of the mass matrix (Featherstone §6.5, Table 6.3).
//!
//! `M = Lᵀ D L` with `L` unit lower triangular. Because `M[k][i]` is zero
//! unless coordinate i supports coordinate k, `L` has the same sparsity and
//! no fill-in is created.
//!
//! The factors are formed a column of `L` at a time, leaves to root (the
//! order of Pinocchio's `cholesky::decompose`, not the row updates of
//! Table 6.3): `L[k][i]` for every i supporting k is one dot product over
//! the coordinates that k supports, which follow k in a
//! [`depth_first`](crate::topology::Topology::depth_first) tree. `L` is
//! therefore stored transposed, `ltdl[i][k] = L[k][i]`, so that these dot
//! products and the solves run along rows.

use crate::data::Data;
use crate::error::{Error, Result};
use crate::model::Model;
use crate::space::Space;
use crate::topology::Topology;
use crate::Scalar;

/// A pivot below this fraction of the largest diagonal entry, in units of
/// the scalar's epsilon, means `M` is not numerically positive definite.
const PIVOT_TOLERANCE_EPS: f64 = 64.0;

/// On hosts, the value that each step of a recurrence has just formed
/// enters that step's sums last, and in the solve by `L` the next
/// coordinate is updated on its own, so that every pass reads the rest
/// with the alignment the previous pass stored it in: an out-of-order
/// core then does not wait on the newest value or on a load spanning two
/// stores (Panda factor and solve about -17 % time). The Cortex-M4 keeps
/// the plain order (these cost it about 380 instructions on the Panda).
const HOST_ORDER: bool = cfg!(not(target_arch = "arm"));

/// The ranges of coordinates that support coordinate `k` (`k` included),
/// from `k` towards the root: `(first, last)` pairs, each one unbroken
/// stretch of the λ chain (see [`Topology::chain_start_v`]).
///
/// [`Topology::chain_start_v`]: crate::topology::Topology::chain_start_v
#[inline]
pub(crate) fn supporting_ranges<const NB: usize, const NV: usize>(
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

/// `x · y` over slices of equal length, in four interleaved partial sums:
/// independent additions that the host runs two lanes at a time.
#[inline]
fn dot<S: Scalar>(x: &[S], y: &[S]) -> S {
    let y = &y[..x.len()];
    let (x4, y4) = (x.chunks_exact(4), y.chunks_exact(4));
    let (x_rest, y_rest) = (x4.remainder(), y4.remainder());
    let mut sums = [S::ZERO; 4];
    for (x, y) in x4.zip(y4) {
        for j in 0..4 {
            sums[j] += x[j] * y[j];
        }
    }
    let mut sum = (sums[0] + sums[2]) + (sums[1] + sums[3]);
    for (x, y) in x_rest.iter().zip(y_rest) {
        sum += *x * *y;
    }
    sum
}

/// Factors `data.mass_matrix` into `data.ltdl`: `D` on the diagonal, `L`
/// transposed above it (`ltdl[i][k] = L[k][i]` for i < k).
///
/// Inputs: the lower triangle of `data.mass_matrix` (diagonal included), as
/// [`crba`](crate::algorithm::crba::crba) leaves it. Leaves valid: the
/// diagonal and upper triangle of `ltdl` (the lower one is not written).
/// Entries of `L` that the sparsity makes zero are not written either, except
/// in a tree that is not [`depth_first`](crate::topology::Topology::depth_first),
/// where the solves read them.
///
/// Pivots are formed and tested leaves to root, so the coordinate reported
/// is the highest-numbered one whose pivot fails.
///
/// # Errors
/// [`Error::MassMatrixNotPositiveDefinite`] when a pivot is not safely positive.
pub fn ltdl_factor<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
) -> Result<()> {
    let topology = model.topology();
    let m = &data.mass_matrix;
    let h = &mut data.ltdl;
    // Compared in S, like ABA's pivots: no f64 on the hot path.
    let mut scale = S::ZERO;
    for (k, row) in m.iter().enumerate() {
        scale = scale.max(row[k].abs());
    }
    let tolerance = S::from_f64(PIVOT_TOLERANCE_EPS * S::EPSILON) * scale;
    // The pivots, and D[s] L[s][k] for the coordinates s that k supports.
    let mut pivots = [S::ZERO; NV];
    let mut d_l = [S::ZERO; NV];
    for k in (0..NV).rev() {
        // D[k] = M[k][k] - Σ D[s] L[s][k]² over the coordinates s below k.
        let below = k + 1..topology.last_supported_v[k] + 1;
        let mut d = m[k][k];
        let mut subtract = |s: usize| {
            let l = h[k][s];
            let dl = pivots[s] * l;
            d_l[s] = dl;
            d -= l * dl;
        };
        if HOST_ORDER {
            // `L[k + 1][k]`, the entry formed just before, ends the chain
            // of subtractions instead of starting it.
            below.clone().rev().for_each(&mut subtract);
        } else {
            below.clone().for_each(&mut subtract);
        }
        if !(d.is_finite() && d > tolerance) {
            let scale = scale.to_f64();
            return Err(Error::MassMatrixNotPositiveDefinite {
                dof: k,
                relative_pivot: if scale > 0.0 { d.to_f64() / scale } else { 0.0 },
            });
        }
        pivots[k] = d;
        h[k][k] = d;
        if !topology.depth_first {
            // The rows that do not support k read this column as zeros.
            for row in &mut h[..k] {
                row[k] = S::ZERO;
            }
        }
        // L[k][i] = (M[k][i] - Σ D[s] L[s][k] L[s][i]) / D[k] over the
        // coordinates s below k, for every i supporting k.
        let inverse = S::ONE / d;
        let d_l = &d_l[below.clone()];
        let m_k = &m[k];
        for (first, last) in supporting_ranges(topology, topology.lambda_v[k]) {
            let rows = h[first..=last].iter_mut().zip(&m_k[first..=last]);
            if d_l.is_empty() {
                for (row, m_ki) in rows {
                    row[k] = *m_ki * inverse;
                }
            } else {
                for (row, m_ki) in rows {
                    row[k] = (*m_ki - dot(&row[below.clone()], d_l)) * inverse;
                }
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
    // Lᵀ y = b, leaves to root: b[k] -= Σ L[s][k] b[s] over the s below k.
    for k in (0..NV).rev() {
        let (b_to_k, b_below) = b.split_at_mut(k + 1);
        let end = topology.last_supported_v[k] + 1;
        let (l, b_below) = (&h[k][k + 1..end], &b_below[..end - k - 1]);
        match (l, b_below) {
            // `b[k + 1]`, final only just now, enters last.
            ([l_next, l_rest @ ..], [b_next, b_rest @ ..]) if HOST_ORDER => {
                b_to_k[k] = (b_to_k[k] - dot(l_rest, b_rest)) - *l_next * *b_next;
            }
            _ => b_to_k[k] -= dot(l, b_below),
        }
    }
    // D z = y.
    for (k, bk) in b.iter_mut().enumerate() {
        *bk /= h[k][k];
    }
    // L x = z, root to leaves: once b[k] is final, b[s] -= L[s][k] b[k]
    // over the s below k.
    for k in 0..NV {
        let (b_to_k, b_below) = b.split_at_mut(k + 1);
        let end = topology.last_supported_v[k] + 1;
        match (&mut b_below[..end - k - 1], &h[k][k + 1..end]) {
            // `b[k + 1]`, final after this update, on its own; the rest
            // then starts at `k + 2`, where the next pass's reads start.
            ([b_next, b_rest @ ..], [l_next, l_rest @ ..]) if HOST_ORDER => {
                *b_next -= *l_next * b_to_k[k];
                sub_scaled(b_rest, b_to_k[k], l_rest);
            }
            (b_below, l) => sub_scaled(b_below, b_to_k[k], l),
        }
    }
}
