//! Planar rigid transforms: a rotation about z and a translation in the plane.
//!
//! [`PlanarTransform`] `aMb` stores the cosine and sine of the angle of b's
//! x axis in a, and the origin of b in a; the method table of
//! [`Transform`](crate::spatial::Transform) applies unchanged.

use super::Vec2;
use crate::spatial::ParameterProblem;
use crate::Scalar;

/// A planar rigid transform `aMb`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanarTransform<S> {
    /// Cosine of the rotation angle.
    pub cos: S,
    /// Sine of the rotation angle.
    pub sin: S,
    /// Origin of b in a (m).
    pub trans: Vec2<S>,
}

impl<S: Scalar> PlanarTransform<S> {
    /// `true` when every entry is finite.
    #[inline]
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.cos.is_finite() && self.sin.is_finite() && self.trans.is_finite()
    }
    /// Checks a placement: finite, a translation whose `|p|⁴` is finite
    /// (as the 3-D placements: ABA multiplies two `m |p|²` entries), and
    /// `cos² + sin² = 1` to 10³ ε.
    ///
    /// # Errors
    /// The first [`ParameterProblem`] found.
    pub fn validate(&self) -> Result<(), ParameterProblem> {
        // Compared in `S`, as the 3-D placements.
        let n = self.cos * self.cos + self.sin * self.sin;
        if !self.is_finite() {
            Err(ParameterProblem::NonFinite)
        } else if !self.trans.norm_squared().squared().is_finite() {
            // As the 3-D placements: ABA multiplies two m |p|² entries.
            Err(ParameterProblem::Overflow)
        } else if (n - S::ONE).abs() <= S::from_f64(1e3 * S::EPSILON) {
            Ok(())
        } else {
            Err(ParameterProblem::RotationNotOrthonormal)
        }
    }
    /// From the cosine and sine of the angle and the translation (usable in `const`).
    #[must_use]
    pub const fn from_cos_sin(cos: S, sin: S, trans: Vec2<S>) -> Self {
        Self { cos, sin, trans }
    }
    /// A pure translation.
    #[must_use]
    pub const fn from_translation(trans: Vec2<S>) -> Self {
        Self::from_cos_sin(S::ONE, S::ZERO, trans)
    }
    /// A rotation by `angle` (rad) followed by the translation.
    #[must_use]
    pub fn from_angle(angle: S, trans: Vec2<S>) -> Self {
        let (sin, cos) = angle.sin_cos();
        Self::from_cos_sin(cos, sin, trans)
    }
    /// The rotation angle (rad).
    #[must_use]
    pub fn angle(&self) -> S {
        self.sin.atan2(self.cos)
    }
    /// `R v`.
    #[inline]
    #[must_use]
    pub fn rotate(&self, v: &Vec2<S>) -> Vec2<S> {
        Vec2::new(
            self.cos * v.x - self.sin * v.y,
            self.sin * v.x + self.cos * v.y,
        )
    }
    /// `Rᵀ v`.
    #[inline]
    #[must_use]
    pub fn rotate_inv(&self, v: &Vec2<S>) -> Vec2<S> {
        Vec2::new(
            self.cos * v.x + self.sin * v.y,
            -self.sin * v.x + self.cos * v.y,
        )
    }
    /// Converts the scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> PlanarTransform<T> {
        PlanarTransform::from_cos_sin(
            T::from_f64(self.cos.to_f64()),
            T::from_f64(self.sin.to_f64()),
            self.trans.cast(),
        )
    }
}
