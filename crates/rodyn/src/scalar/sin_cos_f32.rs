//! Single-precision sine and cosine for FPUs without double precision.
//!
//! libm's `sincosf` evaluates its polynomials in `f64`, which a Cortex-M4F
//! emulates in software: more than a whole joint's dynamics otherwise
//! costs, paid once per revolute joint per algorithm call (figures in
//! docs/sections/performance_notebook.md, "Sine and cosine"). This
//! version stays in `f32`: a
//! three-part Cody-Waite reduction by π/2 and minimax polynomials on
//! [-π/4, π/4] (the coefficients of Cephes' `sinf`/`cosf`), a few ulp
//! accurate for |x| ≤ 8192 rad. Larger arguments are reduced exactly
//! (Payne–Hanek) in integer arithmetic: the 24-bit mantissa times a 96-bit
//! window of the bits of 2/π gives `x · 2/π` modulo 4 with 64 fraction bits,
//! then the same polynomials. No `f64` operation is involved, so no software
//! double-precision routine is linked; NaN and ±∞ give NaN.

/// Arguments up to this size are reduced in f32 without losing accuracy:
/// `k · π/2` split in three parts stays exact while `k < 2¹³`.
const FAST_LIMIT: f32 = 8192.0;
const FRAC_2_PI: f32 = core::f32::consts::FRAC_2_PI;
// π/2 = PIO2_1 + PIO2_2 + PIO2_3, the first two exactly representable with
// few significant bits so that `k · PIO2_n` is exact.
const PIO2_1: f32 = 1.570_312_5;
const PIO2_2: f32 = 4.837_513e-4;
const PIO2_3: f32 = 7.549_79e-8;

/// The binary digits of 2/π after the point, shifted right by 12 bits (the
/// first word starts with 12 zero bits), 212 bits in all: bit `i` of this
/// table (from the top, `i ≥ 1`) is bit `i − 12` of 2/π. The leading zeros
/// let the window start after bit `j = biased exponent − 140 ≥ 0` for every
/// `|x| > 8192`. Generated with Python's `mpmath` (`floor(2/π · 2²¹²)` at
/// 400 bits of precision) and checked against a `decimal` computation of π
/// by Machin's formula; they are the published hexadecimal digits
/// `0.A2F9836E4E441529FC2757D1F534DDC0DB6295993C439041FE516…` of 2/π.
const TWO_OVER_PI: [u32; 7] = [
    0x000a_2f98,
    0x36e4_e441,
    0x529f_c275,
    0x7d1f_534d,
    0xdc0d_b629,
    0x5993_c439,
    0x041f_e516,
];
/// π/2 · 2³¹, rounded to nearest.
const PIO2_Q31: u64 = 0xc90f_daa2;

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

/// The slow path: exact reduction of `|x| > 8192` (or non-finite `x`) to
/// `x = k · π/2 + y` with |y| ≤ π/4, returning `(k mod 4, y)`.
///
/// With `x = m · 2^e` (`m` the 24-bit mantissa) and `2/π = T · 2¹²` (`T` the
/// table), `x · 2/π = m · T · 2^(j+2)` with `j = e + 10 ≥ 0`. The bits of `T`
/// before bit `j + 1` contribute a multiple of 4, which changes neither sine
/// nor cosine; the 96 bits `W` after it give `x · 2/π ≡ m · W · 2⁻⁹⁴ (mod 4)`
/// with an error below `2²⁴ · 2⁻⁹⁴ = 2⁻⁷⁰` for the bits of `T` left out. The
/// integer part (mod 4) is the quadrant, the signed fraction in [-½, ½)
/// keeps 64 bits: no f32 comes closer to a multiple of π/2 than about 2⁻³⁰
/// (in units of π/2; see `exhaustive_large_arguments`), so at least some 34
/// significant bits are left.
#[inline]
fn reduce_large(x: f32) -> (i32, f32) {
    let bits = x.to_bits();
    let biased = (bits >> 23) & 0xff;
    if biased == 0xff {
        // NaN or ±∞: the kernels of NaN are NaN.
        return (0, f32::NAN);
    }
    // Only called for |x| > 8192 (biased exponent ≥ 140); `j ≤ 115` keeps
    // every table index below in bounds.
    let j = biased.saturating_sub(140);
    let (q, r) = ((j / 32) as usize, j % 32);
    // Bits `j + 1 + 32·i ..= j + 32·(i + 1)` of the table.
    let word = |i: usize| {
        let pair = (u64::from(TWO_OVER_PI[q + i]) << 32) | u64::from(TWO_OVER_PI[q + i + 1]);
        (pair >> (32 - r)) as u32
    };
    let m = (bits & 0x007f_ffff) | 0x0080_0000;
    // P = m · W mod 2⁹⁶ in three 32-bit words: hi, mid, lo.
    let p_lo = u64::from(m) * u64::from(word(2));
    let p_mid = (p_lo >> 32) + u64::from(m) * u64::from(word(1));
    let hi = m.wrapping_mul(word(0)).wrapping_add((p_mid >> 32) as u32);
    // The top two bits of P are the integer part of x · 2/π mod 4; the next
    // 64 bits, read as a signed number, the fraction rounded to [-½, ½).
    let frac = ((((u64::from(hi) << 32) | (p_mid & 0xffff_ffff)) << 2)
        | ((p_lo & 0xffff_ffff) >> 30)) as i64;
    let k = (hi >> 30) + u32::from(frac < 0);
    // y = frac · 2⁻⁶⁴ · π/2: normalise, multiply by π/2 in 32-bit fixed
    // point (relative error below 2⁻³⁰), convert and scale.
    let a = frac.unsigned_abs();
    let lz = a.leading_zeros() & 63; // a == 0 cannot happen; it would give y = 0
    let prod = ((a << lz) >> 32) * PIO2_Q31; // = |y| · 2^(63 + lz), ≥ 2⁶²
    let scale = f32::from_bits((96 - lz) << 23); // 2^-(31 + lz)
    let y = ((prod >> 32) as u32) as f32 * scale;
    let y = if frac < 0 { -y } else { y };
    // sin(-x) = -sin(x): x = -(k · π/2 + y) = (-k) · π/2 + (-y).
    if x < 0.0 {
        (k.wrapping_neg() as i32, -y)
    } else {
        (k as i32, y)
    }
}

