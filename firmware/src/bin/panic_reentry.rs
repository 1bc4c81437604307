//! Checks that a panic inside the panic handler's own logging ends the run.
//!
//! Not an example: `cargo xtask test` runs it and requires exit code
//! [`PANICKED`](rodyn_firmware::exit::PANICKED). A value whose `defmt::Format`
//! panics is logged, so the panic arrives while defmt's logger is held; the
//! handler's own log line then finds the logger taken and panics again. The
//! handler must notice the second entry and exit, where without its guard it
//! would recurse until the stack overflows and the emulator hangs in a fault.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn_firmware::exit::{exit, CHECK_FAILED};

/// A value that cannot be formatted.
struct PanicsWhenFormatted;

impl defmt::Format for PanicsWhenFormatted {
    fn format(&self, _f: defmt::Formatter<'_>) {
        panic!("formatting panicked")
    }
}

#[entry]
fn main() -> ! {
    defmt::info!("panic_reentry: logging a value whose formatting panics");
    defmt::info!("{}", PanicsWhenFormatted);
    // Reached only if the log line above returned.
    exit(CHECK_FAILED)
}
