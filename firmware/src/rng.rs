//! A seeded xorshift generator for reproducible random states.
//!
//! Marsaglia's 32-bit xorshift (shifts 13, 17, 5). The host recomputes the
//! same states from the printed inputs, so the generator only has to be
//! deterministic, cheap and free of allocation, not statistically strong.

/// Marsaglia's xorshift32.
#[derive(Clone, Copy, Debug)]
pub struct XorShift32 {
    state: u32,
}

impl XorShift32 {
    /// A generator from a non-zero seed (zero is replaced by a fixed constant,
    /// since xorshift would stay at zero forever).
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self {
            state: if seed == 0 { 0x9E37_79B9 } else { seed },
        }
    }

    /// The next 32 random bits.
    pub fn next_u32(&mut self) -> u32 {
        let mut x = self.state;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.state = x;
        x
    }

    /// A uniform value in `[lo, hi)`, from the top 24 bits (exact in f32).
    pub fn uniform(&mut self, lo: f32, hi: f32) -> f32 {
        let unit = (self.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0);
        lo + (hi - lo) * unit
    }

    /// Fills `out` with uniform values in `[-range, range)`.
    pub fn fill_symmetric(&mut self, out: &mut [f32], range: f32) {
        for x in out {
            *x = self.uniform(-range, range);
        }
    }
}
