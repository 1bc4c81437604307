//! Planar motion vectors `[ω; vx; vy]`: rotation about z, velocity in the x-y plane.

use super::Vec2;
use crate::Scalar;
use core::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

/// A planar motion vector (rad/s, m/s).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PlanarMotion<S> {
    /// Angular rate ω about z.
    pub ang: S,
    /// Linear part in the plane.
    pub lin: Vec2<S>,
}

impl<S: Scalar> PlanarMotion<S> {
    /// A vector from its angular and linear parts.
    #[must_use]
    pub const fn new(ang: S, lin: Vec2<S>) -> Self {
        Self { ang, lin }
    }
}
impl<S: Scalar> Add for PlanarMotion<S> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self::new(self.ang + o.ang, self.lin + o.lin)
    }
}
impl<S: Scalar> Sub for PlanarMotion<S> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self::new(self.ang - o.ang, self.lin - o.lin)
    }
}
impl<S: Scalar> Neg for PlanarMotion<S> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.ang, -self.lin)
    }
}
impl<S: Scalar> Mul<S> for PlanarMotion<S> {
    type Output = Self;
    #[inline]
    fn mul(self, s: S) -> Self {
        Self::new(self.ang * s, self.lin * s)
    }
}
impl<S: Scalar> AddAssign for PlanarMotion<S> {
    #[inline]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}
impl<S: Scalar> SubAssign for PlanarMotion<S> {
    #[inline]
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}
