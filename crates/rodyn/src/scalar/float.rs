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
    }};
}

impl Scalar for f64 {
    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
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
        #[cfg(feature = "std")]
        {
            self.sin_cos()
        }
        #[cfg(all(not(feature = "std"), feature = "libm"))]
        {
            libm::sincos(self)
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
            libm::atan2(self, x)
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
    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
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
/// bit-by-bit software loop (hundreds of instructions per call on the MCU).
#[inline]
fn sqrt_f32(x: f32) -> f32 {
    #[cfg(all(not(feature = "std"), target_arch = "arm", target_feature = "vfp2"))]
    {
        let root: f32;
        // SAFETY: VSQRT.F32 reads one S register and writes another; it has no
        // memory or flag side effects. Measured reason: libm's sqrtf is a
        // software loop, VSQRT is 14 cycles (see the firmware cost probe).
        unsafe {
            core::arch::asm!(
                "vsqrt.f32 {r}, {x}",
                r = lateout(sreg) root,
                x = in(sreg) x,
                options(pure, nomem, nostack, preserves_flags)
            );
        }
        root
    }
    #[cfg(not(all(not(feature = "std"), target_arch = "arm", target_feature = "vfp2")))]
    {
        float_fn!(sqrt, libm::sqrtf, x)
    }
}
