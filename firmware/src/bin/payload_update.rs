//! On-line model update: the Panda carries a 2 kg payload its controller
//! does not know. While the arm moves, the controller identifies the
//! payload's mass and centre of mass from the torque residual (least
//! squares on the Newton–Euler regressor), stages the updated model in a
//! `rodyn::update::DoubleBuffered` and publishes it between two ticks.
//! The log shows the tracking error before and after; the example fails
//! (exit code 1) unless the error falls fivefold and the mass is found
//! within 2 %.
//!
//! The scene is `rodyn_scenarios::payload_scene`, which a host test runs
//! too (`crates/rodyn-scenarios/tests/payload_update.rs`).
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn::update::DoubleBuffered;
use rodyn_firmware::exit::{exit, exit_with, CHECK_FAILED};
use rodyn_firmware::measure::InstructionCounter;
use rodyn_scenarios::panda;
use rodyn_scenarios::payload_scene::{PayloadScene, SWAP_AT, TICKS, TRUE_PAYLOAD};

#[entry]
fn main() -> ! {
    let Some(mut peripherals) = cortex_m::Peripherals::take() else {
        exit(CHECK_FAILED)
    };
    let counter = InstructionCounter::start(&mut peripherals.SYST);
    // Both copies of the controller's model; `main` never returns.
    let mut models = DoubleBuffered::new(panda::MODEL_F32);
    let mut scene = match PayloadScene::new(&mut models) {
        Ok(scene) => scene,
        Err(e) => {
            defmt::error!("scene: {}", e);
            exit(CHECK_FAILED)
        }
    };
    defmt::println!(
        "payload_update: Panda with an unknown {} kg payload at the flange, computed torque at 1 kHz; model swapped at tick {} of {}",
        TRUE_PAYLOAD.mass,
        SWAP_AT,
        TICKS
    );
    let mut found = None;
    let mut max_tick = 0u32;
    while !scene.done() {
        let (outcome, instructions) = counter.count(|| scene.step());
        let outcome = match outcome {
            Ok(outcome) => outcome,
            Err(e) => {
                defmt::error!("tick: {}", e);
                exit(CHECK_FAILED)
            }
        };
        max_tick = max_tick.max(instructions);
        if let Some(payload) = outcome.swapped {
            defmt::println!(
                "t = {} ms: identified {} kg, centre of mass {} m in the flange frame (true {} kg, {} m); published",
                outcome.tick,
                payload.mass,
                [payload.com.x, payload.com.y, payload.com.z],
                TRUE_PAYLOAD.mass,
                [TRUE_PAYLOAD.com.x, TRUE_PAYLOAD.com.y, TRUE_PAYLOAD.com.z]
            );
            found = Some(payload);
        }
    }
    let (before, after) = (scene.before, scene.after);
    defmt::println!(
        "tracking error before the swap (0.5-1.5 s): rms {} rad, max {} rad",
        before.rms(),
        before.max
    );
    defmt::println!(
        "tracking error after the swap (2-3 s): rms {} rad, max {} rad",
        after.rms(),
        after.max
    );
    defmt::println!(
        "scene tick (controller, plant, estimator): {} instructions at most",
        max_tick
    );
    let mass_found =
        found.is_some_and(|p| (p.mass - TRUE_PAYLOAD.mass).abs() < 0.02 * TRUE_PAYLOAD.mass);
    let passed = mass_found && after.rms() < 0.2 * before.rms() && after.max < 0.2 * before.max;
    defmt::println!(
        "tracking error fell {}-fold: {=str}",
        before.rms() / after.rms(),
        if passed { "ok" } else { "FAILED" }
    );
    exit_with(passed)
}
