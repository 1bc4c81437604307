//! What each rodyn algorithm costs on a Cortex-M4F, per model.
//!
//! For every model and algorithm, [`STATES`] random states (seeded
//! xorshift) are fed to one call each; the log reports the minimum and
//! maximum instructions per call (QEMU `-icount shift=6` and SysTick, see
//! `measure`) and the most stack bytes a call used (painted window). Equal
//! minimum and maximum mean the cost does not depend on the data.
//! `cargo xtask costs` turns the log into the table of the README.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn::algorithm::crba::crba;
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::algorithm::rnea::rnea;
use rodyn::space::Space;
use rodyn::{Data, Model, Scalar};
use rodyn_firmware::exit::{exit, exit_with, CHECK_FAILED};
use rodyn_firmware::measure::{stack_bytes, InstructionCounter};
use rodyn_firmware::models::aibo::MODEL_F32 as QUADRUPED;
use rodyn_firmware::models::panda::MODEL_F32 as PANDA;
use rodyn_firmware::models::pendulum::MODEL_F32 as PENDULUM;
use rodyn_firmware::models::PENDULUM_PLANAR;
use rodyn_firmware::rng::XorShift32;

/// Random states per model and algorithm.
const STATES: u32 = 100;
/// Seed of the state generator.
const SEED: u32 = 0x5EED_0001;

/// The algorithms probed, as they appear in the table.
#[derive(Clone, Copy)]
enum Algorithm {
    Rnea,
    Crba,
    CrbaForwardDynamics,
    Aba,
}

impl Algorithm {
    const ALL: [Self; 4] = [Self::Rnea, Self::Crba, Self::CrbaForwardDynamics, Self::Aba];
    fn name(self) -> &'static str {
        match self {
            Self::Rnea => "RNEA",
            Self::Crba => "CRBA",
            Self::CrbaForwardDynamics => "CRBA+LTDL-FD",
            Self::Aba => "ABA",
        }
    }
}

/// Min and max instructions and max stack over random states.
struct Cost {
    min: u32,
    max: u32,
    stack: Option<u32>,
}

/// Probes every algorithm on `model`, printing one `cost` line each
/// (`name` without spaces: the xtask splits the line at whitespace).
/// Returns false when an algorithm failed.
fn probe<const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    name: &str,
    model: &Model<f32, NB, NQ, NV, G>,
    counter: &InstructionCounter,
) -> bool {
    let mut data = Data::<f32, NB, NV, G>::new();
    for algorithm in Algorithm::ALL {
        let mut rng = XorShift32::new(SEED);
        let mut cost = Cost {
            min: u32::MAX,
            max: 0,
            stack: Some(0),
        };
        for _ in 0..STATES {
            let mut q = [0.0f32; NQ];
            rng.fill_symmetric(&mut q, core::f32::consts::PI);
            model.normalize(&mut q);
            let mut v = [0.0f32; NV];
            rng.fill_symmetric(&mut v, 2.0);
            let mut u = [0.0f32; NV];
            rng.fill_symmetric(&mut u, 5.0);
            let mut call = || -> bool {
                match algorithm {
                    Algorithm::Rnea => rnea(model, &mut data, &q, &v, &u, None).is_ok(),
                    Algorithm::Crba => crba(model, &mut data, &q).is_ok(),
                    Algorithm::CrbaForwardDynamics => {
                        Crba::forward_dynamics(model, &mut data, &q, &v, &u, None).is_ok()
                    }
                    Algorithm::Aba => {
                        Aba::forward_dynamics(model, &mut data, &q, &v, &u, None).is_ok()
                    }
                }
            };
            let (ok, instructions) = counter.count(&mut call);
            let (ok_again, stack) = stack_bytes(&mut call);
            if !(ok && ok_again) {
                defmt::error!(
                    "{=str} {=str}: the algorithm returned an error",
                    name,
                    algorithm.name()
                );
                return false;
            }
            cost.min = cost.min.min(instructions);
            cost.max = cost.max.max(instructions);
            cost.stack = match (cost.stack, stack) {
                (Some(a), Some(b)) => Some(a.max(b)),
                _ => None,
            };
        }
        match cost.stack {
            Some(stack) => defmt::println!(
                "cost model={=str} algorithm={=str} min={} max={} stack={}",
                name,
                algorithm.name(),
                cost.min,
                cost.max,
                stack
            ),
            None => defmt::println!(
                "cost model={=str} algorithm={=str} min={} max={} stack=>16384",
                name,
                algorithm.name(),
                cost.min,
                cost.max
            ),
        }
    }
    true
}

/// One f32 `sin_cos` as rodyn's scalar computes it without std (libm): every
/// revolute joint pays it once per call of an algorithm.
fn sin_cos_cost(counter: &InstructionCounter) {
    let mut rng = XorShift32::new(SEED);
    let (mut min, mut max) = (u32::MAX, 0);
    for _ in 0..STATES {
        let angle = rng.uniform(-core::f32::consts::PI, core::f32::consts::PI);
        let (_, instructions) = counter.count(|| core::hint::black_box(angle).sin_cos());
        min = min.min(instructions);
        max = max.max(instructions);
    }
    defmt::println!(
        "cost model=scalar algorithm=f32-sin_cos min={} max={} stack=-",
        min,
        max
    );
}

#[entry]
fn main() -> ! {
    let Some(mut peripherals) = cortex_m::Peripherals::take() else {
        exit(CHECK_FAILED)
    };
    let counter = InstructionCounter::start(&mut peripherals.SYST);
    defmt::println!(
        "cost_probe: f32, {} random states per model and algorithm",
        STATES
    );
    sin_cos_cost(&counter);
    let passed = probe("pendulum", &PENDULUM, &counter)
        & probe("pendulum-planar", &PENDULUM_PLANAR, &counter)
        & probe("panda-7dof", &PANDA, &counter)
        & probe("quadruped-floating", &QUADRUPED, &counter);
    exit_with(passed)
}
