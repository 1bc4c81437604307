//! The Aibo-size quadruped trotting on the MCU with rigid feet and a
//! controller that holds its trunk: both halves of a model-based legged
//! robot in f32 at 1 kHz.
//!
//! - **Controller** (`quadruped_balance::TrunkController`): every tick,
//!   inverse dynamics with the touching feet as contacts gives the joint
//!   torques that keep the trunk at its stance height, level and heading
//!   forward, while the swing legs follow the trot (3 Hz, diagonal pairs).
//! - **Plant** (`rodyn::sim::time_stepping`): rigid point feet on the
//!   ground with Coulomb friction (μ = 0.8), one Moreau–Jean step of 1 ms
//!   per tick with the drives' joint damping taken implicitly; it also
//!   tells the controller which feet touch, as foot switches would.
//!
//! The trot lasts [`TROT_SECONDS`]; the run fails if the trunk's height
//! leaves its target by more than [`MAX_HEIGHT_ERROR`], if it tilts past
//! [`MIN_UPRIGHT`], or if it walks less than [`MIN_DISTANCE`]. The log
//! reports height, tilt and distance every half second.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn::sim::time_stepping::time_step;
use rodyn::Data;
use rodyn_firmware::exit::{exit, exit_with, CHECK_FAILED};
use rodyn_firmware::models::aibo::{self, MODEL_F32};
use rodyn_firmware::models::quadruped::{self, RigidContactData, LEGS};
use rodyn_scenarios::quadruped_balance::{TrunkController, TrunkControllerData};

/// Ticks per second.
const RATE_HZ: u32 = 1_000;
/// Tick (s).
const DT: f32 = 1.0 / RATE_HZ as f32;
/// Ticks per logged sample: 0.5 s.
const LOG_EVERY: u32 = RATE_HZ / 2;
/// Time trotting (s).
const TROT_SECONDS: u32 = 3;
/// Largest departure of the trunk from its target height (m); the host's
/// f64 runs stay within 4.1 mm.
const MAX_HEIGHT_ERROR: f32 = 6.0e-3;
/// Least cosine of the trunk's tilt (0.14 rad); the host's runs stay
/// above 0.9935.
const MIN_UPRIGHT: f32 = 0.99;
/// Least forward distance (m); the host's runs cover 0.85 m in 3 s.
const MIN_DISTANCE: f32 = 0.5;

/// Logs `error` with the model file's name of what it is about (a joint,
/// a coordinate, a body), when it names one.
fn report(stage: &str, tick: u32, error: &rodyn::Error) {
    match aibo::Named(error).subject() {
        Some((kind, name)) => {
            defmt::error!(
                "{=str}, tick {}: {=str} {=str}: {}",
                stage,
                tick,
                kind,
                name,
                error
            )
        }
        None => defmt::error!("{=str}, tick {}: {}", stage, tick, error),
    }
}

#[entry]
fn main() -> ! {
    let controller = TrunkController::<f32>::trotting();
    let ground = quadruped::rigid_ground::<f32>();
    let damping = controller.joint_damping();
    let feet = quadruped::foot_frames::<f32>();
    let mut state = controller.gait.initial_state(controller.height);
    let mut data = Data::new();
    let mut contact = RigidContactData::<f32>::new();
    let mut control = TrunkControllerData::<f32>::new();
    let mut touching = [true; LEGS];
    defmt::println!(
        "quadruped_rigid (aibo.toml, {} kg): trunk held at {} m, rigid feet, mu = {}, dt = {} s",
        MODEL_F32.total_mass(),
        controller.height,
        ground.friction,
        DT
    );

    let (mut worst_height, mut least_upright) = (0.0f32, 1.0f32);
    for tick in 1..=TROT_SECONDS * RATE_HZ {
        let tau = match controller.torques(
            &MODEL_F32,
            &mut data,
            &mut control,
            state.t,
            &state.q,
            &state.v,
            &touching,
        ) {
            Ok(tau) => *tau,
            Err(e) => {
                report("controller", tick, &e);
                exit(CHECK_FAILED)
            }
        };
        if let Err(e) = time_step(
            &MODEL_F32,
            &mut data,
            &mut contact,
            &mut state,
            &tau,
            &damping,
            &feet,
            &ground,
            DT,
        ) {
            report("plant", tick, &e);
            exit(CHECK_FAILED)
        }
        touching = contact.impulses.map(|i| i.z > 0.0);
        let trunk = quadruped::trunk_position(&state.q);
        // The trunk's z axis, world z component: cos of its tilt.
        let upright = 1.0 - 2.0 * (state.q[3] * state.q[3] + state.q[4] * state.q[4]);
        worst_height = worst_height.max((trunk.z - controller.height).abs());
        least_upright = least_upright.min(upright);
        if tick % LOG_EVERY == 0 {
            defmt::println!(
                "t = {} ms: height {} m, cos tilt {}, forward {} m, feet down {}",
                tick * 1_000 / RATE_HZ,
                trunk.z,
                upright,
                trunk.x,
                touching.iter().filter(|t| **t).count()
            );
        }
    }
    let distance = quadruped::trunk_position(&state.q).x;
    let held = worst_height < MAX_HEIGHT_ERROR && least_upright > MIN_UPRIGHT;
    let walked = distance > MIN_DISTANCE;
    defmt::println!(
        "trot: height within {} m (at most {}), cos tilt at least {} (at least {}), {} m forward (at least {}): {=str}",
        worst_height,
        MAX_HEIGHT_ERROR,
        least_upright,
        MIN_UPRIGHT,
        distance,
        MIN_DISTANCE,
        if held && walked { "ok" } else { "FAILED" }
    );
    exit_with(held && walked)
}
