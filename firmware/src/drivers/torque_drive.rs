//! A joint torque command through a PWM duty cycle.
//!
//! Typical of motor drivers with a PWM torque (current) input: a duty cycle
//! of 50 % commands zero torque, 0 % and 100 % the negative and positive
//! limits. With a timer period of 10 000 counts one step is
//! `limit / 5000`, 0.017 N m on a Panda shoulder.

use embedded_hal::pwm::SetDutyCycle;

/// Why a torque could not be commanded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, defmt::Format)]
pub enum DriveError {
    /// The PWM peripheral refused the duty cycle.
    Pwm,
    /// The torque was NaN.
    NotANumber,
}

/// A torque-controlled joint drive behind a PWM output.
#[derive(Debug)]
pub struct TorqueDrive<PWM> {
    pwm: PWM,
    limit: f32,
}

impl<PWM: SetDutyCycle> TorqueDrive<PWM> {
    /// A drive whose full-scale torque is `limit` (N m, positive).
    pub fn new(pwm: PWM, limit: f32) -> Self {
        Self { pwm, limit }
    }

    /// Commands `torque` (N m), clamped to the drive's limit. Returns the
    /// torque actually commanded after clamping and quantisation.
    ///
    /// # Errors
    /// A NaN torque or a PWM failure; the previous command then stays.
    pub fn set_torque(&mut self, torque: f32) -> Result<f32, DriveError> {
        if torque.is_nan() {
            return Err(DriveError::NotANumber);
        }
        let max = self.pwm.max_duty_cycle();
        let fraction = (0.5 + 0.5 * torque / self.limit).clamp(0.0, 1.0);
        // Round to the nearest duty step (+0.5 then truncate: fraction >= 0).
        let duty = (fraction * f32::from(max) + 0.5) as u16;
        self.pwm.set_duty_cycle(duty).map_err(|_| DriveError::Pwm)?;
        Ok(duty_to_torque(duty, max, self.limit))
    }
}

/// The torque a duty cycle commands (the driver side of the convention).
#[must_use]
pub fn duty_to_torque(duty: u16, max: u16, limit: f32) -> f32 {
    (2.0 * f32::from(duty) / f32::from(max) - 1.0) * limit
}
