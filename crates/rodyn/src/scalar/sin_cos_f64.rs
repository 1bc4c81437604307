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
//! [`sin_cos_array`] gives the same for many angles at once.

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
    // Never built (the `compile_error!` in `float.rs` stops such a build);
    // keeps that error the only one.
    #[cfg(not(any(feature = "std", feature = "libm")))]
    {
        (x, x)
    }
}

/// `(sin x, cos x)`.
#[inline]
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    // One comparison: NaN fails it too, and takes the library's path.
    if x.abs() <= FAST_LIMIT {
        let (k, y) = reduce(x);
        turn_by_quadrant(k, sin_kernel(y), cos_kernel(y))
    } else {
        library_sin_cos(x)
    }
}

/// `x = y + k π/2` with `|y| ≤ π/4`: the bits of a float whose low bits
/// hold `k`, and `y`. k = round(x · 2/π), without a branch or a saturating
/// conversion: adding 1.5 · 2⁵² rounds to an integer (ties to even) held
/// in the low bits of the sum, so `k mod 4` is read from its bit pattern.
#[inline(always)]
fn reduce(x: f64) -> (u64, f64) {
    let shifted = x * FRAC_2_PI + ROUND_SHIFT;
    let k_f = shifted - ROUND_SHIFT;
    let y = ((x - k_f * PIO2_1) - k_f * PIO2_2) - k_f * PIO2_3;
    (shifted.to_bits(), y)
}

/// `sin` and `cos` of every angle of `x`, the same bits as [`sin_cos`]
/// gives. The fast path runs over the whole array without a jump, two
/// angles side by side, which x86-64 compiles two per SSE2 instruction;
/// the quadrant's swap and signs come from the bits of `k` (a table read
/// per lane would not pack). Angles outside the fast range are then
/// redone one by one.
#[inline]
pub(crate) fn sin_cos_array<const N: usize>(x: &[f64; N]) -> ([f64; N], [f64; N]) {
    let (mut sin, mut cos) = ([0.0; N], [0.0; N]);
    // An odd count leaves one angle alone: the first, a model's root,
    // whose angle is zero when it has none (a floating base's); zero's
    // pair is then written without the kernels (the same bits).
    let lone = N % 2;
    if lone == 1 {
        (sin[0], cos[0]) = if x[0].to_bits() == 0 {
            (0.0, 1.0)
        } else {
            fast_sin_cos(x[0])
        };
    }
    for p in 0..N / 2 {
        let (i, j) = (lone + 2 * p, lone + 2 * p + 1);
        let (a, b) = (fast_sin_cos(x[i]), fast_sin_cos(x[j]));
        (sin[i], cos[i], sin[j], cos[j]) = (a.0, a.1, b.0, b.1);
    }
    // One test for the whole array, whose comparisons pair up (NaN fails
    // them too), before any angle is looked at again.
    let all_fast = x.iter().fold(true, |all, x| all & (x.abs() <= FAST_LIMIT));
    if !all_fast {
        for k in 0..N {
            let fast = x[k].abs() <= FAST_LIMIT;
            if !fast {
                (sin[k], cos[k]) = library_sin_cos(x[k]);
            }
        }
    }
    (sin, cos)
}

/// [`sin_cos`]'s fast path without a jump: meaningless outside it.
#[inline(always)]
fn fast_sin_cos(x: f64) -> (f64, f64) {
    let (k, y) = reduce(x);
    let (s, c) = (sin_kernel(y), cos_kernel(y));
    // Odd quadrants swap: (sin, cos) = (c, -s); the second bit negates both.
    let swap = 0u64.wrapping_sub(k & 1);
    let negate = (k << 62) & (1 << 63);
    let (s_bits, c_bits, minus_s_bits) = (s.to_bits(), c.to_bits(), (-s).to_bits());
    (
        f64::from_bits(((s_bits & !swap) | (c_bits & swap)) ^ negate),
        f64::from_bits(((c_bits & !swap) | (minus_s_bits & swap)) ^ negate),
    )
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
    use super::{sin_cos, sin_cos_array};

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

    /// Every angle of `x` through [`sin_cos_array`] against [`sin_cos`], bit for bit.
    fn assert_array_matches<const N: usize>(x: [f64; N]) {
        let (sin, cos) = sin_cos_array(&x);
        for k in 0..N {
            let (s, c) = sin_cos(x[k]);
            assert_eq!(
                (sin[k].to_bits(), cos[k].to_bits()),
                (s.to_bits(), c.to_bits()),
                "angle {k} of {N}: {}: ({}, {}) against ({s}, {c})",
                x[k],
                sin[k],
                cos[k]
            );
        }
    }

    #[test]
    fn the_array_form_gives_the_same_bits_in_every_quadrant_and_outside_the_fast_range() {
        // Angles of every quadrant, signed zeros, the ends of the fast
        // range, beyond it and non-finite, in odd and even counts.
        let mut angles = [0.0; 64];
        for (k, a) in angles.iter_mut().enumerate() {
            let quarter = (k as f64 - 32.0) * core::f64::consts::FRAC_PI_4;
            *a = quarter + 0.013 * k as f64;
        }
        angles[0] = -0.0;
        angles[1] = 0.0;
        angles[2] = 1.0e5;
        angles[3] = -1.0e5 - 0.25;
        angles[4] = f64::NAN;
        angles[5] = f64::INFINITY;
        angles[6] = 3.0e200;
        angles[7] = core::f64::consts::FRAC_PI_2;
        angles[8] = -core::f64::consts::PI;
        assert_array_matches(angles);
        let odd: [f64; 7] = core::array::from_fn(|k| angles[k * 9]);
        assert_array_matches(odd);
        assert_array_matches([f64::NEG_INFINITY]);
        assert_array_matches([2.5]);
        assert_array_matches::<0>([]);
        // A dense sweep, where each quadrant's swap and signs are taken.
        for start in 0..200 {
            let x: [f64; 16] = core::array::from_fn(|k| (start * 16 + k) as f64 * 0.0123 - 20.0);
            assert_array_matches(x);
        }
    }
}
