//! Double-precision sine and cosine from one argument reduction.
//!
//! `f64::sin_cos` calls the C library's `sin` and `cos` one after the other,
//! and each reduces the argument again: two library calls per revolute joint
//! per algorithm call, a large share of RNEA's time on a 7-DoF arm. Here one
//! reduction by π/64 (four-part Cody-Waite, its remainder kept as two
//! floats) leaves `x = k π/64 + r` with |r| ≤ π/128; a table holds the sine
//! and cosine of the 128 multiples of π/64 (correctly rounded), and short
//! Taylor polynomials give those of r (the first terms they leave out are
//! below 10⁻²⁰ for the sine and 4·10⁻¹⁸ for the cosine), combined by the
//! angle-sum formulas. For |x| ≤ 5·10⁴ rad the result is the C library's or
//! a neighbouring float (the tests sweep the range); larger or non-finite
//! arguments take the library path, which reduces exactly.
//! [`sin_cos_array`] gives the same for many angles at once.
//!
//! Why a table rather than polynomials on [-π/4, π/4] (fdlibm's kernels,
//! which this module used before): every pass over the bodies starts from
//! the sines, and each angle's two polynomials (degree 13 and 14) were
//! chains of dependent products that the bodies' work waited on; over
//! ±π/128 they are three terms long and the quadrant needs no swap (the
//! performance notebook, "Sines from a table"). The table is 2 KiB of
//! read-only data.

/// Beyond this (rad) the library reduces the argument: `|k| < 2²⁰`.
const FAST_LIMIT: f64 = 5.0e4;
/// 64/π (2/π times 32: the same rounding).
const SIXTY_FOUR_OVER_PI: f64 = core::f64::consts::FRAC_2_PI * 32.0;
/// π/64 = `PIO64_1 + PIO64_2 + PIO64_3 + PIO64_3T` (to 10⁻⁴⁸), the
/// first two of 33 significant bits, so that `k · PIO64_1` and `k ·
/// PIO64_2` are exact for |k| < 2²⁰ (Sun's fdlibm parts of π/2, over 32).
/// The fourth keeps the remainder's relative accuracy where x is within
/// 10⁻¹⁵ of a multiple of π and its sine is that small.
const PIO64_1: f64 = 1.570_796_326_734_125_6 / 32.0;
const PIO64_2: f64 = 6.077_100_506_303_966e-11 / 32.0;
const PIO64_3: f64 = 2.022_266_248_711_166_5e-21 / 32.0;
const PIO64_3T: f64 = 8.478_427_660_368_9e-32 / 32.0;
/// 1.5 · 2⁵²: `t + ROUND_SHIFT - ROUND_SHIFT` rounds `|t| < 2⁵¹` to an integer.
const ROUND_SHIFT: f64 = 6_755_399_441_055_744.0;

