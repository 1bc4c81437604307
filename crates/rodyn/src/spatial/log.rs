//! The logarithms of SO(3) and SE(3): the rotation vector of a rotation
//! and the twist that moves the identity to a placement in unit time.
//! Inverse kinematics and the task-space controller use `log3` for the
//! orientation error, frame contacts `log6` for their placement error
//! (Pinocchio's `log3` and `log6` compute the same maps).

use super::{Mat3, Motion, Transform, Vec3};
use crate::Scalar;

/// Below this angle (rad) the series of `V⁻¹` replaces its closed form,
/// whose quotient loses its digits near 0.
const SMALL_ANGLE: f64 = 1e-4;

/// The rotation vector (axis times angle, rad, angle in `[0, π]`) of a
/// rotation matrix.
#[must_use]
pub fn log3<S: Scalar>(r: &Mat3<S>) -> Vec3<S> {
    let m = &r.m;
    let half = S::from_f64(0.5);
    // sin θ times the axis, and cos θ.
    let w = Vec3::new(m[2][1] - m[1][2], m[0][2] - m[2][0], m[1][0] - m[0][1]) * half;
    let c = ((m[0][0] + m[1][1] + m[2][2] - S::ONE) * half)
        .max(S::NEG_ONE)
        .min(S::ONE);
    let s = w.norm();
    let theta = s.atan2(c);
    if c > S::from_f64(-0.9) {
        // sin θ / θ is well away from zero for θ < 2.69 rad; below 1e-8
        // rad it is 1 to the last bit.
        return if s > S::from_f64(1e-8) {
            w * (theta / s)
        } else {
            w
        };
    }
    // Near half a turn the axis comes from the symmetric part, R + Rᵀ =
    // 2 c I + 2 (1 - c) a aᵀ, its largest diagonal entry first.
    let one_c = S::ONE - c;
    let mut k = 0;
    for i in 1..3 {
        if m[i][i] > m[k][k] {
            k = i;
        }
    }
    let ak = ((m[k][k] - c) / one_c).max(S::ZERO).sqrt();
    let mut a = [S::ZERO; 3];
    for i in 0..3 {
        a[i] = if i == k {
            ak
        } else {
            (m[i][k] + m[k][i]) * half / (one_c * ak)
        };
    }
    let mut axis = Vec3::from_array(a);
    if axis.dot(&w) < S::ZERO {
        axis = axis * S::NEG_ONE;
    }
    axis * theta
}

/// The twist `ξ = (ω, u)` with `exp(ξ) = x` (angular part `log3(R)`,
/// linear part `V(ω)⁻¹ p`), in the frame the twist starts from, as
/// Pinocchio's `log6`.
#[must_use]
pub fn log6<S: Scalar>(x: &Transform<S>) -> Motion<S> {
    let w = log3(&x.rot);
    let theta2 = w.norm_squared();
    let theta = theta2.sqrt();
    let half = S::from_f64(0.5);
    // V⁻¹ = I − ½ [ω]× + β [ω]×², β = (1 − θ sin θ / (2 (1 − cos θ))) / θ².
    let beta = if theta.to_f64() < SMALL_ANGLE {
        S::from_f64(1.0 / 12.0) + theta2 / S::from_f64(720.0)
    } else {
        let (s, c) = theta.sin_cos();
        (S::ONE - theta * s / (S::from_f64(2.0) * (S::ONE - c))) / theta2
    };
    let p = x.trans;
    let wp = w.cross(&p);
    let u = p - wp * half + w.cross(&wp) * beta;
    Motion::new(w, u)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exp6(xi: &Motion<f64>) -> Transform<f64> {
        let theta = xi.ang.norm();
        let rot = if theta == 0.0 {
            Mat3::IDENTITY
        } else {
            Mat3::from_axis_angle(&(xi.ang * (1.0 / theta)), theta)
        };
        // V = I + (1 − cos θ)/θ² [ω]× + (θ − sin θ)/θ³ [ω]×².
        let (a, b) = if theta < 1e-6 {
            (0.5, 1.0 / 6.0)
        } else {
            (
                (1.0 - theta.cos()) / (theta * theta),
                (theta - theta.sin()) / (theta * theta * theta),
            )
        };
        let wu = xi.ang.cross(&xi.lin);
        let trans = xi.lin + wu * a + xi.ang.cross(&wu) * b;
        Transform::new(rot, trans)
    }

    /// `log6(exp6(ξ)) = ξ` for angles from 0 to just below π, through the
    /// three branches of `log3`.
    #[test]
    fn log6_inverts_exp6() {
        let axis = Vec3::new(0.3, -0.5, 0.8) * (1.0 / 0.989_949_493_661_166_5);
        for theta in [
            0.0,
            1e-9,
            1e-5,
            0.3,
            2.0,
            2.9,
            3.05,
            core::f64::consts::PI - 1e-3,
        ] {
            let xi = Motion::new(axis * theta, Vec3::new(0.2, -0.7, 0.4));
            let back = log6(&exp6(&xi));
            let err = (back.ang - xi.ang).norm() + (back.lin - xi.lin).norm();
            assert!(err < 1e-9, "θ = {theta}: off by {err:e}");
        }
    }
}
