//! Two humanoids in single precision, where a pivot test relative to the
//! largest entry of a matrix refused them: Talos with its grippers (50
//! velocity coordinates; a gripper joint's pivot is a millionth of the
//! trunk's diagonal entry of `M`) and Unitree's G1 (35) standing on both
//! soles as 6-D frame contacts (a contact's force rows in 1/kg beside its
//! moment rows in 1/(kg m²) in the Delassus matrix). Each pivot is now
//! compared with its own row's diagonal entry, so both factor in f32 and
//! agree with the same algorithm in f64.
//!
//! The measure: `‖x₃₂ − x₆₄‖₂ / ‖x₆₄‖₂` over the whole result vector (or
//! matrix, for the derivatives), the worst over the fixture's states. The
//! inputs are rounded to f32 first and the f64 run takes the rounded
//! values, so the difference is the f32 arithmetic's alone. The models and
//! states come from `tools/pinocchio/make_contact_fixtures.py`
//! (`fixtures/contacts/talos_full.json`, `g1.json`).

use rodyn::algorithm::constrained_dynamics::{
    constrained_forward_dynamics, impulse_dynamics, ConstraintData, ConstraintSettings, Contact,
};
use rodyn::algorithm::crba::crba;
use rodyn::algorithm::derivatives::{aba_derivatives, DerivativeData};
use rodyn::algorithm::forward_dynamics::{Crba, ForwardDynamics};
use rodyn::algorithm::ltdl::ltdl_factor;
use rodyn::{Data, Error, Model, Scalar};
use rodyn_host_tests::contact_fixture::{array, contacts};
use rodyn_host_tests::fixture::{fixtures_dir, Fixture};
use serde_json::Value;

const TALOS_NB: usize = 45;
const TALOS_NQ: usize = 51;
const TALOS_NV: usize = 50;
const G1_NB: usize = 30;
const G1_NQ: usize = 36;
const G1_NV: usize = 35;
/// Two 6-D sole contacts.
const NC: usize = 12;

/// The bound on every measure below: the 1e-4 relative.
const BOUND: f64 = 1e-4;

fn load<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
) -> (Model<f64, NB, NQ, NV>, Value) {
    let path = fixtures_dir().join(format!("contacts/{name}.json"));
    let model = Fixture::load(&path).unwrap().model::<NB, NQ, NV>().unwrap();
    let text = std::fs::read_to_string(path).unwrap();
    (model, serde_json::from_str(&text).unwrap())
}

/// `‖x − y‖₂ / ‖y‖₂`.
fn relative_norm(x: &[f64], y: &[f64]) -> f64 {
    let diff: f64 = x.iter().zip(y).map(|(a, b)| (a - b) * (a - b)).sum();
    let norm: f64 = y.iter().map(|b| b * b).sum();
    (diff / norm).sqrt()
}

fn widen<S: Scalar>(x: &[S]) -> Vec<f64> {
    x.iter().map(|v| v.to_f64()).collect()
}

/// A state's `(q, v, τ)` rounded to f32, in both precisions.
struct State<const NQ: usize, const NV: usize> {
    q: [f32; NQ],
    v: [f32; NV],
    tau: [f32; NV],
}

impl<const NQ: usize, const NV: usize> State<NQ, NV> {
    fn read(state: &Value) -> Self {
        Self {
            q: array::<NQ>(&state["q"]).map(|x| x as f32),
            v: array::<NV>(&state["v"]).map(|x| x as f32),
            tau: array::<NV>(&state["tau"]).map(|x| x as f32),
        }
    }
    /// The same numbers in f64, the base's quaternion normalised again
    /// (rounded to f32, its norm is off by more than f64's tolerance).
    fn wide<const NB: usize>(
        &self,
        model: &Model<f64, NB, NQ, NV>,
    ) -> ([f64; NQ], [f64; NV], [f64; NV]) {
        let mut q = self.q.map(f64::from);
        model.normalize(&mut q).unwrap();
        (q, self.v.map(f64::from), self.tau.map(f64::from))
    }
}

