//! The run-time model's cost against the compiled model's: RNEA and ABA
//! (and CRBA) on the Panda and Solo12, the same states through both, in
//! interleaved rounds (compiled, run-time, compiled, …) so that a change
//! of clock or a noisy neighbour hits both alike. Prints, per model and
//! algorithm, the median over rounds of each one's ns per call and of
//! their ratio (run-time / compiled).
//!
//! `cargo run --release -p rodyn-bench --example runtime_vs_const [-- --ms M --rounds R]`
//!
//! The run-time calls go through the public slice API
//! (`RuntimeModel::rnea(&mut ws, &q, &v, &a, &mut tau)`): the copies in and
//! out, the length checks and the size-class dispatch are all counted.

use clap::Parser;
use rodyn::algorithm::aba::aba;
use rodyn::algorithm::crba::crba_planned;
use rodyn::algorithm::rnea::rnea;
use rodyn::Data;
use rodyn_bench::arguments::{milliseconds, Rounds};
use rodyn_bench::models::urdf_models::{panda, solo12};
use rodyn_bench::models::{PANDA, PANDA_URDF, SOLO12, SOLO12_URDF};
use rodyn_bench::state::random_states;
use rodyn_bench::timing::{calls_for, median, ns_per_call};
use rodyn_model::runtime::RuntimeModel;
use std::hint::black_box;
use std::path::Path;
use std::process::ExitCode;

/// `runtime_vs_const`: the run-time model against the compiled one.
#[derive(Parser, Debug)]
struct Args {
    /// Milliseconds per measurement.
    #[arg(long, default_value = "50", value_parser = milliseconds)]
    ms: f64,
    /// Interleaved rounds per model and algorithm.
    #[arg(long, default_value = "15")]
    rounds: Rounds,
}

const STATES: usize = 64;

/// Median ns per call of `compiled` and `runtime`, and of their ratio,
/// over `rounds` interleaved rounds.
fn race(
    ms: f64,
    rounds: usize,
    mut compiled: impl FnMut(usize),
    mut runtime: impl FnMut(usize),
) -> (f64, f64, f64) {
    let calls = calls_for(ms * 1e6, STATES, &mut compiled);
    let (mut c, mut r, mut ratio) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..rounds {
        let tc = ns_per_call(calls, STATES, &mut compiled);
        let tr = ns_per_call(calls, STATES, &mut runtime);
        c.push(tc);
        r.push(tr);
        ratio.push(tr / tc);
    }
    (median(&mut c), median(&mut r), median(&mut ratio))
}

macro_rules! compare {
    ($name:expr, $model:expr, $plan:expr, $urdf:expr, $floating:expr, $args:expr) => {{
        let model = &$model;
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let runtime =
            RuntimeModel::from_urdf(&root.join($urdf), $floating).map_err(|d| d.to_string())?;
        let states = random_states(model, STATES, 11);
        let mut data = Box::new(Data::new());
        let mut ws = runtime.workspace();
        let nv = runtime.nv();
        let mut out = vec![0.0; nv];
        let mut m_out = vec![0.0; nv * nv];
        let (ms, rounds) = ($args.ms, $args.rounds.get());
        let (nb, nq, nvc) = runtime.capacity();
        println!(
            "{} (nq = {}, nv = {}; size class NB = {nb}, NQ = {nq}, NV = {nvc})",
            $name,
            runtime.nq(),
            nv
        );
        let rows = [
            (
                "rnea",
                race(
                    ms,
                    rounds,
                    |k| {
                        let s = &states[k];
                        black_box(
                            rnea(model, &mut data, &s.q, &s.v, &s.a, None)
                                .map(|t| t[0])
                                .ok(),
                        );
                    },
                    |k| {
                        let s = &states[k];
                        black_box(runtime.rnea(&mut ws, &s.q, &s.v, &s.a, &mut out).ok());
                    },
                ),
            ),
            (
                "aba",
                race(
                    ms,
                    rounds,
                    |k| {
                        let s = &states[k];
                        black_box(
                            aba(model, &mut data, &s.q, &s.v, &s.tau, None)
                                .map(|t| t[0])
                                .ok(),
                        );
                    },
                    |k| {
                        let s = &states[k];
                        black_box(runtime.aba(&mut ws, &s.q, &s.v, &s.tau, &mut out).ok());
                    },
                ),
            ),
            (
                "crba",
                race(
                    ms,
                    rounds,
                    |k| {
                        let s = &states[k];
                        black_box(
                            crba_planned(model, &$plan, &mut data, &s.q)
                                .map(|m| m[0][0])
                                .ok(),
                        );
                    },
                    |k| {
                        let s = &states[k];
                        black_box(runtime.crba(&mut ws, &s.q, &mut m_out).ok());
                    },
                ),
            ),
        ];
        for (algorithm, (c, r, ratio)) in rows {
            println!("  {algorithm:<5} compiled {c:8.1} ns  run-time {r:8.1} ns  ratio {ratio:.3}");
        }
    }};
}

fn run(args: &Args) -> Result<(), String> {
    compare!(
        "panda",
        PANDA,
        panda::CRBA_PLAN_F64,
        PANDA_URDF,
        false,
        args
    );
    compare!(
        "solo12",
        SOLO12,
        solo12::CRBA_PLAN_F64,
        SOLO12_URDF,
        true,
        args
    );
    Ok(())
}

fn main() -> ExitCode {
    let args = Args::parse();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
