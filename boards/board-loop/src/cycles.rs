//! Cycles per call from the DWT's cycle counter.
//!
//! `CYCCNT` counts core clock cycles: unlike QEMU's instruction counts it
//! includes flash wait states, cache misses, pipeline stalls and the FPU's
//! latencies, so it is the figure to hold against a control period.

use core::sync::atomic::{compiler_fence, Ordering};
use cortex_m::peripheral::{DCB, DWT};

/// The running cycle counter. Owning the DWT keeps anything else from
/// stopping or resetting it.
pub struct CycleCounter {
    _dwt: DWT,
}

impl core::fmt::Debug for CycleCounter {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("CycleCounter")
    }
}

impl CycleCounter {
    /// Enables the trace unit and starts the cycle counter. A Cortex-M7
    /// ignores writes to the DWT until its software lock is opened: call
    /// `DWT::unlock()` first there.
    pub fn start(dcb: &mut DCB, mut dwt: DWT) -> Self {
        dcb.enable_trace();
        dwt.enable_cycle_counter();
        Self { _dwt: dwt }
    }

    /// Runs `f` and returns its result with the cycles it took (up to
    /// 2³² - 1, 4 s at 1 GHz). The fences keep the compiler from moving
    /// the call's work across the counter's reads.
    #[inline(always)]
    pub fn measure<T>(&self, f: impl FnOnce() -> T) -> (T, u32) {
        compiler_fence(Ordering::SeqCst);
        let start = DWT::cycle_count();
        compiler_fence(Ordering::SeqCst);
        let result = f();
        compiler_fence(Ordering::SeqCst);
        let cycles = DWT::cycle_count().wrapping_sub(start);
        compiler_fence(Ordering::SeqCst);
        (result, cycles)
    }
}

/// Fewest, most and mean cycles over a window of calls.
#[derive(Clone, Copy, Debug, Default)]
pub struct CycleStats {
    /// Fewest cycles of a call (0 before the first).
    pub min: u32,
    /// Most cycles of a call.
    pub max: u32,
    total: u64,
    calls: u32,
}

impl CycleStats {
    /// Counts one call of `cycles`.
    pub fn add(&mut self, cycles: u32) {
        self.min = if self.calls == 0 {
            cycles
        } else {
            self.min.min(cycles)
        };
        self.max = self.max.max(cycles);
        self.total += u64::from(cycles);
        self.calls += 1;
    }

    /// Mean cycles per call (0 before the first).
    pub fn mean(&self) -> u32 {
        if self.calls == 0 {
            return 0;
        }
        u32::try_from(self.total / u64::from(self.calls)).unwrap_or(u32::MAX)
    }

    /// Calls counted.
    pub const fn calls(&self) -> u32 {
        self.calls
    }
}