/// `(sin x, cos x)` from `x = k · π/2 + y`, |y| ≤ π/4.
#[inline(always)]
fn from_quadrant(k: i32, y: f32) -> (f32, f32) {
    super::turn_by_quadrant((k & 3) as u8, sin_kernel(y), cos_kernel(y))
}

/// The slow path, kept out of line so that the fast path stays short.
#[inline(never)]
fn large_sin_cos(x: f32) -> (f32, f32) {
    let (k, y) = reduce_large(x);
    from_quadrant(k, y)
}

/// `(sin x, cos x)` in single precision.
#[inline]
pub(crate) fn sin_cos(x: f32) -> (f32, f32) {
    // NaN and infinities take the exact path too (they compare false).
    if x.is_nan() || x.abs() > FAST_LIMIT {
        return large_sin_cos(x);
    }
    // Nearest multiple k of π/2, rounded half away from zero (as-casts truncate).
    let kf = x * FRAC_2_PI;
    let k = (kf + if kf >= 0.0 { 0.5 } else { -0.5 }) as i32;
    let k_f = k as f32;
    let y = ((x - k_f * PIO2_1) - k_f * PIO2_2) - k_f * PIO2_3;
    from_quadrant(k, y)
}

#[cfg(test)]
mod tests {
    use super::{reduce_large, sin_cos};
    use crate::test_points;

    /// Largest absolute error of `sin_cos(x)` against the host's f64 sine
    /// and cosine of the same value (which reduce exactly).
    fn error(x: f32) -> f64 {
        let (s, c) = sin_cos(x);
        let xd = f64::from(x);
        (f64::from(s) - xd.sin())
            .abs()
            .max((f64::from(c) - xd.cos()).abs())
    }

