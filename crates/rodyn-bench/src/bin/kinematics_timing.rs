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

use rodyn::algorithm::centroidal::{centroidal_map, CentroidalData};
use rodyn::algorithm::frames::ReferenceFrame;
use rodyn::algorithm::jacobian::{frame_jacobian, joint_jacobians, JacobianData};
use rodyn::space::VectorOps;
use rodyn::spatial::{Force, Motion, Transform};
use rodyn::{Data, Frame, Model};
use rodyn_bench::models::{PANDA, SOLO12, UR5};
use rodyn_bench::state::random_states;
use rodyn_bench::timing::{median_ns as time, ms_argument};

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

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mode = match args.iter().position(|a| a == "--only") {
        Some(i) => {
            let usage = "--only MODEL ALGORITHM CALLS";
            let calls = args.get(i + 3).and_then(|c| c.parse().ok()).expect(usage);
            Mode::Only(args.get(i + 2).expect(usage), calls)
        }
        None => Mode::Timed(ms_argument(50.0)),
    };
    let only_model = match args.iter().position(|a| a == "--only") {
        Some(i) => args.get(i + 1).map(String::as_str),
        None => None,
    };
    for (name, run_model) in [
        ("ur5", (|m: &Mode| run("ur5", &UR5, m)) as fn(&Mode)),
        ("panda", |m| run("panda", &PANDA, m)),
        ("solo12", |m| run("solo12", &SOLO12, m)),
    ] {
        if only_model.is_none_or(|m| m == name) {
            run_model(&mode);
        }
    }
}
