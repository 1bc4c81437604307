//! 3x3 matrices: rotations and general blocks.

use super::{Sym3, Vec3};
use crate::Scalar;

/// A general 3x3 matrix, row-major: `m[row][col]`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Mat3<S> {
    /// Rows of the matrix.
    pub m: [[S; 3]; 3],
}

impl<S: Scalar> Mat3<S> {
    /// The identity matrix.
    pub const IDENTITY: Self = Self::from_rows([
        [S::ONE, S::ZERO, S::ZERO],
        [S::ZERO, S::ONE, S::ZERO],
        [S::ZERO, S::ZERO, S::ONE],
    ]);
    /// The zero matrix.
    pub const ZERO: Self = Self::from_rows([[S::ZERO; 3]; 3]);

    /// `self == Mat3::IDENTITY`, the six off-diagonal entries tested
    /// together ([`Scalar::all_zero`]) rather than compared one by one.
    #[inline(always)]
    #[must_use]
    pub(crate) fn is_identity(&self) -> bool {
        let m = &self.m;
        S::all_zero([m[0][1], m[0][2], m[1][0], m[1][2], m[2][0], m[2][1]])
            && m[0][0] == S::ONE
            && m[1][1] == S::ONE
            && m[2][2] == S::ONE
    }

    /// A matrix from its rows.
    #[must_use]
    pub const fn from_rows(m: [[S; 3]; 3]) -> Self {
        Self { m }
    }

    /// Rotation by `angle` (radians) about the unit axis `axis` (Rodrigues).
    #[must_use]
    pub fn from_axis_angle(axis: &Vec3<S>, angle: S) -> Self {
        let (s, c) = angle.sin_cos();
        Self::from_axis_sin_cos(axis, s, c)
    }

    /// Rotation about the unit axis `a` given the sine and cosine of the angle.
    #[must_use]
    pub fn from_axis_sin_cos(a: &Vec3<S>, s: S, c: S) -> Self {
        let t = S::ONE - c;
        let (x, y, z) = (a.x, a.y, a.z);
        Self::from_rows([
            [t * x * x + c, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c],
        ])
    }

    /// Rotation about coordinate axis `k` (0 = x, 1 = y, 2 = z).
    #[must_use]
    pub fn from_axis_index(k: usize, s: S, c: S) -> Self {
        let (o, z) = (S::ONE, S::ZERO);
        match k {
            0 => Self::from_rows([[o, z, z], [z, c, -s], [z, s, c]]),
            1 => Self::from_rows([[c, z, s], [z, o, z], [-s, z, c]]),
            _ => Self::from_rows([[c, -s, z], [s, c, z], [z, z, o]]),
        }
    }

    /// Rotation matrix of the unit quaternion `(x, y, z, w)`.
    #[must_use]
    pub fn from_quaternion(x: S, y: S, z: S, w: S) -> Self {
        let two = S::from_f64(2.0);
        let (xx, yy, zz) = (x * x, y * y, z * z);
        let (xy, xz, yz) = (x * y, x * z, y * z);
        let (wx, wy, wz) = (w * x, w * y, w * z);
        Self::from_rows([
            [S::ONE - two * (yy + zz), two * (xy - wz), two * (xz + wy)],
            [two * (xy + wz), S::ONE - two * (xx + zz), two * (yz - wx)],
            [two * (xz - wy), two * (yz + wx), S::ONE - two * (xx + yy)],
        ])
    }

    /// Column `k`; a `k` past 2 reads the last column (as
    /// [`Sym3::column`](super::Sym3::column)), which keeps a panic path out
    /// of the callers whose `k` the optimiser cannot bound.
    #[inline]
    #[must_use]
    pub fn column(&self, k: usize) -> Vec3<S> {
        let k = k.min(2);
        Vec3::new(self.m[0][k], self.m[1][k], self.m[2][k])
    }
    /// Row `k`; a `k` past 2 reads the last row (as [`Self::column`]).
    #[inline]
    #[must_use]
    pub fn row(&self, k: usize) -> Vec3<S> {
        Vec3::from_array(self.m[k.min(2)])
    }

