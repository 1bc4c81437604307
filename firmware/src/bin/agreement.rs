//! The no_std f32 build against the std f64 build: the firmware side.
//!
//! For each model, [`STATES`] random states from a seeded xorshift
//! generator: the log prints the inputs `q`, `v`, `a`, `u` exactly (shortest
//! round-trip f32), RNEA's torques for `(q, v, a)`, ABA's accelerations
//! for `(q, v, u)`, CRBA's mass matrix at `q` (row `r` as the field `m<r>`)
//! and CRBA forward dynamics' accelerations for `(q, v, u)` (or, where the
//! f32 factorisation refuses `M`, the coordinate and relative pivot it
//! refused it at). The host test
//! `host-tests/tests/firmware_agreement.rs` recomputes each in f64 from the
//! printed inputs and bounds the relative difference.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn::algorithm::aba::aba;
use rodyn::algorithm::crba::{crba_planned, CrbaPlan};
use rodyn::algorithm::forward_dynamics::Crba;
use rodyn::algorithm::rnea::rnea;
use rodyn::{Data, Error, Model};
use rodyn_firmware::exit::exit_with;
use rodyn_firmware::models::aibo::{CRBA_PLAN_F32 as QUADRUPED_PLAN, MODEL_F32 as QUADRUPED};
use rodyn_firmware::models::panda::{CRBA_PLAN_F32 as PANDA_PLAN, MODEL_F32 as PANDA};
use rodyn_firmware::models::pendulum::{CRBA_PLAN_F32 as PENDULUM_PLAN, MODEL_F32 as PENDULUM};
use rodyn_firmware::rng::XorShift32;

/// Random states per model.
const STATES: u32 = 8;
/// Seed of the state generator.
const SEED: u32 = 0xA61E_E000;

/// Prints inputs and results for `STATES` random states; false on an error.
fn report<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model: &Model<f32, NB, NQ, NV>,
    plan: &CrbaPlan<f32, NB>,
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
        // Every entry of M, both triangles: which pass fills the upper one
        // is a choice of the tuning profile.
        match crba_planned(model, plan, &mut data, &q) {
            Ok(m) => {
                for (r, row) in m.iter().enumerate() {
                    defmt::println!("agree {=str} {} m{} {}", name, k, r, row);
                }
            }
            Err(e) => {
                defmt::error!("{=str} {}: CRBA: {}", name, k, e);
                return false;
            }
        }
        match Crba::forward_dynamics_planned(model, plan, &mut data, &q, &v, &u, None) {
            Ok(ddq) => defmt::println!("agree {=str} {} crba_fd {}", name, k, ddq),
            // In f32 the quadruped's light legs on its heavy trunk leave
            // some states' pivots below the factorisation's tolerance (see
            // docs/sections/firmware.md); the host checks the pivot in f64.
            Err(Error::MassMatrixNotPositiveDefinite {
                dof,
                relative_pivot,
            }) => defmt::println!(
                "agree {=str} {} crba_fd_refused [{}, {}]",
                name,
                k,
                dof as f32,
                relative_pivot as f32
            ),
            Err(e) => {
                defmt::error!("{=str} {}: CRBA forward dynamics: {}", name, k, e);
                return false;
            }
        }
    }
    true
}

#[entry]
fn main() -> ! {
    let mut rng = XorShift32::new(SEED);
    defmt::println!(
        "agreement: f32 RNEA, ABA, CRBA and CRBA forward dynamics on {} random states per model",
        STATES
    );
    let passed = report("pendulum", &PENDULUM, &PENDULUM_PLAN, &mut rng)
        & report("panda", &PANDA, &PANDA_PLAN, &mut rng)
        & report("quadruped", &QUADRUPED, &QUADRUPED_PLAN, &mut rng);
    exit_with(passed)
}
