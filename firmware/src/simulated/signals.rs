//! The wires between the simulated plant and the fake peripherals.

use core::cell::Cell;

/// Joint angles the plant publishes and duty cycles the drives set, one per
/// joint. `Cell`s, because the plant writes what the peripherals read and
/// vice versa within one single-threaded loop.
#[derive(Debug)]
pub struct Signals<const N: usize> {
    /// True joint angles (rad), as the encoders' magnets see them.
    pub angles: [Cell<f32>; N],
    /// PWM duty cycles (counts of [`PWM_PERIOD`](super::PWM_PERIOD)).
    pub duties: [Cell<u16>; N],
}

impl<const N: usize> Signals<N> {
    /// All angles zero, all duties at 50 % (zero torque).
    #[must_use]
    pub fn new() -> Self {
        Self {
            angles: core::array::from_fn(|_| Cell::new(0.0)),
            duties: core::array::from_fn(|_| Cell::new(super::PWM_PERIOD / 2)),
        }
    }
}

impl<const N: usize> Default for Signals<N> {
    fn default() -> Self {
        Self::new()
    }
}
