//! Joint conformance: every built-in 3-D joint, every planar joint, and two
//! custom ones (a helical joint, nq = nv = 1, and a quaternion ball joint,
//! nq = 4, nv = 3) pass the same checks, which a new joint type must pass
//! too. Each check compares two things the joint states independently:
//!
//! * **Motion subspace against the transform.** Moving along `v` for a time
//!   `h` (through `integrate`) changes `jMi` by the body-frame twist `S v h`:
//!   `jMi(q)⁻¹ jMi(q ⊕ v h) = exp(S v h)`. Central differences of the
//!   transform give `S v` to O(h²); with h = 1e-5 the truncation is below
//!   1e-9 and the rounding about ε/h ≈ 2e-11, so the tolerance is 1e-8.
//!   `subspace_column(k)` must equal `motion(eₖ)` exactly (up to 1e-15).
//! * **Configuration rate against `integrate`.** `q̇ = Q(q) v` must be the
//!   derivative of `q ⊕ v dt` at dt = 0; same differences and tolerance.
//! * **Force projection as the adjoint of motion.** `f · (S v) = (Sᵀ f) · v`
//!   for any force f and velocity v (to 1e-12 relative: a few roundings of
//!   products of O(1) numbers).
//! * **The configuration flag is honest.** A joint that says every finite
//!   `q` is valid (`constrains_configuration() == false`) accepts arbitrary
//!   finite coordinates; one with a quaternion rejects a scaled one, so it
//!   must say it constrains its configuration (the trap a list of variants
//!   in `Model::new` used to hide).

use rodyn::joint::{CustomJoint, JointBehaviour, JointModel, MAX_JOINT_NV};
use rodyn::planar::{Planar, PlanarJoint};
use rodyn::prelude::*;

const H: f64 = 1e-5;
const TOL_FD: f64 = 1e-8;
const TOL_ADJOINT: f64 = 1e-12;
const MAX_NQ: usize = 8;

/// A deterministic stream of numbers in [-1, 1) (a 64-bit LCG).
struct Numbers(u64);
impl Numbers {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
    fn vec3(&mut self) -> Vec3<f64> {
        Vec3::new(self.next(), self.next(), self.next())
    }
}

// ---------------------------------------------------------------- custom joints

/// Rotation `q` about z with translation `pitch · q` along z.
struct Helical {
    pitch: f64,
}
impl JointBehaviour<f64> for Helical {
    fn transform(&self, q: &[f64]) -> Transform<f64> {
        Transform::new(
            Mat3::from_axis_angle(&Vec3::new(0.0, 0.0, 1.0), q[0]),
            Vec3::new(0.0, 0.0, self.pitch * q[0]),
        )
    }
    fn motion(&self, qd: &[f64]) -> Motion<f64> {
        Motion::new(
            Vec3::new(0.0, 0.0, qd[0]),
            Vec3::new(0.0, 0.0, self.pitch * qd[0]),
        )
    }
    fn subspace_column(&self, _k: usize) -> Motion<f64> {
        self.motion(&[1.0])
    }
    fn project_force(&self, f: &Force<f64>, out: &mut [f64]) {
        out[0] = f.ang.z + self.pitch * f.lin.z;
    }
    fn neutral(&self, q: &mut [f64]) {
        q[0] = 0.0;
    }
    fn integrate(&self, q: &[f64], v: &[f64], dt: f64, out: &mut [f64]) {
        out[0] = q[0] + v[0] * dt;
    }
}

/// A ball joint: unit quaternion `[x y z w]`, body-frame angular velocity.
struct Ball;
impl JointBehaviour<f64> for Ball {
    fn transform(&self, q: &[f64]) -> Transform<f64> {
        Transform::from_rotation(Mat3::from_quaternion(q[0], q[1], q[2], q[3]))
    }
    fn motion(&self, qd: &[f64]) -> Motion<f64> {
        Motion::new(Vec3::new(qd[0], qd[1], qd[2]), Vec3::ZERO)
    }
    fn subspace_column(&self, k: usize) -> Motion<f64> {
        Motion::new(Vec3::unit(k), Vec3::ZERO)
    }
    fn project_force(&self, f: &Force<f64>, out: &mut [f64]) {
        out[..3].copy_from_slice(&f.ang.to_array());
    }
    fn neutral(&self, q: &mut [f64]) {
        q[..4].copy_from_slice(&[0.0, 0.0, 0.0, 1.0]);
    }
    fn integrate(&self, q: &[f64], v: &[f64], dt: f64, out: &mut [f64]) {
        // q ⊗ exp(ω dt / 2), ω in the body frame.
        let w = Vec3::new(v[0], v[1], v[2]) * dt;
        let theta = w.norm();
        let (s, c) = ((theta / 2.0).sin(), (theta / 2.0).cos());
        let k = if theta > 1e-12 { s / theta } else { 0.5 };
        let d = [w.x * k, w.y * k, w.z * k, c];
        let (x, y, z, qw) = (q[0], q[1], q[2], q[3]);
        out[0] = qw * d[0] + x * d[3] + y * d[2] - z * d[1];
        out[1] = qw * d[1] - x * d[2] + y * d[3] + z * d[0];
        out[2] = qw * d[2] + x * d[1] - y * d[0] + z * d[3];
        out[3] = qw * d[3] - x * d[0] - y * d[1] - z * d[2];
    }
    fn check_configuration(&self, q: &[f64]) -> Result<(), rodyn::joint::ConfigurationError> {
        let n = q[..4].iter().map(|x| x * x).sum::<f64>().sqrt();
        if !n.is_finite() {
            Err(rodyn::joint::ConfigurationError::NonFinite)
        } else if (n - 1.0).abs() > 1e-9 {
            Err(rodyn::joint::ConfigurationError::QuaternionNotUnit { norm: n })
        } else {
            Ok(())
        }
    }
    fn normalize(&self, q: &mut [f64]) {
        let n = q[..4].iter().map(|x| x * x).sum::<f64>().sqrt();
        q[..4].iter_mut().for_each(|x| *x /= n);
    }
}

