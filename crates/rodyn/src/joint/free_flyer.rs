//! The free-floating base: six degrees of freedom. nq = 7, nv = 6.
//!
//! Pinocchio's convention: `q = [x y z qx qy qz qw]` (position of the body
//! frame in the parent frame, then the unit quaternion of its orientation),
//! `v = [vx vy vz ωx ωy ωz]` in the body frame, linear part first.
//! `S` is the identity in that order.

use super::ConfigurationError;
use crate::spatial::{ArticulatedInertia6, Force, Mat3, Motion, Transform, Vec3};
use crate::Scalar;

/// A free-floating joint.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FreeFlyer;

impl FreeFlyer {
    /// Configuration coordinates: position and unit quaternion.
    pub const NQ: usize = 7;
    /// Velocity coordinates: body-frame linear and angular velocity.
    pub const NV: usize = 6;
    /// The orientation is a quaternion that must stay of unit length, so a
    /// finite `q` is not necessarily valid.
    pub const CONSTRAINS_CONFIGURATION: bool = true;
}

/// How far a quaternion's norm may stray from one, in units of the scalar's
/// epsilon, before the configuration is rejected.
const QUATERNION_TOLERANCE_EPS: f64 = 1.0e3;

/// Hamilton product of quaternions stored `[x y z w]`.
fn quat_mul<S: Scalar>(a: &[S; 4], b: &[S; 4]) -> [S; 4] {
    let [ax, ay, az, aw] = *a;
    let [bx, by, bz, bw] = *b;
    [
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    ]
}

