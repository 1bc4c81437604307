//! The pieces rodyn's command-line tools and examples share, so that each
//! tool rejects a bad argument the same way, with the argument's name and
//! the limit in the message, before any work starts:
//!
//! - [`PositiveFinite`]: a step, a duration, a size in pixels, a time
//!   budget; rejects NaN, infinities, zero, negatives and subnormals.
//! - [`NonNegativeFinite`]: a friction coefficient, a coefficient of
//!   restitution; rejects NaN, infinities and negatives, zero allowed.
//! - [`Count`]: a whole number within stated bounds (rounds, calls, nodes).
//! - [`step_count`]: the number of steps of a run, bounded.
//! - [`writable_dir`] and [`writable_file`]: an output checked before a
//!   long computation rather than after it.
//! - [`no_arguments`]: a program without options refuses arguments
//!   rather than ignoring them.
//! - [`outln!`] and [`out!`]: `println!` and `print!` that take a reader
//!   closing the pipe early (`| head -1`) calmly, where `println!` panics.
//! - [`probe`]: the test harness that runs a tool with hostile values of
//!   every argument and requires a clean refusal.
//!
//! The value types implement [`FromStr`](core::str::FromStr), which is
//! what clap's derive uses as a value parser (`#[arg(long)] dt:
//! PositiveFinite`), and what a hand-written parser calls with `parse`.

#[macro_use]
mod number;
mod count;
mod no_arguments;
mod non_negative;
mod output;
mod positive;
pub mod probe;
pub mod stdout;
mod steps;

pub use count::Count;
pub use no_arguments::no_arguments;
pub use non_negative::NonNegativeFinite;
pub use number::shown;
pub use output::{writable_dir, writable_file};
pub use positive::PositiveFinite;
pub use stdout::emit;
pub use steps::step_count;
