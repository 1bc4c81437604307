//! Symmetric 3x3 matrices: rotational inertias and articulated-inertia blocks.

use super::mat3::dot3;
use super::{Mat3, Vec3};
use crate::Scalar;
use core::ops::{Add, AddAssign, Sub, SubAssign};

/// A symmetric 3x3 matrix stored as its upper triangle (six numbers).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Sym3<S> {
    /// Entry (0, 0).
    pub xx: S,
    /// Entries (0, 1) and (1, 0).
    pub xy: S,
    /// Entries (0, 2) and (2, 0).
    pub xz: S,
    /// Entry (1, 1).
    pub yy: S,
    /// Entries (1, 2) and (2, 1).
    pub yz: S,
    /// Entry (2, 2).
    pub zz: S,
}

impl<S: Scalar> Sym3<S> {
    /// The zero matrix.
    pub const ZERO: Self = Self::new(S::ZERO, S::ZERO, S::ZERO, S::ZERO, S::ZERO, S::ZERO);

    /// A symmetric matrix from its upper triangle, row by row.
    #[must_use]
    pub const fn new(xx: S, xy: S, xz: S, yy: S, yz: S, zz: S) -> Self {
        Self {
            xx,
            xy,
            xz,
            yy,
            yz,
            zz,
        }
    }
    /// A diagonal matrix.
    #[must_use]
    pub const fn diagonal(xx: S, yy: S, zz: S) -> Self {
        Self::new(xx, S::ZERO, S::ZERO, yy, S::ZERO, zz)
    }
    /// `s` times the identity.
    #[must_use]
    pub const fn identity_scaled(s: S) -> Self {
        Self::diagonal(s, s, s)
    }
    /// The full matrix.
    #[must_use]
    pub fn to_mat3(&self) -> Mat3<S> {
        Mat3::from_rows(self.rows())
    }
    /// The three rows (equal to the columns).
    #[inline]
    #[must_use]
    pub fn rows(&self) -> [[S; 3]; 3] {
        [
            [self.xx, self.xy, self.xz],
            [self.xy, self.yy, self.yz],
            [self.xz, self.yz, self.zz],
        ]
    }
    /// The upper triangle of a general matrix (its lower triangle is ignored).
    #[must_use]
    pub fn from_upper(m: &Mat3<S>) -> Self {
        let m = &m.m;
        Self::new(m[0][0], m[0][1], m[0][2], m[1][1], m[1][2], m[2][2])
    }
    /// Entry (i, j).
    #[inline]
    #[must_use]
    pub fn get(&self, i: usize, j: usize) -> S {
        match (i.min(j), i.max(j)) {
            (0, 0) => self.xx,
            (0, 1) => self.xy,
            (0, 2) => self.xz,
            (1, 1) => self.yy,
            (1, 2) => self.yz,
            _ => self.zz,
        }
    }
    /// Entry (i, j) for writing (the same storage as (j, i)).
    #[inline]
    pub fn get_mut(&mut self, i: usize, j: usize) -> &mut S {
        match (i.min(j), i.max(j)) {
            (0, 0) => &mut self.xx,
            (0, 1) => &mut self.xy,
            (0, 2) => &mut self.xz,
            (1, 1) => &mut self.yy,
            (1, 2) => &mut self.yz,
            _ => &mut self.zz,
        }
    }
    /// Column `k` (equal to row `k`).
    #[inline]
    #[must_use]
    pub fn column(&self, k: usize) -> Vec3<S> {
        match k {
            0 => Vec3::new(self.xx, self.xy, self.xz),
            1 => Vec3::new(self.xy, self.yy, self.yz),
            _ => Vec3::new(self.xz, self.yz, self.zz),
        }
    }
    /// `self * v`.
    #[inline]
    #[must_use]
    pub fn mul_vec(&self, v: &Vec3<S>) -> Vec3<S> {
        Vec3::new(
            self.xx * v.x + self.xy * v.y + self.xz * v.z,
            self.xy * v.x + self.yy * v.y + self.yz * v.z,
            self.xz * v.x + self.yz * v.y + self.zz * v.z,
        )
    }
    /// `R self Rᵀ`: the same tensor seen from a frame rotated by `R`.
    #[must_use]
    #[inline]
    pub fn rotate(&self, r: &Mat3<S>) -> Self {
        // (R S Rᵀ)ᵢⱼ = rᵢ · (S rⱼ) with rᵢ the rows of R: the three products
        // S rⱼ (27), then only the upper triangle (18), the lower one being
        // its mirror. Written on the rows, so that nothing goes through a
        // temporary matrix.
        let (m, r) = (self.rows(), &r.m);
        let s_r = |j: usize| [dot3(&m[0], &r[j]), dot3(&m[1], &r[j]), dot3(&m[2], &r[j])];
        let (t0, t1, t2) = (s_r(0), s_r(1), s_r(2));
        Self::new(
            dot3(&r[0], &t0),
            dot3(&r[0], &t1),
            dot3(&r[0], &t2),
            dot3(&r[1], &t1),
            dot3(&r[1], &t2),
            dot3(&r[2], &t2),
        )
    }
    /// `Rᵀ self R`: the tensor of `self` brought back through `R`.
    #[must_use]
    pub fn rotate_inv(&self, r: &Mat3<S>) -> Self {
        self.rotate(&r.transpose())
    }
    /// `-[c×][c×] = |c|² 1 - c cᵀ`, the parallel-axis term for offset `c`.
    #[must_use]
    pub fn parallel_axis(c: &Vec3<S>) -> Self {
        let (x, y, z) = (c.x, c.y, c.z);
        Self::new(
            y * y + z * z,
            -x * y,
            -x * z,
            x * x + z * z,
            -y * z,
            x * x + y * y,
        )
    }
    /// The outer product `s a aᵀ`.
    #[must_use]
    pub fn outer(a: &Vec3<S>, s: S) -> Self {
        let (x, y, z) = (a.x * s, a.y * s, a.z * s);
        Self::new(x * a.x, x * a.y, x * a.z, y * a.y, y * a.z, z * a.z)
    }
    /// The symmetrised outer product `s (a bᵀ + b aᵀ)`.
    #[must_use]
    pub fn outer_sym(a: &Vec3<S>, b: &Vec3<S>, s: S) -> Self {
        let (ax, ay, az) = (a.x * s, a.y * s, a.z * s);
        Self::new(
            (ax * b.x) + (ax * b.x),
            ax * b.y + ay * b.x,
            ax * b.z + az * b.x,
            (ay * b.y) + (ay * b.y),
            ay * b.z + az * b.y,
            (az * b.z) + (az * b.z),
        )
    }
    /// Every entry times `s`.
    #[must_use]
    pub fn scale(&self, s: S) -> Self {
        Self::new(
            self.xx * s,
            self.xy * s,
            self.xz * s,
            self.yy * s,
            self.yz * s,
            self.zz * s,
        )
    }
    /// The trace.
    #[must_use]
    pub fn trace(&self) -> S {
        self.xx + self.yy + self.zz
    }
    /// Converts the scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> Sym3<T> {
        let c = |v: S| T::from_f64(v.to_f64());
        Sym3::new(
            c(self.xx),
            c(self.xy),
            c(self.xz),
            c(self.yy),
            c(self.yz),
            c(self.zz),
        )
    }
    /// `true` when every entry is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        [self.xx, self.xy, self.xz, self.yy, self.yz, self.zz]
            .iter()
            .all(|v| v.is_finite())
    }
}

impl<S: Scalar> Add for Sym3<S> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self::new(
            self.xx + o.xx,
            self.xy + o.xy,
            self.xz + o.xz,
            self.yy + o.yy,
            self.yz + o.yz,
            self.zz + o.zz,
        )
    }
}
impl<S: Scalar> Sub for Sym3<S> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self::new(
            self.xx - o.xx,
            self.xy - o.xy,
            self.xz - o.xz,
            self.yy - o.yy,
            self.yz - o.yz,
            self.zz - o.zz,
        )
    }
}
impl<S: Scalar> AddAssign for Sym3<S> {
    #[inline]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}
impl<S: Scalar> SubAssign for Sym3<S> {
    #[inline]
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}
