//! 2-vectors: positions and linear parts of planar vectors.

use crate::Scalar;
use core::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

/// A 2-vector in the model's plane (x, y).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vec2<S> {
    /// x component.
    pub x: S,
    /// y component.
    pub y: S,
}

impl<S: Scalar> Vec2<S> {
    /// The zero vector.
    pub const ZERO: Self = Self::new(S::ZERO, S::ZERO);
    /// A vector from its components.
    #[must_use]
    pub const fn new(x: S, y: S) -> Self {
        Self { x, y }
    }
    /// Dot product.
    #[inline]
    #[must_use]
    pub fn dot(&self, o: &Self) -> S {
        self.x * o.x + self.y * o.y
    }
    /// The z component of the cross product `self × o`.
    #[inline]
    #[must_use]
    pub fn cross(&self, o: &Self) -> S {
        self.x * o.y - self.y * o.x
    }
    /// `ω ẑ × self` for an angular rate `w`: `w (-y, x)`.
    #[inline]
    #[must_use]
    pub fn perp_scaled(&self, w: S) -> Self {
        Self::new(-self.y * w, self.x * w)
    }
    /// Every component multiplied by `s`.
    #[inline]
    #[must_use]
    pub fn scale(&self, s: S) -> Self {
        Self::new(self.x * s, self.y * s)
    }
    /// Squared norm.
    #[inline]
    #[must_use]
    pub fn norm_squared(&self) -> S {
        self.dot(self)
    }
    /// Converts the scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> Vec2<T> {
        Vec2::new(T::from_f64(self.x.to_f64()), T::from_f64(self.y.to_f64()))
    }
    /// `true` when both components are finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }
}

impl<S: Scalar> Add for Vec2<S> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y)
    }
}
impl<S: Scalar> Sub for Vec2<S> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y)
    }
}
impl<S: Scalar> Neg for Vec2<S> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y)
    }
}
impl<S: Scalar> Mul<S> for Vec2<S> {
    type Output = Self;
    #[inline]
    fn mul(self, s: S) -> Self {
        self.scale(s)
    }
}
impl<S: Scalar> AddAssign for Vec2<S> {
    #[inline]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}
impl<S: Scalar> SubAssign for Vec2<S> {
    #[inline]
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}
