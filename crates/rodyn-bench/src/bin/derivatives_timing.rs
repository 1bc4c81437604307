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

use std::hint::black_box;

use rodyn::algorithm::derivatives::{aba_derivatives, rnea_derivatives, DerivativeData};
use rodyn::{Data, Model};
use rodyn_bench::models::{PANDA, SOLO12, UR5};
use rodyn_bench::state::random_states;
use rodyn_bench::timing::{median_ns, ms_argument};

fn run<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model: &Model<f64, NB, NQ, NV>,
    ms: f64,
) {
    let states = random_states(model, 64, 0xDE1F);
    let mut data = Box::new(Data::<f64, NB, NV>::new());
    let mut deriv = Box::new(DerivativeData::<f64, NB, NV>::new());
    let n = states.len();
    let t = median_ns(ms, n, |k| {
        let s = &states[k];
        rnea_derivatives(model, &mut data, &mut deriv, &s.q, &s.v, &s.a, None).unwrap();
        black_box(&deriv.dtau_dq);
    });
    println!("{name} rnea_derivatives {t:.1}");
    let t = median_ns(ms, n, |k| {
        let s = &states[k];
        aba_derivatives(model, &mut data, &mut deriv, &s.q, &s.v, &s.tau, None).unwrap();
        black_box(&deriv.ddq_dq);
    });
    println!("{name} aba_derivatives {t:.1}");
}

fn main() {
    let ms = ms_argument(50.0);
    run("ur5", &UR5, ms);
    run("panda", &PANDA, ms);
    run("solo12", &SOLO12, ms);
}
