//! The run-time model's drives against its dynamics: ABA alone, ABA under
//! the file's drives (`aba_with_drives`) and the drives' generalized
//! forces (`drive_generalized_forces`) on the model files that have drives
//! (the pendulum's spring, the Panda's seven motors, the two-link arm's
//! four muscles), at the same seeded states, in interleaved rounds. Prints
//! the median ns per call and the drives' share: what `aba_with_drives`
//! adds to `aba`, over `aba`.
//!
//! `cargo run --release -p rodyn-bench --example runtime_drives [-- --ms M --rounds R]`

use clap::Parser;
use rodyn_bench::arguments::{milliseconds, Rounds};
use rodyn_bench::timing::{calls_for, median, ns_per_call};
use rodyn_model::runtime::RuntimeModel;
use std::hint::black_box;
use std::path::Path;
use std::process::ExitCode;

/// `runtime_drives`: what the drives cost next to the dynamics.
#[derive(Parser, Debug)]
struct Args {
    /// Milliseconds per measurement.
    #[arg(long, default_value = "50", value_parser = milliseconds)]
    ms: f64,
    /// Interleaved rounds per model.
    #[arg(long, default_value = "15")]
    rounds: Rounds,
}

const STATES: usize = 64;

/// Seeded states `(q, v, tau, w)` of `model`, `w` in `[0, 1]`.
fn states(model: &RuntimeModel) -> Vec<[Vec<f64>; 4]> {
    let mut x = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..STATES as u64)
        .map(|seed| {
            let mut vector = |n: usize| (0..n).map(|_| next()).collect::<Vec<f64>>();
            let v = vector(model.nv()).iter().map(|x| 2.0 * x - 1.0).collect();
            let tau = vector(model.nv()).iter().map(|x| 2.0 * x - 1.0).collect();
            let w = vector(model.nu());
            [model.random_configuration(seed), v, tau, w]
        })
        .collect()
}

fn measure(file: &str, args: &Args) -> Result<(), String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let model =
        RuntimeModel::from_file(&root.join("models").join(file)).map_err(|d| d.to_string())?;
    let (model, states) = (&model, &states(&model));
    let mut calls: [Box<dyn FnMut(usize) -> bool + '_>; 3] = [
        Box::new({
            let mut ws = model.workspace();
            let mut out = vec![0.0; model.nv()];
            move |k| {
                let [q, v, tau, _] = &states[k];
                model.aba(&mut ws, q, v, tau, &mut out).is_ok()
            }
        }),
        Box::new({
            let mut ws = model.workspace();
            let mut out = vec![0.0; model.nv()];
            move |k| {
                let [q, v, tau, w] = &states[k];
                model
                    .aba_with_drives(&mut ws, q, v, tau, w, &mut out)
                    .is_ok()
            }
        }),
        Box::new({
            let mut ws = model.workspace();
            let mut out = vec![0.0; model.nv()];
            move |k| {
                let [q, v, _, w] = &states[k];
                model
                    .drive_generalized_forces(&mut ws, q, v, w, &mut out)
                    .is_ok()
            }
        }),
    ];
    if !(0..STATES).all(|k| calls.iter_mut().all(|f| f(k))) {
        return Err(format!("{file}: a call failed"));
    }
    let n = calls_for(args.ms * 1e6, STATES, |k| black_box(calls[1](k)));
    let mut times: [Vec<f64>; 3] = Default::default();
    let mut share = Vec::new();
    for _ in 0..args.rounds.get() {
        let t: Vec<f64> = calls
            .iter_mut()
            .map(|f| ns_per_call(n, STATES, |k| black_box(f(k))))
            .collect();
        share.push((t[1] - t[0]) / t[0]);
        for (all, x) in times.iter_mut().zip(t) {
            all.push(x);
        }
    }
    let [aba, with_drives, forces] = times.map(|mut t| median(&mut t));
    println!(
        "{file} (nv = {}, {} drives): aba {aba:7.1} ns  aba_with_drives {with_drives:7.1} ns  drive_generalized_forces {forces:7.1} ns  drives' share {:+.0} %",
        model.nv(),
        model.drive_names().len(),
        100.0 * median(&mut share)
    );
    Ok(())
}

fn main() -> ExitCode {
    let args = Args::parse();
    for file in ["pendulum.toml", "panda.toml", "two_link_muscles.toml"] {
        if let Err(e) = measure(file, &args) {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    }
    ExitCode::SUCCESS
}
