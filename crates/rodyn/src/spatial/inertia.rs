//! Rigid-body spatial inertia (Featherstone §2.13), stored compactly.
//!
//! Stored as Pinocchio does: mass `m` (kg), centre of mass `c` (m) and the
//! rotational inertia `I_c` about the centre of mass (kg m²), all in the
//! body's frame. Ten numbers, and transforming it is a rotation and a shift.

use super::ParameterProblem;
use super::{Sym3, Vec3};
use crate::Scalar;

/// Mass, centre of mass and rotational inertia about the centre of mass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Inertia<S> {
    /// Mass m (kg).
    pub mass: S,
    /// Centre of mass c in the body frame (m).
    pub com: Vec3<S>,
    /// Rotational inertia about the centre of mass, I_c (kg m²).
    pub rot_inertia: Sym3<S>,
}

impl<S: Scalar> Inertia<S> {
    /// `true` when every entry is finite.
    #[inline]
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.mass.is_finite() && self.com.is_finite() && self.rot_inertia.is_finite()
    }
    /// An inertia from mass, centre of mass and rotational inertia about the centre of mass.
    #[must_use]
    pub const fn new(mass: S, com: Vec3<S>, rot_inertia: Sym3<S>) -> Self {
        Self {
            mass,
            com,
            rot_inertia,
        }
    }
    /// A point mass at `com`.
    #[must_use]
    pub const fn point_mass(mass: S, com: Vec3<S>) -> Self {
        Self::new(mass, com, Sym3::ZERO)
    }
    /// The rotational inertia about the frame origin: `I_c + m [c×][c×]ᵀ`.
    #[must_use]
    pub fn rot_inertia_at_origin(&self) -> Sym3<S> {
        self.rot_inertia + Sym3::parallel_axis(&self.com).scale(self.mass)
    }
    /// Converts the scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> Inertia<T> {
        Inertia::new(
            T::from_f64(self.mass.to_f64()),
            self.com.cast(),
            self.rot_inertia.cast(),
        )
    }
}
impl<S: Scalar> Inertia<S> {
    /// Checks that the inertia is physical: finite, non-negative mass,
    /// products that do not overflow (`m |c|²`, the trace, `m²` and the
    /// squared trace about the origin, which ABA forms), a rotational
    /// inertia that is positive semi-definite and satisfies the triangle
    /// inequality of its diagonal (with a relative slack of 1e-9 for
    /// rounding). Used by [`Model::validate`](crate::Model::validate) and
    /// the setters.
    ///
    /// # Errors
    /// [`ParameterProblem::NonFinite`], [`ParameterProblem::InvalidMass`],
    /// [`ParameterProblem::Overflow`] or [`ParameterProblem::InvalidInertia`].
    ///
    /// # Example
    ///
    /// ```
    /// use rodyn::spatial::ParameterProblem;
    /// use rodyn::spatial::{Inertia, Sym3, Vec3};
    /// // A 2 kg, 10 x 20 x 30 cm box about its centre is physical.
    /// let (m, a, b, c) = (2.0, 0.1, 0.2, 0.3);
    /// let box_ = Sym3::diagonal(m * (b * b + c * c) / 12.0, m * (a * a + c * c) / 12.0, m * (a * a + b * b) / 12.0);
    /// assert_eq!(Inertia::new(m, Vec3::ZERO, box_).validate(), Ok(()));
    /// // No body has I_zz > I_xx + I_yy.
    /// let impossible = Sym3::diagonal(0.01, 0.01, 0.03);
    /// assert_eq!(Inertia::new(m, Vec3::ZERO, impossible).validate(), Err(ParameterProblem::InvalidInertia));
    /// assert_eq!(Inertia::new(-1.0, Vec3::ZERO, box_).validate(), Err(ParameterProblem::InvalidMass));
    /// ```
    pub fn validate(&self) -> Result<(), ParameterProblem> {
        if !self.is_finite() {
            return Err(ParameterProblem::NonFinite);
        }
        if self.mass.to_f64() < 0.0 {
            return Err(ParameterProblem::InvalidMass);
        }
        // The algorithms form m c, m |c|² (the inertia about the body's
        // origin) and traces, and ABA products of two such entries (U Uᵀ):
        // finite parameters whose sums or products overflow are refused
        // (a 1e300 kg body here, not later as a singular joint).
        let r = &self.rot_inertia;
        let trace = r.xx + r.yy + r.zz;
        let origin = self.rot_inertia_at_origin();
        let trace_at_origin = origin.xx + origin.yy + origin.zz;
        if !(self.mass * self.com.norm_squared()).is_finite()
            || !(self.mass * self.mass).is_finite()
            || !(trace_at_origin * trace_at_origin).is_finite()
            || !trace.is_finite()
            || !self.rot_inertia_at_origin().is_finite()
        {
            return Err(ParameterProblem::Overflow);
        }
        // Scaled to the largest entry, so that the minors below cannot
        // overflow (an inertia with 1e308 entries would otherwise pass as NaN).
        let largest = [r.xx, r.yy, r.zz, r.xy, r.xz, r.yz]
            .iter()
            .fold(f64::MIN_POSITIVE, |m, v| m.max(v.to_f64().abs()));
        let unit = |v: S| v.to_f64() / largest;
        let (xx, yy, zz) = (unit(r.xx), unit(r.yy), unit(r.zz));
        let (xy, xz, yz) = (unit(r.xy), unit(r.xz), unit(r.yz));
        // Positive semi-definite through the leading minors, with a small slack
        // for rounding, and the triangle inequality of the diagonal.
        let scale = (xx.abs() + yy.abs() + zz.abs()).max(f64::MIN_POSITIVE);
        let tol = 1e-9 * scale;
        let minor2 = xx * yy - xy * xy;
        let det = xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * xz) + xz * (xy * yz - yy * xz);
        let psd = xx >= -tol
            && yy >= -tol
            && zz >= -tol
            && minor2 >= -tol * scale
            && det >= -tol * scale * scale;
        let triangle = xx + yy + tol >= zz && xx + zz + tol >= yy && yy + zz + tol >= xx;
        if psd && triangle {
            Ok(())
        } else {
            Err(ParameterProblem::InvalidInertia)
        }
    }
}
