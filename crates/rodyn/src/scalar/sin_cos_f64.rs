//! Double-precision sine and cosine from one argument reduction.
//!
//! `f64::sin_cos` calls the C library's `sin` and `cos` one after the other,
//! and each reduces the argument again: two library calls per revolute joint
//! per algorithm call, a large share of RNEA's time on a 7-DoF arm. Here one
//! reduction by π/2 (three-part Cody-Waite: the parts of π/2 carry 33 bits
//! each, so `k · part` is exact for |k| < 2²⁰) feeds both minimax polynomials
//! on [-π/4, π/4] (the coefficients of Sun's fdlibm kernels). Within about
//! one ulp of the correctly rounded result for |x| ≤ 10⁵ rad; larger or
//! non-finite arguments take the library path, which reduces exactly.

/// Beyond this (rad) the library reduces the argument.
const FAST_LIMIT: f64 = 1.0e5;
const FRAC_2_PI: f64 = core::f64::consts::FRAC_2_PI;
/// π/2 = `PIO2_1 + PIO2_2 + PIO2_3` (+ 8.5e-32), 33 significant bits each.
const PIO2_1: f64 = 1.570_796_326_734_125_6;
const PIO2_2: f64 = 6.077_100_506_303_966e-11;
const PIO2_3: f64 = 2.022_266_248_711_166_5e-21;
/// 1.5 · 2⁵²: `t + ROUND_SHIFT - ROUND_SHIFT` rounds `|t| < 2⁵¹` to an integer.
const ROUND_SHIFT: f64 = 6_755_399_441_055_744.0;

/// `sin y` for |y| ≤ π/4.
#[inline]
fn sin_kernel(y: f64) -> f64 {
    const S1: f64 = -1.666_666_666_666_663_2e-1;
    const S2: f64 = 8.333_333_333_322_49e-3;
    const S3: f64 = -1.984_126_982_985_795e-4;
    const S4: f64 = 2.755_731_370_707_006_8e-6;
    const S5: f64 = -2.505_076_025_340_686_3e-8;
    const S6: f64 = 1.589_690_995_211_55e-10;
    let z = y * y;
    let r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
    y + z * y * (S1 + z * r)
}

/// `cos y` for |y| ≤ π/4.
#[inline]
fn cos_kernel(y: f64) -> f64 {
    const C1: f64 = 4.166_666_666_666_66e-2;
    const C2: f64 = -1.388_888_888_887_411e-3;
    const C3: f64 = 2.480_158_728_947_673e-5;
    const C4: f64 = -2.755_731_435_139_066_3e-7;
    const C5: f64 = 2.087_572_321_298_175e-9;
    const C6: f64 = -1.135_964_755_778_819_5e-11;
    let z = y * y;
    let r = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
    // 1 - z/2 loses the low bits of z/2; they are recovered as
    // (1 - w) - z/2, exact, and added back with the polynomial's tail.
    let half_z = 0.5 * z;
    let w = 1.0 - half_z;
    w + (((1.0 - w) - half_z) + z * r)
}

/// The library's pair, for arguments outside the fast range.
#[inline(never)]
fn library_sin_cos(x: f64) -> (f64, f64) {
    #[cfg(feature = "std")]
    {
        x.sin_cos()
    }
    #[cfg(all(not(feature = "std"), feature = "libm"))]
    {
        libm::sincos(x)
    }
}

/// `(sin x, cos x)`.
#[inline]
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    // One comparison: NaN fails it too, and takes the library's path.
    if x.abs() <= FAST_LIMIT {
        // k = round(x · 2/π), without a branch or a saturating conversion:
        // adding 1.5 · 2⁵² rounds to an integer (ties to even) held in the
        // low bits of the sum, so k mod 4 is read from its bit pattern.
        let shifted = x * FRAC_2_PI + ROUND_SHIFT;
        let k_f = shifted - ROUND_SHIFT;
        let y = ((x - k_f * PIO2_1) - k_f * PIO2_2) - k_f * PIO2_3;
        turn_by_quadrant(shifted.to_bits(), sin_kernel(y), cos_kernel(y))
    } else {
        library_sin_cos(x)
    }
}

