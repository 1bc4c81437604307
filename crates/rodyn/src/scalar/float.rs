//! [`Scalar`] for the primitive floats.

use super::Scalar;

#[cfg(not(any(feature = "std", feature = "libm")))]
compile_error!(
    "rodyn needs float functions: enable the `std` feature (host) or the `libm` feature (no_std)"
);

macro_rules! float_fn {
    ($std:ident, $libm:path, $x:expr) => {{
        #[cfg(feature = "std")]
        {
            $x.$std()
        }
        #[cfg(all(not(feature = "std"), feature = "libm"))]
        {
            $libm($x)
        }
        // Never built: the `compile_error!` above stops such a build; this
        // arm only keeps the compiler from adding a dozen type errors to it.
        #[cfg(not(any(feature = "std", feature = "libm")))]
        {
            $x
        }
    }};
}

impl Scalar for f64 {
    /// The bits of all, or-ed, without their signs.
    #[inline(always)]
    fn all_zero<const N: usize>(values: [Self; N]) -> bool {
        values.iter().fold(0, |acc: u64, v| acc | v.to_bits()) << 1 == 0
    }
    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
    const NEG_ONE: Self = -1.0;
    const EPSILON: f64 = f64::EPSILON;

    #[inline]
    fn from_f64(value: f64) -> Self {
        value
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self
    }
    #[inline]
    fn sqrt(self) -> Self {
        float_fn!(sqrt, libm::sqrt, self)
    }
    #[inline]
    fn sin_cos(self) -> (Self, Self) {
        // One reduction for both, with or without std (see sin_cos_f64).
        super::sin_cos_f64::sin_cos(self)
    }
    #[inline]
    fn sin_cos_array<const N: usize>(x: &[Self; N]) -> ([Self; N], [Self; N]) {
        super::sin_cos_f64::sin_cos_array(x)
    }
    #[inline]
    fn atan2(self, x: Self) -> Self {
        #[cfg(feature = "std")]
        {
            self.atan2(x)
        }
        #[cfg(all(not(feature = "std"), feature = "libm"))]
        {
            libm::atan2(self, x)
        }
        #[cfg(not(any(feature = "std", feature = "libm")))]
        {
            let _ = x;
            self
        }
    }
    #[inline]
    fn exp(self) -> Self {
        float_fn!(exp, libm::exp, self)
    }
    #[inline]
    fn ln(self) -> Self {
        float_fn!(ln, libm::log, self)
    }
    #[inline]
    fn tanh(self) -> Self {
        float_fn!(tanh, libm::tanh, self)
    }
    #[inline]
    fn abs(self) -> Self {
        f64::abs(self)
    }
    #[inline]
    fn is_finite(self) -> bool {
        f64::is_finite(self)
    }
}

impl Scalar for f32 {
    /// The bits of all, or-ed, without their signs.
    #[inline(always)]
    fn all_zero<const N: usize>(values: [Self; N]) -> bool {
        values.iter().fold(0, |acc: u32, v| acc | v.to_bits()) << 1 == 0
    }
    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
    const NEG_ONE: Self = -1.0;
    const EPSILON: f64 = f32::EPSILON as f64;

    #[inline]
    fn from_f64(value: f64) -> Self {
        value as f32
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self as f64
    }
    #[inline]
    fn sqrt(self) -> Self {
        sqrt_f32(self)
    }
    #[inline]
    fn sin_cos(self) -> (Self, Self) {
        #[cfg(feature = "std")]
        {
            self.sin_cos()
        }
        #[cfg(all(not(feature = "std"), feature = "libm"))]
        {
            super::sin_cos_f32::sin_cos(self)
        }
        #[cfg(not(any(feature = "std", feature = "libm")))]
        {
            (self, self)
        }
    }
    #[inline]
    fn atan2(self, x: Self) -> Self {
        #[cfg(feature = "std")]
        {
            self.atan2(x)
        }
        #[cfg(all(not(feature = "std"), feature = "libm"))]
        {
            libm::atan2f(self, x)
        }
        #[cfg(not(any(feature = "std", feature = "libm")))]
        {
            let _ = x;
            self
        }
    }
    #[inline]
    fn exp(self) -> Self {
        float_fn!(exp, libm::expf, self)
    }
    #[inline]
    fn ln(self) -> Self {
        float_fn!(ln, libm::logf, self)
    }
    #[inline]
    fn tanh(self) -> Self {
        float_fn!(tanh, libm::tanhf, self)
    }
    #[inline]
    fn abs(self) -> Self {
        f32::abs(self)
    }
    #[inline]
    fn is_finite(self) -> bool {
        f32::is_finite(self)
    }
}

/// `f32` square root: the FPU instruction on Cortex-M4F/M7, never libm's
/// bit-by-bit software loop (a long loop per call on the MCU, where the
/// FPU's takes one instruction).
///
/// The test is the hard-float ABI (`target_abi = "eabihf"`): every such Arm
/// target has a single-precision VSQRT. The FPU's `target_feature` names are
/// not visible to `cfg` on stable Rust, and inline `asm!` cannot name S
/// registers on a single-precision FPU, so the instruction sits in a
/// two-instruction function: the hard-float ABI passes and returns the value
/// in `s0`.
///
/// A test of the instruction set, not of the tuning profile
/// (`crate::tuning`): the instruction exists on every hard-float Arm
/// target, whatever kind of core runs it.
#[inline]
fn sqrt_f32(x: f32) -> f32 {
    #[cfg(all(not(feature = "std"), target_arch = "arm", target_abi = "eabihf"))]
    {
        // SAFETY: `rodyn_vsqrt_f32` (below) reads s0, writes s0 and returns;
        // it touches no memory and follows the AAPCS-VFP calling convention.
        unsafe { rodyn_vsqrt_f32(x) }
    }
    #[cfg(not(all(not(feature = "std"), target_arch = "arm", target_abi = "eabihf")))]
    {
        float_fn!(sqrt, libm::sqrtf, x)
    }
}

#[cfg(all(not(feature = "std"), target_arch = "arm", target_abi = "eabihf"))]
unsafe extern "C" {
    /// VSQRT.F32 on s0 (defined in the `global_asm!` below).
    fn rodyn_vsqrt_f32(x: f32) -> f32;
}

#[cfg(all(not(feature = "std"), target_arch = "arm", target_abi = "eabihf"))]
core::arch::global_asm!(
    ".section .text.rodyn_vsqrt_f32,\"ax\",%progbits",
    ".globl rodyn_vsqrt_f32",
    ".type rodyn_vsqrt_f32,%function",
    ".thumb_func",
    // The assembler is not told the target's FPU; the M4F's is named here
    // (VSQRT.F32 has the same encoding on every VFP unit).
    ".fpu fpv4-sp-d16",
    "rodyn_vsqrt_f32:",
    "vsqrt.f32 s0, s0",
    "bx lr",
    ".size rodyn_vsqrt_f32, . - rodyn_vsqrt_f32",
);
