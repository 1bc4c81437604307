//! rodyn's time per call of the kinematics-for-control algorithms, printed
//! as `model algorithm ns` lines for `tools/pinocchio/bench/compare_kinematics.sh`,
//! which puts them beside Pinocchio's (`bench_kinematics.cpp`):
//!
//! * `joint_jacobians`: all joint Jacobians at q (Pinocchio's
//!   `computeJointJacobians`);
//! * `frame_jacobian`: the LOCAL Jacobian of a frame on the last body, the
//!   joint Jacobians already computed (`getFrameJacobian`);
//! * `centroidal_map`: `A_g` and `I_g` at q (`computeCentroidalMap`);
//! * `ccrba`: the same and `h_G = A_g v` (`ccrba(q, v)`);
//! * `frame_jacobian_from_q`: one frame's Jacobian at q,
//!   LOCAL_WORLD_ALIGNED, along its chain (`frame_chain::frame_jacobian_from_q`;
//!   Pinocchio's `computeFrameJacobian`), with the variants
//!   `frame_jacobian_from_q_chain` (the path found once, `chain_jacobian`),
//!   `frame_jacobian_from_q_const` (the path a constant, Solo12's foot from
//!   its generated frame constants) and `frame_jacobian_from_q_alljoints`
//!   (`joint_jacobians` + `frame_jacobian`, every joint's columns);
//! * `feet_jacobians`: a quadruped's four feet at q, LOCAL_WORLD_ALIGNED,
//!   as a set (`chains_jacobians`), and `feet_jacobians_single` one foot
//!   at a time (`chain_jacobian` four times); Pinocchio's line is four
//!   `computeFrameJacobian` calls.
//!
//! The frames: the last body of the UR5 and the Panda; Solo12's and
//! ANYmal's front left foot, the G1's left hand, Talos's left gripper
//! (ANYmal, the G1 and Talos from `host-tests/fixtures/frame_chain/`, which
//! lists them; only the frame lines for those three).
//!
//! `cargo run --release -p rodyn-bench --example kinematics_timing [-- --ms M]`
//!
//! An example rather than a binary: the fixture robots come from the
//! unpublished test crate, a dev-dependency.
//!
//! For profilers, `-- --only MODEL ALGORITHM CALLS` runs one algorithm on
//! one model for exactly CALLS calls and prints nothing: under callgrind
//! the difference between two call counts' totals, over the difference of
//! the counts, is the instructions per call.

use std::hint::black_box;

use clap::Parser;
use rodyn::algorithm::centroidal::{centroidal_map, CentroidalData};
use rodyn::algorithm::frame_chain::{
    chain_jacobian, chains_jacobians, frame_jacobian_from_q, FrameChain,
};
use rodyn::algorithm::frames::ReferenceFrame;
use rodyn::algorithm::jacobian::{frame_jacobian, joint_jacobians, JacobianData};
use rodyn::space::VectorOps;
use rodyn::spatial::{Force, Motion, Transform};
use rodyn::{Data, Frame, Model};
use rodyn_bench::arguments::{milliseconds, Only};
use rodyn_bench::models::urdf_models::solo12;
use rodyn_bench::models::{PANDA, SOLO12, UR5};
use rodyn_bench::state::random_states;
use rodyn_bench::timing::median_ns as time;
use rodyn_host_tests::frame_chain_fixture::{load, ANYMAL, G1, TALOS};
use std::process::ExitCode;

/// How each algorithm is measured: timed over about `ms` milliseconds and
/// printed, or (`only`) one of them called a fixed number of times.
enum Mode<'a> {
    Timed(f64),
    Only(&'a str, usize),
}

/// Solo12's front left foot, its path a constant (the generated frame
/// constants of the compiled model).
const SOLO12_FOOT: FrameChain<f64, 13> =
    FrameChain::new(&SOLO12, solo12::FRAMES_F64[solo12::frame::FL_FOOT]).unwrap();

/// Which measurements a model takes.
#[derive(Clone, Copy, PartialEq)]
enum Suite {
    /// Everything: the arms and Solo12.
    All,
    /// The from-q frame lines only: the fixture robots.
    Frames,
}