/// CRBA forward dynamics and the derivatives of ABA in f32 against f64:
/// the worst relative differences of q̈ and of `∂q̈/∂q`, `∂q̈/∂v`, `M⁻¹`.
fn unconstrained<const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<f64, NB, NQ, NV>,
    fixture: &Value,
) -> (f64, f64) {
    let model32 = model.cast::<f32>().unwrap();
    let (mut d64, mut d32) = (Box::new(Data::new()), Box::new(Data::new()));
    let mut deriv64 = Box::new(DerivativeData::<f64, NB, NV>::new());
    let mut deriv32 = Box::new(DerivativeData::<f32, NB, NV>::new());
    let (mut worst_fd, mut worst_deriv) = (0.0_f64, 0.0_f64);
    for state in fixture["contact_states"].as_array().unwrap() {
        let s = State::<NQ, NV>::read(state);
        let (q, v, tau) = s.wide(model);
        let a64 = widen(Crba::forward_dynamics(model, &mut d64, &q, &v, &tau, None).unwrap());
        let a32 = Crba::forward_dynamics(&model32, &mut d32, &s.q, &s.v, &s.tau, None)
            .unwrap_or_else(|e| panic!("CRBA forward dynamics in f32: {e}"));
        worst_fd = worst_fd.max(relative_norm(&widen(a32), &a64));

        aba_derivatives(model, &mut d64, &mut deriv64, &q, &v, &tau, None).unwrap();
        aba_derivatives(&model32, &mut d32, &mut deriv32, &s.q, &s.v, &s.tau, None)
            .unwrap_or_else(|e| panic!("ABA derivatives in f32: {e}"));
        for (m32, m64) in [
            (&deriv32.ddq_dq, &deriv64.ddq_dq),
            (&deriv32.ddq_dv, &deriv64.ddq_dv),
            (&deriv32.minv, &deriv64.minv),
        ] {
            let x: Vec<f64> = m32.iter().flat_map(|r| widen(r)).collect();
            let y: Vec<f64> = m64.iter().flat_map(|r| widen(r)).collect();
            worst_deriv = worst_deriv.max(relative_norm(&x, &y));
        }
    }
    (worst_fd, worst_deriv)
}

/// The KKT constraint dynamics (`q̈`, `λ`) and impulse dynamics (`v⁺`,
/// `Λ`) of every contact case in f32 against f64: the worst relative
/// difference of each.
fn constrained<const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<f64, NB, NQ, NV>,
    fixture: &Value,
) -> [f64; 4] {
    let model32 = model.cast::<f32>().unwrap();
    let (mut d64, mut d32) = (Box::new(Data::new()), Box::new(Data::new()));
    let mut c64 = Box::new(ConstraintData::<f64, NV, NC>::new());
    let mut c32 = Box::new(ConstraintData::<f32, NV, NC>::new());
    let mut worst = [0.0_f64; 4];
    for state in fixture["contact_states"].as_array().unwrap() {
        let s = State::<NQ, NV>::read(state);
        let (q, v, tau) = s.wide(model);
        for case in state["cases"].as_array().unwrap() {
            let held64: Vec<Contact<f64>> = contacts(case)
                .iter()
                .map(|c| c.cast::<f32>().cast::<f64>())
                .collect();
            let held32: Vec<Contact<f32>> = held64.iter().map(Contact::cast).collect();
            let (a64, l64) = constrained_forward_dynamics(
                model,
                &mut d64,
                &mut c64,
                &q,
                &v,
                &tau,
                &held64,
                &ConstraintSettings::default(),
            )
            .map(|(a, l)| (widen(a), widen(l)))
            .unwrap();
            let (a32, l32) = constrained_forward_dynamics(
                &model32,
                &mut d32,
                &mut c32,
                &s.q,
                &s.v,
                &s.tau,
                &held32,
                &ConstraintSettings::default(),
            )
            .map(|(a, l)| (widen(a), widen(l)))
            .unwrap_or_else(|e| panic!("KKT constraint dynamics in f32: {e}"));
            worst[0] = worst[0].max(relative_norm(&a32, &a64));
            worst[1] = worst[1].max(relative_norm(&l32, &l64));

            let (v64, i64) = impulse_dynamics(model, &mut d64, &mut c64, &q, &v, &held64, 0.0, 0.0)
                .map(|(a, l)| (widen(a), widen(l)))
                .unwrap();
            let (v32, i32) =
                impulse_dynamics(&model32, &mut d32, &mut c32, &s.q, &s.v, &held32, 0.0, 0.0)
                    .map(|(a, l)| (widen(a), widen(l)))
                    .unwrap_or_else(|e| panic!("impulse dynamics in f32: {e}"));
            worst[2] = worst[2].max(relative_norm(&v32, &v64));
            worst[3] = worst[3].max(relative_norm(&i32, &i64));
        }
    }
    worst
}

#[test]
fn talos_with_grippers_in_f32() {
    let (model, fixture) = load::<TALOS_NB, TALOS_NQ, TALOS_NV>("talos_full");
    let (fd, deriv) = unconstrained(&model, &fixture);
    let [ddq, lambda, v_plus, impulse] = constrained(&model, &fixture);
    eprintln!(
        "Talos (50 DoF) f32 against f64: CRBA FD {fd:.1e}, ABA derivatives {deriv:.1e}, \
         KKT q̈ {ddq:.1e} λ {lambda:.1e}, impulses v⁺ {v_plus:.1e} Λ {impulse:.1e}"
    );
    for (what, x) in [
        ("CRBA forward dynamics", fd),
        ("ABA derivatives", deriv),
        ("KKT q̈", ddq),
        ("KKT λ", lambda),
        ("impulse v⁺", v_plus),
        ("impulse Λ", impulse),
    ] {
        assert!(x < BOUND, "{what}: {x:e}");
    }
}

