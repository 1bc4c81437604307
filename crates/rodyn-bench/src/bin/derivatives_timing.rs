//! rodyn's time per call of the analytic derivatives, printed as
//! `model algorithm ns` lines for `tools/pinocchio/bench/compare_derivatives.sh`,
//! which puts them beside Pinocchio's (`bench_derivatives.cpp`):
//!
//! * `rnea_derivatives`: `τ`, `∂τ/∂q`, `∂τ/∂v` and `M` at `(q, v, a)`
//!   (Pinocchio's `computeRNEADerivatives`);
//! * `aba_derivatives`: `q̈`, `∂q̈/∂q`, `∂q̈/∂v` and `M⁻¹` at `(q, v, τ)`
//!   (`computeABADerivatives`).
//!
//! `cargo run --release -p rodyn-bench --bin derivatives_timing [-- --ms M]`
//!
//! For profilers, `-- --only MODEL ALGORITHM CALLS` runs one algorithm on
//! one model for exactly CALLS calls and prints nothing: under callgrind
//! the difference between two call counts' totals, over the difference of
//! the counts, is the instructions per call. MODEL is one of the timed
//! models or, for this mode only, `chain20`, `chain30`, `chain40` or
//! `chain60` (spatial chains
//! of revolute joints).

use std::hint::black_box;

use clap::Parser;
use rodyn::algorithm::derivatives::{aba_derivatives, rnea_derivatives, DerivativeData};
use rodyn::{Data, Model};
use rodyn_bench::arguments::{milliseconds, Only};
use rodyn_bench::models::{planar_chain_3d, PANDA, SOLO12, UR5};
use rodyn_bench::state::random_states;
use rodyn_bench::timing::median_ns;
use std::process::ExitCode;

/// How each algorithm is measured: timed over about `ms` milliseconds and
/// printed, or (`only`) one of them called a fixed number of times.
enum Mode<'a> {
    Timed(f64),
    Only(&'a str, usize),
}

fn run<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model: &Model<f64, NB, NQ, NV>,
    mode: &Mode,
) {
    let states = random_states(model, 64, 0xDE1F);
    let mut data = Box::new(Data::<f64, NB, NV>::new());
    let mut deriv = Box::new(DerivativeData::<f64, NB, NV>::new());
    let n = states.len();
    // A macro rather than a helper taking the closure, so that each
    // measurement keeps its own monomorphised loop.
    macro_rules! measure {
        ($algorithm:literal, $f:expr) => {
            match *mode {
                Mode::Timed(ms) => {
                    let t = median_ns(ms, n, $f);
                    rodyn_cli::outln!("{name} {} {t:.1}", $algorithm);
                }
                Mode::Only(only, calls) if only == $algorithm => {
                    let mut f = $f;
                    for k in 0..calls {
                        f(k % n);
                    }
                }
                Mode::Only(..) => {}
            }
        };
    }
    measure!("rnea_derivatives", |k: usize| {
        let s = &states[k];
        rnea_derivatives(model, &mut data, &mut deriv, &s.q, &s.v, &s.a, None).unwrap();
        black_box(&deriv.dtau_dq);
    });
    measure!("aba_derivatives", |k: usize| {
        let s = &states[k];
        aba_derivatives(model, &mut data, &mut deriv, &s.q, &s.v, &s.tau, None).unwrap();
        black_box(&deriv.ddq_dq);
    });
}

/// The timed models, then those of `--only` alone.
const TIMED: [&str; 3] = ["ur5", "panda", "solo12"];
const MODELS: [&str; 7] = [
    "ur5", "panda", "solo12", "chain20", "chain30", "chain40", "chain60",
];
const ALGORITHMS: [&str; 2] = ["rnea_derivatives", "aba_derivatives"];

/// rodyn's time per call of the analytic derivatives.
#[derive(Parser)]
struct Cli {
    /// Milliseconds per measurement (at most 10000).
    #[arg(long, default_value = "50", value_parser = milliseconds, allow_hyphen_values = true)]
    ms: f64,
    /// One algorithm on one model for exactly CALLS calls (1 to 100000000),
    /// printing nothing: for profilers.
    #[arg(long, num_args = 3, value_names = ["MODEL", "ALGORITHM", "CALLS"], allow_hyphen_values = true)]
    only: Option<Vec<String>>,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let only = match cli
        .only
        .as_deref()
        .map(|v| Only::parse(v, &MODELS, &ALGORITHMS))
    {
        Some(Err(e)) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
        Some(Ok(only)) => Some(only),
        None => None,
    };
    match &only {
        None => {
            let mode = Mode::Timed(cli.ms);
            for model in TIMED {
                by_name(model, &mode);
            }
        }
        Some(only) => by_name(&only.model, &Mode::Only(&only.algorithm, only.calls)),
    }
    ExitCode::SUCCESS
}

/// Runs the model called `name` (one of [`MODELS`]).
fn by_name(name: &str, mode: &Mode) {
    match name {
        "ur5" => run(name, &UR5, mode),
        "panda" => run(name, &PANDA, mode),
        "solo12" => run(name, &SOLO12, mode),
        "chain20" => run(name, &planar_chain_3d::<20>(), mode),
        "chain30" => run(name, &planar_chain_3d::<30>(), mode),
        "chain40" => run(name, &planar_chain_3d::<40>(), mode),
        "chain60" => run(name, &planar_chain_3d::<60>(), mode),
        // `Only::parse` admits only the names above.
        _ => unreachable!("model {name} is not in MODELS"),
    }
}
