//! Reading the contact fixtures of `tools/pinocchio/make_contact_fixtures.py`
//! (`fixtures/contacts/*.json`): states, contact sets and Pinocchio's
//! results as JSON values, with helpers to turn them into rodyn's types.

use crate::fixture::{fixtures_dir, Fixture};
use rodyn::algorithm::constrained_dynamics::Contact;
use rodyn::spatial::{Mat3, Transform, Vec3};
use rodyn::{Frame, Model};
use serde_json::Value;

/// Solo12's sizes: 13 moving bodies, a free flyer.
pub const SOLO_NB: usize = 13;
/// Solo12's configuration size.
pub const SOLO_NQ: usize = 19;
/// Solo12's velocity size.
pub const SOLO_NV: usize = 18;
/// Talos (`talos_reduced`): 33 moving bodies, a free flyer.
pub const TALOS_NB: usize = 33;
/// Talos's configuration size.
pub const TALOS_NQ: usize = 39;
/// Talos's velocity size.
pub const TALOS_NV: usize = 38;

/// Solo12 as its fixture describes it.
///
/// # Panics
/// When the fixture is missing or malformed (a test's failure).
#[must_use]
pub fn solo12() -> Model<f64, SOLO_NB, SOLO_NQ, SOLO_NV> {
    Fixture::load_named("solo12")
        .unwrap()
        .model::<SOLO_NB, SOLO_NQ, SOLO_NV>()
        .unwrap()
}

/// `fixtures/contacts/solo12.json`: `states[k]` holds `q`, `v`, `tau`
/// and `cases`.
///
/// # Panics
/// When the fixture is missing or malformed.
#[must_use]
pub fn solo12_contacts() -> Value {
    read("contacts/solo12.json")
}

/// Talos and `fixtures/contacts/talos.json` (its states under
/// `contact_states`).
///
/// # Panics
/// When the fixture is missing or malformed.
#[must_use]
pub fn talos() -> (Model<f64, TALOS_NB, TALOS_NQ, TALOS_NV>, Value) {
    let path = fixtures_dir().join("contacts/talos.json");
    let model = Fixture::load(&path)
        .unwrap()
        .model::<TALOS_NB, TALOS_NQ, TALOS_NV>()
        .unwrap();
    (model, read("contacts/talos.json"))
}

fn read(name: &str) -> Value {
    let text = std::fs::read_to_string(fixtures_dir().join(name)).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// Every number in `v` (nested arrays flattened).
///
/// # Panics
/// On anything but numbers and arrays.
#[must_use]
pub fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(a) => a.iter().flat_map(numbers).collect(),
        Value::Number(n) => vec![n.as_f64().unwrap()],
        _ => panic!("not numbers: {v}"),
    }
}

/// `v`'s numbers as an array of `N`.
///
/// # Panics
/// When there are not exactly `N`.
#[must_use]
pub fn array<const N: usize>(v: &Value) -> [f64; N] {
    numbers(v).try_into().unwrap()
}

/// A placement `{"rotation": 9 numbers by rows, "translation": 3}`.
#[must_use]
pub fn transform(p: &Value) -> Transform<f64> {
    let r = numbers(&p["rotation"]);
    let t = numbers(&p["translation"]);
    Transform::new(
        Mat3::from_rows([[r[0], r[1], r[2]], [r[3], r[4], r[5]], [r[6], r[7], r[8]]]),
        Vec3::new(t[0], t[1], t[2]),
    )
}

/// One contact of a case: a point or a frame on its body, with its anchor.
///
/// # Panics
/// On an unknown kind or a malformed entry.
#[must_use]
pub fn contact(c: &Value) -> Contact<f64> {
    let frame = Frame::new(
        usize::try_from(c["body"].as_u64().unwrap()).unwrap(),
        transform(&c["placement"]),
    );
    match c["kind"].as_str().unwrap() {
        "point" => {
            let a = numbers(&c["anchor"]);
            Contact::point(frame, Vec3::new(a[0], a[1], a[2]))
        }
        "frame" => Contact::frame(frame, transform(&c["anchor"])),
        kind => panic!("unknown contact kind {kind}"),
    }
}

/// A case's contacts.
#[must_use]
pub fn contacts(case: &Value) -> Vec<Contact<f64>> {
    case["contacts"]
        .as_array()
        .unwrap()
        .iter()
        .map(contact)
        .collect()
}

/// The largest difference of `x` from `reference`, relative to the larger
/// of 1 and `reference`'s largest entry.
#[must_use]
pub fn relative(x: &[f64], reference: &[f64]) -> f64 {
    let scale = reference.iter().fold(1.0_f64, |m, r| m.max(r.abs()));
    x.iter()
        .zip(reference)
        .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()))
        / scale
}