static HELICAL: Helical = Helical { pitch: 0.05 };
static BALL: Ball = Ball;

fn joints() -> Vec<(&'static str, Joint<f64>)> {
    let tilted = Vec3::new(1.0, -2.0, 2.0) * (1.0 / 3.0);
    vec![
        ("revolute x", Joint::revolute(Axis::X)),
        ("revolute y", Joint::revolute(Axis::Y)),
        ("revolute z", Joint::revolute(Axis::Z)),
        ("revolute tilted", Joint::revolute(Axis::Unit(tilted))),
        ("prismatic x", Joint::prismatic(Axis::X)),
        ("prismatic z", Joint::prismatic(Axis::Z)),
        ("prismatic tilted", Joint::prismatic(Axis::Unit(tilted))),
        ("fixed", Joint::Fixed),
        ("free flyer", Joint::free_flyer()),
        (
            "custom helical",
            Joint::Custom(CustomJoint {
                nq: 1,
                nv: 1,
                behaviour: &HELICAL,
            }),
        ),
        (
            "custom ball",
            Joint::Custom(CustomJoint {
                nq: 4,
                nv: 3,
                behaviour: &BALL,
            }),
        ),
    ]
}

/// A valid configuration away from the neutral one, and a velocity.
fn state(joint: &Joint<f64>, numbers: &mut Numbers) -> ([f64; MAX_NQ], [f64; MAX_JOINT_NV]) {
    let (nq, nv) = (joint.nq(), joint.nv());
    let mut neutral = [0.0; MAX_NQ];
    joint.neutral(&mut neutral[..nq]);
    let mut v0 = [0.0; MAX_JOINT_NV];
    v0[..nv].iter_mut().for_each(|x| *x = 2.0 * numbers.next());
    let mut q = [0.0; MAX_NQ];
    joint.integrate(&neutral[..nq], &v0[..nv], 1.0, &mut q[..nq]);
    let mut v = [0.0; MAX_JOINT_NV];
    v[..nv].iter_mut().for_each(|x| *x = 1.5 * numbers.next());
    (q, v)
}

fn moved(joint: &Joint<f64>, q: &[f64], v: &[f64], dt: f64) -> [f64; MAX_NQ] {
    let mut out = [0.0; MAX_NQ];
    joint.integrate(q, v, dt, &mut out[..joint.nq()]);
    out
}

/// vee of the skew part of R: the small rotation vector R ≈ I + [θ×].
fn rotation_vector(r: &Mat3<f64>) -> Vec3<f64> {
    let m = &r.m;
    Vec3::new(m[2][1] - m[1][2], m[0][2] - m[2][0], m[1][0] - m[0][1]) * 0.5
}

#[test]
fn motion_subspace_matches_finite_differences_of_the_transform() {
    let mut numbers = Numbers(1);
    for (name, joint) in joints() {
        for _ in 0..5 {
            let (q, v) = state(&joint, &mut numbers);
            let (nq, nv) = (joint.nq(), joint.nv());
            let x0 = joint.transform(&q[..nq]);
            let rel = |dt: f64| {
                let qh = moved(&joint, &q[..nq], &v[..nv], dt);
                x0.inverse().compose(&joint.transform(&qh[..nq]))
            };
            let (ahead, behind) = (rel(H), rel(-H));
            let ang = (rotation_vector(&ahead.rot) - rotation_vector(&behind.rot)) * (0.5 / H);
            let lin = (ahead.trans - behind.trans) * (0.5 / H);
            let s_v = joint.motion(&v[..nv]);
            let err = (ang - s_v.ang).norm().max((lin - s_v.lin).norm());
            assert!(
                err < TOL_FD,
                "{name}: S v {s_v:?} vs finite differences ({ang:?}, {lin:?}): {err:e}"
            );
            // Each column is the motion of a unit rate.
            for k in 0..nv {
                let mut e = [0.0; MAX_JOINT_NV];
                e[k] = 1.0;
                let (col, m) = (joint.subspace_column(k), joint.motion(&e[..nv]));
                let err = (col.ang - m.ang).norm().max((col.lin - m.lin).norm());
                assert!(
                    err < 1e-15,
                    "{name}: column {k} {col:?} vs motion(e_k) {m:?}"
                );
            }
        }
    }
}

