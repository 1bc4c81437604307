//! A rodyn firmware to start from.
//!
//! The arm of `models/arm.toml` follows a smooth joint trajectory in a
//! 1 kHz loop paced by SysTick. Each tick computes
//! - the joint torques that produce the trajectory's acceleration: RNEA,
//!   inverse dynamics, what a computed-torque controller sends to its drives;
//! - the accelerations those torques produce: ABA, forward dynamics, what a
//!   simulation or an observer needs.
//!
//! After [`TICKS`] ticks the firmware checks the two against each other and
//! against the arm's energy, logs the result through defmt and ends QEMU
//! with exit code 0 (every check passed) or 1. Replace the trajectory with
//! your sensors and drives, and the fixed number of ticks with `loop {}`.
#![no_std]
#![no_main]

use core::sync::atomic::{AtomicBool, Ordering};
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m::peripheral::SYST;
use cortex_m_rt::entry;
use defmt_semihosting as _; // the global defmt logger (defmt_rtt on a board)
use rodyn::algorithm::aba::aba;
use rodyn::algorithm::energy::{kinetic_energy, potential_energy};
use rodyn::algorithm::rnea::rnea;
use rodyn::{Data, Scalar};

// `mod arm`, compiled from models/arm.toml by build.rs: `MODEL_F32`,
// `MODEL_F64`, the sizes `NB`, `NQ`, `NV` and named indices.
include!(concat!(env!("OUT_DIR"), "/arm.rs"));
use arm::{MODEL_F32 as ARM, NB, NV};

/// SysTick's clock (Hz): the core clock, 25 MHz on QEMU's mps2-an386. Set
/// your chip's.
const CORE_CLOCK_HZ: u32 = 25_000_000;
/// The control rate (Hz).
const LOOP_HZ: u32 = 1_000;
/// SysTick counts per tick.
const COUNTS_PER_TICK: u32 = CORE_CLOCK_HZ / LOOP_HZ;
/// The period (s).
const DT: f32 = 1.0 / LOOP_HZ as f32;
/// Ticks before the checks and the exit: 2 s.
const TICKS: u32 = 2_000;
/// Ticks between two log lines.
const LOG_EVERY: u32 = 500;

/// Largest accepted |ABA(RNEA(q, v, a)) - a| (rad/s²): f32 round-off on
/// accelerations of up to 25 rad/s² stays below 1e-4.
const ACCELERATION_TOLERANCE: f32 = 1.0e-3;
/// Largest accepted difference between the work of RNEA's torques and the
/// change of the arm's energy, as a fraction of the work's magnitude
/// `∫ |vᵀτ| dt` (the trapezoid rule at 1 kHz and f32 sums leave less than 1e-5).
const ENERGY_TOLERANCE: f32 = 1.0e-3;

/// The reference: each joint swings about `OFFSET` with amplitude
/// `AMPLITUDE` (rad) at angular frequency `OMEGA` (rad/s).
const OFFSET: [f32; NV] = [0.0, -0.4, 0.8];
const AMPLITUDE: [f32; NV] = [0.8, 0.6, 1.0];
const OMEGA: [f32; NV] = [2.0, 3.0, 5.0];

/// Exit codes: QEMU ends with them, and so does `cargo run`.
const SUCCESS: i32 = 0;
const CHECK_FAILED: i32 = 1;
const PANICKED: i32 = 101;

/// Position, velocity and acceleration of the reference at `t` (s).
fn reference(t: f32) -> ([f32; NV], [f32; NV], [f32; NV]) {
    let joint: [(f32, f32, f32); NV] = core::array::from_fn(|i| {
        let (s, c) = (OMEGA[i] * t).sin_cos();
        let (amplitude, omega) = (AMPLITUDE[i], OMEGA[i]);
        (
            OFFSET[i] + amplitude * s,
            amplitude * omega * c,
            -amplitude * omega * omega * s,
        )
    });
    (joint.map(|j| j.0), joint.map(|j| j.1), joint.map(|j| j.2))
}

/// The power of the torques `τ` at velocity `v` (W).
fn power(v: &[f32; NV], tau: &[f32; NV]) -> f32 {
    v.iter().zip(tau).map(|(v, tau)| v * tau).sum()
}