/// `(sin x, cos x)` from `(sin y, cos y)` with `x = y + k π/2`: `sin x =
/// A s - B c` and `cos x = C c - D s` with the coefficients of quadrant
/// `k mod 4`, read from a table without a jump (the quadrant of a joint
/// angle is random, and a jump on it is mispredicted). The unused
/// coefficient of each pair is zero, and its product (with `c > 0.7` or
/// `|s| ≤ 0.71`) leaves the other term exact: 4 products and 2
/// subtractions, two of each per SSE2 instruction, where swapping and
/// negating bit patterns took 20 integer instructions.
#[inline(always)]
fn turn_by_quadrant(k: u64, s: f64, c: f64) -> (f64, f64) {
    /// `[A, C]` and `[B, D]` per quadrant.
    const QUADRANTS: [[[f64; 2]; 2]; 4] = [
        [[1.0, 1.0], [0.0, 0.0]],
        [[0.0, 0.0], [-1.0, 1.0]],
        [[-1.0, -1.0], [0.0, 0.0]],
        [[0.0, 0.0], [1.0, -1.0]],
    ];
    let [[a, c_], [b, d]] = QUADRANTS[(k & 3) as usize];
    (a * s - b * c, c_ * c - d * s)
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::sin_cos;

    /// Largest absolute error against the library over `xs`.
    fn worst(xs: impl Iterator<Item = f64>) -> f64 {
        let mut worst = 0.0f64;
        for x in xs {
            let (s, c) = sin_cos(x);
            worst = worst.max((s - x.sin()).abs()).max((c - x.cos()).abs());
        }
        worst
    }

    #[test]
    fn agrees_with_the_library_to_an_ulp_or_two() {
        // A dense sweep over the joint-angle range, quadrant boundaries included.
        let dense = worst((-400_000..400_000).map(|i| f64::from(i) * 1.25e-4));
        assert!(dense < 3.4e-16, "worst error {dense:e} on [-50, 50]");
        // Multiples of π/2 and their neighbours, where the reduction cancels.
        let near_quadrants = worst((-2000..2000).flat_map(|k| {
            let x = f64::from(k) * core::f64::consts::FRAC_PI_2;
            [x, x.next_up(), x.next_down()]
        }));
        assert!(
            near_quadrants < 3.4e-16,
            "worst error {near_quadrants:e} near kπ/2"
        );
        // Up to the fast path's limit, where k reaches 6.4e4.
        let far = worst((0..20_000).map(|i| -1.0e5 + f64::from(i) * 9.999_73));
        assert!(far < 1.0e-15, "worst error {far:e} up to 1e5 rad");
    }

    #[test]
    fn small_arguments_keep_their_relative_accuracy() {
        for x in [1e-300, -3e-200, 1e-20, 2.5e-9, -7e-5] {
            let (s, c) = sin_cos(x);
            assert!((s - x.sin()).abs() <= x.abs() * 2.3e-16, "sin {x:e}");
            assert_eq!(c, x.cos(), "cos {x:e}");
        }
    }

    #[test]
    fn each_quadrant_gives_its_signs() {
        assert_eq!(sin_cos(0.0), (0.0, 1.0));
        // One argument in each quadrant, both directions: the signs of
        // the pair are the quadrant's.
        for k in -8..8 {
            let x = (f64::from(k) + 0.5) * core::f64::consts::FRAC_PI_2;
            let (s, c) = sin_cos(x);
            assert_eq!(
                (s.is_sign_negative(), c.is_sign_negative()),
                (x.sin() < 0.0, x.cos() < 0.0),
                "quadrant of {x}"
            );
        }
    }

    #[test]
    fn large_and_non_finite_arguments_take_the_library_path() {
        for x in [1.0e5 + 0.5, -3.0e7, 1.0e300] {
            assert_eq!(sin_cos(x), (x.sin(), x.cos()));
        }
        for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let (s, c) = sin_cos(x);
            assert!(s.is_nan() && c.is_nan());
        }
    }
}
