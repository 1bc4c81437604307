//! Rigid transforms (Featherstone §2.8, Pinocchio's `SE3`).
//!
//! A [`Transform`] `aMb` holds the rotation `rot` whose columns are b's axes
//! in a, and `trans`, the origin of b in a. A point maps as
//! `p_a = rot p_b + trans`. Its Plücker form is `ᵃX_b = [E 0; -E r× E]ᵀ`-style:
//! the book's `E = rotᵀ` and `r = trans`.
//!
//! | method             | maps            | book            |
//! |--------------------|-----------------|-----------------|
//! | `act_motion`       | motion b → a    | `ᵃX_b m`        |
//! | `act_inv_motion`   | motion a → b    | `ᵇX_a m`        |
//! | `act_force`        | force b → a     | `ᵃX_b* f`       |
//! | `act_inv_force`    | force a → b     | `ᵇX_a* f`       |

use super::ParameterProblem;
use super::{Mat3, Vec3};
use crate::Scalar;

/// A rigid transform `aMb` (rotation, then translation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform<S> {
    /// Rotation from b coordinates to a coordinates.
    pub rot: Mat3<S>,
    /// Origin of b expressed in a (m).
    pub trans: Vec3<S>,
}

impl<S: Scalar> Transform<S> {
    /// `true` when every entry is finite.
    #[inline]
    #[must_use]
    pub fn is_finite(&self) -> bool {
        // One test of the sum (a NaN or infinity makes it non-finite); the
        // entries one by one only when it fails, since finite entries can
        // overflow it.
        let (m, t) = (&self.rot.m, &self.trans);
        let rows = (m[0][0] + m[0][1] + m[0][2])
            + (m[1][0] + m[1][1] + m[1][2])
            + (m[2][0] + m[2][1] + m[2][2]);
        (rows + (t.x + t.y + t.z)).is_finite()
            || crate::scalar::entries_finite(&[
                m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2],
                t.x, t.y, t.z,
            ])
    }
    /// The identity transform.
    pub const IDENTITY: Self = Self::new(Mat3::IDENTITY, Vec3::ZERO);
    /// A transform from rotation and translation.
    #[must_use]
    pub const fn new(rot: Mat3<S>, trans: Vec3<S>) -> Self {
        Self { rot, trans }
    }
    /// A pure translation.
    #[must_use]
    pub const fn from_translation(trans: Vec3<S>) -> Self {
        Self::new(Mat3::IDENTITY, trans)
    }
    /// A pure rotation.
    #[must_use]
    pub const fn from_rotation(rot: Mat3<S>) -> Self {
        Self::new(rot, Vec3::ZERO)
    }
    /// Converts the scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> Transform<T> {
        Transform::new(self.rot.cast(), self.trans.cast())
    }
}

impl<S: Scalar> Default for Transform<S> {
    fn default() -> Self {
        Self::IDENTITY
    }
}
impl<S: Scalar> Transform<S> {
    /// Checks a placement: finite, with a translation whose `|p|⁴` is
    /// finite, and a proper rotation: orthonormal to 10³ ε (`RᵀR = 1`) and
    /// not a reflection (`det R = +1`). Used by
    /// [`Model::validate`](crate::Model::validate) and the setters.
    ///
    /// # Errors
    /// [`ParameterProblem::NonFinite`], [`ParameterProblem::Overflow`],
    /// [`ParameterProblem::RotationNotOrthonormal`] or
    /// [`ParameterProblem::Reflection`].
    ///
    /// # Example
    ///
    /// ```
    /// use rodyn::spatial::ParameterProblem;
    /// use rodyn::spatial::{Mat3, Transform, Vec3};
    /// let turned = Transform::from_rotation(Mat3::from_axis_angle(&Vec3::new(0.0, 0.6, 0.8), 1.2));
    /// assert_eq!(turned.validate(), Ok(()));
    /// // A rotation scaled by 1 % is not a rotation.
    /// let mut scaled = turned;
    /// scaled.rot.m[0] = [scaled.rot.m[0][0] * 1.01, scaled.rot.m[0][1] * 1.01, scaled.rot.m[0][2] * 1.01];
    /// assert_eq!(scaled.validate(), Err(ParameterProblem::RotationNotOrthonormal));
    /// ```
    pub fn validate(&self) -> Result<(), ParameterProblem> {
        if !self.is_finite() {
            return Err(ParameterProblem::NonFinite);
        }
        // Moving an inertia by p forms m |p|², and ABA multiplies two such
        // entries: a translation whose |p|⁴ overflows (beyond 1e77 m in
        // f64, 1e9 m in f32) is refused here, naming the body, rather than
        // read later as a singular joint.
        if !self.trans.norm_squared().squared().is_finite() {
            return Err(ParameterProblem::Overflow);
        }
        // Compared in `S`: an `f32` target would otherwise pull software
        // doubles into a Cortex-M4F image.
        let rtr = self.rot.tr_mul_mat(&self.rot);
        let tol = S::from_f64(1e3 * S::EPSILON);
        for a in 0..3 {
            for b in 0..3 {
                let expect = if a == b { S::ONE } else { S::ZERO };
                if (rtr.m[a][b] - expect).abs() > tol {
                    return Err(ParameterProblem::RotationNotOrthonormal);
                }
            }
        }
        // Orthonormal, so the determinant is ±1: the sign tells a reflection.
        let m = &self.rot.m;
        let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        if det < S::ZERO {
            return Err(ParameterProblem::Reflection);
        }
        Ok(())
    }
}
