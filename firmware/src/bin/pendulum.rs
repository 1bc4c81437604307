//! The seed pendulum with its return spring, simulated in real time on the MCU.
//!
//! A 0.5 m, 1 kg rod, pulled by a spring from its tip to an anchor beside
//! the pivot (rodyn's drives: the spring's tension becomes an external force
//! on the rod), is released from 1 rad and swings for 2 s of simulated time,
//! stepped at 1 kHz by ABA and semi-implicit Euler. SysTick paces the loop
//! to real time (one step per millisecond); the log reports the load of the
//! step on the 1 ms budget, missed deadlines, and the energy drift, which
//! must stay below 1 % (the check that sets the exit code).
#![no_std]
#![no_main]

use cortex_m::peripheral::syst::SystClkSource;
use cortex_m::peripheral::SYST;
use cortex_m_rt::entry;
use rodyn::algorithm::energy::{kinetic_energy, potential_energy};
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::drive::{forward_dynamics_with_drives, DriveForces};
use rodyn::Data;
use rodyn_firmware::exit::{exit, exit_with, CHECK_FAILED};
use rodyn_firmware::models::pendulum::{
    MODEL_F32 as PENDULUM, RETURN_SPRING_F32 as PENDULUM_SPRING,
};

/// SysTick counts per millisecond: mps2-an386's SysTick runs at 25 MHz.
const TICKS_PER_STEP: u32 = 25_000;
/// Step (s), equal to the real-time period.
const DT: f32 = 1.0e-3;
/// Steps simulated: 2 s.
const STEPS: u32 = 2_000;
/// Largest accepted drift of the total energy (kinetic, gravity, spring),
/// relative to `|E(q₀, 0) - E(0, 0)|`, the energy difference between the
/// release and the hanging position.
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
        let mechanical =
            kinetic_energy(&PENDULUM, data, q, v)? + potential_energy(&PENDULUM, data, q)?;
        // potential_energy leaves the body poses valid for the spring's path.
        let length = PENDULUM_SPRING.path.kinematics(data)?.length;
        Ok(mechanical + PENDULUM_SPRING.potential_energy(length)?)
    };
    let (Ok(e0), Ok(e_bottom)) = (energy(&mut data, &q, &v), energy(&mut data, &[0.0], &[0.0]))
    else {
        exit(CHECK_FAILED)
    };
    let swing = (e0 - e_bottom).abs();
    let mut forces = DriveForces::new();
    defmt::println!(
        "pendulum with return spring: q0 = {} rad, 1 kHz real time, {} steps",
        q[0],
        STEPS
    );

    let (mut missed, mut busiest, mut max_drift) = (0u32, 0u32, 0.0f32);
    for step in 1..=STEPS {
        // Wait for the next period; a flag already set means the last step overran.
        if syst.has_wrapped() {
            missed += 1;
        } else {
            while !syst.has_wrapped() {}
        }
        let step_result = forward_dynamics_with_drives::<Aba, _, _, _, 1, 1, 1>(
            &PENDULUM,
            &mut data,
            &q,
            &v,
            &[0.0],
            &PENDULUM_SPRING,
            &[],
            &mut forces,
        );
        match step_result {
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
    defmt::println!(
        "step load: {} % of the 1 ms budget, missed deadlines: {}",
        load_percent,
        missed
    );
    let passed = max_drift <= MAX_ENERGY_DRIFT && missed == 0;
    defmt::println!(
        "energy drift: {} of |E(q0) - E(0)| (bound {}): {=str}",
        max_drift,
        MAX_ENERGY_DRIFT,
        if passed { "ok" } else { "FAILED" }
    );
    exit_with(passed)
}
