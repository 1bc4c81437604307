//! The no_std f32 build against the std f64 build: the firmware side.
//!
//! For each model, [`STATES`] random states from a seeded xorshift
//! generator: the log prints the inputs `q`, `v`, `a`, `u` exactly (shortest
//! round-trip f32), RNEA's torques for `(q, v, a)` and ABA's accelerations
//! for `(q, v, u)`. The host test `host-tests/tests/firmware_agreement.rs`
//! recomputes both in f64 from the printed inputs and bounds the relative
//! difference.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn::algorithm::aba::aba;
use rodyn::algorithm::rnea::rnea;
use rodyn::{Data, Model};
use rodyn_firmware::exit::exit_with;
use rodyn_firmware::models::aibo::MODEL_F32 as QUADRUPED;
use rodyn_firmware::models::panda::MODEL_F32 as PANDA;
use rodyn_firmware::models::pendulum::MODEL_F32 as PENDULUM;
use rodyn_firmware::rng::XorShift32;

/// Random states per model.
const STATES: u32 = 8;
/// Seed of the state generator.
const SEED: u32 = 0xA61E_E000;

/// Prints inputs and results for `STATES` random states; false on an error.
fn report<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model: &Model<f32, NB, NQ, NV>,
    rng: &mut XorShift32,
) -> bool {
    let mut data = Data::new();
    for k in 0..STATES {
        let mut q = [0.0f32; NQ];
        rng.fill_symmetric(&mut q, core::f32::consts::PI);
        if let Err(e) = model.normalize(&mut q) {
            defmt::error!("{=str} {}: normalize: {}", name, k, e);
            return false;
        }
        let (mut v, mut a, mut u) = ([0.0f32; NV], [0.0f32; NV], [0.0f32; NV]);
        rng.fill_symmetric(&mut v, 2.0);
        rng.fill_symmetric(&mut a, 5.0);
        rng.fill_symmetric(&mut u, 5.0);
        let tau = match rnea(model, &mut data, &q, &v, &a, None) {
            Ok(tau) => *tau,
            Err(e) => {
                defmt::error!("{=str} {}: RNEA: {}", name, k, e);
                return false;
            }
        };
        let ddq = match aba(model, &mut data, &q, &v, &u, None) {
            Ok(ddq) => *ddq,
            Err(e) => {
                defmt::error!("{=str} {}: ABA: {}", name, k, e);
                return false;
            }
        };
        defmt::println!("agree {=str} {} q {}", name, k, q);
        defmt::println!("agree {=str} {} v {}", name, k, v);
        defmt::println!("agree {=str} {} a {}", name, k, a);
        defmt::println!("agree {=str} {} u {}", name, k, u);
        defmt::println!("agree {=str} {} rnea {}", name, k, tau);
        defmt::println!("agree {=str} {} aba {}", name, k, ddq);
    }
    true
}

#[entry]
fn main() -> ! {
    let mut rng = XorShift32::new(SEED);
    defmt::println!(
        "agreement: f32 RNEA and ABA on {} random states per model",
        STATES
    );
    let passed = report("pendulum", &PENDULUM, &mut rng)
        & report("panda", &PANDA, &mut rng)
        & report("quadruped", &QUADRUPED, &mut rng);
    exit_with(passed)
}