    /// In each binade from 2¹³ to 2¹²⁷, the f32 closest to a multiple of π/2
    /// (bit patterns, found by `exhaustive_large_arguments`).
    #[rustfmt::skip]
    const HARDEST: [u32; 115] = [
        0x460b_e628, 0x468b_e628, 0x474d_246f, 0x47cd_246f, 0x484d_246f, 0x4882_665e,
        0x4902_665e, 0x4982_665e, 0x4a25_62ae, 0x4aa5_62ae, 0x4b25_62ae, 0x4bf3_b47b,
        0x4c23_32e9, 0x4ca3_32e9, 0x4d23_32e9, 0x4d84_7661, 0x4e13_d4a5, 0x4e93_d4a5,
        0x4f0f_fd14, 0x4fdb_d32f, 0x507f_d274, 0x50a3_e87f, 0x5123_e87f, 0x51a3_e87f,
        0x5223_e87f, 0x52a3_e87f, 0x5323_e87f, 0x53b1_46a6, 0x5431_46a6, 0x54b1_46a6,
        0x5531_46a6, 0x55b1_46a6, 0x5678_7577, 0x56f8_7577, 0x5778_7577, 0x57b8_2989,
        0x5838_2989, 0x58dc_36c9, 0x596e_3d69, 0x59f7_40b9, 0x5a7b_c261, 0x5afe_0335,
        0x5b7f_239f, 0x5bff_b3d4, 0x5c07_bcd0, 0x5c87_bcd0, 0x5d07_bcd0, 0x5d87_bcd0,
        0x5e07_bcd0, 0x5e87_bcd0, 0x5f07_bcd0, 0x5fe4_112c, 0x6064_112c, 0x60ab_0ce1,
        0x617c_556b, 0x61d3_b126, 0x6253_b126, 0x62ec_1b4a, 0x636c_1b4a, 0x63e6_00c1,
        0x642e_0733, 0x64ae_0733, 0x652e_0733, 0x6589_8498, 0x6609_8498, 0x6689_8498,
        0x6709_8498, 0x6789_8498, 0x6809_8498, 0x6889_8498, 0x6946_e3bb, 0x69c6_e3bb,
        0x6a19_76f1, 0x6a99_76f1, 0x6b19_76f1, 0x6b99_76f1, 0x6c55_da58, 0x6cd5_da58,
        0x6d20_63c2, 0x6d85_a877, 0x6e05_a877, 0x6e85_a877, 0x6f79_be45, 0x6ff9_be45,
        0x7079_be45, 0x70f9_be45, 0x7179_be45, 0x71f9_be45, 0x723f_a09a, 0x72bf_a09a,
        0x733f_a09a, 0x73e6_1c18, 0x7452_de59, 0x74d2_de59, 0x756f_a1dc, 0x7594_9471,
        0x7650_7ce8, 0x76a4_26eb, 0x7758_4625, 0x77d8_4625, 0x7858_4625, 0x78a8_b883,
        0x7940_7f54, 0x79c0_7f54, 0x7a10_5f7f, 0x7afc_cbab, 0x7b16_75c0, 0x7b96_75c0,
        0x7c6c_3305, 0x7cff_01bd, 0x7d7f_01bd, 0x7dff_01bd, 0x7e7f_01bd, 0x7ebd_cda0,
        0x7f3d_cda0,
    ];

    /// The absolute error bound the fast path meets: 2 f32 ulp of 1.
    const BOUND: f64 = 2.4e-7;

    /// xorshift32, for reproducible mantissas.
    fn next(state: &mut u32) -> u32 {
        *state ^= *state << 13;
        *state ^= *state >> 17;
        *state ^= *state << 5;
        *state
    }

    #[test]
    fn fast_path_boundary() {
        let limit = 8192.0f32;
        let around = [
            8191.9,
            f32::from_bits(limit.to_bits() - 1),
            limit,
            f32::from_bits(limit.to_bits() + 1),
            8192.001,
            8193.0,
        ];
        for x in around {
            for x in [x, -x] {
                assert!(error(x) < BOUND, "x = {x:e}: error {:e}", error(x));
            }
        }
    }

    /// Random mantissas in every binade from 2¹³ to f32::MAX, both signs.
    #[test]
    fn large_arguments_every_binade() {
        let mut state = 0x9e37_79b9;
        let mut worst_overall = (0.0f64, 0.0f32);
        for biased in 140..=254u32 {
            let mut worst = 0.0f64;
            let edges = [0, 1, 0x7f_fffe, 0x7f_ffff];
            let random = (0..test_points(2000, 2)).map(|_| next(&mut state) & 0x7f_ffff);
            for mantissa in edges.into_iter().chain(random) {
                let x = f32::from_bits(biased << 23 | mantissa);
                for x in [x, -x] {
                    let e = error(x);
                    worst = worst.max(e);
                    if e > worst_overall.0 {
                        worst_overall = (e, x);
                    }
                }
            }
            assert!(
                worst < BOUND,
                "binade 2^{}: error {worst:e}",
                biased as i32 - 127
            );
        }
        println!(
            "worst error above 8192: {:e} at {:e}",
            worst_overall.0, worst_overall.1
        );
    }

