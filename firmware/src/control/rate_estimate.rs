//! Joint rates from successive encoder angles.
//!
//! The rate is not measured: it is the backward difference of successive
//! angles, low-pass filtered (first order), because one 24 µrad encoder
//! count per 1 ms tick is already 0.024 rad/s.

/// A filtered backward difference of joint angles.
#[derive(Clone, Copy, Debug)]
pub struct RateEstimate<const N: usize> {
    /// Weight of the previous estimate, `exp(-dt / T_filter)`.
    filter: f32,
    /// Sampling period (s).
    dt: f32,
    previous: Option<[f32; N]>,
    /// The current estimate (rad/s); zero until two angles were seen.
    pub v: [f32; N],
}

impl<const N: usize> RateEstimate<N> {
    /// An estimate sampled every `dt` seconds, keeping the weight `filter`
    /// (`exp(-dt / T_filter)`) of its previous value.
    #[must_use]
    pub const fn new(filter: f32, dt: f32) -> Self {
        Self {
            filter,
            dt,
            previous: None,
            v: [0.0; N],
        }
    }

    /// Takes the angles `q` (rad) of this sample; returns the new estimate.
    pub fn update(&mut self, q: &[f32; N]) -> &[f32; N] {
        if let Some(previous) = self.previous {
            let alpha = self.filter;
            for k in 0..N {
                let raw = (q[k] - previous[k]) / self.dt;
                self.v[k] = alpha * self.v[k] + (1.0 - alpha) * raw;
            }
        }
        self.previous = Some(*q);
        &self.v
    }
}