/// `[sin, cos]` of `k π/64` for k = 0..128, correctly rounded (exact zeros
/// and ones at the quarter turns): `python3 tools/sin_cos_table.py`
/// prints it (mpmath at 300 bits).
// Generated literals, √½ among them, as the script prints them.
#[rustfmt::skip]
#[allow(clippy::approx_constant)]
static MULTIPLES_OF_PI_OVER_64: [[f64; 2]; 128] = [
    [0.0, 1.0],
    [0.049067674327418015, 0.9987954562051724],
    [0.0980171403295606, 0.9951847266721969],
    [0.14673047445536175, 0.989176509964781],
    [0.19509032201612828, 0.9807852804032304],
    [0.2429801799032639, 0.970031253194544],
    [0.2902846772544624, 0.9569403357322088],
    [0.33688985339222005, 0.9415440651830208],
    [0.3826834323650898, 0.9238795325112867],
    [0.4275550934302821, 0.9039892931234433],
    [0.47139673682599764, 0.881921264348355],
    [0.5141027441932218, 0.8577286100002721],
    [0.5555702330196022, 0.8314696123025452],
    [0.5956993044924334, 0.8032075314806449],
    [0.6343932841636455, 0.773010453362737],
    [0.6715589548470184, 0.7409511253549591],
    [0.7071067811865476, 0.7071067811865476],
    [0.7409511253549591, 0.6715589548470184],
    [0.773010453362737, 0.6343932841636455],
    [0.8032075314806449, 0.5956993044924334],
    [0.8314696123025452, 0.5555702330196022],
    [0.8577286100002721, 0.5141027441932218],
    [0.881921264348355, 0.47139673682599764],
    [0.9039892931234433, 0.4275550934302821],
    [0.9238795325112867, 0.3826834323650898],
    [0.9415440651830208, 0.33688985339222005],
    [0.9569403357322088, 0.2902846772544624],
    [0.970031253194544, 0.2429801799032639],
    [0.9807852804032304, 0.19509032201612828],
    [0.989176509964781, 0.14673047445536175],
    [0.9951847266721969, 0.0980171403295606],
    [0.9987954562051724, 0.049067674327418015],
    [1.0, 0.0],
    [0.9987954562051724, -0.049067674327418015],
    [0.9951847266721969, -0.0980171403295606],
    [0.989176509964781, -0.14673047445536175],
    [0.9807852804032304, -0.19509032201612828],
    [0.970031253194544, -0.2429801799032639],
    [0.9569403357322088, -0.2902846772544624],
    [0.9415440651830208, -0.33688985339222005],
    [0.9238795325112867, -0.3826834323650898],
    [0.9039892931234433, -0.4275550934302821],
    [0.881921264348355, -0.47139673682599764],
    [0.8577286100002721, -0.5141027441932218],
    [0.8314696123025452, -0.5555702330196022],
    [0.8032075314806449, -0.5956993044924334],
    [0.773010453362737, -0.6343932841636455],
    [0.7409511253549591, -0.6715589548470184],
    [0.7071067811865476, -0.7071067811865476],
    [0.6715589548470184, -0.7409511253549591],
    [0.6343932841636455, -0.773010453362737],
    [0.5956993044924334, -0.8032075314806449],
    [0.5555702330196022, -0.8314696123025452],
    [0.5141027441932218, -0.8577286100002721],
    [0.47139673682599764, -0.881921264348355],
    [0.4275550934302821, -0.9039892931234433],
    [0.3826834323650898, -0.9238795325112867],
    [0.33688985339222005, -0.9415440651830208],
    [0.2902846772544624, -0.9569403357322088],
    [0.2429801799032639, -0.970031253194544],
    [0.19509032201612828, -0.9807852804032304],
    [0.14673047445536175, -0.989176509964781],
    [0.0980171403295606, -0.9951847266721969],
    [0.049067674327418015, -0.9987954562051724],
    [0.0, -1.0],
    [-0.049067674327418015, -0.9987954562051724],
    [-0.0980171403295606, -0.9951847266721969],
    [-0.14673047445536175, -0.989176509964781],
    [-0.19509032201612828, -0.9807852804032304],
    [-0.2429801799032639, -0.970031253194544],
    [-0.2902846772544624, -0.9569403357322088],
    [-0.33688985339222005, -0.9415440651830208],
    [-0.3826834323650898, -0.9238795325112867],
    [-0.4275550934302821, -0.9039892931234433],
    [-0.47139673682599764, -0.881921264348355],
    [-0.5141027441932218, -0.8577286100002721],
    [-0.5555702330196022, -0.8314696123025452],
    [-0.5956993044924334, -0.8032075314806449],
    [-0.6343932841636455, -0.773010453362737],
    [-0.6715589548470184, -0.7409511253549591],
    [-0.7071067811865476, -0.7071067811865476],
    [-0.7409511253549591, -0.6715589548470184],
    [-0.773010453362737, -0.6343932841636455],
    [-0.8032075314806449, -0.5956993044924334],
    [-0.8314696123025452, -0.5555702330196022],
    [-0.8577286100002721, -0.5141027441932218],
    [-0.881921264348355, -0.47139673682599764],
    [-0.9039892931234433, -0.4275550934302821],
    [-0.9238795325112867, -0.3826834323650898],
    [-0.9415440651830208, -0.33688985339222005],
    [-0.9569403357322088, -0.2902846772544624],
    [-0.970031253194544, -0.2429801799032639],
    [-0.9807852804032304, -0.19509032201612828],
    [-0.989176509964781, -0.14673047445536175],
    [-0.9951847266721969, -0.0980171403295606],
    [-0.9987954562051724, -0.049067674327418015],
    [-1.0, 0.0],
    [-0.9987954562051724, 0.049067674327418015],
    [-0.9951847266721969, 0.0980171403295606],
    [-0.989176509964781, 0.14673047445536175],
    [-0.9807852804032304, 0.19509032201612828],
    [-0.970031253194544, 0.2429801799032639],
    [-0.9569403357322088, 0.2902846772544624],
    [-0.9415440651830208, 0.33688985339222005],
    [-0.9238795325112867, 0.3826834323650898],
    [-0.9039892931234433, 0.4275550934302821],
    [-0.881921264348355, 0.47139673682599764],
    [-0.8577286100002721, 0.5141027441932218],
    [-0.8314696123025452, 0.5555702330196022],
    [-0.8032075314806449, 0.5956993044924334],
    [-0.773010453362737, 0.6343932841636455],
    [-0.7409511253549591, 0.6715589548470184],
    [-0.7071067811865476, 0.7071067811865476],
    [-0.6715589548470184, 0.7409511253549591],
    [-0.6343932841636455, 0.773010453362737],
    [-0.5956993044924334, 0.8032075314806449],
    [-0.5555702330196022, 0.8314696123025452],
    [-0.5141027441932218, 0.8577286100002721],
    [-0.47139673682599764, 0.881921264348355],
    [-0.4275550934302821, 0.9039892931234433],
    [-0.3826834323650898, 0.9238795325112867],
    [-0.33688985339222005, 0.9415440651830208],
    [-0.2902846772544624, 0.9569403357322088],
    [-0.2429801799032639, 0.970031253194544],
    [-0.19509032201612828, 0.9807852804032304],
    [-0.14673047445536175, 0.989176509964781],
    [-0.0980171403295606, 0.9951847266721969],
    [-0.049067674327418015, 0.9987954562051724],
];

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
        fast_sin_cos(x)
    } else {
        library_sin_cos(x)
    }
}

