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
use crate::Scalar;

/// A pivot below this fraction of the largest diagonal entry, in units of
/// the scalar's epsilon, means `M` is not numerically positive definite.
const PIVOT_TOLERANCE_EPS: f64 = 64.0;

/// Factors `data.mass_matrix` into `data.ltdl` (D on the diagonal, L below).
///
/// Inputs: `data.mass_matrix` as [`crba`](crate::algorithm::crba::crba) left
/// it. Leaves valid: `ltdl`.
///
/// # Errors
/// [`Error::MassMatrixNotPositiveDefinite`] when a pivot is not safely positive.
pub fn ltdl_factor<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
) -> Result<()> {
    let lambda = &model.topology().lambda_v;
    let h = &mut data.ltdl;
    *h = data.mass_matrix;
    // Compared in S, like ABA's pivots: no f64 on the hot path.
    let mut scale = S::ZERO;
    for (k, row) in h.iter().enumerate() {
        scale = scale.max(row[k].abs());
    }
    let tolerance = S::from_f64(PIVOT_TOLERANCE_EPS * S::EPSILON) * scale;
    for k in (0..NV).rev() {
        let d = h[k][k];
        if !(d.is_finite() && d > tolerance) {
            let scale = scale.to_f64();
            return Err(Error::MassMatrixNotPositiveDefinite {
                dof: k,
                relative_pivot: if scale > 0.0 { d.to_f64() / scale } else { 0.0 },
            });
        }
        let mut i = lambda[k];
        while let Some(ii) = i {
            let a = h[k][ii] / d;
            let mut j = Some(ii);
            while let Some(jj) = j {
                h[ii][jj] -= a * h[k][jj];
                j = lambda[jj];
            }
            h[k][ii] = a;
            i = lambda[ii];
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
    let lambda = &model.topology().lambda_v;
    let h = &data.ltdl;
    // Lᵀ y = b, leaves to root.
    for i in (0..NV).rev() {
        let mut j = lambda[i];
        while let Some(jj) = j {
            b[jj] -= h[i][jj] * b[i];
            j = lambda[jj];
        }
    }
    // D z = y.
    for (i, bi) in b.iter_mut().enumerate() {
        *bi /= h[i][i];
    }
    // L x = z, root to leaves.
    for i in 0..NV {
        let mut j = lambda[i];
        while let Some(jj) = j {
            let (hij, bj) = (h[i][jj], b[jj]);
            b[i] -= hij * bj;
            j = lambda[jj];
        }
    }
}
