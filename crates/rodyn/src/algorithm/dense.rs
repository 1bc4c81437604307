//! Small dense linear algebra that algorithms and controllers share: a
//! Cholesky factorisation and solve on fixed-size arrays, for the few
//! coupled unknowns of a contact set, an inverse-kinematics step or an
//! optimal-control stage (not for the mass matrix, whose branch-aware
//! factorisation is [`ltdl`](super::ltdl)).
//!
//! ```
//! use rodyn::algorithm::dense::{cholesky_in_place, cholesky_solve};
//! // A = [[4, 2], [2, 3]], b = [2, 1]: x = [0.5, 0].
//! let mut a: [[f64; 2]; 2] = [[4.0, 2.0], [2.0, 3.0]];
//! cholesky_in_place(&mut a, 2, 0.0).expect("positive definite");
//! let mut b: [f64; 2] = [2.0, 1.0];
//! cholesky_solve(&a, 2, &mut b).expect("a finite solution");
//! assert!((b[0] - 0.5).abs() < 1e-15 && b[1].abs() < 1e-15);
//! ```

use crate::error::{Error, Quantity, Result};
use crate::model::check_result;
use crate::Scalar;

/// The lower Cholesky factor `L` (`A = L Lᵀ`) of the leading `n × n` block
/// of `a`, in place (lower triangle; the upper is left as it was). The
/// pivot of row j (`L[j][j]²`) must exceed `tolerance · ε · A[j][j]`, its
/// own row's diagonal entry (0 asks only for a positive one).
///
/// Each row against its own diagonal: the test is then the same for `A`
/// and for `S A S` with any positive diagonal `S`, so rows in different
/// units (a contact's forces in 1/kg, its moments in 1/(kg m²)) or of
/// very different sizes do not make the small ones look dependent.
/// `L[j][j]² / A[j][j]` is the share of row j that the rows before it do
/// not already span; near zero only for a (nearly) dependent row.
///
/// # Errors
/// The row of the first pivot that does not (NaN included); the factor
/// is then incomplete.
pub fn cholesky_in_place<S: Scalar, const N: usize>(
    a: &mut [[S; N]; N],
    n: usize,
    tolerance: f64,
) -> core::result::Result<(), usize> {
    let n = n.min(N);
    let relative = S::from_f64(S::EPSILON * tolerance);
    // Plain indexing: on the Cortex-M4 it ran fewer instructions than rows
    // split at the pivot (docs/sections/performance_notebook.md,
    // "Derivatives and the small dense Cholesky").
    for j in 0..n {
        let a_jj = a[j][j];
        let mut d = a_jj;
        for k in 0..j {
            d -= a[j][k] * a[j][k];
        }
        // A NaN pivot fails too (both comparisons are false for it); the
        // second also refuses a non-positive pivot when `tolerance · ε`
        // is 1 or more and `A[j][j]` negative.
        if !(d > relative * a_jj && d > S::ZERO) {
            return Err(j);
        }
        let d = d.sqrt();
        a[j][j] = d;
        for i in j + 1..n {
            let mut s = a[i][j];
            for k in 0..j {
                s -= a[i][k] * a[j][k];
            }
            a[i][j] = s / d;
        }
    }
    Ok(())
}

/// Solves `L Lᵀ x = b` in place for the factor of [`cholesky_in_place`]
/// (its leading `n × n` block), `b`'s first `n` entries becoming `x`.
///
/// # Errors
/// [`Error::TooManyConstraints`] for `n` above `N`;
/// [`Error::NonFinite`] ([`Quantity::LinearSystem`], the row) for a
/// non-finite entry of `b`, or of `L`'s rows, when `x` comes out
/// non-finite; [`Error::NonFiniteResult`] when finite inputs overflow (a
/// zero or tiny pivot of `L`). `b` then holds the partial solution. One
/// finiteness test of `x` when all is well.
pub fn cholesky_solve<S: Scalar, const N: usize>(
    l: &[[S; N]; N],
    n: usize,
    b: &mut [S; N],
) -> Result<()> {
    if n > N {
        return Err(Error::TooManyConstraints {
            rows: n,
            capacity: N,
        });
    }
    // Where `b` is bad, kept as an index (the solve overwrites `b`, and an
    // index is lighter on the stack than an error).
    let bad_b = b[..n].iter().position(|x| !x.is_finite());
    cholesky_solve_unchecked(l, n, b);
    if check_result(&b[..n], Quantity::LinearSystem).is_err() {
        let bad_l = (0..n).find(|&i| l[i][..=i].iter().any(|x| !x.is_finite()));
        if let Some(row) = bad_b.or(bad_l) {
            return Err(Error::NonFinite {
                quantity: Quantity::LinearSystem,
                index: row,
            });
        }
        check_result(&b[..n], Quantity::LinearSystem)?;
    }
    Ok(())
}

/// [`cholesky_solve`] without its checks, for the constraint and
/// inverse-kinematics solvers, which check what they form from `x`.
pub(crate) fn cholesky_solve_unchecked<S: Scalar, const N: usize>(
    l: &[[S; N]; N],
    n: usize,
    b: &mut [S; N],
) {
    let n = n.min(N);
    for i in 0..n {
        let mut s = b[i];
        for k in 0..i {
            s -= l[i][k] * b[k];
        }
        b[i] = s / l[i][i];
    }
    for i in (0..n).rev() {
        let mut s = b[i];
        for k in i + 1..n {
            s -= l[k][i] * b[k];
        }
        b[i] = s / l[i][i];
    }
}
