//! rodyn's time per call of the kinematics-for-control algorithms, printed
//! as `model algorithm ns` lines for `tools/pinocchio/bench/compare_kinematics.sh`,
//! which puts them beside Pinocchio's (`bench_kinematics.cpp`):
//!
//! * `joint_jacobians`: all joint Jacobians at q (Pinocchio's
//!   `computeJointJacobians`);
//! * `frame_jacobian`: the LOCAL Jacobian of a frame on the last body, the
//!   joint Jacobians already computed (`getFrameJacobian`);
//! * `centroidal_map`: `A_g` and `I_g` at q (`computeCentroidalMap`);
//! * `ccrba`: the same and `h_G = A_g v` (`ccrba(q, v)`).
//!
//! `cargo run --release -p rodyn-bench --bin kinematics_timing [-- --ms M]`
//!
//! For profilers, `-- --only MODEL ALGORITHM CALLS` runs one algorithm on
//! one model for exactly CALLS calls and prints nothing: under callgrind
//! the difference between two call counts' totals, over the difference of
//! the counts, is the instructions per call.

use std::hint::black_box;

use clap::Parser;
use rodyn::algorithm::centroidal::{centroidal_map, CentroidalData};
use rodyn::algorithm::frames::ReferenceFrame;
use rodyn::algorithm::jacobian::{frame_jacobian, joint_jacobians, JacobianData};
use rodyn::space::VectorOps;
use rodyn::spatial::{Force, Motion, Transform};
use rodyn::{Data, Frame, Model};
use rodyn_bench::arguments::{milliseconds, Only};
use rodyn_bench::models::{PANDA, SOLO12, UR5};
use rodyn_bench::state::random_states;
use rodyn_bench::timing::median_ns as time;
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
    let states = random_states(model, 64, 0x4B1E);
    let mut data = Box::new(Data::<f64, NB, NV>::new());
    let mut jac = Box::new(JacobianData::<f64, NV>::new());
    let mut cd = Box::new(CentroidalData::<f64, NB, NV>::new());
    let mut cols = [Motion::ZERO; NV];
    let frame = Frame::new(NB - 1, Transform::IDENTITY);
    let n = states.len();
    // A macro rather than a helper taking the closure, so that each
    // measurement keeps its own monomorphised loop.
    macro_rules! measure {
        ($algorithm:literal, $f:expr) => {
            match *mode {
                Mode::Timed(ms) => {
                    let t = time(ms, n, $f);
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

    measure!("joint_jacobians", |k: usize| {
        joint_jacobians(model, &mut data, &mut jac, &states[k].q).unwrap();
        black_box(&jac.j);
    });
    joint_jacobians(model, &mut data, &mut jac, &states[0].q).unwrap();
    measure!("frame_jacobian", |_: usize| {
        frame_jacobian(model, &data, &jac, &frame, ReferenceFrame::Local, &mut cols).unwrap();
        black_box(&cols);
    });
    measure!("centroidal_map", |k: usize| {
        centroidal_map(model, &mut data, &mut cd, &states[k].q).unwrap();
        black_box(&cd.ag);
    });
    measure!("ccrba", |k: usize| {
        centroidal_map(model, &mut data, &mut cd, &states[k].q).unwrap();
        let mut h = Force::ZERO;
        for (c, v) in cd.ag.iter().zip(&states[k].v) {
            h += *c * *v;
        }
        cd.hg = h;
        black_box(&cd.hg);
    });
}

const MODELS: [&str; 3] = ["ur5", "panda", "solo12"];
const ALGORITHMS: [&str; 4] = [
    "joint_jacobians",
    "frame_jacobian",
    "centroidal_map",
    "ccrba",
];

/// rodyn's time per call of the kinematics-for-control algorithms.
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
    let mode = match &only {
        Some(only) => Mode::Only(&only.algorithm, only.calls),
        None => Mode::Timed(cli.ms),
    };
    for (name, run_model) in [
        ("ur5", (|m: &Mode| run("ur5", &UR5, m)) as fn(&Mode)),
        ("panda", |m| run("panda", &PANDA, m)),
        ("solo12", |m| run("solo12", &SOLO12, m)),
    ] {
        if only.as_ref().is_none_or(|o| o.model == name) {
            run_model(&mode);
        }
    }
    ExitCode::SUCCESS
}
