//! A plain timing loop for the measuring binaries (criterion times the benches).

use std::hint::black_box;
use std::time::Instant;

/// Nanoseconds per call of `f(k)`, for `calls` calls cycling `k` over
/// `0..states`: each call sees a different state, as in a control loop.
pub fn ns_per_call<R>(calls: usize, states: usize, mut f: impl FnMut(usize) -> R) -> f64 {
    let start = Instant::now();
    for k in 0..calls {
        black_box(f(black_box(k % states)));
    }
    start.elapsed().as_nanos() as f64 / calls as f64
}

/// Calls needed for one measurement of about `target_ns`, from a short probe.
pub fn calls_for<R>(target_ns: f64, states: usize, mut f: impl FnMut(usize) -> R) -> usize {
    let mut calls = 16;
    loop {
        let per_call = ns_per_call(calls, states, &mut f);
        if per_call * calls as f64 > 2.0e6 || calls >= 1 << 24 {
            return ((target_ns / per_call.max(1.0)) as usize).clamp(16, 1 << 26);
        }
        calls *= 4;
    }
}

/// The median of `values` (which it sorts); NaN for an empty slice.
pub fn median(values: &mut [f64]) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    values.sort_by(f64::total_cmp);
    let mid = values.len() / 2;
    if values.len() % 2 == 1 {
        values[mid]
    } else {
        0.5 * (values[mid - 1] + values[mid])
    }
}

/// Nanoseconds per call of `f(k)` over about `ms` milliseconds, median of
/// five measurements (the loop of `bench_timing.hpp` on Pinocchio's side).
pub fn median_ns<R>(ms: f64, states: usize, mut f: impl FnMut(usize) -> R) -> f64 {
    let calls = calls_for(ms * 1e6, states, &mut f);
    let mut runs: Vec<f64> = (0..5).map(|_| ns_per_call(calls, states, &mut f)).collect();
    median(&mut runs)
}
