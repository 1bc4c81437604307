//! Planar force vectors `[n; fx; fy]`: moment about z, force in the x-y plane.

use super::Vec2;
use crate::Scalar;
use core::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

/// A planar force vector (N m, N).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PlanarForce<S> {
    /// Moment n about z through the frame origin.
    pub ang: S,
    /// Linear part in the plane.
    pub lin: Vec2<S>,
}

impl<S: Scalar> PlanarForce<S> {
    /// A vector from its angular and linear parts.
    #[must_use]
    pub const fn new(ang: S, lin: Vec2<S>) -> Self {
        Self { ang, lin }
    }
}
impl<S: Scalar> Add for PlanarForce<S> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self::new(self.ang + o.ang, self.lin + o.lin)
    }
}
impl<S: Scalar> Sub for PlanarForce<S> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self::new(self.ang - o.ang, self.lin - o.lin)
    }
}
impl<S: Scalar> Neg for PlanarForce<S> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.ang, -self.lin)
    }
}
impl<S: Scalar> Mul<S> for PlanarForce<S> {
    type Output = Self;
    #[inline]
    fn mul(self, s: S) -> Self {
        Self::new(self.ang * s, self.lin * s)
    }
}
impl<S: Scalar> AddAssign for PlanarForce<S> {
    #[inline]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}
impl<S: Scalar> SubAssign for PlanarForce<S> {
    #[inline]
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}
impl<S: Scalar> PlanarForce<S> {
    /// A pure force `f` applied at point `p` (both in this frame).
    #[must_use]
    pub fn at_point(f: Vec2<S>, p: &Vec2<S>) -> Self {
        Self::new(p.cross(&f), f)
    }
}
