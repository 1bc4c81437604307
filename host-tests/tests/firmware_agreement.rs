//! The no_std f32 firmware build against the std f64 build.
//!
//! The `agreement` firmware example (run in QEMU by `cargo xtask test`)
//! prints seeded random inputs and its f32 results of RNEA, ABA, CRBA (the
//! whole mass matrix) and CRBA forward dynamics. This test reads that log,
//! recomputes each in f64 on the host from the same
//! inputs and the same model parameters (the f32 models that
//! `rodyn-scenarios` generates from `models/` for the firmware, cast to
//! f64), and bounds the norm-wise relative difference
//! `‖x_f32 − x_f64‖∞ / ‖x_f64‖∞`.
//!
//! The log is `firmware/expected/agreement.log` (checked in, produced by the
//! firmware in QEMU), or the file named by `RODYN_AGREEMENT_LOG`, which
//! `cargo xtask test` sets to the log of the run it just made.

use rodyn::algorithm::aba::aba;
use rodyn::algorithm::crba::crba;
use rodyn::algorithm::forward_dynamics::{Crba, ForwardDynamics};
use rodyn::algorithm::ltdl::ltdl_factor;
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
/// Bound on the mass matrix's relative difference (over all its entries),
/// 32 f32 epsilons like RNEA's.
const CRBA_BOUND: f64 = 32.0 * f32::EPSILON as f64;
/// Bound on CRBA forward dynamics' relative difference, 32 f32 epsilons
/// like ABA's: the factorisation of M divides by its pivots as ABA does by
/// the articulated inertias.
const CRBA_FD_BOUND: f64 = 32.0 * f32::EPSILON as f64;

/// Where the firmware's f32 factorisation refuses `M` (the quadruped's
/// 20 g shoulders and light legs on a 1 kg trunk), the f64 pivot at that
/// coordinate must be under this many f32 epsilons of the largest diagonal
/// entry: twice the factorisation's tolerance (64), so the refusal comes
/// from the matrix's conditioning, not from an error in the firmware.
const REFUSED_PIVOT_EPS: f64 = 128.0;
/// States per model that may be refused; none of the pendulum's or the
/// Panda's are.
const MAX_REFUSED: usize = 2;

/// Inputs and f32 results of one state, by field name (`q`, `v`, `a`, `u`,
/// `rnea`, `aba`, `m0`, `m1`, ... for the mass matrix's rows, `crba_fd`,
/// or `crba_fd_refused` with the coordinate and the relative pivot).
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

/// Largest relative differences over the states of one model.
#[derive(Default)]
struct Worst {
    rnea: f64,
    aba: f64,
    crba: f64,
    crba_fd: f64,
    states: usize,
    refused: usize,
}

/// Checks one result against its bound and keeps the largest difference.
fn check(name: &str, index: usize, what: &str, worst: &mut f64, error: f64, bound: f64) {
    assert!(
        error <= bound,
        "{name} state {index}: {what} f32 vs f64 relative difference {error:e} > {bound:e}"
    );
    *worst = worst.max(error);
}

/// Recomputes every result of one model's states in f64 and checks them.
fn check_model<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model_f32: &Model<f32, NB, NQ, NV>,
    states: &HashMap<(String, usize), State>,
) -> Worst {
    let model = model_f32.cast::<f64>().unwrap();
    let mut data = Data::new();
    let mut worst = Worst::default();
    for ((_, index), state) in states.iter().filter(|((m, _), _)| m == name) {
        let index = *index;
        let mut q: [f64; NQ] = array(&state["q"]);
        // The f32 quaternion is unit to f32 precision; f64 checks are stricter.
        model.normalize(&mut q).unwrap();
        let v: [f64; NV] = array(&state["v"]);
        let u: [f64; NV] = array(&state["u"]);
        let tau = rnea(&model, &mut data, &q, &v, &array(&state["a"]), None).unwrap();
        let e = relative_difference(&state["rnea"], tau);
        check(name, index, "RNEA", &mut worst.rnea, e, RNEA_BOUND);
        let ddq = aba(&model, &mut data, &q, &v, &u, None).unwrap();
        let e = relative_difference(&state["aba"], ddq);
        check(name, index, "ABA", &mut worst.aba, e, ABA_BOUND);
        // The whole matrix, row after row, against the f64 one.
        let m_f32: Vec<f64> = (0..NV)
            .flat_map(|r| state[&format!("m{r}")].iter().copied())
            .collect();
        let m = crba(&model, &mut data, &q).unwrap();
        let e = relative_difference(&m_f32, m.as_flattened());
        check(name, index, "CRBA", &mut worst.crba, e, CRBA_BOUND);
        let ddq = Crba::forward_dynamics(&model, &mut data, &q, &v, &u, None).unwrap();
        if let Some(refused) = state.get("crba_fd_refused") {
            // The f64 factorisation of the same M (the one just formed).
            let dof = refused[0] as usize;
            ltdl_factor(&model, &mut data).unwrap();
            let scale = (0..NV).fold(0.0f64, |s, k| s.max(data.mass_matrix[k][k]));
            let pivot = data.ltdl[dof][dof] / scale;
            let bound = REFUSED_PIVOT_EPS * f64::from(f32::EPSILON);
            assert!(
                pivot < bound,
                "{name} state {index}: the firmware refused M at coordinate {dof}, \
                 where the f64 relative pivot is {pivot:e} (not under {bound:e})"
            );
            println!(
                "{name} state {index}: CRBA forward dynamics refused in f32 at coordinate {dof} \
                 (relative pivot {:.2e}; f64 {pivot:.2e})",
                refused[1]
            );
            worst.refused += 1;
        } else {
            let e = relative_difference(&state["crba_fd"], ddq);
            check(
                name,
                index,
                "CRBA forward dynamics",
                &mut worst.crba_fd,
                e,
                CRBA_FD_BOUND,
            );
        }
        worst.states += 1;
    }
    worst
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
    for (name, worst) in [
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
        println!(
            "{name}: {} states, max relative difference RNEA {:.2e}, ABA {:.2e}, \
             CRBA {:.2e}, CRBA forward dynamics {:.2e} ({} refused)",
            worst.states, worst.rnea, worst.aba, worst.crba, worst.crba_fd, worst.refused
        );
        let refusable = if name == "quadruped" { MAX_REFUSED } else { 0 };
        assert!(
            worst.refused <= refusable,
            "{name}: CRBA forward dynamics refused {} states in f32",
            worst.refused
        );
        assert!(
            worst.states >= 8,
            "{name}: only {} states in {path}",
            worst.states
        );
    }
}
