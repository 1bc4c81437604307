//! Stack bytes per call, from a painted window below the stack pointer.
//!
//! cortex-m-rt's `paint-stack` fills the whole stack with `0xCCCC_CCCC` at
//! reset, which gives the high-water mark of the program. For one call we
//! repaint a window just below the current stack pointer, run the call, and
//! find the deepest word it overwrote. The window is small (scanning the
//! whole 4 MiB stack of the emulated board per call would dwarf the call).

use super::call_opaque;

/// The paint value cortex-m-rt uses.
const PAINT: u32 = 0xCCCC_CCCC;
/// Size of the repainted window; a call that uses more is reported as `None`.
pub const STACK_WINDOW_BYTES: u32 = 16 * 1024;
/// Words just below the stack pointer left unpainted: the measuring code's
/// own spills may land there.
const GUARD_WORDS: usize = 16;

/// Runs `f` and returns its result and the stack bytes it used below the
/// caller's stack pointer, or `None` when it used more than the window.
#[inline(always)]
pub fn stack_bytes<R>(f: impl FnOnce() -> R) -> (R, Option<u32>) {
    let sp = cortex_m::register::msp::read() as usize;
    let top = (sp & !3) - 4 * GUARD_WORDS;
    let words = STACK_WINDOW_BYTES as usize / 4;
    let bottom = top - 4 * words;
    // SAFETY: [bottom, top) lies below the stack pointer, in the stack region
    // (4 MiB of RAM on mps2-an386, far deeper than any call here), so no live
    // value is stored there and nothing but this program runs (no interrupt
    // handlers are enabled). Volatile, so the stores are not elided.
    for k in 0..words {
        unsafe { core::ptr::write_volatile((bottom + 4 * k) as *mut u32, PAINT) };
    }
    let result = call_opaque(f);
    let mut deepest = None;
    for k in 0..words {
        // SAFETY: as above; reading plain words of RAM.
        let word = unsafe { core::ptr::read_volatile((bottom + 4 * k) as *const u32) };
        if word != PAINT {
            deepest = Some(bottom + 4 * k);
            break;
        }
    }
    let used = match deepest {
        Some(address) if address == bottom => None,
        Some(address) => Some((sp - address) as u32),
        None => Some(0),
    };
    (result, used)
}
