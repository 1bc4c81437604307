//! [`Mat3`] ↔ `Matrix3`, [`Sym3`] → `Matrix3`, and rodyn's row arrays
//! (the mass matrix) ↔ `SMatrix`.

use ::nalgebra::{Matrix3, SMatrix};

use crate::spatial::{Mat3, Sym3};
use crate::Scalar;

impl<S: Scalar> From<Mat3<S>> for Matrix3<S> {
    /// The same matrix: entry `(r, c)` is `m[r][c]`.
    ///
    /// ```
    /// use nalgebra::Matrix3;
    /// use rodyn::prelude::Mat3;
    ///
    /// let m = Mat3::from_rows([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0], [7.0, 8.0, 9.0]]);
    /// let n: Matrix3<f64> = m.into();
    /// assert_eq!(n[(0, 1)], 2.0);
    /// ```
    fn from(m: Mat3<S>) -> Self {
        matrix_from_rows(&m.m)
    }
}

impl<S: Scalar> From<Matrix3<S>> for Mat3<S> {
    /// The same matrix: `m[r][c]` is entry `(r, c)`.
    ///
    /// ```
    /// use nalgebra::Matrix3;
    /// use rodyn::prelude::Mat3;
    ///
    /// let m = Mat3::from(Matrix3::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0));
    /// assert_eq!(m.m[0][1], 2.0);
    /// ```
    fn from(m: Matrix3<S>) -> Self {
        Mat3::from_rows(rows_from_matrix(&m))
    }
}

impl<S: Scalar> From<Sym3<S>> for Matrix3<S> {
    /// The full symmetric matrix (a rotational inertia, say).
    ///
    /// ```
    /// use nalgebra::Matrix3;
    /// use rodyn::prelude::Sym3;
    ///
    /// let i: Matrix3<f64> = Sym3::new(1.0, 0.1, 0.2, 2.0, 0.3, 3.0).into();
    /// assert_eq!(i, i.transpose());
    /// assert_eq!((i[(0, 2)], i[(1, 2)]), (0.2, 0.3));
    /// ```
    fn from(m: Sym3<S>) -> Self {
        matrix_from_rows(&m.rows())
    }
}

/// The matrix whose row `r` is `rows[r]`: rodyn's `[[S; C]; R]` arrays,
/// such as the mass matrix (`data.mass_matrix`, what `crba` returns).
///
/// nalgebra's own `From<[[S; R]; C]>` reads an array of columns instead.
///
/// ```
/// use rodyn::interop::nalgebra::matrix_from_rows;
///
/// let a = matrix_from_rows(&[[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
/// assert_eq!((a.nrows(), a.ncols(), a[(0, 2)], a[(1, 0)]), (2, 3, 3.0, 4.0));
/// ```
#[must_use]
pub fn matrix_from_rows<S: Scalar, const R: usize, const C: usize>(
    rows: &[[S; C]; R],
) -> SMatrix<S, R, C> {
    SMatrix::from_fn(|r, c| rows[r][c])
}

/// The rows of `m`, as rodyn's `[[S; C]; R]` arrays hold a matrix.
///
/// ```
/// use nalgebra::Matrix2x3;
/// use rodyn::interop::nalgebra::rows_from_matrix;
///
/// let a = Matrix2x3::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0);
/// assert_eq!(rows_from_matrix(&a), [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
/// ```
#[must_use]
pub fn rows_from_matrix<S: Scalar, const R: usize, const C: usize>(
    m: &SMatrix<S, R, C>,
) -> [[S; C]; R] {
    let mut rows = [[S::ZERO; C]; R];
    for (r, row) in rows.iter_mut().enumerate() {
        for (c, entry) in row.iter_mut().enumerate() {
            *entry = m[(r, c)];
        }
    }
    rows
}