#[entry]
fn main() -> ! {
    let Some(peripherals) = cortex_m::Peripherals::take() else {
        exit(CHECK_FAILED)
    };
    let mut syst = peripherals.SYST;
    syst.set_clock_source(SystClkSource::Core);
    syst.set_reload(COUNTS_PER_TICK - 1);
    syst.clear_current();
    syst.enable_counter();

    // rodyn's work space: every algorithm writes into it, nothing is allocated.
    let mut data = Data::new();
    let (q, v, a) = reference(0.0);
    let (Ok(e_start), Ok(tau)) = (
        energy(&mut data, &q, &v),
        rnea(&ARM, &mut data, &q, &v, &a, None).copied(),
    ) else {
        defmt::error!("the dynamics failed at the start");
        exit(CHECK_FAILED)
    };
    let mut last_power = power(&v, &tau);
    defmt::println!(
        "arm with {} joints, {} Hz loop, {} ticks",
        NV,
        LOOP_HZ,
        TICKS
    );

    let (mut work, mut work_magnitude) = (0.0f32, 0.0f32);
    let (mut worst_acceleration_error, mut missed, mut busiest) = (0.0f32, 0u32, 0u32);
    for tick in 1..=TICKS {
        // Wait for the next period; a flag already set means the last tick overran.
        if syst.has_wrapped() {
            missed += 1;
        } else {
            while !syst.has_wrapped() {}
        }
        let t = tick as f32 * DT;
        let (q, v, a) = reference(t);

        let tau = match rnea(&ARM, &mut data, &q, &v, &a, None) {
            Ok(tau) => *tau,
            Err(e) => {
                defmt::error!("tick {}: RNEA: {}", tick, e);
                exit(CHECK_FAILED)
            }
        };
        let ddq = match aba(&ARM, &mut data, &q, &v, &tau, None) {
            Ok(ddq) => *ddq,
            Err(e) => {
                defmt::error!("tick {}: ABA: {}", tick, e);
                exit(CHECK_FAILED)
            }
        };
        for (ddq, a) in ddq.iter().zip(&a) {
            worst_acceleration_error = worst_acceleration_error.max((ddq - a).abs());
        }
        // The torques' work by the trapezoid rule.
        let p = power(&v, &tau);
        work += 0.5 * (last_power + p) * DT;
        work_magnitude += 0.5 * (last_power.abs() + p.abs()) * DT;
        last_power = p;

        busiest = busiest.max(COUNTS_PER_TICK - SYST::get_current());
        if tick % LOG_EVERY == 0 {
            defmt::println!("t = {} ms: q = {} rad, tau = {} N m", tick, q, tau);
        }
    }

    let (q, v, _) = reference(TICKS as f32 * DT);
    let Ok(e_end) = energy(&mut data, &q, &v) else {
        defmt::error!("the energy failed at the end");
        exit(CHECK_FAILED)
    };
    let energy_change = e_end - e_start;
    let mismatch = (work - energy_change).abs() / work_magnitude;
    let rnea_ok = mismatch <= ENERGY_TOLERANCE;
    let aba_ok = worst_acceleration_error <= ACCELERATION_TOLERANCE;
    let on_time = missed == 0;
    defmt::println!(
        "rnea {=str}: the torques' work {} J = the energy change {} J within {} of {} J (bound {})",
        verdict(rnea_ok),
        work,
        energy_change,
        mismatch,
        work_magnitude,
        ENERGY_TOLERANCE
    );
    defmt::println!(
        "aba {=str}: ABA(RNEA(q, v, a)) = a within {} rad/s2 (bound {})",
        verdict(aba_ok),
        worst_acceleration_error,
        ACCELERATION_TOLERANCE
    );
    defmt::println!(
        "loop {=str}: busiest tick {} of {} SysTick counts, {} missed",
        verdict(on_time),
        busiest,
        COUNTS_PER_TICK,
        missed
    );
    exit(if rnea_ok && aba_ok && on_time {
        SUCCESS
    } else {
        CHECK_FAILED
    })
}

/// The arm's kinetic plus potential energy (J).
fn energy(data: &mut Data<f32, NB, NV>, q: &[f32; NV], v: &[f32; NV]) -> rodyn::Result<f32> {
    Ok(kinetic_energy(&ARM, data, q, v)? + potential_energy(&ARM, data, q)?)
}

fn verdict(passed: bool) -> &'static str {
    if passed {
        "ok"
    } else {
        "FAILED"
    }
}

/// Ends QEMU with `code` through semihosting. On a board without a debugger
/// this call traps: reset there instead (`cortex_m::peripheral::SCB::sys_reset`).
fn exit(code: i32) -> ! {
    semihosting::process::exit(code)
}

/// Set by the first panic: a panic inside the handler's own log line exits
/// at once instead of entering the handler again.
static PANICKING: AtomicBool = AtomicBool::new(false);

#[panic_handler]
fn panic(info: &core::panic::PanicInfo<'_>) -> ! {
    if !PANICKING.swap(true, Ordering::Relaxed) {
        match info.location() {
            Some(at) => defmt::error!("panic at {=str}:{=u32}", at.file(), at.line()),
            None => defmt::error!("panic"),
        }
    }
    exit(PANICKED)
}

/// Where `defmt::panic!` and failed `defmt::assert!`s end.
#[defmt::panic_handler]
fn defmt_panic() -> ! {
    exit(PANICKED)
}
