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

fn run<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model: &Model<f64, NB, NQ, NV>,
    ms: f64,
) {
    let states = random_states(model, 64, 0x4B1E);
    let mut data = Box::new(Data::<f64, NB, NV>::new());
    let mut jac = Box::new(JacobianData::<f64, NV>::new());
    let mut cd = Box::new(CentroidalData::<f64, NB, NV>::new());
    let mut cols = [Motion::ZERO; NV];
    let frame = Frame::new(NB - 1, Transform::IDENTITY);
    let n = states.len();

    let t = time(ms, n, |k| {
        joint_jacobians(model, &mut data, &mut jac, &states[k].q).unwrap();
        black_box(&jac.j);
    });
    println!("{name} joint_jacobians {t:.1}");
    joint_jacobians(model, &mut data, &mut jac, &states[0].q).unwrap();
    let t = time(ms, n, |_| {
        frame_jacobian(model, &data, &jac, &frame, ReferenceFrame::Local, &mut cols).unwrap();
        black_box(&cols);
    });
    println!("{name} frame_jacobian {t:.1}");
    let t = time(ms, n, |k| {
        centroidal_map(model, &mut data, &mut cd, &states[k].q).unwrap();
        black_box(&cd.ag);
    });
    println!("{name} centroidal_map {t:.1}");
    let t = time(ms, n, |k| {
        centroidal_map(model, &mut data, &mut cd, &states[k].q).unwrap();
        let mut h = Force::ZERO;
        for (c, v) in cd.ag.iter().zip(&states[k].v) {
            h += *c * *v;
        }
        cd.hg = h;
        black_box(&cd.hg);
    });
    println!("{name} ccrba {t:.1}");
}

fn main() {
    let ms = ms_argument(50.0);
    run("ur5", &UR5, ms);
    run("panda", &PANDA, ms);
    run("solo12", &SOLO12, ms);
}
