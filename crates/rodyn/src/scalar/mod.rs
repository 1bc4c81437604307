//! The scalar type every algorithm is generic over.
//!
//! [`Scalar`] is implemented for `f32` (the microcontroller scalar), `f64`
//! (the host scalar) and [`Dual`] (a forward-mode dual number that carries a
//! derivative along with each value, for parameter sensitivities).
//!
//! Float functions come from `std` on a host and from `libm` on a bare-metal
//! target. On `thumbv7em-none-eabihf` the `f32` square root uses the FPU's
//! `VSQRT.F32` instead of libm's software routine, and no algorithm calls a
//! fused multiply-add (libm's `fmaf` emulates it in software doubles).
//! Without `std`, `f32` sine and cosine are computed in single precision
//! (libm's `sincosf` works in `f64`, which a Cortex-M4F emulates).

mod dual;
mod float;
#[cfg(any(feature = "libm", test))]
mod sin_cos_f32;
mod sin_cos_f64;

/// `(sin x, cos x)` for `x = k · π/2 + y`, given `(s, c) = (sin y, cos y)`
/// and `quadrant = k mod 4`: the reduced pair turned by a quarter turn per
/// quadrant. (The `f64` path has its own, branch-free.)
#[cfg(any(feature = "libm", test))]
#[inline(always)]
fn turn_by_quadrant<T: Copy + core::ops::Neg<Output = T>>(quadrant: u8, s: T, c: T) -> (T, T) {
    match quadrant & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

pub use dual::Dual;

use core::fmt::Debug;
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A real number as the dynamics algorithms need it.
///
/// Only plain arithmetic and a handful of elementary functions are required,
/// so that a dual number or an interval type can implement it too.
pub trait Scalar:
    Copy
    + Debug
    + PartialEq
    + PartialOrd
    + Default
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + DivAssign
    + 'static
{
    /// Additive identity.
    const ZERO: Self;
    /// Multiplicative identity.
    const ONE: Self;
    /// Minus one (for exact signs in `const` code, where `-Self::ONE`
    /// cannot be evaluated).
    const NEG_ONE: Self;
    /// Machine epsilon of the underlying floating-point type.
    const EPSILON: f64;

    /// Converts a constant; used for literals in generic code.
    fn from_f64(value: f64) -> Self;
    /// The real value, dropping any derivative part (used for checks and reports).
    fn to_f64(self) -> f64;
    /// Square root.
    fn sqrt(self) -> Self;
    /// Sine and cosine of an angle in radians.
    fn sin_cos(self) -> (Self, Self);
    /// Sines and cosines of many angles (radians), each as
    /// [`sin_cos`](Self::sin_cos) gives it. A type may compute them
    /// several at a time (`f64` on a host does, two per SSE2 instruction).
    #[inline]
    fn sin_cos_array<const N: usize>(x: &[Self; N]) -> ([Self; N], [Self; N]) {
        let (mut sin, mut cos) = ([Self::ZERO; N], [Self::ONE; N]);
        for k in 0..N {
            (sin[k], cos[k]) = x[k].sin_cos();
        }
        (sin, cos)
    }
    /// Four-quadrant arctangent of `self / x`.
    fn atan2(self, x: Self) -> Self;
    /// Exponential function.
    fn exp(self) -> Self;
    /// Natural logarithm.
    fn ln(self) -> Self;
    /// Hyperbolic tangent.
    fn tanh(self) -> Self;
    /// Absolute value.
    fn abs(self) -> Self;

    /// `true` unless the value (or any derivative part) is NaN or infinite.
    fn is_finite(self) -> bool;

    /// Sine of an angle in radians.
    #[inline]
    fn sin(self) -> Self {
        self.sin_cos().0
    }
    /// Cosine of an angle in radians.
    #[inline]
    fn cos(self) -> Self {
        self.sin_cos().1
    }
    /// The larger of two values (`self` when they compare unordered).
    #[inline]
    fn max(self, other: Self) -> Self {
        if other > self {
            other
        } else {
            self
        }
    }
    /// The smaller of two values (`self` when they compare unordered).
    #[inline]
    fn min(self, other: Self) -> Self {
        if other < self {
            other
        } else {
            self
        }
    }
    /// `self * self`.
    #[inline]
    fn squared(self) -> Self {
        self * self
    }
    /// `true` when every value is exactly zero (of either sign). A
    /// floating-point type may test the bits of all at once: one branch
    /// instead of one comparison each.
    #[inline(always)]
    fn all_zero<const N: usize>(values: [Self; N]) -> bool {
        values.iter().all(|v| *v == Self::ZERO)
    }
}

/// `true` when every entry of `x` is finite, tested one by one: the
/// fallback of the tests that sum a small vector's entries first (a
/// spatial motion, a transform), out of line and shared, since it runs
/// only when the sum is not finite.
#[cold]
#[inline(never)]
pub(crate) fn entries_finite<S: Scalar>(x: &[S]) -> bool {
    x.iter().all(|v| v.is_finite())
}
