//! The no_std f32 firmware build against the std f64 build.
//!
//! The `agreement` firmware example (run in QEMU by `cargo xtask test`)
//! prints seeded random inputs and its f32 results of RNEA and ABA. This
//! test reads that log, recomputes both in f64 on the host from the same
//! inputs and the same model parameters (the f32 models that
//! `rodyn-scenarios` generates from `models/` for the firmware, cast to
//! f64), and bounds the norm-wise relative difference
//! `‖x_f32 − x_f64‖∞ / ‖x_f64‖∞`.
//!
//! The log is `firmware/expected/agreement.log` (checked in, produced by the
//! firmware in QEMU), or the file named by `RODYN_AGREEMENT_LOG`, which
//! `cargo xtask test` sets to the log of the run it just made.

use rodyn::algorithm::aba::aba;
use rodyn::algorithm::rnea::rnea;
use rodyn::{Data, Model};
use rodyn_scenarios::{aibo, panda, pendulum};
use std::collections::HashMap;

/// Bound on RNEA's relative difference: 32 f32 epsilons (3.8e-6).
/// Measured largest (`cargo test -p rodyn-host-tests --test
/// firmware_agreement -- --nocapture`): 1.2e-7 pendulum, 1.3e-7 Panda,
/// 2.2e-7 quadruped, under two epsilons; the bound leaves a factor of 16
/// for longer chains and other summation orders.
const RNEA_BOUND: f64 = 32.0 * f32::EPSILON as f64;
/// Bound on ABA's relative difference, also 32 f32 epsilons. ABA divides by
/// articulated inertias, so its error can grow with the conditioning of the
/// mass matrix; measured: 1.1e-7 pendulum and Panda, 1.5e-7 quadruped (whose
/// 50 g legs hang on a 1 kg trunk).
const ABA_BOUND: f64 = 32.0 * f32::EPSILON as f64;

/// Inputs and f32 results of one state, by field name (`q`, `v`, `a`, `u`,
/// `rnea`, `aba`).
type State = HashMap<String, Vec<f64>>;

fn parse_log(text: &str) -> HashMap<(String, usize), State> {
    let mut states: HashMap<(String, usize), State> = HashMap::new();
    for line in text.lines() {
        let Some(rest) = line.strip_prefix("agree ") else {
            continue;
        };
        let (head, values) = rest.split_once('[').expect("an array on each agree line");
        let head: Vec<&str> = head.split_whitespace().collect();
        let (model, index, field) = (head[0], head[1].parse().unwrap(), head[2]);
        // Shortest round-trip f32 text parses back to the exact f32 value.
        let values: Vec<f64> = values
            .trim_end_matches(']')
            .split(',')
            .map(|x| f64::from(x.trim().parse::<f32>().expect("an f32")))
            .collect();
        states
            .entry((model.to_string(), index))
            .or_default()
            .insert(field.to_string(), values);
    }
    states
}

fn relative_difference(f32_result: &[f64], f64_result: &[f64]) -> f64 {
    let scale = f64_result.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let diff = f32_result
        .iter()
        .zip(f64_result)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    diff / scale.max(f64::MIN_POSITIVE)
}

fn array<const N: usize>(values: &[f64]) -> [f64; N] {
    values.try_into().expect("the model's dimension")
}

/// Largest RNEA and ABA relative differences over the states of one model.
fn check_model<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model_f32: &Model<f32, NB, NQ, NV>,
    states: &HashMap<(String, usize), State>,
) -> (f64, f64, usize) {
    let model = model_f32.cast::<f64>().unwrap();
    let mut data = Data::new();
    let (mut worst_rnea, mut worst_aba, mut count) = (0.0f64, 0.0f64, 0);
    for ((_, index), state) in states.iter().filter(|((m, _), _)| m == name) {
        let mut q: [f64; NQ] = array(&state["q"]);
        // The f32 quaternion is unit to f32 precision; f64 checks are stricter.
        model.normalize(&mut q).unwrap();
        let v: [f64; NV] = array(&state["v"]);
        let tau = rnea(&model, &mut data, &q, &v, &array(&state["a"]), None).unwrap();
        let e_rnea = relative_difference(&state["rnea"], tau);
        let ddq = aba(&model, &mut data, &q, &v, &array(&state["u"]), None).unwrap();
        let e_aba = relative_difference(&state["aba"], ddq);
        assert!(
            e_rnea <= RNEA_BOUND,
            "{name} state {index}: RNEA f32 vs f64 relative difference {e_rnea:e} > {RNEA_BOUND:e}"
        );
        assert!(
            e_aba <= ABA_BOUND,
            "{name} state {index}: ABA f32 vs f64 relative difference {e_aba:e} > {ABA_BOUND:e}"
        );
        worst_rnea = worst_rnea.max(e_rnea);
        worst_aba = worst_aba.max(e_aba);
        count += 1;
    }
    (worst_rnea, worst_aba, count)
}

#[test]
fn firmware_f32_results_agree_with_host_f64() {
    let path = std::env::var("RODYN_AGREEMENT_LOG").unwrap_or_else(|_| {
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../firmware/expected/agreement.log"
        )
        .to_string()
    });
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let states = parse_log(&text);
    for (name, (rnea_err, aba_err, count)) in [
        (
            "pendulum",
            check_model("pendulum", &pendulum::MODEL_F32, &states),
        ),
        ("panda", check_model("panda", &panda::MODEL_F32, &states)),
        (
            "quadruped",
            check_model("quadruped", &aibo::MODEL_F32, &states),
        ),
    ] {
        println!("{name}: {count} states, max relative difference RNEA {rnea_err:.2e}, ABA {aba_err:.2e}");
        assert!(count >= 8, "{name}: only {count} states in {path}");
    }
}
