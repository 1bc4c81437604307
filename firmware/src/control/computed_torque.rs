//! Computed-torque control: `τ = RNEA(q, q̇, q̈_d + K_d (q̇_d - q̇) + K_p (q_d - q))`.
//!
//! With an exact model the closed loop is `ë + K_d ė + K_p e = 0` per joint,
//! so the gains set a natural frequency `ωₙ = √K_p` and damping
//! `ζ = K_d / (2 ωₙ)`. The rate `q̇` is estimated from the encoder angles
//! ([`RateEstimate`]).

use super::{RateEstimate, Reference};
use crate::drivers::{AbsoluteEncoder, DriveError, EncoderError, TorqueDrive};
use embedded_hal::pwm::SetDutyCycle;
use embedded_hal::spi::SpiDevice;
use rodyn::algorithm::rnea::rnea;
use rodyn::{Data, Model};

/// Feedback gains and the rate filter.
#[derive(Clone, Copy, Debug)]
pub struct Gains {
    /// Position gain K_p (1/s²).
    pub kp: f32,
    /// Rate gain K_d (1/s).
    pub kd: f32,
    /// Weight of the previous rate estimate, `exp(-dt / T_filter)`.
    pub rate_filter: f32,
}

impl Gains {
    /// Gains for natural frequency `omega` (rad/s) and damping `zeta`.
    #[must_use]
    pub const fn from_natural_frequency(omega: f32, zeta: f32, rate_filter: f32) -> Self {
        Self {
            kp: omega * omega,
            kd: 2.0 * zeta * omega,
            rate_filter,
        }
    }
}

/// What stopped a control tick.
#[derive(Clone, Copy, Debug, PartialEq, defmt::Format)]
pub enum ControlError {
    /// An encoder could not be read (joint index).
    Encoder(usize, EncoderError),
    /// A drive refused the command (joint index).
    Drive(usize, DriveError),
    /// Inverse dynamics, kinematics or a Jacobian failed.
    Dynamics(rodyn::Error),
    /// A task-space controller's damped pseudo-inverse was not finite
    /// (non-finite Jacobian entries).
    PseudoInverse,
}

/// What one tick measured and commanded.
#[derive(Clone, Copy, Debug)]
pub struct TickReport<const N: usize> {
    /// Measured joint angles (rad).
    pub q: [f32; N],
    /// Torques commanded after clamping and PWM quantisation (N m).
    pub tau: [f32; N],
}

/// A computed-torque controller for a fixed-base chain of `N` revolute joints.
#[derive(Debug)]
pub struct ComputedTorque<'m, SPI, PWM, const N: usize> {
    model: &'m Model<f32, N, N, N>,
    data: Data<f32, N, N>,
    encoders: [AbsoluteEncoder<SPI>; N],
    drives: [TorqueDrive<PWM>; N],
    gains: Gains,
    rate: RateEstimate<N>,
}

impl<'m, SPI: SpiDevice, PWM: SetDutyCycle, const N: usize> ComputedTorque<'m, SPI, PWM, N> {
    /// A controller ticking every `dt` seconds.
    pub fn new(
        model: &'m Model<f32, N, N, N>,
        encoders: [AbsoluteEncoder<SPI>; N],
        drives: [TorqueDrive<PWM>; N],
        gains: Gains,
        dt: f32,
    ) -> Self {
        Self {
            model,
            data: Data::new(),
            encoders,
            drives,
            gains,
            rate: RateEstimate::new(gains.rate_filter, dt),
        }
    }

    /// One control tick: read the encoders, compute the torques that track
    /// `reference`, command the drives.
    ///
    /// # Errors
    /// A sensor, drive or dynamics failure; the drives keep their last command.
    pub fn tick(&mut self, reference: &Reference<N>) -> Result<TickReport<N>, ControlError> {
        let mut q = [0.0; N];
        for (k, encoder) in self.encoders.iter_mut().enumerate() {
            q[k] = encoder
                .read_angle()
                .map_err(|e| ControlError::Encoder(k, e))?;
        }
        let v = *self.rate.update(&q);
        let g = self.gains;
        let mut a = [0.0; N];
        for k in 0..N {
            a[k] = reference.a[k] + g.kd * (reference.v[k] - v[k]) + g.kp * (reference.q[k] - q[k]);
        }
        let tau =
            *rnea(self.model, &mut self.data, &q, &v, &a, None).map_err(ControlError::Dynamics)?;
        let mut commanded = [0.0; N];
        for (k, drive) in self.drives.iter_mut().enumerate() {
            commanded[k] = drive
                .set_torque(tau[k])
                .map_err(|e| ControlError::Drive(k, e))?;
        }
        Ok(TickReport { q, tau: commanded })
    }
}
