//! The scalar the cost probes compute in: f32, or f64 with the firmware's
//! `f64` feature (the Cortex-M7's double-precision FPU, see
//! `docs/sections/cortex_m_family.md`). The random states are drawn in f32
//! either way and widened, so both builds probe the same states.

use crate::rng::XorShift32;

/// The probes' scalar.
#[cfg(not(feature = "f64"))]
pub type Real = f32;
/// The probes' scalar.
#[cfg(feature = "f64")]
pub type Real = f64;

/// [`Real`]'s name, as the probes print it.
#[cfg(not(feature = "f64"))]
pub const REAL_NAME: &str = "f32";
/// [`Real`]'s name, as the probes print it.
#[cfg(feature = "f64")]
pub const REAL_NAME: &str = "f64";

/// Fills `out` with uniform values in `[-range, range)`, drawn as f32 (the
/// same draws in both builds) and widened to [`Real`].
pub fn fill_symmetric(rng: &mut XorShift32, out: &mut [Real], range: f32) {
    for x in out {
        *x = Real::from(rng.uniform(-range, range));
    }
}