fn run<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model: &Model<f64, NB, NQ, NV>,
    frames: &[Frame<f64>],
    suite: Suite,
    mode: &Mode,
) {
    let states = random_states(model, 64, 0x4B1E);
    let mut data = Box::new(Data::<f64, NB, NV>::new());
    let mut jac = Box::new(JacobianData::<f64, NV>::new());
    let mut cd = Box::new(CentroidalData::<f64, NB, NV>::new());
    let mut cols = [Motion::ZERO; NV];
    // The stored Jacobians' frame: the last body.
    let frame = Frame::new(NB - 1, Transform::IDENTITY);
    let n = states.len();
    // A macro rather than a helper taking the closure, so that each
    // measurement keeps its own monomorphised loop.
    macro_rules! measure {
        ($algorithm:literal, $f:expr) => {
            match *mode {
                Mode::Timed(ms) => {
                    let t = time(ms, n, $f);
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

    let lwa = ReferenceFrame::LocalWorldAligned;
    let one = frames[0];
    let chain = FrameChain::try_new(model, &one).unwrap();
    measure!("frame_jacobian_from_q", |k: usize| {
        frame_jacobian_from_q(model, &states[k].q, &one, lwa, &mut cols).unwrap();
        black_box(&cols);
    });
    measure!("frame_jacobian_from_q_chain", |k: usize| {
        chain_jacobian(model, &states[k].q, black_box(&chain), lwa, &mut cols).unwrap();
        black_box(&cols);
    });
    measure!("frame_jacobian_from_q_alljoints", |k: usize| {
        joint_jacobians(model, &mut data, &mut jac, &states[k].q).unwrap();
        frame_jacobian(model, &data, &jac, &one, lwa, &mut cols).unwrap();
        black_box(&cols);
    });
    if let Ok(feet) = <&[Frame<f64>; 4]>::try_from(frames) {
        let chains = feet.map(|f| FrameChain::try_new(model, &f).unwrap());
        let mut set = Box::new([[Motion::ZERO; NV]; 4]);
        measure!("feet_jacobians", |k: usize| {
            chains_jacobians(
                model,
                &mut data,
                &states[k].q,
                black_box(&chains),
                lwa,
                &mut set,
            )
            .unwrap();
            black_box(&set);
        });
        measure!("feet_jacobians_single", |k: usize| {
            for (chain, out) in black_box(&chains).iter().zip(set.iter_mut()) {
                chain_jacobian(model, &states[k].q, chain, lwa, out).unwrap();
            }
            black_box(&set);
        });
    }
    if suite == Suite::Frames {
        return;
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

/// Solo12's foot with its path a constant the compiler sees
/// (`frame_jacobian_from_q_const`), on `run`'s states.
fn solo12_constant_path(mode: &Mode) {
    let states = random_states(&SOLO12, 64, 0x4B1E);
    let mut cols = [Motion::ZERO; 18];
    let lwa = ReferenceFrame::LocalWorldAligned;
    let f = |k: usize| {
        chain_jacobian(&SOLO12, &states[k].q, &SOLO12_FOOT, lwa, &mut cols).unwrap();
        black_box(&cols);
    };
    match *mode {
        Mode::Timed(ms) => {
            let t = time(ms, states.len(), f);
            rodyn_cli::outln!("solo12 frame_jacobian_from_q_const {t:.1}");
        }
        Mode::Only("frame_jacobian_from_q_const", calls) => {
            let mut f = f;
            for k in 0..calls {
                f(k % states.len());
            }
        }
        Mode::Only(..) => {}
    }
}

const MODELS: [&str; 6] = ["ur5", "panda", "solo12", "anymal", "g1", "talos"];
const ALGORITHMS: [&str; 10] = [
    "frame_jacobian_from_q",
    "frame_jacobian_from_q_chain",
    "frame_jacobian_from_q_alljoints",
    "frame_jacobian_from_q_const",
    "feet_jacobians",
    "feet_jacobians_single",
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
    let only_model = only.as_ref().map(|o| o.model.as_str());
    let last = |nb: usize| [Frame::new(nb - 1, Transform::IDENTITY)];
    let solo_feet = [
        solo12::frame::FL_FOOT,
        solo12::frame::FR_FOOT,
        solo12::frame::HL_FOOT,
        solo12::frame::HR_FOOT,
    ]
    .map(|f| solo12::FRAMES_F64[f]);
    let wanted = |name: &str| only_model.is_none_or(|m| m == name);
    if wanted("ur5") {
        run("ur5", &UR5, &last(6), Suite::All, &mode);
    }
    if wanted("panda") {
        run("panda", &PANDA, &last(7), Suite::All, &mode);
    }
    if wanted("solo12") {
        run("solo12", &SOLO12, &solo_feet, Suite::All, &mode);
        solo12_constant_path(&mode);
    }
    // The fixture robots: the frames in the file's order (for ANYmal its
    // four feet, the front left first; for the G1 and Talos the left hand
    // or gripper first, then the other and the feet, of which only the
    // first is timed).
    macro_rules! fixture_robot {
        ($name:literal, $sizes:path, $set:expr) => {
            if wanted($name) {
                const NB: usize = $sizes.0;
                const NQ: usize = $sizes.1;
                const NV: usize = $sizes.2;
                let fixture = load::<NB, NQ, NV>($name);
                let frames: Vec<Frame<f64>> = fixture.frames.iter().map(|(_, f)| *f).collect();
                let frames = if $set { &frames[..] } else { &frames[..1] };
                run($name, &fixture.model, frames, Suite::Frames, &mode);
            }
        };
    }
    fixture_robot!("anymal", ANYMAL, true);
    fixture_robot!("g1", G1, false);
    fixture_robot!("talos", TALOS, false);
    ExitCode::SUCCESS
}
