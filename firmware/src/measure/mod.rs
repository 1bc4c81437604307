//! Measuring what a call costs: instructions and stack bytes.
//!
//! Both measurements wrap the call in [`call_opaque`], a function that is
//! never inlined, so the algorithm runs in a frame of its own below the
//! measuring code whatever the optimiser decides about the algorithm itself.

mod instructions;
mod precision;
mod probe;
mod stack;

pub use instructions::{InstructionCounter, MAX_INSTRUCTIONS};
pub use precision::{fill_symmetric, Real, REAL_NAME};
pub use probe::{branch_state, probe_scene, Cost, StateIndex, BRANCH_EVERY, SEED, STATES, WOUND};
pub use stack::{stack_bytes, STACK_WINDOW_BYTES};

/// Calls `f` in a frame of its own; the optimiser sees neither through the
/// call nor through the result.
#[inline(never)]
pub fn call_opaque<R>(f: impl FnOnce() -> R) -> R {
    core::hint::black_box(f())
}
