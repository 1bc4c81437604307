//! Runs one algorithm on one model many times, for profilers.
//!
//! Timings on a shared machine are noisy; instruction counts are not. Under
//! callgrind the count per call is deterministic:
//!
//! ```text
//! cargo build -p rodyn-bench --release --bin profile
//! valgrind --tool=callgrind --callgrind-out-file=/tmp/cg.out \
//!     target/release/profile aba panda 1000
//! callgrind_annotate /tmp/cg.out | head -30
//! ```
//!
//! Without a profiler it prints the wall-clock time per call.
//! Models: `panda`, `ur5`, `solo12`, `chainN` (N in 5, 10, 20, 30, 40, 50, 60)
//! and `chainN_planar` (N in 5, 10, 20, 30, 40, 50, 60).

use clap::builder::PossibleValuesParser;
use clap::Parser;
use rodyn_bench::arguments::Calls;
use rodyn_bench::cases::{Case, ModelCase};
use rodyn_bench::models::{planar_chain, planar_chain_3d, PANDA, SOLO12, UR5};
use rodyn_bench::Algorithm;

fn case(name: &str) -> Option<Box<dyn Case>> {
    const STATES: usize = 16;
    const SEED: u64 = 7;
    Some(match name {
        "panda" => Box::new(ModelCase::new(PANDA, STATES, SEED)),
        "ur5" => Box::new(ModelCase::new(UR5, STATES, SEED)),
        "solo12" => Box::new(ModelCase::new(SOLO12, STATES, SEED)),
        "chain5" => Box::new(ModelCase::new(planar_chain_3d::<5>(), STATES, SEED)),
        "chain10" => Box::new(ModelCase::new(planar_chain_3d::<10>(), STATES, SEED)),
        "chain20" => Box::new(ModelCase::new(planar_chain_3d::<20>(), STATES, SEED)),
        "chain30" => Box::new(ModelCase::new(planar_chain_3d::<30>(), STATES, SEED)),
        "chain40" => Box::new(ModelCase::new(planar_chain_3d::<40>(), STATES, SEED)),
        "chain50" => Box::new(ModelCase::new(planar_chain_3d::<50>(), STATES, SEED)),
        "chain60" => Box::new(ModelCase::new(planar_chain_3d::<60>(), STATES, SEED)),
        "chain5_planar" => Box::new(ModelCase::new(planar_chain::<5>(), STATES, SEED)),
        "chain10_planar" => Box::new(ModelCase::new(planar_chain::<10>(), STATES, SEED)),
        "chain20_planar" => Box::new(ModelCase::new(planar_chain::<20>(), STATES, SEED)),
        "chain30_planar" => Box::new(ModelCase::new(planar_chain::<30>(), STATES, SEED)),
        "chain40_planar" => Box::new(ModelCase::new(planar_chain::<40>(), STATES, SEED)),
        "chain50_planar" => Box::new(ModelCase::new(planar_chain::<50>(), STATES, SEED)),
        "chain60_planar" => Box::new(ModelCase::new(planar_chain::<60>(), STATES, SEED)),
        _ => return None,
    })
}

/// Runs one algorithm on one model many times, for profilers.
#[derive(Parser)]
struct Cli {
    /// The algorithm.
    #[arg(value_parser = PossibleValuesParser::new(Algorithm::ALL.map(Algorithm::name)))]
    algorithm: String,
    /// The model: panda, ur5, solo12, chainN or chainN_planar (N in 5, 10,
    /// 20, 30, 40, 50, 60).
    model: String,
    /// How many calls (1 to 100000000).
    #[arg(default_value = "100000", allow_hyphen_values = true)]
    calls: Calls,
}

fn main() -> Result<(), String> {
    let cli = Cli::parse();
    let algorithm = Algorithm::ALL
        .into_iter()
        .find(|a| a.name() == cli.algorithm)
        .ok_or(format!("unknown algorithm {}", cli.algorithm))?;
    let name = &cli.model;
    let mut case = case(name).ok_or(format!("<MODEL>: unknown model {name}"))?;
    let calls = cli.calls.get();
    let ns = case.time(algorithm, calls);
    rodyn_cli::outln!(
        "{} {name}: {ns:.1} ns/call over {calls} calls",
        algorithm.name()
    );
    Ok(())
}
