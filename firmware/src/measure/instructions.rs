//! Instructions per call, read from SysTick under QEMU's `-icount`.
//!
//! With `-icount shift=6` QEMU advances virtual time by 2⁶ = 64 ns per
//! executed instruction, and the mps2-an386 SysTick counts its 25 MHz clock
//! (40 ns per tick) in that virtual time, so `instructions = ticks · 40 / 64`
//! exactly. The other MPS2 machines of the Cortex-M family's tables
//! (mps2-an385, mps2-an500) run at the same 25 MHz; mps2-an505 at 20 MHz
//! (50 ns per tick, QEMU's `hw/arm/mps2-tz.c`). QEMU does not model the DWT cycle counter, and without `-icount`
//! SysTick follows host time, so this is the only deterministic count. These
//! are executed instructions, not cycles: on a real Cortex-M4F a load takes
//! two cycles, `VDIV`/`VSQRT` fourteen.

use super::call_opaque;
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m::peripheral::SYST;

/// SysTick is a 24-bit down-counter.
const SYSTICK_MASK: u32 = 0x00FF_FFFF;
/// Virtual nanoseconds per instruction (`-icount shift=6`).
const NS_PER_INSTRUCTION: u32 = 64;
/// Nanoseconds per SysTick tick (25 MHz).
#[cfg(not(mps2_an505))]
const NS_PER_TICK: u32 = 40;
/// Nanoseconds per SysTick tick (20 MHz).
#[cfg(mps2_an505)]
const NS_PER_TICK: u32 = 50;
/// Longest call the 24-bit counter can time without wrapping twice.
pub const MAX_INSTRUCTIONS: u32 = SYSTICK_MASK / NS_PER_INSTRUCTION * NS_PER_TICK;

/// Counts executed instructions of a call through the free-running SysTick.
#[derive(Debug)]
pub struct InstructionCounter {
    /// The count of an empty call, subtracted from every measurement.
    overhead: u32,
}

impl InstructionCounter {
    /// Starts SysTick free-running on the core clock, and calibrates the
    /// measurement overhead on an empty call.
    pub fn start(syst: &mut SYST) -> Self {
        syst.set_clock_source(SystClkSource::Core);
        syst.set_reload(SYSTICK_MASK);
        syst.clear_current();
        syst.enable_counter();
        let mut counter = Self { overhead: 0 };
        let mut overhead = u32::MAX;
        for _ in 0..4 {
            overhead = overhead.min(counter.count(|| ()).1);
        }
        counter.overhead = overhead;
        counter
    }

    /// Runs `f` and returns its result and the instructions it executed
    /// (saturating at [`MAX_INSTRUCTIONS`] for longer calls).
    pub fn count<R>(&self, f: impl FnOnce() -> R) -> (R, u32) {
        let start = SYST::get_current();
        let result = call_opaque(f);
        let end = SYST::get_current();
        let ticks = start.wrapping_sub(end) & SYSTICK_MASK;
        let instructions = ticks * NS_PER_TICK / NS_PER_INSTRUCTION;
        (result, instructions.saturating_sub(self.overhead))
    }

    /// Instructions elapsed since `start` (a value of [`Self::now`]), for
    /// spans that contain more than one call.
    #[must_use]
    pub fn since(&self, start: u32) -> u32 {
        let ticks = start.wrapping_sub(SYST::get_current()) & SYSTICK_MASK;
        ticks * NS_PER_TICK / NS_PER_INSTRUCTION
    }

    /// The current counter value, to pass to [`Self::since`].
    #[must_use]
    pub fn now(&self) -> u32 {
        SYST::get_current()
    }
}
