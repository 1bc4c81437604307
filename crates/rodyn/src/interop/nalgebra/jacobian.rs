//! A Jacobian's columns (`[Motion<S>; NV]`, what
//! [`frame_jacobian`](crate::algorithm::jacobian::frame_jacobian) writes)
//! as a 6×NV `SMatrix`.

use ::nalgebra::SMatrix;

use crate::spatial::Motion;
use crate::Scalar;

/// The 6×NV matrix of Jacobian `columns`, **linear rows first** (`vx vy vz
/// ωx ωy ωz`), as Pinocchio's `getFrameJacobian` returns it; column `k` is
/// `columns[k]`. The same matrix as
/// [`to_linear_first`](crate::algorithm::jacobian::to_linear_first).
///
/// ```
/// use rodyn::interop::nalgebra::jacobian_matrix;
/// use rodyn::prelude::*;
///
/// let columns = [
///     Motion::new(Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.0, 1.0, 0.0)),
///     Motion::new(Vec3::ZERO, Vec3::new(1.0, 0.0, 0.0)),
/// ];
/// let j = jacobian_matrix(&columns);
/// assert_eq!((j[(1, 0)], j[(5, 0)], j[(0, 1)]), (1.0, 1.0, 1.0));
/// ```
#[must_use]
pub fn jacobian_matrix<S: Scalar, const NV: usize>(columns: &[Motion<S>; NV]) -> SMatrix<S, 6, NV> {
    SMatrix::from_fn(|r, c| columns[c].to_linear_first()[r])
}
