//! The seed pendulum, simulated in real time on the MCU.
//!
//! A 0.5 m, 1 kg rod released from 1 rad swings for 2 s of simulated time,
//! stepped at 1 kHz by ABA and semi-implicit Euler. SysTick paces the loop
//! to real time (one step per millisecond); the log reports the load of the
//! step on the 1 ms budget, missed deadlines, and the energy drift, which
//! must stay below 1 % (the check that sets the exit code).
//!
//! The return spring of the seed paper follows once rodyn's drives module
//! is available to firmware.
#![no_std]
#![no_main]

use cortex_m::peripheral::syst::SystClkSource;
use cortex_m::peripheral::SYST;
use cortex_m_rt::entry;
use rodyn::algorithm::aba::aba;
use rodyn::algorithm::energy::{kinetic_energy, potential_energy};
use rodyn::Data;
use rodyn_firmware::exit::{exit, exit_with, CHECK_FAILED};
use rodyn_firmware::models::PENDULUM;

/// SysTick counts per millisecond: mps2-an386's SysTick runs at 25 MHz.
const TICKS_PER_STEP: u32 = 25_000;
/// Step (s), equal to the real-time period.
const DT: f32 = 1.0e-3;
/// Steps simulated: 2 s.
const STEPS: u32 = 2_000;
/// Largest accepted drift of the total energy, relative to the initial
/// potential energy measured from the lowest point, `m g l/2 (1 - cos q₀)`.
const MAX_ENERGY_DRIFT: f32 = 0.01;

#[entry]
fn main() -> ! {
    let Some(peripherals) = cortex_m::Peripherals::take() else {
        exit(CHECK_FAILED)
    };
    let mut syst = peripherals.SYST;
    syst.set_clock_source(SystClkSource::Core);
    syst.set_reload(TICKS_PER_STEP - 1);
    syst.clear_current();
    syst.enable_counter();

    let mut data = Data::new();
    let (mut q, mut v) = ([1.0f32], [0.0f32]);
    let energy = |data: &mut Data<f32, 1, 1>, q: &[f32; 1], v: &[f32; 1]| -> rodyn::Result<f32> {
        Ok(kinetic_energy(&PENDULUM, data, q, v)? + potential_energy(&PENDULUM, data, q)?)
    };
    let (Ok(e0), Ok(e_bottom)) = (energy(&mut data, &q, &v), energy(&mut data, &[0.0], &[0.0]))
    else {
        exit(CHECK_FAILED)
    };
    let swing = e0 - e_bottom;
    defmt::println!("pendulum: q0 = {} rad, 1 kHz real time, {} steps", q[0], STEPS);

    let (mut missed, mut busiest, mut max_drift) = (0u32, 0u32, 0.0f32);
    for step in 1..=STEPS {
        // Wait for the next period; a flag already set means the last step overran.
        if syst.has_wrapped() {
            missed += 1;
        } else {
            while !syst.has_wrapped() {}
        }
        match aba(&PENDULUM, &mut data, &q, &v, &[0.0], None) {
            Ok(ddq) => {
                v[0] += DT * ddq[0];
                q[0] += DT * v[0];
            }
            Err(e) => {
                defmt::error!("step {}: {}", step, e);
                exit(CHECK_FAILED)
            }
        }
        busiest = busiest.max(TICKS_PER_STEP - SYST::get_current());
        if let Ok(e) = energy(&mut data, &q, &v) {
            max_drift = max_drift.max(((e - e0) / swing).abs());
        }
        if step % 500 == 0 {
            defmt::println!("t = {} ms: q = {} rad, v = {} rad/s", step, q[0], v[0]);
        }
    }
    let load_percent = 100 * busiest / TICKS_PER_STEP;
    defmt::println!("step load: {} % of the 1 ms budget, missed deadlines: {}", load_percent, missed);
    let passed = max_drift <= MAX_ENERGY_DRIFT && missed == 0;
    defmt::println!(
        "energy drift: {} of the swing energy (bound {}): {=str}",
        max_drift,
        MAX_ENERGY_DRIFT,
        if passed { "ok" } else { "FAILED" }
    );
    exit_with(passed)
}