    /// The f32 values closest to multiples of π/2, where the reduced angle is
    /// tiny and an inexact reduction loses its sign or all its digits. The
    /// loop rounds `k · π/2` (f64) to f32 for many large `k` in every binade
    /// and keeps each binade's closest value (and its ulp neighbours). It
    /// finds values some 4e-7 rad from a multiple; [`HARDEST`] adds the
    /// closest of every binade, among them the closest f32 of all,
    /// `16367173 · 2⁷²`, 1.6e-9 rad from one. The small one of sine and
    /// cosine must be accurate relative to its size.
    #[test]
    fn near_multiples_of_pi_over_2() {
        let mut state = 0x2545_f491;
        let mut hard: Vec<f32> = HARDEST.into_iter().map(f32::from_bits).collect();
        assert!(hard.contains(&(16_367_173.0 * 2f32.powi(72))));
        let mut nearest = f64::INFINITY;
        for e in 13..128 {
            // Multiples of π/2 in [2^e, 2^(e+1)).
            let k0 = 2f64.powi(e) / core::f64::consts::FRAC_PI_2;
            let mut closest = (f64::INFINITY, 0.0f32);
            for _ in 0..test_points(2000, 2) {
                let u = f64::from(next(&mut state)) / 2f64.powi(32);
                let k = (k0 * (1.0 + u)).round();
                let x = (k * core::f64::consts::FRAC_PI_2) as f32;
                for x in [
                    x,
                    f32::from_bits(x.to_bits() - 1),
                    f32::from_bits(x.to_bits() + 1),
                ] {
                    if x <= 8192.0 || !x.is_finite() {
                        continue;
                    }
                    let d = f64::from(x).sin().abs().min(f64::from(x).cos().abs());
                    if d < closest.0 {
                        closest = (d, x);
                    }
                    for x in [x, -x] {
                        assert!(error(x) < BOUND, "x = {x:e}: error {:e}", error(x));
                    }
                }
            }
            nearest = nearest.min(closest.0);
            hard.push(closest.1);
        }
        println!("search: closest to a multiple of π/2 {nearest:e}");
        let (mut worst_relative, mut worst) = (0.0f64, 0.0f64);
        for x in hard {
            for x in [x, -x] {
                let (s, c) = sin_cos(x);
                let xd = f64::from(x);
                let (small, exact) = if xd.sin().abs() < xd.cos().abs() {
                    (s, xd.sin())
                } else {
                    (c, xd.cos())
                };
                let relative = (f64::from(small) - exact).abs() / exact.abs();
                worst_relative = worst_relative.max(relative);
                worst = worst.max(error(x));
                assert!(
                    relative < 1e-6 && error(x) < BOUND,
                    "x = {x:e}: {small:e} against {exact:e}"
                );
            }
        }
        println!("near multiples of π/2: error {worst:e}, relative {worst_relative:e}");
    }

    #[test]
    fn non_finite_give_nan() {
        let quiet_payload = f32::from_bits(0x7fc0_1234);
        for x in [
            f32::NAN,
            -f32::NAN,
            quiet_payload,
            f32::INFINITY,
            f32::NEG_INFINITY,
        ] {
            let (s, c) = sin_cos(x);
            assert!(s.is_nan() && c.is_nan(), "{x}");
        }
    }

    /// Every f32 above 8192, both signs: the largest error, and in each
    /// binade the value closest to a multiple of π/2, which must be the one
    /// listed in [`HARDEST`]. Slow (minutes):
    /// `cargo test --release -p rodyn -- --ignored exhaustive`.
    #[test]
    #[ignore]
    fn exhaustive_large_arguments() {
        let threads = std::thread::available_parallelism().map_or(2, |n| n.get() as u32);
        let lo = 8192.0f32.to_bits() + 1;
        let end = f32::MAX.to_bits() + 1;
        let chunk = (end - lo).div_ceil(threads);
        let handles: Vec<_> = (0..threads)
            .map(|t| {
                std::thread::spawn(move || {
                    let mut closest = [(f32::INFINITY, 0u32); 256];
                    let mut worst = (0.0f64, 0.0f32);
                    for b in lo + t * chunk..(lo + (t + 1) * chunk).min(end) {
                        let x = f32::from_bits(b);
                        let y = reduce_large(x).1.abs();
                        let binade = &mut closest[(b >> 23) as usize];
                        if y < binade.0 {
                            *binade = (y, b);
                        }
                        for x in [x, -x] {
                            let e = error(x);
                            if e > worst.0 {
                                worst = (e, x);
                            }
                        }
                    }
                    (closest, worst)
                })
            })
            .collect();
        let mut closest = [(f32::INFINITY, 0u32); 256];
        let mut worst = (0.0f64, 0.0f32);
        for h in handles {
            let (c, w) = h.join().unwrap();
            for (all, c) in closest.iter_mut().zip(c) {
                if c.0 < all.0 {
                    *all = c;
                }
            }
            if w.0 > worst.0 {
                worst = w;
            }
        }
        let hardest: Vec<u32> = closest[140..255].iter().map(|c| c.1).collect();
        let list: Vec<String> = hardest.iter().map(|b| format!("{b:#010x}")).collect();
        println!(
            "closest to a multiple of π/2 per binade: [{}]",
            list.join(", ")
        );
        let overall = closest
            .iter()
            .fold(closest[140], |a, &c| if c.0 < a.0 { c } else { a });
        println!(
            "closest of all: |y| = {:e} at {:e} ({:#x}); worst error {:e} at {:e}",
            overall.0,
            f32::from_bits(overall.1),
            overall.1,
            worst.0,
            worst.1
        );
        assert!(worst.0 < BOUND);
        assert_eq!(hardest, HARDEST);
    }

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
            x += if cfg!(miri) { 0.731 } else { 0.000_731 };
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
