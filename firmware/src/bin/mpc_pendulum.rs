//! Model-predictive control of the seed pendulum on the MCU: iterative LQR
//! over 25 stages of 20 ms (0.5 s ahead), warm-started every tick, on
//! rodyn's analytic derivatives of the pendulum with its return spring
//! (`rodyn_scenarios::pendulum_mpc`), all in f32.
//!
//! The plant is the same pendulum stepped at 1 kHz (ABA and semi-implicit
//! Euler); every 20 ms the controller reads its state, runs one iLQR
//! iteration and holds the first torque of its plan until the next tick.
//! The reference rests hanging, swings to 0.8 rad and back to 0.2 rad. The
//! log reports the tracking error, the largest torque, and the
//! instructions per controller tick (which do not depend on the data) with
//! the control rate a 168 MHz Cortex-M4F would sustain; the run fails when
//! the tracking error exceeds its bounds.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::drive::{forward_dynamics_with_drives, DriveForces};
use rodyn::{Data, Scalar};
use rodyn_firmware::exit::{exit, exit_with, CHECK_FAILED};
use rodyn_firmware::measure::InstructionCounter;
use rodyn_firmware::models::pendulum::{MODEL_F32 as PENDULUM, RETURN_SPRING_F32 as SPRING};
use rodyn_scenarios::pendulum_mpc::{reference, PendulumMpc, STEP, TORQUE_LIMIT};

/// Plant steps of 1 ms per controller tick.
const PLANT_STEPS_PER_TICK: u32 = 20;
/// Controller ticks: 4.5 s.
const TICKS: u32 = 225;
/// Largest accepted tracking error at the ticks (rad).
const MAX_ERROR: f32 = 0.01;
/// Largest accepted error at the end, at rest (rad).
const MAX_FINAL_ERROR: f32 = 0.002;
/// The clock the control rate is stated for (Hz).
const CLOCK_HZ: u32 = 168_000_000;

#[entry]
fn main() -> ! {
    let Some(mut peripherals) = cortex_m::Peripherals::take() else {
        exit(CHECK_FAILED)
    };
    let counter = InstructionCounter::start(&mut peripherals.SYST);
    let dt = STEP as f32 / PLANT_STEPS_PER_TICK as f32;
    let mut mpc = PendulumMpc::new(&PENDULUM, &SPRING);
    let mut data = Data::new();
    let mut forces = DriveForces::new();
    let (mut q, mut v) = ([0.0f32], [0.0f32]);
    defmt::println!(
        "mpc_pendulum: iLQR, 25 stages of {} s, a tick every {} s, plant at 1 kHz, torque limit {} N m",
        STEP as f32,
        STEP as f32,
        TORQUE_LIMIT as f32
    );
    let (mut max_error, mut sum_squares, mut max_torque) = (0.0f32, 0.0f32, 0.0f32);
    let (mut fewest, mut most) = (u32::MAX, 0u32);
    for tick in 0..TICKS {
        let t = STEP as f32 * tick as f32;
        let (result, instructions) = counter.count(|| mpc.tick(t, &[q[0], v[0]]));
        let tau = match result {
            Ok((tau, _)) => tau,
            Err(e) => {
                defmt::error!("tick {}: {}", tick, e);
                exit(CHECK_FAILED)
            }
        };
        // The first tick warms the plan up from zero torques.
        if tick > 0 {
            fewest = fewest.min(instructions);
            most = most.max(instructions);
        }
        max_torque = max_torque.max(tau.abs());
        for _ in 0..PLANT_STEPS_PER_TICK {
            match forward_dynamics_with_drives::<Aba, _, _, _, 1, 1, 1>(
                &PENDULUM,
                &mut data,
                &q,
                &v,
                &[tau],
                &SPRING,
                &[],
                &mut forces,
            ) {
                Ok(ddq) => {
                    v[0] += dt * ddq[0];
                    q[0] += dt * v[0];
                }
                Err(e) => {
                    defmt::error!("plant at tick {}: {}", tick, e);
                    exit(CHECK_FAILED)
                }
            }
        }
        let r = reference::<f32>(t + STEP as f32);
        let error = (q[0] - r[0]).abs();
        max_error = max_error.max(error);
        sum_squares += error * error;
        if (tick + 1) % 50 == 0 {
            defmt::println!(
                "t = {} s: q = {} rad (reference {}), tau = {} N m",
                t + STEP as f32,
                q[0],
                r[0],
                tau
            );
        }
    }
    let rms = (sum_squares / TICKS as f32).sqrt();
    let final_error = (q[0] - reference::<f32>(STEP as f32 * TICKS as f32)[0]).abs();
    defmt::println!(
        "tracking error: max {} rad, rms {} rad, final {} rad; largest torque {} N m",
        max_error,
        rms,
        final_error,
        max_torque
    );
    defmt::println!("controller tick: {} - {} instructions", fewest, most);
    defmt::println!("at 168 MHz: {} ticks per second", CLOCK_HZ / most.max(1));
    let passed = max_error <= MAX_ERROR && final_error <= MAX_FINAL_ERROR;
    defmt::println!(
        "max tracking error {} rad, final {} rad (bounds {}, {}): {=str}",
        max_error,
        final_error,
        MAX_ERROR,
        MAX_FINAL_ERROR,
        if passed { "ok" } else { "FAILED" }
    );
    exit_with(passed)
}
