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

use rodyn::algorithm::derivatives::{aba_derivatives, rnea_derivatives, DerivativeData};
use rodyn::{Data, Model};
use rodyn_bench::models::{planar_chain_3d, PANDA, SOLO12, UR5};
use rodyn_bench::state::random_states;
use rodyn_bench::timing::{median_ns, ms_argument};

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
                    println!("{name} {} {t:.1}", $algorithm);
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

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let only = args.iter().position(|a| a == "--only").map(|i| {
        let usage = "--only MODEL ALGORITHM CALLS";
        let calls = args.get(i + 3).and_then(|c| c.parse().ok()).expect(usage);
        let model = args.get(i + 1).expect(usage).as_str();
        (model, Mode::Only(args.get(i + 2).expect(usage), calls))
    });
    match only {
        None => {
            let mode = Mode::Timed(ms_argument(50.0));
            run("ur5", &UR5, &mode);
            run("panda", &PANDA, &mode);
            run("solo12", &SOLO12, &mode);
        }
        Some((model, mode)) => match model {
            "ur5" => run(model, &UR5, &mode),
            "panda" => run(model, &PANDA, &mode),
            "solo12" => run(model, &SOLO12, &mode),
            "chain20" => run(model, &planar_chain_3d::<20>(), &mode),
            "chain30" => run(model, &planar_chain_3d::<30>(), &mode),
            "chain40" => run(model, &planar_chain_3d::<40>(), &mode),
            "chain60" => run(model, &planar_chain_3d::<60>(), &mode),
            _ => panic!("unknown model {model}"),
        },
    }
}
