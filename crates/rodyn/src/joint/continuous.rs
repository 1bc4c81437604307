//! Continuous joints in Pinocchio's configuration layout.
//!
//! A URDF `continuous` joint is a revolute joint without limits. rodyn
//! keeps its angle `θ` as one configuration coordinate (nq = 1), as for a
//! `revolute` joint; Pinocchio keeps the pair `(cos θ, sin θ)`
//! (`JointModelRUBX` and the like, nq = 2). Velocities, accelerations and
//! torques are the same in both (nv = 1). The generated module of a model
//! file converts whole configuration vectors (`q_from_pinocchio`,
//! `q_to_pinocchio`) with these two functions.

use super::ConfigurationError;
use crate::Scalar;

/// How far `cos² + sin²` may be from 1, in units of the scalar's epsilon
/// (the quaternion check's tolerance): Pinocchio's own configurations stay
/// on the circle to rounding.
const UNIT_TOLERANCE_EPS: f64 = 2.0e3;

/// The angle `θ` of a continuous joint from Pinocchio's `(cos θ, sin θ)`,
/// in `(-π, π]`.
///
/// # Errors
/// [`ConfigurationError::NonFinite`] for a non-finite entry;
/// [`ConfigurationError::AngleNotUnit`] when `cos² + sin²` is further from 1
/// than rounding (2·10³ ε of the scalar type), as Pinocchio's pairs are not:
/// such a pair is no configuration of the joint.
///
/// # Example
/// ```
/// use rodyn::joint::angle_from_cos_sin;
/// let theta = angle_from_cos_sin(f64::cos(2.5), f64::sin(2.5)).unwrap();
/// assert!((theta - 2.5).abs() < 1e-15);
/// assert!(angle_from_cos_sin(0.0_f64, 0.0).is_err());
/// ```
pub fn angle_from_cos_sin<S: Scalar>(cos: S, sin: S) -> Result<S, ConfigurationError> {
    if !(cos.is_finite() && sin.is_finite()) {
        return Err(ConfigurationError::NonFinite);
    }
    let norm_squared = cos * cos + sin * sin;
    if (norm_squared - S::ONE).abs() > S::from_f64(UNIT_TOLERANCE_EPS * S::EPSILON) {
        return Err(ConfigurationError::AngleNotUnit {
            norm: norm_squared.sqrt().to_f64(),
        });
    }
    Ok(sin.atan2(cos))
}

/// Pinocchio's `(cos θ, sin θ)` of a continuous joint at angle `θ`.
///
/// # Errors
/// [`ConfigurationError::NonFinite`] for a non-finite angle.
pub fn cos_sin_from_angle<S: Scalar>(theta: S) -> Result<(S, S), ConfigurationError> {
    if !theta.is_finite() {
        return Err(ConfigurationError::NonFinite);
    }
    let (s, c) = theta.sin_cos();
    Ok((c, s))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angles_round_trip_and_off_circle_pairs_are_refused() {
        for k in -12..=12 {
            let theta = f64::from(k) * 0.26;
            let (c, s) = cos_sin_from_angle(theta).unwrap();
            let back = angle_from_cos_sin(c, s).unwrap();
            // Angles beyond π come back wrapped into (-π, π].
            let d = (back - theta).rem_euclid(2.0 * core::f64::consts::PI);
            assert!(
                d < 1e-14 || 2.0 * core::f64::consts::PI - d < 1e-14,
                "{theta}"
            );
        }
        let (c, s) = cos_sin_from_angle(0.7_f32).unwrap();
        assert!((angle_from_cos_sin(c, s).unwrap() - 0.7).abs() < 1e-6);
        assert_eq!(
            angle_from_cos_sin(0.6_f64, 0.6),
            Err(ConfigurationError::AngleNotUnit {
                norm: 0.72_f64.sqrt()
            })
        );
        assert_eq!(
            angle_from_cos_sin(f64::NAN, 0.0),
            Err(ConfigurationError::NonFinite)
        );
        assert_eq!(
            cos_sin_from_angle(f64::INFINITY),
            Err(ConfigurationError::NonFinite)
        );
    }
}
