//! A fake PWM channel that stores its duty cycle for the plant to read.

use core::cell::Cell;
use core::convert::Infallible;
use embedded_hal::pwm::{ErrorType, SetDutyCycle};

/// Timer period of the simulated PWM, in counts.
pub const PWM_PERIOD: u16 = 10_000;

/// One PWM channel whose duty cycle the simulated plant reads.
#[derive(Debug)]
pub struct SimulatedPwm<'a> {
    duty: &'a Cell<u16>,
}

impl<'a> SimulatedPwm<'a> {
    /// A channel writing its duty cycle to `duty`.
    #[must_use]
    pub fn new(duty: &'a Cell<u16>) -> Self {
        Self { duty }
    }
}

impl ErrorType for SimulatedPwm<'_> {
    type Error = Infallible;
}

impl SetDutyCycle for SimulatedPwm<'_> {
    fn max_duty_cycle(&self) -> u16 {
        PWM_PERIOD
    }
    fn set_duty_cycle(&mut self, duty: u16) -> Result<(), Infallible> {
        self.duty.set(duty.min(PWM_PERIOD));
        Ok(())
    }
}