#[test]
fn g1_on_two_soles_in_f32() {
    let (model, fixture) = load::<G1_NB, G1_NQ, G1_NV>("g1");
    let (fd, deriv) = unconstrained(&model, &fixture);
    let [ddq, lambda, v_plus, impulse] = constrained(&model, &fixture);
    eprintln!(
        "G1 (35 DoF) f32 against f64: CRBA FD {fd:.1e}, ABA derivatives {deriv:.1e}, \
         KKT q̈ {ddq:.1e} λ {lambda:.1e}, impulses v⁺ {v_plus:.1e} Λ {impulse:.1e}"
    );
    for (what, x) in [
        ("CRBA forward dynamics", fd),
        ("ABA derivatives", deriv),
        ("KKT q̈", ddq),
        ("KKT λ", lambda),
        ("impulse v⁺", v_plus),
        ("impulse Λ", impulse),
    ] {
        assert!(x < BOUND, "{what}: {x:e}");
    }
}

/// A mass matrix that is genuinely singular is still refused, in both
/// precisions: Talos's mass matrix with one gripper coordinate's row and
/// column made a copy of another's (its pivot is then rounding), and one
/// with a zero diagonal entry.
#[test]
fn a_singular_mass_matrix_is_still_refused() {
    fn refused<S: Scalar>(model: &Model<f64, TALOS_NB, TALOS_NQ, TALOS_NV>, q: &[f64; TALOS_NQ]) {
        let model = model.cast::<S>().unwrap();
        let q = q.map(S::from_f64);
        let mut data = Box::new(Data::new());
        crba(&model, &mut data, &q).unwrap();
        ltdl_factor(&model, &mut data).unwrap();
        let (copy, of) = (TALOS_NV - 1, TALOS_NV - 2);
        // Row `copy` := row `of` (lower triangle), so M has two equal
        // columns: a rank-deficient matrix.
        let m = &mut data.mass_matrix;
        for c in 0..TALOS_NV {
            let (r_of, c_of) = if c <= of { (of, c) } else { (c, of) };
            let value = m[r_of][c_of];
            if c <= copy {
                m[copy][c] = value;
            } else {
                m[c][copy] = value;
            }
        }
        m[copy][copy] = m[of][of];
        m[copy][of] = m[of][of];
        let error = ltdl_factor(&model, &mut data).unwrap_err();
        assert!(
            matches!(error, Error::MassMatrixNotPositiveDefinite { .. }),
            "{error}"
        );
        crba(&model, &mut data, &q).unwrap();
        data.mass_matrix[10][10] = S::ZERO;
        assert!(matches!(
            ltdl_factor(&model, &mut data),
            Err(Error::MassMatrixNotPositiveDefinite { dof: 10, .. })
        ));
    }
    let (model, fixture) = load::<TALOS_NB, TALOS_NQ, TALOS_NV>("talos_full");
    let q = array::<TALOS_NQ>(&fixture["contact_states"][0]["q"]);
    refused::<f64>(&model, &q);
    refused::<f32>(&model, &q);
}

/// Two contacts that hold the same sole twice are redundant in both
/// precisions: the Delassus matrix's test per row still finds the copy.
#[test]
fn redundant_sole_contacts_are_still_refused() {
    fn refused<S: Scalar>(
        model: &Model<f64, G1_NB, G1_NQ, G1_NV>,
        q: &[f64; G1_NQ],
        sole: &Contact<f64>,
    ) {
        let model = model.cast::<S>().unwrap();
        let q = q.map(S::from_f64);
        let mut data = Box::new(Data::new());
        let mut cdata = Box::new(ConstraintData::<S, G1_NV, NC>::new());
        let twice = [sole.cast::<S>(), sole.cast::<S>()];
        let error = constrained_forward_dynamics(
            &model,
            &mut data,
            &mut cdata,
            &q,
            &[S::ZERO; G1_NV],
            &[S::ZERO; G1_NV],
            &twice,
            &ConstraintSettings::default(),
        )
        .unwrap_err();
        assert!(
            matches!(error, Error::RedundantConstraints { contact: 1, .. }),
            "{error}"
        );
    }
    let (model, fixture) = load::<G1_NB, G1_NQ, G1_NV>("g1");
    let state = &fixture["contact_states"][0];
    let q = array::<G1_NQ>(&state["q"]);
    let sole = contacts(&state["cases"][1])[0];
    refused::<f64>(&model, &q, &sole);
    refused::<f32>(&model, &q, &sole);
}
