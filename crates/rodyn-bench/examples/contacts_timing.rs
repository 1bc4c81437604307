//! rodyn's time per call of forward dynamics with rigid contacts, printed
//! as `model algorithm ns` lines for `tools/pinocchio/bench/compare_contacts.sh`,
//! which puts them beside Pinocchio's `constraintDynamics`
//! (`bench_contacts.cpp`):
//!
//! * `solo12 constrained_4_points`: Solo12 with its four feet held as 3-D
//!   point contacts (world-aligned);
//! * `talos constrained_2_soles`: Talos (`talos_reduced`, 38 velocity
//!   coordinates) with both soles held as 6-D frame contacts (local).
//!
//! Each by the KKT method and, as `…_articulated`, by the articulated-body
//! method (Pinocchio's line is its one `constraintDynamics`).
//!
//! The robots and contacts are those of the Pinocchio contact fixtures
//! (`host-tests/fixtures/contacts/`); each side draws its own 64 random
//! states. No Baumgarte gains: the exact KKT solve on both sides.
//!
//! `cargo run --release -p rodyn-bench --example contacts_timing [-- --ms M]`
//!
//! An example rather than a binary: the fixtures come from the unpublished
//! `rodyn-host-tests`, which only a dev-dependency may name (`cargo package
//! --workspace` resolves every normal dependency from the packaged set).

use std::hint::black_box;

use clap::Parser;
use rodyn::algorithm::constrained_dynamics::{
    constrained_forward_dynamics_with, ConstraintData, ConstraintMethod, ConstraintSettings,
    Contact,
};
use rodyn::{Data, Model};
use rodyn_bench::arguments::milliseconds;
use rodyn_bench::state::random_states;
use rodyn_bench::timing::median_ns;
use rodyn_host_tests::contact_fixture::{contacts, solo12, solo12_contacts, talos};

fn run<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    algorithm: &str,
    model: &Model<f64, NB, NQ, NV>,
    contacts: &[Contact<f64>],
    ms: f64,
) {
    let states = random_states(model, 64, 0xC0C7);
    let mut data = Box::new(Data::<f64, NB, NV>::new());
    let mut cdata = Box::new(ConstraintData::<f64, NV, 12>::new());
    let settings = ConstraintSettings::default();
    for (method, suffix) in [
        (ConstraintMethod::Kkt, ""),
        (ConstraintMethod::ArticulatedBody, "_articulated"),
    ] {
        let t = median_ns(ms, states.len(), |k| {
            let s = &states[k];
            let (ddq, _) = constrained_forward_dynamics_with(
                method, model, &mut data, &mut cdata, &s.q, &s.v, &s.tau, contacts, &settings,
            )
            .unwrap();
            black_box(ddq);
        });
        rodyn_cli::outln!("{name} {algorithm}{suffix} {t:.1}");
    }
}

/// rodyn's time per call of constrained forward dynamics.
#[derive(Parser)]
struct Cli {
    /// Milliseconds per measurement (at most 10000).
    #[arg(long, default_value = "50", value_parser = milliseconds, allow_hyphen_values = true)]
    ms: f64,
}

fn main() {
    let ms = Cli::parse().ms;
    let solo_feet = contacts(&solo12_contacts()["states"][0]["cases"][3]);
    run("solo12", "constrained_4_points", &solo12(), &solo_feet, ms);
    let (talos, fixture) = talos();
    let soles = contacts(&fixture["contact_states"][0]["cases"][0]);
    run("talos", "constrained_2_soles", &talos, &soles, ms);
}
