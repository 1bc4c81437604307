//! Costs over seeded random inputs: the `cost` lines of the probes that
//! `cargo xtask costs` turns into the cost table.

use super::{stack_bytes, InstructionCounter};
use crate::rng::XorShift32;

/// Random states per model and algorithm.
pub const STATES: u32 = 100;
/// Seed of the state generator.
pub const SEED: u32 = 0x5EED_0001;
/// One state in this many (the last of every ten) is drawn across a
/// data-dependent branch that the row's ordinary states do not reach: the
/// joints wound beyond the f32 sine's fast range, the muscles shortening
/// faster than they can pull, the feet in the air (the branch table of
/// `docs/sections/firmware.md`). The other states are drawn as before, so
/// the row's minimum and maximum span both sides.
pub const BRANCH_EVERY: u32 = 10;

/// Whether state `index` (from 0) is one of [`BRANCH_EVERY`]'s.
#[must_use]
pub const fn branch_state(index: u32) -> bool {
    index % BRANCH_EVERY == BRANCH_EVERY - 1
}

/// 1592 turns (10,002.8 rad): an angle plus this is beyond the f32 sine's
/// fast range (|x| ≤ 8192 rad), where `sin_cos` reduces the argument
/// exactly in integer arithmetic (Payne–Hanek), and is the same angle to
/// within the f32 spacing there (5e-4 rad).
pub const WOUND: f32 = 1592.0 * 2.0 * core::f32::consts::PI;

/// Counts the inputs a `probe_scene` draw makes, for draws that mark
/// [`branch_state`]s: wraps after [`STATES`], so the same counter serves
/// every row it is shared by.
pub struct StateIndex(core::cell::Cell<u32>);

impl StateIndex {
    /// Before the first state.
    #[must_use]
    pub const fn new() -> Self {
        Self(core::cell::Cell::new(0))
    }

    /// Whether the next state drawn is a [`branch_state`].
    pub fn next_is_branch(&self) -> bool {
        let index = self.0.get();
        self.0.set((index + 1) % STATES);
        branch_state(index)
    }
}

impl Default for StateIndex {
    fn default() -> Self {
        Self::new()
    }
}

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