/// `x = r + r_lo + k π/64` with `|r| ≤ π/128` and `r_lo` of the order of
/// half an ulp of r: the bits of a float whose low bits hold `k`, then r and
/// `r_lo`. k = round(x · 64/π), without a branch or a saturating
/// conversion: adding 1.5 · 2⁵² rounds to an integer (ties to even) held
/// in the low bits of the sum, so `k mod 128` is read from its bit
/// pattern. `x − k·PIO64_1` and `k·PIO64_2` are exact, so the rounding of
/// their difference is recovered exactly (r carried as two floats keeps
/// the result within an ulp where the table's entry and `C r` nearly
/// cancel).
#[inline(always)]
fn reduce(x: f64) -> (u64, f64, f64) {
    let shifted = x * SIXTY_FOUR_OVER_PI + ROUND_SHIFT;
    let k_f = shifted - ROUND_SHIFT;
    let w = x - k_f * PIO64_1;
    let t = k_f * PIO64_2;
    let r = w - t;
    let r_lo = ((w - r) - t) - (k_f * PIO64_3 + k_f * PIO64_3T);
    (shifted.to_bits(), r, r_lo)
}

/// `sin` and `cos` of every angle of `x`, the same bits as [`sin_cos`]
/// gives. The fast path runs over the whole array without a jump, two
/// angles side by side, which x86-64 compiles two per SSE2 instruction.
/// Angles outside the fast range are then redone one by one.
#[inline]
pub(crate) fn sin_cos_array<const N: usize>(x: &[f64; N]) -> ([f64; N], [f64; N]) {
    let (mut sin, mut cos) = ([0.0; N], [0.0; N]);
    // An odd count leaves one angle alone: the first, a model's root,
    // whose angle is zero when it has none (a floating base's); zero's
    // pair is then written without the table (the same bits).
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
///
/// With `(S, C)` the table's pair for k, `x = k π/64 + r + r_lo`, `sin(r +
/// r_lo) = r + τ` and `cos r = 1 + z p_c` (z = r², `τ = r z p_s + r_lo`):
/// `sin x = S + (C r + (S z p_c + C τ))` and `cos x = C + ((C z p_c − S τ)
/// − S r)`, the small terms summed first so that the result is rounded
/// once at the scale of the table's entry.
#[inline(always)]
fn fast_sin_cos(x: f64) -> (f64, f64) {
    // Taylor's coefficients: over |r| ≤ π/128 the terms they leave out
    // are below the results' rounding (the module documentation).
    const S1: f64 = -1.0 / 6.0;
    const S2: f64 = 1.0 / 120.0;
    const S3: f64 = -1.0 / 5040.0;
    const C1: f64 = -0.5;
    const C2: f64 = 1.0 / 24.0;
    const C3: f64 = -1.0 / 720.0;
    let (k, r, r_lo) = reduce(x);
    let [s, c] = MULTIPLES_OF_PI_OVER_64[(k & 127) as usize];
    let z = r * r;
    let p_s = S1 + z * (S2 + z * S3);
    let p_c = C1 + z * (C2 + z * C3);
    // τ: the sine's terms beyond r, with the part of the remainder that r
    // could not hold (where S and C r nearly cancel it is worth an ulp).
    let (z_pc, tau) = (z * p_c, r * z * p_s + r_lo);
    (
        s + (c * r + (s * z_pc + c * tau)),
        c + ((c * z_pc - s * tau) - s * r),
    )
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::{sin_cos, sin_cos_array};
    use crate::test_points;

    /// `a`'s distance from `b` in units of the spacing of floats at `b`.
    fn ulps(a: f64, b: f64) -> f64 {
        (a - b).abs() / (b.abs().next_up() - b.abs())
    }

    /// The largest distance from the library's pair over `xs`, in ulps,
    /// and where it is.
    fn worst(xs: impl Iterator<Item = f64>) -> (f64, f64) {
        let mut worst = (0.0, 0.0);
        for x in xs {
            let (s, c) = sin_cos(x);
            let e = ulps(s, x.sin()).max(ulps(c, x.cos()));
            if e > worst.0 {
                worst = (e, x);
            }
        }
        worst
    }

    /// Uniform angles in `[-half, half]` from a fixed linear congruential
    /// sequence.
    fn spread(n: usize, half: f64, seed: u64) -> impl Iterator<Item = f64> {
        let mut state = seed;
        (0..n).map(move |_| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let u = (state >> 11) as f64 / (1u64 << 53) as f64;
            (2.0 * u - 1.0) * half
        })
    }

    #[test]
    fn gives_the_librarys_result_or_a_neighbouring_float() {
        // A dense sweep over the joint-angle range, the table's joins
        // (odd multiples of π/128) included.
        let dense = worst(
            (-400_000..400_000)
                .step_by(test_points(1, 3_989))
                .map(|i| f64::from(i) * 1.25e-4),
        );
        assert!(
            dense.0 <= 1.0,
            "{} ulps at {} on [-50, 50]",
            dense.0,
            dense.1
        );
        // The table's points and their neighbours, where the reduction
        // cancels and the sine or cosine of a quarter turn is zero.
        let near_points = worst(
            (-20_000..20_000)
                .step_by(test_points(1, 397))
                .flat_map(|k| {
                    let x = f64::from(k) * (core::f64::consts::PI / 64.0);
                    [x, x.next_up(), x.next_down(), x + 1e-9, x - 3e-7]
                }),
        );
        assert!(
            near_points.0 <= 1.0,
            "{} ulps at {} near kπ/64",
            near_points.0,
            near_points.1
        );
        // Anywhere in the fast range, where k reaches 10⁶.
        for (half, seed) in [(10.0, 1), (1.0e3, 2), (5.0e4, 3)] {
            let far = worst(spread(test_points(200_000, 200), half, seed));
            assert!(far.0 <= 1.0, "{} ulps at {} within ±{half}", far.0, far.1);
        }
    }

    #[test]
    fn the_table_holds_the_multiples_of_pi_over_64() {
        let table = &super::MULTIPLES_OF_PI_OVER_64;
        for (k, [s, c]) in table.iter().enumerate() {
            // The library at x, the float nearest kπ/64, moved on by δ =
            // kπ/64 − x (below 4·10⁻¹⁵ rad; k · PIO64_1 is exact and near x).
            let (kf, x) = (k as f64, k as f64 * (core::f64::consts::PI / 64.0));
            let off = ((kf * super::PIO64_1 - x) + kf * super::PIO64_2) + kf * super::PIO64_3;
            let (s_ref, c_ref) = (x.sin() + x.cos() * off, x.cos() - x.sin() * off);
            assert!(
                (s - s_ref).abs() <= 1.2e-16 && (c - c_ref).abs() <= 1.2e-16,
                "entry {k}"
            );
            assert!((s * s + c * c - 1.0).abs() <= 4.5e-16, "entry {k}");
        }
        // The quarter turns exactly.
        for (k, pair) in [
            (0, [0.0, 1.0]),
            (32, [1.0, 0.0]),
            (64, [0.0, -1.0]),
            (96, [-1.0, 0.0]),
        ] {
            assert_eq!(table[k], pair, "entry {k}");
        }
        // Each entry's mirror images: sin(π − a) = sin a, cos(−a) = cos a.
        for k in 1..64 {
            assert_eq!(table[k][0], table[64 - k][0], "entry {k}");
            assert_eq!(table[k][1], table[128 - k][1], "entry {k}");
        }
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
        for x in [5.0e4 + 1e-3, -6.0e4, 1.0e5 + 0.5, -3.0e7, 1.0e300] {
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
        for start in (0..200).step_by(test_points(1, 19)) {
            let x: [f64; 16] = core::array::from_fn(|k| (start * 16 + k) as f64 * 0.0123 - 20.0);
            assert_array_matches(x);
        }
    }
}
