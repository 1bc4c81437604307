//! Criterion benchmarks of RNEA, CRBA, CRBA forward dynamics and ABA.
//!
//! `cargo bench -p rodyn-bench --bench dynamics [-- <filter>]`; ids read
//! `<algorithm>/<model>/<scalar>`, e.g. `aba/panda/f64` or
//! `crba_fd/planar_chain_20_planar/f32`. Each iteration uses the next of 64
//! random states, as a controller sees a new state every tick.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use rodyn::algorithm::crba::CrbaPlan;
use rodyn::space::Space;
use rodyn::{Data, Model, Scalar};
use rodyn_bench::models::{planar_chain, planar_chain_3d, PANDA, SOLO12, UR5};
use rodyn_bench::state::{random_states, State};
use rodyn_bench::Algorithm;
use std::hint::black_box;
use std::time::Duration;

const STATES: usize = 64;
const SEED: u64 = 0x5EED;

fn bench_scalar<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    c: &mut Criterion,
    name: &str,
    scalar: &str,
    model: &Model<S, NB, NQ, NV, G>,
    states: &[State<S, NQ, NV>],
) {
    let mut data = Box::new(Data::<S, NB, NV, G>::new());
    let plan = CrbaPlan::new(model);
    for algorithm in Algorithm::ALL {
        let mut group = c.benchmark_group(algorithm.name());
        let mut k = 0;
        group.bench_function(BenchmarkId::new(name, scalar), |b| {
            b.iter(|| {
                k = (k + 1) % states.len();
                algorithm.run(model, &plan, &mut data, black_box(&states[k]))
            });
        });
        group.finish();
    }
}

/// `model` in f64 and f32, on the same states.
fn bench_model<const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    c: &mut Criterion,
    name: &str,
    model: &Model<f64, NB, NQ, NV, G>,
) {
    let states = random_states(model, STATES, SEED);
    bench_scalar(c, name, "f64", model, &states);
    let model_f32 = model.cast::<f32>().expect("built-in joints cast");
    let states_f32: Vec<_> = states.iter().map(State::cast::<f32>).collect();
    bench_scalar(c, name, "f32", &model_f32, &states_f32);
}

/// A planar chain as a 3-D model and on planar algebra.
fn bench_chain<const N: usize>(c: &mut Criterion) {
    bench_model(c, &format!("planar_chain_{N}_3d"), &planar_chain_3d::<N>());
    bench_model(c, &format!("planar_chain_{N}_planar"), &planar_chain::<N>());
}

fn robots(c: &mut Criterion) {
    bench_model(c, "panda", &PANDA);
    bench_model(c, "ur5", &UR5);
    bench_model(c, "solo12", &SOLO12);
}

fn chains(c: &mut Criterion) {
    bench_chain::<2>(c);
    bench_chain::<5>(c);
    bench_chain::<10>(c);
    bench_chain::<20>(c);
    bench_chain::<60>(c);
}

fn config() -> Criterion {
    // Sub-microsecond calls: short windows still give tight intervals.
    Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .sample_size(30)
}

criterion_group! {
    name = benches;
    config = config();
    targets = robots, chains
}
criterion_main!(benches);
