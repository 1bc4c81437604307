//! Smooth end-effector pose trajectories.

use rodyn::spatial::{Mat3, Motion, Transform, Vec3};
use rodyn::Scalar;

/// A desired pose of a frame and its time derivatives at one instant, all
/// in the world's axes at the frame's origin (rodyn's `LocalWorldAligned`:
/// the frame's classical velocity and acceleration).
#[derive(Clone, Copy, Debug)]
pub struct PoseReference {
    /// World from frame: orientation and origin (m).
    pub pose: Transform<f32>,
    /// Angular velocity (rad/s) and velocity of the origin (m/s).
    pub velocity: Motion<f32>,
    /// Angular acceleration (rad/s²) and acceleration of the origin (m/s²).
    pub acceleration: Motion<f32>,
}

/// The origin runs round a circle through the start, in the plane spanned
/// by the unit vectors `toward_centre` and `along`; the axes turn back and
/// forth about a fixed world axis.
///
/// * `p(t) = p₀ + r ((1 - cos θ) u + sin θ w)`, `u` = `toward_centre`,
///   `w` = `along`, with `θ̇` ramped from rest to `omega` over `ramp`
///   seconds by a half cosine, so that the start is at rest and the
///   acceleration is continuous;
/// * `R(t) = R_a(φ) R₀` with `φ = A (1 - cos Ωt)` about the unit axis `a`:
///   also at rest at the start, within `[0, 2A]`.
#[derive(Clone, Copy, Debug)]
pub struct CirclePoseTrajectory {
    /// The pose at `t = 0`: where the circle starts (world from frame).
    pub start: Transform<f32>,
    /// Unit vector from the start toward the circle's centre.
    pub toward_centre: Vec3<f32>,
    /// Unit vector along the initial direction of travel, orthogonal to
    /// `toward_centre`.
    pub along: Vec3<f32>,
    /// Radius (m).
    pub radius: f32,
    /// Angular rate round the circle after the ramp (rad/s).
    pub omega: f32,
    /// Duration of the speed ramp (s), > 0.
    pub ramp: f32,
    /// Unit axis (world) the orientation turns about.
    pub turn_axis: Vec3<f32>,
    /// Half the largest turn, `A` (rad).
    pub turn_amplitude: f32,
    /// Angular frequency of the turn, `Ω` (rad/s).
    pub turn_omega: f32,
}

impl CirclePoseTrajectory {
    /// The angle round the circle and its first two derivatives at `t` (s).
    fn phase(&self, t: f32) -> (f32, f32, f32) {
        let (w, tr) = (self.omega, self.ramp);
        if t < tr {
            // θ̇ = ω (1 - cos(π t / T)) / 2.
            let k = core::f32::consts::PI / tr;
            let (s, c) = (k * t).sin_cos();
            (0.5 * w * (t - s / k), 0.5 * w * (1.0 - c), 0.5 * w * k * s)
        } else {
            (w * (t - 0.5 * tr), w, 0.0)
        }
    }

    /// The reference at time `t` (s).
    #[must_use]
    pub fn at(&self, t: f32) -> PoseReference {
        let (theta, dtheta, ddtheta) = self.phase(t);
        let (s, c) = theta.sin_cos();
        let (u, w, r) = (self.toward_centre, self.along, self.radius);
        // Unit vectors toward the centre and along the tangent at θ.
        let inward = u * c - w * s;
        let tangent = u * s + w * c;
        let position = self.start.trans + (u * (1.0 - c) + w * s) * r;
        let velocity = tangent * (r * dtheta);
        let acceleration = tangent * (r * ddtheta) + inward * (r * dtheta * dtheta);

        let (a, big_w) = (self.turn_amplitude, self.turn_omega);
        let (sw, cw) = (big_w * t).sin_cos();
        let phi = a * (1.0 - cw);
        let turn = Mat3::from_axis_angle(&self.turn_axis, phi);
        PoseReference {
            pose: Transform::new(turn.mul_mat(&self.start.rot), position),
            velocity: Motion::new(self.turn_axis * (a * big_w * sw), velocity),
            acceleration: Motion::new(self.turn_axis * (a * big_w * big_w * cw), acceleration),
        }
    }
}
