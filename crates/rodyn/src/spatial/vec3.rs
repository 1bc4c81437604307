//! 3-vectors, the building block of the 6-D spatial types.

use crate::Scalar;
use core::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

/// A 3-vector of scalars.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vec3<S> {
    /// x component.
    pub x: S,
    /// y component.
    pub y: S,
    /// z component.
    pub z: S,
}

impl<S: Scalar> Vec3<S> {
    /// The zero vector.
    pub const ZERO: Self = Self::new(S::ZERO, S::ZERO, S::ZERO);

    /// A vector from its components.
    #[must_use]
    pub const fn new(x: S, y: S, z: S) -> Self {
        Self { x, y, z }
    }
    /// A vector from an array `[x, y, z]`.
    #[must_use]
    pub const fn from_array(a: [S; 3]) -> Self {
        let [x, y, z] = a;
        Self { x, y, z }
    }
    /// The components as `[x, y, z]`.
    #[must_use]
    pub const fn to_array(self) -> [S; 3] {
        [self.x, self.y, self.z]
    }
    /// Unit vector along coordinate axis `k` (0, 1, 2).
    #[must_use]
    pub fn unit(k: usize) -> Self {
        let mut v = Self::ZERO;
        match k {
            0 => v.x = S::ONE,
            1 => v.y = S::ONE,
            _ => v.z = S::ONE,
        }
        v
    }
    /// Component `k` (0, 1, 2).
    #[inline]
    #[must_use]
    pub fn get(&self, k: usize) -> S {
        match k {
            0 => self.x,
            1 => self.y,
            _ => self.z,
        }
    }
    /// Dot product.
    #[inline]
    #[must_use]
    pub fn dot(&self, o: &Self) -> S {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    /// Cross product `self × o`.
    #[inline]
    #[must_use]
    pub fn cross(&self, o: &Self) -> Self {
        Self::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }
    /// Squared Euclidean norm.
    #[inline]
    #[must_use]
    pub fn norm_squared(&self) -> S {
        self.dot(self)
    }
    /// Euclidean norm.
    #[inline]
    #[must_use]
    pub fn norm(&self) -> S {
        self.norm_squared().sqrt()
    }
    /// Every component multiplied by `s`.
    #[inline]
    #[must_use]
    pub fn scale(&self, s: S) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
    /// Converts the scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> Vec3<T> {
        Vec3::new(
            T::from_f64(self.x.to_f64()),
            T::from_f64(self.y.to_f64()),
            T::from_f64(self.z.to_f64()),
        )
    }
    /// `true` when every component is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }
}

impl<S: Scalar> Add for Vec3<S> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}
impl<S: Scalar> Sub for Vec3<S> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}
impl<S: Scalar> Neg for Vec3<S> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}
impl<S: Scalar> Mul<S> for Vec3<S> {
    type Output = Self;
    #[inline]
    fn mul(self, s: S) -> Self {
        self.scale(s)
    }
}
impl<S: Scalar> AddAssign for Vec3<S> {
    #[inline]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}
impl<S: Scalar> SubAssign for Vec3<S> {
    #[inline]
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}
