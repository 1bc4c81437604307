//! Smooth joint reference trajectories.

use rodyn::Scalar;

/// Desired joint angles, rates and accelerations at one instant.
#[derive(Clone, Copy, Debug)]
pub struct Reference<const N: usize> {
    /// Angles (rad).
    pub q: [f32; N],
    /// Rates (rad/s).
    pub v: [f32; N],
    /// Accelerations (rad/s²).
    pub a: [f32; N],
}

/// `q(t) = q₀ + A (1 - cos ωt)` per joint: starts at rest at `q₀`, stays
/// within `[q₀, q₀ + 2A]`, smooth in all derivatives.
#[derive(Clone, Copy, Debug)]
pub struct CosineTrajectory<const N: usize> {
    /// Start (rad).
    pub start: [f32; N],
    /// Amplitudes A (rad).
    pub amplitude: [f32; N],
    /// Angular frequencies ω (rad/s).
    pub omega: [f32; N],
}

impl<const N: usize> CosineTrajectory<N> {
    /// The reference at time `t` (s).
    #[must_use]
    pub fn at(&self, t: f32) -> Reference<N> {
        let mut r = Reference {
            q: [0.0; N],
            v: [0.0; N],
            a: [0.0; N],
        };
        for k in 0..N {
            let (a, w) = (self.amplitude[k], self.omega[k]);
            let (s, c) = (w * t).sin_cos();
            r.q[k] = self.start[k] + a * (1.0 - c);
            r.v[k] = a * w * s;
            r.a[k] = a * w * w * c;
        }
        r
    }
}
