//! What an on-line model update costs on a Cortex-M4F: staging a payload
//! at the Panda's flange in a `rodyn::update::DoubleBuffered` (a copy of
//! the active model, the payload's checks, its inertia moved into the
//! flange's body and added, the sum's checks) and publishing it, and the
//! control tick's read of the active model around an empty closure.
//!
//! Measured as `cost_probe` measures (seeded random inputs, instructions
//! by QEMU `-icount` and SysTick, stack bytes from a painted window), in an
//! image of its own, so that the rows of the other probes keep their
//! inlining. `cargo xtask costs` appends these rows to the cost table.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn::spatial::{Inertia, Sym3, Vec3};
use rodyn::update::{DoubleBuffered, ModelUpdate, ParameterChange};
use rodyn_firmware::exit::{exit, exit_with, CHECK_FAILED};
use rodyn_firmware::measure::{probe_scene, InstructionCounter, STATES};
use rodyn_firmware::models::panda::MODEL_F32 as PANDA;
use rodyn_firmware::models::PANDA_FLANGE;
use rodyn_firmware::rng::XorShift32;
use rodyn_scenarios::payload_scene::PandaModel;

/// A payload of 0.1 to 3 kg whose centre of mass lies within 10 cm of the
/// flange, with a small box's rotational inertia, staged and published;
/// then one read of the active model.
fn probe_update(counter: &InstructionCounter, models: &mut DoubleBuffered<PandaModel>) -> bool {
    let (mut tick, mut writer) = models.split();
    let draw = |rng: &mut XorShift32| {
        let mass = rng.uniform(0.1, 3.0);
        let com = Vec3::new(
            rng.uniform(-0.1, 0.1),
            rng.uniform(-0.1, 0.1),
            rng.uniform(0.0, 0.1),
        );
        let moment = mass * 1.7e-3;
        ModelUpdate::new([ParameterChange::Payload {
            frame: PANDA_FLANGE,
            inertia: Inertia::new(mass, com, Sym3::diagonal(moment, moment, moment)),
        }])
    };
    let update = probe_scene(
        "panda-7dof",
        "model-update(stage+publish)",
        counter,
        draw,
        |update| writer.stage_update(update).is_ok() && writer.publish(),
    );
    let read = probe_scene(
        "panda-7dof",
        "model-read(tick)",
        counter,
        |_| (),
        |()| tick.read(|model| core::hint::black_box(model).inertia(6).mass > 0.0),
    );
    update & read
}

#[entry]
fn main() -> ! {
    let Some(mut peripherals) = cortex_m::Peripherals::take() else {
        exit(CHECK_FAILED)
    };
    let counter = InstructionCounter::start(&mut peripherals.SYST);
    defmt::println!("update_cost_probe: f32, {} random states per call", STATES);
    // Both copies of the model; `main` never returns.
    let mut models = DoubleBuffered::new(PANDA);
    exit_with(probe_update(&counter, &mut models))
}
