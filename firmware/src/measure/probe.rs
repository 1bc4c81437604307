//! Costs over seeded random inputs: the `cost` lines of the probes that
//! `cargo xtask costs` turns into the cost table.

use super::{stack_bytes, InstructionCounter};
use crate::rng::XorShift32;

/// Random states per model and algorithm.
pub const STATES: u32 = 100;
/// Seed of the state generator.
pub const SEED: u32 = 0x5EED_0001;

/// Min and max instructions and max stack over random states.
pub struct Cost {
    /// Fewest instructions of a call.
    pub min: u32,
    /// Most instructions of a call.
    pub max: u32,
    /// Most stack bytes of a call; `None` once a call overflowed the window.
    pub stack: Option<u32>,
}

impl Cost {
    /// No call seen yet.
    pub const NONE: Self = Self {
        min: u32::MAX,
        max: 0,
        stack: Some(0),
    };

    /// Adds one call's instructions and stack bytes.
    pub fn add(&mut self, instructions: u32, stack: Option<u32>) {
        self.min = self.min.min(instructions);
        self.max = self.max.max(instructions);
        self.stack = match (self.stack, stack) {
            (Some(a), Some(b)) => Some(a.max(b)),
            _ => None,
        };
    }

    /// One `cost` line (`model` and `algorithm` without spaces: the xtask
    /// splits the line at whitespace).
    pub fn report(&self, model: &str, algorithm: &str) {
        match self.stack {
            Some(stack) => defmt::println!(
                "cost model={=str} algorithm={=str} min={} max={} stack={}",
                model,
                algorithm,
                self.min,
                self.max,
                stack
            ),
            None => defmt::println!(
                "cost model={=str} algorithm={=str} min={} max={} stack=>16384",
                model,
                algorithm,
                self.min,
                self.max
            ),
        }
    }
}

/// Probes one scene-level call on [`STATES`] random inputs: `draw` makes
/// an input (not counted), `call` runs on it (counted, then run again on a
/// fresh copy for its stack). Returns false when a call failed.
pub fn probe_scene<T: Clone>(
    model: &str,
    algorithm: &str,
    counter: &InstructionCounter,
    mut draw: impl FnMut(&mut XorShift32) -> T,
    mut call: impl FnMut(&mut T) -> bool,
) -> bool {
    let mut rng = XorShift32::new(SEED);
    let mut cost = Cost::NONE;
    for _ in 0..STATES {
        let input = draw(&mut rng);
        let mut first = input.clone();
        let (ok, instructions) = counter.count(|| call(&mut first));
        let mut second = input;
        let (ok_again, stack) = stack_bytes(|| call(&mut second));
        if !(ok && ok_again) {
            defmt::error!(
                "{=str} {=str}: the call returned an error",
                model,
                algorithm
            );
            return false;
        }
        cost.add(instructions, stack);
    }
    cost.report(model, algorithm);
    true
}
