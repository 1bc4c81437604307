//! Leaving QEMU with an exit code, and what a panic does.
//!
//! Semihosting's exit call ends the emulator with the code given, so
//! `cargo run`, `cargo xtask test` and CI see a failing firmware as a failing
//! process. On a board without a debugger attached the call would trap;
//! production firmware would reset instead.

use core::sync::atomic::{AtomicBool, Ordering};

/// The firmware ran and every check passed.
pub const SUCCESS: i32 = 0;
/// A check failed (a bound exceeded, an algorithm returned an error).
pub const CHECK_FAILED: i32 = 1;
/// The firmware panicked.
pub const PANICKED: i32 = 101;

/// Ends the emulator with `code`.
pub fn exit(code: i32) -> ! {
    semihosting::process::exit(code)
}

/// Ends the emulator with [`SUCCESS`] when `passed`, else [`CHECK_FAILED`].
pub fn exit_with(passed: bool) -> ! {
    exit(if passed { SUCCESS } else { CHECK_FAILED })
}

/// Set by the first panic. The handler logs through defmt, and a panic
/// while defmt's logger is held (a `Format` implementation that panics, or
/// the logger's own "already taken" check) would enter the handler again
/// and again; a second entry exits at once instead.
static PANICKING: AtomicBool = AtomicBool::new(false);

#[panic_handler]
fn panic(info: &core::panic::PanicInfo<'_>) -> ! {
    if PANICKING.swap(true, Ordering::Relaxed) {
        exit(PANICKED)
    }
    match info.location() {
        Some(at) => defmt::error!("panic at {=str}:{=u32}", at.file(), at.line()),
        None => defmt::error!("panic"),
    }
    exit(PANICKED)
}

#[defmt::panic_handler]
fn defmt_panic() -> ! {
    exit(PANICKED)
}
