//! Single-precision sine and cosine for FPUs without double precision.
//!
//! libm's `sincosf` evaluates its polynomials in `f64`, which a Cortex-M4F
//! emulates in software: about 2,400 instructions per call, paid once per
//! revolute joint per algorithm call. This version stays in `f32`: a
//! three-part Cody-Waite reduction by π/2 and minimax polynomials on
//! [-π/4, π/4] (the coefficients of Cephes' `sinf`/`cosf`), a few ulp
//! accurate for |x| ≤ 8192 rad. Larger or non-finite arguments take libm's
//! path, which reduces exactly.

/// Arguments up to this size are reduced in f32 without losing accuracy:
/// `k · π/2` split in three parts stays exact while `k < 2¹³`.
const FAST_LIMIT: f32 = 8192.0;
const FRAC_2_PI: f32 = core::f32::consts::FRAC_2_PI;
// π/2 = PIO2_1 + PIO2_2 + PIO2_3, the first two exactly representable with
// few significant bits so that `k · PIO2_n` is exact.
const PIO2_1: f32 = 1.570_312_5;
const PIO2_2: f32 = 4.837_513e-4;
const PIO2_3: f32 = 7.549_79e-8;

/// `sin(y)` for |y| ≤ π/4.
#[inline]
fn sin_kernel(y: f32) -> f32 {
    let z = y * y;
    y + y * z * (-1.666_665_5e-1 + z * (8.332_161e-3 + z * -1.951_529_6e-4))
}

/// `cos(y)` for |y| ≤ π/4.
#[inline]
fn cos_kernel(y: f32) -> f32 {
    let z = y * y;
    1.0 - 0.5 * z + z * z * (4.166_664_6e-2 + z * (-1.388_731_6e-3 + z * 2.443_315_7e-5))
}

/// The slow path with exact range reduction.
#[inline(never)]
fn exact_sin_cos(x: f32) -> (f32, f32) {
    #[cfg(feature = "libm")]
    {
        libm::sincosf(x)
    }
    #[cfg(not(feature = "libm"))]
    {
        x.sin_cos()
    }
}

/// `(sin x, cos x)` in single precision.
#[inline]
pub(crate) fn sin_cos(x: f32) -> (f32, f32) {
    // NaN and infinities take the exact path too (they compare false).
    if x.is_nan() || x.abs() > FAST_LIMIT {
        return exact_sin_cos(x);
    }
    // Nearest multiple k of π/2, rounded half away from zero (as-casts truncate).
    let kf = x * FRAC_2_PI;
    let k = (kf + if kf >= 0.0 { 0.5 } else { -0.5 }) as i32;
    let k_f = k as f32;
    let y = ((x - k_f * PIO2_1) - k_f * PIO2_2) - k_f * PIO2_3;
    let (s, c) = (sin_kernel(y), cos_kernel(y));
    match k & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

#[cfg(test)]
mod tests {
    use super::sin_cos;

    /// Against f64 sine and cosine on a dense grid of joint-like angles:
    /// within 2 f32 ulp of 1 (absolute 2.4e-7).
    #[test]
    fn matches_double_precision() {
        let mut worst = 0.0f64;
        let mut x = -50.0f32;
        while x < 50.0 {
            let (s, c) = sin_cos(x);
            let xd = x as f64;
            worst = worst
                .max((s as f64 - xd.sin()).abs())
                .max((c as f64 - xd.cos()).abs());
            x += 0.000_731;
        }
        assert!(worst < 2.4e-7, "worst error {worst:e}");
        for x in [1000.0f32, -4096.5, 8191.0] {
            let (s, c) = sin_cos(x);
            assert!(
                (s as f64 - (x as f64).sin()).abs() < 1e-6
                    && (c as f64 - (x as f64).cos()).abs() < 1e-6
            );
        }
        let (s, c) = sin_cos(f32::NAN);
        assert!(s.is_nan() && c.is_nan());
    }
}
