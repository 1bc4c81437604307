//! Spatial motion vectors (Featherstone §2.2): `[ω; v]`.
//!
//! Frame conventions: a body velocity `v_i` is expressed in body frame i and
//! `v` is the velocity of the point of the body at the frame's origin
//! (Pinocchio's "local" convention). Angular part first in memory; use
//! [`Motion::to_linear_first`] for Pinocchio's `[v; ω]` layout.

use super::Vec3;
use crate::Scalar;
use core::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

/// A spatial motion vector: angular part `ang` (rad/s) and linear part `lin` (m/s).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Motion<S> {
    /// Angular component ω.
    pub ang: Vec3<S>,
    /// Linear component v (velocity of the frame origin).
    pub lin: Vec3<S>,
}

impl<S: Scalar> Motion<S> {
    /// A motion vector from its angular and linear parts.
    #[must_use]
    pub const fn new(ang: Vec3<S>, lin: Vec3<S>) -> Self {
        Self { ang, lin }
    }
    /// Pinocchio's layout `[vx vy vz ωx ωy ωz]`.
    #[must_use]
    pub fn to_linear_first(&self) -> [S; 6] {
        [
            self.lin.x, self.lin.y, self.lin.z, self.ang.x, self.ang.y, self.ang.z,
        ]
    }
    /// From Pinocchio's layout `[vx vy vz ωx ωy ωz]`.
    #[must_use]
    pub fn from_linear_first(a: &[S; 6]) -> Self {
        Self::new(Vec3::new(a[3], a[4], a[5]), Vec3::new(a[0], a[1], a[2]))
    }
}
impl<S: Scalar> Add for Motion<S> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self::new(self.ang + o.ang, self.lin + o.lin)
    }
}
impl<S: Scalar> Sub for Motion<S> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self::new(self.ang - o.ang, self.lin - o.lin)
    }
}
impl<S: Scalar> Neg for Motion<S> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.ang, -self.lin)
    }
}
impl<S: Scalar> Mul<S> for Motion<S> {
    type Output = Self;
    #[inline]
    fn mul(self, s: S) -> Self {
        Self::new(self.ang * s, self.lin * s)
    }
}
impl<S: Scalar> AddAssign for Motion<S> {
    #[inline]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}
impl<S: Scalar> SubAssign for Motion<S> {
    #[inline]
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}
