//! Planar rigid-body inertia: mass, centre of mass and moment about z.

use super::Vec2;
use crate::spatial::ParameterProblem;
use crate::Scalar;

/// Mass (kg), centre of mass in the plane (m), moment of inertia about the
/// z axis through the centre of mass (kg m²).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanarInertia<S> {
    /// Mass m.
    pub mass: S,
    /// Centre of mass c in the body frame.
    pub com: Vec2<S>,
    /// Moment of inertia about z through the centre of mass.
    pub izz: S,
}

impl<S: Scalar> PlanarInertia<S> {
    /// `true` when every entry is finite.
    #[inline]
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.mass.is_finite() && self.com.is_finite() && self.izz.is_finite()
    }
    /// Checks that the inertia is physical: finite, a mass and an `izz`
    /// that are not negative, and no overflowing products (`m |c|²`,
    /// `m²`, and the square of the inertia about the origin, which ABA
    /// forms).
    ///
    /// # Errors
    /// The first [`ParameterProblem`] found.
    pub fn validate(&self) -> Result<(), ParameterProblem> {
        let ok = |x: S| x.is_finite() && x.to_f64() >= 0.0;
        if !(self.mass.is_finite() && self.com.is_finite() && self.izz.is_finite()) {
            Err(ParameterProblem::NonFinite)
        } else if !ok(self.mass) {
            Err(ParameterProblem::InvalidMass)
        } else if !(self.mass * self.com.norm_squared() + self.izz).is_finite()
            || !(self.mass * self.mass).is_finite()
            || !((self.mass * self.com.norm_squared() + self.izz).squared()).is_finite()
        {
            // Also the products of two entries ABA forms (U Uᵀ).
            Err(ParameterProblem::Overflow)
        } else if !ok(self.izz) {
            Err(ParameterProblem::InvalidInertia)
        } else {
            Ok(())
        }
    }
    /// An inertia from its parts.
    #[must_use]
    pub const fn new(mass: S, com: Vec2<S>, izz: S) -> Self {
        Self { mass, com, izz }
    }
    /// Converts the scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> PlanarInertia<T> {
        PlanarInertia::new(
            T::from_f64(self.mass.to_f64()),
            self.com.cast(),
            T::from_f64(self.izz.to_f64()),
        )
    }
}
