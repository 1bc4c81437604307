//! Spatial force vectors (Featherstone §2.3): `[n; f]`.
//!
//! `n` is the moment about the frame's origin (N m) and `f` the force (N),
//! both in the frame's coordinates. Angular part first in memory.

use super::Vec3;
use crate::Scalar;
use core::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

/// A spatial force vector: moment `ang` and force `lin`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Force<S> {
    /// Moment n about the frame origin.
    pub ang: Vec3<S>,
    /// Linear force f.
    pub lin: Vec3<S>,
}

impl<S: Scalar> Force<S> {
    /// A force vector from its moment and force parts.
    #[must_use]
    pub const fn new(ang: Vec3<S>, lin: Vec3<S>) -> Self {
        Self { ang, lin }
    }
    /// Pinocchio's layout `[fx fy fz nx ny nz]`.
    #[must_use]
    pub fn to_linear_first(&self) -> [S; 6] {
        [
            self.lin.x, self.lin.y, self.lin.z, self.ang.x, self.ang.y, self.ang.z,
        ]
    }
    /// From Pinocchio's layout `[fx fy fz nx ny nz]`.
    #[must_use]
    pub fn from_linear_first(a: &[S; 6]) -> Self {
        Self::new(Vec3::new(a[3], a[4], a[5]), Vec3::new(a[0], a[1], a[2]))
    }
    /// A pure force `f` applied at point `p` (both in this frame).
    #[must_use]
    pub fn at_point(f: Vec3<S>, p: &Vec3<S>) -> Self {
        Self::new(p.cross(&f), f)
    }
}
impl<S: Scalar> Add for Force<S> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self::new(self.ang + o.ang, self.lin + o.lin)
    }
}
impl<S: Scalar> Sub for Force<S> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self::new(self.ang - o.ang, self.lin - o.lin)
    }
}
impl<S: Scalar> Neg for Force<S> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.ang, -self.lin)
    }
}
impl<S: Scalar> Mul<S> for Force<S> {
    type Output = Self;
    #[inline]
    fn mul(self, s: S) -> Self {
        Self::new(self.ang * s, self.lin * s)
    }
}
impl<S: Scalar> AddAssign for Force<S> {
    #[inline]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}
impl<S: Scalar> SubAssign for Force<S> {
    #[inline]
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}