impl FreeFlyer {
    /// `jMi(q)`.
    #[inline]
    #[must_use]
    pub fn transform<S: Scalar>(&self, q: &[S; 7]) -> Transform<S> {
        Transform::new(
            Mat3::from_quaternion(q[3], q[4], q[5], q[6]),
            Vec3::new(q[0], q[1], q[2]),
        )
    }
    /// `S qd`.
    #[inline]
    #[must_use]
    pub fn motion<S: Scalar>(&self, qd: &[S; 6]) -> Motion<S> {
        Motion::new(
            Vec3::new(qd[3], qd[4], qd[5]),
            Vec3::new(qd[0], qd[1], qd[2]),
        )
    }
    /// Column `k` of `S`: linear axes first.
    #[inline]
    #[must_use]
    pub fn subspace_column<S: Scalar>(&self, k: usize) -> Motion<S> {
        if k < 3 {
            Motion::new(Vec3::ZERO, Vec3::unit(k))
        } else {
            Motion::new(Vec3::unit(k - 3), Vec3::ZERO)
        }
    }
    /// `Sᵀ f`.
    #[inline]
    pub fn project_force<S: Scalar>(&self, f: &Force<S>, out: &mut [S; 6]) {
        let ([x, y, z], [wx, wy, wz]) = (f.lin.to_array(), f.ang.to_array());
        *out = [x, y, z, wx, wy, wz];
    }
    /// `U = I^A S`: the columns of `I^A`, reordered.
    #[inline]
    pub fn articulated_columns<S: Scalar>(
        &self,
        ia: &ArticulatedInertia6<S>,
        u: &mut [Force<S>; 6],
    ) {
        for k in 0..3 {
            u[k] = Force::new(ia.b.column(k), ia.c.column(k));
            u[k + 3] = Force::new(ia.a.column(k), ia.b.row(k));
        }
    }
    /// The identity placement.
    pub fn neutral<S: Scalar>(&self, q: &mut [S; 7]) {
        *q = [S::ZERO, S::ZERO, S::ZERO, S::ZERO, S::ZERO, S::ZERO, S::ONE];
    }
    /// `q ⊕ v dt` through the exponential map of SE(3); the quaternion is
    /// renormalised.
    pub fn integrate<S: Scalar>(&self, q: &[S; 7], v: &[S; 6], dt: S, out: &mut [S; 7]) {
        let rho = Vec3::new(v[0], v[1], v[2]) * dt;
        let omega = Vec3::new(v[3], v[4], v[5]) * dt;
        let theta2 = omega.norm_squared();
        let theta = theta2.sqrt();
        // Coefficients of V = 1 + b [ω×] + c [ω×]², Taylor-expanded near zero.
        let small = theta2 < S::from_f64(1e-8);
        let (half_s, half_c) = (theta * S::from_f64(0.5)).sin_cos();
        let (b, c, k) = if small {
            (
                S::from_f64(0.5) - theta2 / S::from_f64(24.0),
                S::from_f64(1.0 / 6.0) - theta2 / S::from_f64(120.0),
                S::from_f64(0.5) - theta2 / S::from_f64(48.0),
            )
        } else {
            let (s, co) = theta.sin_cos();
            (
                (S::ONE - co) / theta2,
                (theta - s) / (theta2 * theta),
                half_s / theta,
            )
        };
        let w_rho = omega.cross(&rho);
        let delta_p = rho + w_rho * b + omega.cross(&w_rho) * c;
        let rot = Mat3::from_quaternion(q[3], q[4], q[5], q[6]);
        let p = Vec3::new(q[0], q[1], q[2]) + rot.mul_vec(&delta_p);
        let dq = [omega.x * k, omega.y * k, omega.z * k, half_c];
        let quat = quat_mul(&[q[3], q[4], q[5], q[6]], &dq);
        let ([x, y, z], [qx, qy, qz, qw]) = (p.to_array(), quat);
        *out = [x, y, z, qx, qy, qz, qw];
        self.normalize(out);
    }
    /// The configuration rate `q̇ = Q(q) v` (7 entries): the body-frame
    /// linear velocity rotated into the parent, and `½ q ⊗ (ω, 0)` for the
    /// quaternion; the derivative of [`integrate`](Self::integrate) at
    /// `dt = 0`.
    pub fn configuration_rate<S: Scalar>(&self, q: &[S; 7], v: &[S; 6], q_dot: &mut [S; 7]) {
        // The rotation is built from the normalised quaternion so that an
        // unnormalised one does not scale the position rate.
        let (x, y, z, w) = (q[3], q[4], q[5], q[6]);
        let n2 = x * x + y * y + z * z + w * w;
        let inv = if n2 > S::ZERO {
            S::ONE / n2.sqrt()
        } else {
            S::ONE
        };
        let rot = Mat3::from_quaternion(x * inv, y * inv, z * inv, w * inv);
        let p_dot = rot.mul_vec(&Vec3::new(v[0], v[1], v[2]));
        let [px, py, pz] = p_dot.to_array();
        [q_dot[0], q_dot[1], q_dot[2]] = [px, py, pz];
        // q̇ = ½ q ⊗ (ω, 0) is linear in q, so its exact flow keeps |q|
        // constant whatever |q| is.
        let half = S::from_f64(0.5);
        let (wx, wy, wz) = (v[3] * half, v[4] * half, v[5] * half);
        q_dot[3] = w * wx + y * wz - z * wy;
        q_dot[4] = w * wy + z * wx - x * wz;
        q_dot[5] = w * wz + x * wy - y * wx;
        q_dot[6] = -(x * wx + y * wy + z * wz);
    }
    /// Finite coordinates and a quaternion of unit norm.
    pub fn check_configuration<S: Scalar>(&self, q: &[S; 7]) -> Result<(), ConfigurationError> {
        if !q.iter().all(|x| x.is_finite()) {
            return Err(ConfigurationError::NonFinite);
        }
        self.check_unit(q)
    }
    /// [`check_configuration`](Self::check_configuration) of a finite `q`:
    /// the quaternion's norm alone.
    #[inline]
    pub(crate) fn check_unit<S: Scalar>(&self, q: &[S; 7]) -> Result<(), ConfigurationError> {
        // |n² - 1| ≈ 2 |n - 1|; compared in S to keep f64 off the MCU's hot path.
        let norm_squared = q[3] * q[3] + q[4] * q[4] + q[5] * q[5] + q[6] * q[6];
        let tolerance = S::from_f64(2.0 * QUATERNION_TOLERANCE_EPS * S::EPSILON);
        if (norm_squared - S::ONE).abs() > tolerance {
            return Err(ConfigurationError::QuaternionNotUnit {
                norm: norm_squared.sqrt().to_f64(),
            });
        }
        Ok(())
    }
    /// Rescales the quaternion to unit norm. Divided by its largest entry
    /// first, so that a norm whose square overflows (1e200) or underflows
    /// (a subnormal quaternion) still normalises; a zero or non-finite
    /// quaternion is left as it is, for the configuration check to report.
    pub fn normalize<S: Scalar>(&self, q: &mut [S; 7]) {
        let largest = q[3..7].iter().fold(S::ZERO, |m, x| m.max(x.abs()));
        if !(largest.is_finite() && largest > S::ZERO) {
            return;
        }
        // Divided, not multiplied by the reciprocal: that of a subnormal
        // overflows.
        for x in &mut q[3..7] {
            *x /= largest;
        }
        let n = (q[3] * q[3] + q[4] * q[4] + q[5] * q[5] + q[6] * q[6]).sqrt();
        let inv = S::ONE / n;
        for x in &mut q[3..7] {
            *x *= inv;
        }
    }
}