    /// `self * v`.
    #[inline]
    #[must_use]
    pub fn mul_vec(&self, v: &Vec3<S>) -> Vec3<S> {
        let m = &self.m;
        Vec3::new(
            m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z,
        )
    }
    /// `selfᵀ * v`.
    #[inline]
    #[must_use]
    pub fn tr_mul_vec(&self, v: &Vec3<S>) -> Vec3<S> {
        let m = &self.m;
        Vec3::new(
            m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z,
            m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
            m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z,
        )
    }
    /// `self * o`.
    #[must_use]
    pub fn mul_mat(&self, o: &Self) -> Self {
        // Written out rather than looped: at the firmware's size-optimised
        // level a loop over nine entries is not unrolled, and its index
        // arithmetic costs as much as the products.
        let (a, b) = (&self.m, &o.m);
        let entry = |r: &[S; 3], j: usize| r[0] * b[0][j] + r[1] * b[1][j] + r[2] * b[2][j];
        Self::from_rows([
            [entry(&a[0], 0), entry(&a[0], 1), entry(&a[0], 2)],
            [entry(&a[1], 0), entry(&a[1], 1), entry(&a[1], 2)],
            [entry(&a[2], 0), entry(&a[2], 1), entry(&a[2], 2)],
        ])
    }
    /// `self * oᵀ`: every entry a dot product of two rows, no transpose formed.
    #[must_use]
    pub fn mul_mat_tr(&self, o: &Self) -> Self {
        let (a, b) = (&self.m, &o.m);
        Self::from_rows([
            [dot3(&a[0], &b[0]), dot3(&a[0], &b[1]), dot3(&a[0], &b[2])],
            [dot3(&a[1], &b[0]), dot3(&a[1], &b[1]), dot3(&a[1], &b[2])],
            [dot3(&a[2], &b[0]), dot3(&a[2], &b[1]), dot3(&a[2], &b[2])],
        ])
    }
    /// `self * Rₖ(θ)` for a rotation about coordinate axis `k` given `sin θ`
    /// and `cos θ`: the same as `self.mul_mat(&Mat3::from_axis_index(k, s, c))`.
    ///
    /// Only the two columns orthogonal to the axis mix, as a 2-D rotation:
    /// 12 multiplications instead of 27. A revolute joint about a coordinate
    /// axis composes its placement with its rotation this way.
    #[inline]
    #[must_use]
    pub fn mul_axis_rotation(&self, k: usize, s: S, c: S) -> Self {
        // Columns i and j span the plane of the rotation, in right-handed
        // order; one arm per axis, so that the indices are constants.
        match k {
            0 => self.mul_plane_rotation::<1, 2>(s, c),
            1 => self.mul_plane_rotation::<2, 0>(s, c),
            _ => self.mul_plane_rotation::<0, 1>(s, c),
        }
    }
    /// `self * r` for an `r` whose third axis (the one besides `I` and
    /// `J`) it leaves alone: columns `I` and `J` mixed by `r`'s plane
    /// block, each entry summed in the order `self * r` sums it, so that
    /// the result is the full product's, bit for bit (up to the sign of
    /// a zero).
    #[inline(always)]
    #[must_use]
    pub fn mul_plane_block<const I: usize, const J: usize>(&self, r: &Self) -> Self {
        let (ii, ij, ji, jj) = (r.m[I][I], r.m[I][J], r.m[J][I], r.m[J][J]);
        let turn = |row: &[S; 3]| {
            let mut out = *row;
            // `self * r` adds the products in index order.
            if I < J {
                out[I] = row[I] * ii + row[J] * ji;
                out[J] = row[I] * ij + row[J] * jj;
            } else {
                out[I] = row[J] * ji + row[I] * ii;
                out[J] = row[J] * jj + row[I] * ij;
            }
            out
        };
        let m = &self.m;
        Self::from_rows([turn(&m[0]), turn(&m[1]), turn(&m[2])])
    }
    /// `self * r` for an `r` that carries coordinate axis `K` onto axis
    /// `U` (its column K is zero but for row U, and its row U zero but for
    /// column K), as a quarter turn followed by a rotation about K does:
    /// column K of the product is `self`'s column U scaled, and the other
    /// two mix `self`'s other two columns. Each entry is summed in the
    /// order `self * r` sums it, so that the result is the full product's,
    /// bit for bit (up to the sign of a zero).
    #[inline(always)]
    #[must_use]
    pub(crate) fn mul_carried_axis<const K: usize, const U: usize>(&self, r: &Self) -> Self {
        let (i, j) = ((K + 1) % 3, (K + 2) % 3);
        // The two rows of `r` besides U, in index order.
        let (a, b) = if U == 0 {
            (1, 2)
        } else if U == 1 {
            (0, 2)
        } else {
            (0, 1)
        };
        let r = &r.m;
        let turn = |row: &[S; 3]| {
            let mut out = [S::ZERO; 3];
            out[K] = row[U] * r[U][K];
            out[i] = row[a] * r[a][i] + row[b] * r[b][i];
            out[j] = row[a] * r[a][j] + row[b] * r[b][j];
            out
        };
        let m = &self.m;
        Self::from_rows([turn(&m[0]), turn(&m[1]), turn(&m[2])])
    }
    /// `self` with columns `I` and `J` turned by the angle of `(s, c)`.
    #[inline(always)]
    fn mul_plane_rotation<const I: usize, const J: usize>(&self, s: S, c: S) -> Self {
        // Row by row, written out: a loop here is not unrolled at the
        // firmware's size-optimised level and goes through a stack copy.
        let m = &self.m;
        let turn = |row: &[S; 3]| {
            let mut out = *row;
            out[I] = row[I] * c + row[J] * s;
            out[J] = row[J] * c - row[I] * s;
            out
        };
        Self::from_rows([turn(&m[0]), turn(&m[1]), turn(&m[2])])
    }
    /// `selfᵀ * o`.
    #[must_use]
    pub fn tr_mul_mat(&self, o: &Self) -> Self {
        self.transpose().mul_mat(o)
    }
    /// The transpose.
    #[must_use]
    pub fn transpose(&self) -> Self {
        let m = &self.m;
        Self::from_rows([
            [m[0][0], m[1][0], m[2][0]],
            [m[0][1], m[1][1], m[2][1]],
            [m[0][2], m[1][2], m[2][2]],
        ])
    }
    /// `self * [p×]`, the product with the cross-product matrix of `p`.
    #[must_use]
    pub fn mul_cross(&self, p: &Vec3<S>) -> Self {
        // Row i of M [p×] is M_iᵀ [p×] = (M_i × p)ᵀ.
        Self::from_rows([
            self.row(0).cross(p).to_array(),
            self.row(1).cross(p).to_array(),
            self.row(2).cross(p).to_array(),
        ])
    }
    /// `[p×] self`, the product with the cross-product matrix of `p` on the left.
    #[must_use]
    pub fn cross_mul(p: &Vec3<S>, m: &Self) -> Self {
        // Column j of [p×] M is p × M_j; written by rows of the result.
        let (c0, c1, c2) = (
            p.cross(&m.column(0)),
            p.cross(&m.column(1)),
            p.cross(&m.column(2)),
        );
        Self::from_rows([[c0.x, c1.x, c2.x], [c0.y, c1.y, c2.y], [c0.z, c1.z, c2.z]])
    }
    /// The symmetric part `(self + selfᵀ)`: twice the symmetric part.
    #[must_use]
    pub fn sym_sum(&self) -> Sym3<S> {
        let m = &self.m;
        Sym3::new(
            m[0][0] + m[0][0],
            m[0][1] + m[1][0],
            m[0][2] + m[2][0],
            m[1][1] + m[1][1],
            m[1][2] + m[2][1],
            m[2][2] + m[2][2],
        )
    }
    /// Converts the scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> Mat3<T> {
        let mut r = Mat3::<T>::ZERO;
        for i in 0..3 {
            for j in 0..3 {
                r.m[i][j] = T::from_f64(self.m[i][j].to_f64());
            }
        }
        r
    }
}