#[test]
fn configuration_rate_is_the_derivative_of_integrate() {
    let mut numbers = Numbers(2);
    for (name, joint) in joints() {
        for _ in 0..5 {
            let (q, v) = state(&joint, &mut numbers);
            let (nq, nv) = (joint.nq(), joint.nv());
            let mut rate = [0.0; MAX_NQ];
            joint.configuration_rate(&q[..nq], &v[..nv], &mut rate[..nq]);
            let (ahead, behind) = (
                moved(&joint, &q[..nq], &v[..nv], H),
                moved(&joint, &q[..nq], &v[..nv], -H),
            );
            for k in 0..nq {
                let fd = (ahead[k] - behind[k]) / (2.0 * H);
                assert!(
                    (rate[k] - fd).abs() < TOL_FD,
                    "{name}: q̇[{k}] = {} vs {fd}",
                    rate[k]
                );
            }
        }
    }
}

#[test]
fn force_projection_is_the_adjoint_of_motion() {
    let mut numbers = Numbers(3);
    for (name, joint) in joints() {
        let nv = joint.nv();
        for _ in 0..10 {
            let f = Force::new(numbers.vec3(), numbers.vec3());
            let mut v = [0.0; MAX_JOINT_NV];
            v[..nv].iter_mut().for_each(|x| *x = numbers.next());
            let mut st_f = [0.0; MAX_JOINT_NV];
            joint.project_force(&f, &mut st_f[..nv]);
            let left = joint.motion(&v[..nv]).dot(&f);
            let right: f64 = st_f[..nv].iter().zip(&v[..nv]).map(|(a, b)| a * b).sum();
            assert!(
                (left - right).abs() < TOL_ADJOINT * (1.0 + left.abs()),
                "{name}: f·(S v) = {left} vs (Sᵀ f)·v = {right}"
            );
        }
    }
}

#[test]
fn the_configuration_flag_is_honest() {
    let mut numbers = Numbers(4);
    for (name, joint) in joints() {
        let nq = joint.nq();
        let (q, _) = state(&joint, &mut numbers);
        assert!(
            joint.check_configuration(&q[..nq]).is_ok(),
            "{name}: a reached configuration is rejected"
        );
        // Every coordinate scaled: still finite, but a quaternion is no longer unit.
        let scaled: Vec<f64> = q[..nq].iter().map(|x| 1.5 * x + 0.25).collect();
        if !joint.constrains_configuration() {
            assert!(
                joint.check_configuration(&scaled).is_ok(),
                "{name}: says every finite q is valid but rejects one"
            );
        }
        assert_eq!(
            joint.constrains_configuration(),
            joint.const_constrains_configuration(),
            "{name}"
        );
        if joint.check_configuration(&scaled).is_err() {
            assert!(
                joint.constrains_configuration(),
                "{name}: rejects a finite q without saying so"
            );
        }
    }
}

#[test]
fn planar_joints_conform() {
    // The planar geometry's joints: motion against the transform through
    // the point the moving frame's origin and x axis trace, rate against
    // integrate, and the adjoint identity.
    let mut numbers = Numbers(5);
    let joints = [
        PlanarJoint::Revolute,
        PlanarJoint::Prismatic(rodyn::planar::Vec2::new(0.6, 0.8)),
        PlanarJoint::Fixed,
        PlanarJoint::Floating,
    ];
    for joint in joints {
        let (nq, nv) = (
            JointModel::<f64, Planar>::nq(&joint),
            JointModel::<f64, Planar>::nv(&joint),
        );
        let q: Vec<f64> = (0..nq).map(|_| numbers.next()).collect();
        let v: Vec<f64> = (0..nv).map(|_| numbers.next()).collect();
        let mut rate = vec![0.0; nq];
        joint.configuration_rate(&q, &v, &mut rate);
        let (mut ahead, mut behind) = (vec![0.0; nq], vec![0.0; nq]);
        joint.integrate(&q, &v, H, &mut ahead);
        joint.integrate(&q, &v, -H, &mut behind);
        for k in 0..nq {
            let fd = (ahead[k] - behind[k]) / (2.0 * H);
            assert!(
                (rate[k] - fd).abs() < TOL_FD,
                "{joint:?}: q̇[{k}] = {} vs {fd}",
                rate[k]
            );
        }
        for _ in 0..5 {
            let f = rodyn::planar::PlanarForce::new(
                numbers.next(),
                rodyn::planar::Vec2::new(numbers.next(), numbers.next()),
            );
            let w: Vec<f64> = (0..nv).map(|_| numbers.next()).collect();
            let mut st_f = vec![0.0; nv];
            joint.project_force(&f, &mut st_f);
            let left = joint.motion(&w).dot(&f);
            let right: f64 = st_f.iter().zip(&w).map(|(a, b)| a * b).sum();
            assert!(
                (left - right).abs() < TOL_ADJOINT * (1.0 + left.abs()),
                "{joint:?}: {left} vs {right}"
            );
        }
    }
}
