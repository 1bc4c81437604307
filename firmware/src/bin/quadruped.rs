//! The Aibo-size quadruped of `models/aibo.toml` in f32 on the MCU: it
//! falls onto the ground, comes to rest standing, then trots open-loop.
//!
//! The trunk is dropped 3 cm above its stance height with the legs PD-held
//! in the stance pose; after [`STAND_SECONDS`] it must be at rest within
//! 5 mm of the stance height. Then the legs follow the open-loop trot
//! (3 Hz, diagonal pairs) for [`TROT_SECONDS`]; the trunk must move at least
//! [`MIN_TROT_DISTANCE`] forward and stay upright. Compliant contact at the
//! four feet (the model file's ground: 5 kN/m, 50 N s/m, μ = 0.8), ABA and
//! `rodyn::sim`'s semi-implicit Euler at 0.5 ms: that ground's damping on
//! 50 g shanks makes 1 ms steps bounce. The log reports the trunk's height
//! and forward distance every half second; the checks set the exit code.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::sim::SemiImplicitEuler;
use rodyn::Data;
use rodyn_firmware::exit::{exit, exit_with, CHECK_FAILED};
use rodyn_firmware::models::aibo::MODEL_F32;
use rodyn_firmware::models::quadruped::{self, QuadrupedLoads, QuadrupedState};

/// Steps per simulated second.
const RATE_HZ: u32 = 2_000;
/// Step (s).
const DT: f32 = 1.0 / RATE_HZ as f32;
/// Steps per logged sample: 0.5 s.
const LOG_EVERY: u32 = RATE_HZ / 2;
/// Time to land and settle (s).
const STAND_SECONDS: u32 = 2;
/// Time trotting (s).
const TROT_SECONDS: u32 = 3;
/// Height the trunk is dropped from, above its stance height (m).
const DROP: f32 = 0.03;
/// Settled: every trunk and joint rate below this (m/s, rad/s).
const MAX_REST_SPEED: f32 = 1.0e-3;
/// Settled: trunk height within this of the stance height (m); the legs
/// give a little under the PD gains and the feet sink about 1 mm.
const MAX_STANCE_ERROR: f32 = 5.0e-3;
/// Smallest forward distance of the trot (m); the host's f64 run of the
/// same trot covers about 0.8 m.
const MIN_TROT_DISTANCE: f32 = 0.5;
/// Upright: trunk above the knees (m), tilted less than 10° (cos of the half angle).
const MIN_TROT_HEIGHT: f32 = 0.09;
const MIN_UPRIGHT_W: f32 = 0.996;

/// Runs `steps` steps, logging every [`LOG_EVERY`]; exits on an error.
/// `start_ms` is the run's time at the phase's start (for the pose log).
fn simulate(
    phase: &str,
    start_ms: u32,
    steps: u32,
    loads: &mut QuadrupedLoads<f32>,
    state: &mut QuadrupedState<f32>,
    data: &mut Data<f32, { quadruped::NB }, { quadruped::NV }>,
) {
    let mut euler = SemiImplicitEuler::default();
    for step in 1..=steps {
        if let Err(e) = quadruped::step(&mut euler, Aba, &MODEL_F32, data, loads, state, DT) {
            defmt::error!("{=str} step {}: {}", phase, step, e);
            exit(CHECK_FAILED)
        }
        if step % (RATE_HZ / 1_000) == 0 {
            rodyn_firmware::pose_log::log_pose(start_ms + step * 1_000 / RATE_HZ, &state.q);
        }
        if step % LOG_EVERY == 0 {
            let trunk = quadruped::trunk_position(&state.q);
            defmt::println!(
                "{=str} t = {} ms: height {} m, forward {} m",
                phase,
                step * 1_000 / RATE_HZ,
                trunk.z,
                trunk.x
            );
        }
    }
}

#[entry]
fn main() -> ! {
    let mut loads = QuadrupedLoads::<f32>::standing();
    let stance = loads.stance_height();
    let mut state = loads.initial_state(stance + DROP);
    let mut data = Data::new();
    defmt::println!(
        "quadruped (aibo.toml, {} kg): dropped from {} m, stance height {} m, dt = {} s",
        MODEL_F32.total_mass(),
        stance + DROP,
        stance,
        DT
    );

    rodyn_firmware::pose_log::log_pose(0, &state.q);
    simulate(
        "stand",
        0,
        STAND_SECONDS * RATE_HZ,
        &mut loads,
        &mut state,
        &mut data,
    );
    let speed = state.v.iter().fold(0.0f32, |m, v| m.max(v.abs()));
    let height = quadruped::trunk_position(&state.q).z;
    let support: f32 = loads.reports.iter().map(|r| r.force.z).sum();
    let at_rest = speed < MAX_REST_SPEED && (height - stance).abs() < MAX_STANCE_ERROR;
    defmt::println!(
        "at rest: height {} m (stance {} m), fastest rate {}, support {} N: {=str}",
        height,
        stance,
        speed,
        support,
        if at_rest { "ok" } else { "FAILED" }
    );

    // The trot's clock starts with the gait (its amplitudes ramp up over
    // the first stride).
    loads.gait = QuadrupedLoads::<f32>::trotting().gait;
    state.t = 0.0;
    let start = quadruped::trunk_position(&state.q).x;
    simulate(
        "trot",
        STAND_SECONDS * 1_000,
        TROT_SECONDS * RATE_HZ,
        &mut loads,
        &mut state,
        &mut data,
    );
    let trunk = quadruped::trunk_position(&state.q);
    let distance = trunk.x - start;
    let upright = trunk.z > MIN_TROT_HEIGHT && state.q[6] > MIN_UPRIGHT_W;
    let trotted = distance > MIN_TROT_DISTANCE && upright;
    defmt::println!(
        "trot: {} m forward in {} s (at least {}), height {} m, w = {}: {=str}",
        distance,
        TROT_SECONDS,
        MIN_TROT_DISTANCE,
        trunk.z,
        state.q[6],
        if trotted { "ok" } else { "FAILED" }
    );
    exit_with(at_rest && trotted)
}