/// The dot product of two rows.
#[inline]
pub(crate) fn dot3<S: Scalar>(a: &[S; 3], b: &[S; 3]) -> S {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

impl<S: Scalar> core::ops::Add for Mat3<S> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        // Row by row, written out for the size-optimised firmware build
        // (see `mul_mat`).
        let row = |a: [S; 3], b: [S; 3]| [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
        Self::from_rows([
            row(self.m[0], o.m[0]),
            row(self.m[1], o.m[1]),
            row(self.m[2], o.m[2]),
        ])
    }
}
impl<S: Scalar> core::ops::Sub for Mat3<S> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        let row = |a: [S; 3], b: [S; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
        Self::from_rows([
            row(self.m[0], o.m[0]),
            row(self.m[1], o.m[1]),
            row(self.m[2], o.m[2]),
        ])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `is_identity` agrees with the comparison, signed zeros, NaN and
    /// each entry's change included.
    #[test]
    fn is_identity_is_the_comparison() {
        let mut cases = vec![
            Mat3::IDENTITY,
            Mat3::ZERO,
            Mat3::from_axis_angle(&Vec3::new(0.0, 0.0, 1.0), 0.3),
        ];
        for r in 0..3 {
            for c in 0..3 {
                for x in [-0.0, 0.0, 1.0, -1.0, 1e-300, f64::NAN, f64::INFINITY] {
                    let mut m = Mat3::IDENTITY;
                    m.m[r][c] = x;
                    cases.push(m);
                }
            }
        }
        for m in cases {
            assert_eq!(m.is_identity(), m == Mat3::IDENTITY, "{m:?}");
        }
    }

    /// A column index past 2 reads the last column instead of panicking.
    #[test]
    fn column_past_the_end_is_the_last() {
        let m = Mat3::from_rows([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0], [7.0, 8.0, 9.0]]);
        assert_eq!(m.column(1), Vec3::new(2.0, 5.0, 8.0));
        assert_eq!(m.column(3), m.column(2));
        assert_eq!(m.column(usize::MAX), Vec3::new(3.0, 6.0, 9.0));
    }
}
