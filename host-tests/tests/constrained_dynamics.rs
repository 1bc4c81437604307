//! Forward dynamics with rigid point contacts against Pinocchio 4.1's
//! `constraintDynamics` (Solo12, 1 to 4 feet, with and without Baumgarte
//! stabilisation), identities that hold whatever the reference, and bad
//! input.

use rodyn::algorithm::constrained_dynamics::{
    constrained_forward_dynamics, ConstraintData, ConstraintSettings, PointContact,
};
use rodyn::algorithm::forward_dynamics::{Aba, ForwardDynamics};
use rodyn::algorithm::frames::{
    frame_classical_acceleration, frame_placement, frame_velocity, ReferenceFrame,
};
use rodyn::algorithm::kinematics::forward_kinematics_acceleration;
use rodyn::algorithm::rnea::rnea;
use rodyn::prelude::*;
use rodyn::Frame;
use rodyn_host_tests::fixture::{fixtures_dir, Fixture};
use serde_json::Value;

const NB: usize = 13;
const NQ: usize = 19;
const NV: usize = 18;
const NC: usize = 12;

fn model() -> Model<f64, NB, NQ, NV> {
    Fixture::load_named("solo12")
        .unwrap()
        .model::<NB, NQ, NV>()
        .unwrap()
}

fn numbers(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(a) => a.iter().flat_map(numbers).collect(),
        Value::Number(n) => vec![n.as_f64().unwrap()],
        _ => panic!("not numbers: {v}"),
    }
}

fn array<const N: usize>(v: &Value) -> [f64; N] {
    numbers(v).try_into().unwrap()
}

fn contact(c: &Value) -> PointContact<f64> {
    let r = numbers(&c["placement"]["rotation"]);
    let t = numbers(&c["placement"]["translation"]);
    let a = numbers(&c["anchor"]);
    PointContact {
        frame: Frame::new(
            c["body"].as_u64().unwrap() as usize,
            Transform::new(
                Mat3::from_rows([[r[0], r[1], r[2]], [r[3], r[4], r[5]], [r[6], r[7], r[8]]]),
                Vec3::new(t[0], t[1], t[2]),
            ),
        ),
        anchor: Vec3::new(a[0], a[1], a[2]),
    }
}

fn relative(x: &[f64], reference: &[f64]) -> f64 {
    let scale = reference.iter().fold(1.0_f64, |m, r| m.max(r.abs()));
    x.iter()
        .zip(reference)
        .fold(0.0, |m, (a, b)| m.max((a - b).abs()))
        / scale
}

/// q̈ and λ within 1e-9 relative of Pinocchio's on every state and case.
#[test]
fn matches_pinocchio_constraint_dynamics() {
    let text = std::fs::read_to_string(fixtures_dir().join("contacts/solo12.json")).unwrap();
    let fixture: Value = serde_json::from_str(&text).unwrap();
    let model = model();
    let mut data = Data::new();
    let mut cdata = ConstraintData::<f64, NV, NC>::new();
    let (mut worst_ddq, mut worst_lambda, mut cases) = (0.0_f64, 0.0_f64, 0);
    for state in fixture["states"].as_array().unwrap() {
        let (q, v, tau) = (
            array::<NQ>(&state["q"]),
            array::<NV>(&state["v"]),
            array::<NV>(&state["tau"]),
        );
        for case in state["cases"].as_array().unwrap() {
            let contacts: Vec<PointContact<f64>> = case["contacts"]
                .as_array()
                .unwrap()
                .iter()
                .map(contact)
                .collect();
            let settings = ConstraintSettings {
                kp: case["kp"].as_f64().unwrap(),
                kd: case["kd"].as_f64().unwrap(),
                damping: 0.0,
            };
            let (ddq, lambda) = constrained_forward_dynamics(
                &model, &mut data, &mut cdata, &q, &v, &tau, &contacts, &settings,
            )
            .unwrap();
            worst_ddq = worst_ddq.max(relative(ddq, &numbers(&case["ddq"])));
            worst_lambda = worst_lambda.max(relative(lambda, &numbers(&case["lambda"])));
            cases += 1;
        }
    }
    eprintln!("{cases} cases: q̈ within {worst_ddq:.1e}, λ within {worst_lambda:.1e} of Pinocchio");
    assert_eq!(cases, 40);
    assert!(
        worst_ddq < 1e-9 && worst_lambda < 1e-9,
        "q̈ {worst_ddq:e}, λ {worst_lambda:e}"
    );
}

/// The four feet of one fixture state, anchored where they are.
fn feet(model: &Model<f64, NB, NQ, NV>, q: &[f64; NQ]) -> Vec<PointContact<f64>> {
    let text = std::fs::read_to_string(fixtures_dir().join("contacts/solo12.json")).unwrap();
    let fixture: Value = serde_json::from_str(&text).unwrap();
    let mut data = Data::new();
    rodyn::algorithm::kinematics::forward_kinematics(model, &mut data, q).unwrap();
    fixture["states"][0]["cases"][3]["contacts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            let mut contact = contact(c);
            contact.anchor = frame_placement(&data, &contact.frame).unwrap().trans;
            contact
        })
        .collect()
}

/// The equations themselves, on every fixture state with the four feet
/// held and Baumgarte gains: M q̈ + h = τ + J_cᵀ λ (through RNEA with the
/// contact forces as external forces), and each foot's acceleration is the
/// Baumgarte term; with no contact the result is ABA's.
#[test]
fn satisfies_the_equations_of_motion_and_the_constraints() {
    let model = model();
    let base = Fixture::load_named("solo12").unwrap();
    let mut data = Data::new();
    let mut cdata = ConstraintData::<f64, NV, NC>::new();
    let settings = ConstraintSettings {
        kp: 25.0,
        kd: 7.0,
        damping: 0.0,
    };
    for state in &base.states {
        let (q, v, tau): ([f64; NQ], [f64; NV], [f64; NV]) = (
            state.q.clone().try_into().unwrap(),
            state.v.clone().try_into().unwrap(),
            state.tau.clone().try_into().unwrap(),
        );
        let mut contacts = feet(&model, &q);
        for c in &mut contacts {
            c.anchor.z += 0.003; // a drift for the position feedback to act on
        }
        let (ddq, lambda) = constrained_forward_dynamics(
            &model, &mut data, &mut cdata, &q, &v, &tau, &contacts, &settings,
        )
        .unwrap();
        let (ddq, lambda) = (*ddq, lambda.to_vec());

        // Contact forces as external forces on the feet's bodies (body
        // frame, about its origin): RNEA must then return τ.
        rodyn::algorithm::kinematics::forward_kinematics(&model, &mut data, &q).unwrap();
        let mut f_ext = [Force::ZERO; NB];
        for (c, contact) in contacts.iter().enumerate() {
            let o_m_b = data.o_m_i[contact.frame.body];
            let f_world = Vec3::new(lambda[3 * c], lambda[3 * c + 1], lambda[3 * c + 2]);
            let point = contact.frame.placement.trans;
            f_ext[contact.frame.body] += Force::at_point(o_m_b.rot.tr_mul_vec(&f_world), &point);
        }
        let tau_back = *rnea(&model, &mut data, &q, &v, &ddq, Some(&f_ext)).unwrap();
        assert!(
            relative(&tau_back, &tau) < 1e-10,
            "{:e}",
            relative(&tau_back, &tau)
        );

        forward_kinematics_acceleration(&model, &mut data, &q, &v, &ddq).unwrap();
        for contact in &contacts {
            let acc = frame_classical_acceleration(
                &data,
                &contact.frame,
                ReferenceFrame::LocalWorldAligned,
            )
            .unwrap()
            .lin;
            let vel = frame_velocity(&data, &contact.frame, ReferenceFrame::LocalWorldAligned)
                .unwrap()
                .lin;
            let err = frame_placement(&data, &contact.frame).unwrap().trans - contact.anchor;
            let want = -(err * settings.kp) - vel * settings.kd;
            let miss = (acc - want).norm();
            assert!(
                miss < 1e-9 * (1.0 + want.norm()),
                "foot acceleration off by {miss:e}"
            );
        }

        let (none, _) = constrained_forward_dynamics(
            &model,
            &mut data,
            &mut cdata,
            &q,
            &v,
            &tau,
            &[],
            &settings,
        )
        .unwrap();
        let none = *none;
        let aba = *Aba::forward_dynamics(&model, &mut data, &q, &v, &tau, None).unwrap();
        assert!(relative(&none, &aba) < 1e-11);
    }
}

/// Bad input gives errors: too many contacts for the workspace, negative or
/// NaN gains, a missing body, a NaN anchor; redundant contacts (the same
/// foot twice) without damping name the row, and with damping give a
/// finite answer that still holds the foot.
#[test]
fn bad_input_and_redundant_contacts() {
    let model = model();
    let base = Fixture::load_named("solo12").unwrap();
    let q: [f64; NQ] = base.states[0].q.clone().try_into().unwrap();
    let v = [0.0; NV];
    let tau = [0.0; NV];
    let contacts = feet(&model, &q);
    let mut data = Data::new();
    let mut small = ConstraintData::<f64, NV, 6>::new();
    let error = constrained_forward_dynamics(
        &model,
        &mut data,
        &mut small,
        &q,
        &v,
        &tau,
        &contacts,
        &ConstraintSettings::default(),
    )
    .unwrap_err();
    assert_eq!(
        error,
        Error::TooManyConstraints {
            rows: 12,
            capacity: 6
        }
    );
    let mut cdata = ConstraintData::<f64, NV, NC>::new();
    for (settings, index) in [
        (
            ConstraintSettings {
                kp: -1.0,
                ..ConstraintSettings::default()
            },
            0,
        ),
        (
            ConstraintSettings {
                kd: f64::NAN,
                ..ConstraintSettings::default()
            },
            1,
        ),
        (
            ConstraintSettings {
                damping: f64::INFINITY,
                ..ConstraintSettings::default()
            },
            2,
        ),
    ] {
        let error = constrained_forward_dynamics(
            &model, &mut data, &mut cdata, &q, &v, &tau, &contacts, &settings,
        )
        .unwrap_err();
        assert_eq!(error, Error::InvalidGain { index });
    }
    let mut missing = contacts[0];
    missing.frame.body = NB;
    let error = constrained_forward_dynamics(
        &model,
        &mut data,
        &mut cdata,
        &q,
        &v,
        &tau,
        &[missing],
        &ConstraintSettings::default(),
    )
    .unwrap_err();
    assert_eq!(error, Error::FrameBodyOutOfRange { body: NB });
    let mut nan = contacts[1];
    nan.anchor.y = f64::NAN;
    let error = constrained_forward_dynamics(
        &model,
        &mut data,
        &mut cdata,
        &q,
        &v,
        &tau,
        &[contacts[0], nan],
        &ConstraintSettings::default(),
    )
    .unwrap_err();
    assert_eq!(
        error,
        Error::NonFinite {
            quantity: rodyn::error::Quantity::Contact,
            index: 1
        }
    );

    let twice = [contacts[0], contacts[0]];
    let error = constrained_forward_dynamics(
        &model,
        &mut data,
        &mut cdata,
        &q,
        &v,
        &tau,
        &twice,
        &ConstraintSettings::default(),
    )
    .unwrap_err();
    assert!(
        matches!(error, Error::RedundantConstraints { row: 3..=5 }),
        "{error:?}"
    );
    let damped = ConstraintSettings {
        damping: 1e-6,
        ..ConstraintSettings::default()
    };
    let (ddq, lambda) =
        constrained_forward_dynamics(&model, &mut data, &mut cdata, &q, &v, &tau, &twice, &damped)
            .unwrap();
    let (ddq, lambda) = (*ddq, lambda.to_vec());
    let (single, one) = constrained_forward_dynamics(
        &model,
        &mut data,
        &mut cdata,
        &q,
        &v,
        &tau,
        &contacts[..1],
        &ConstraintSettings::default(),
    )
    .unwrap();
    let (single, one) = (*single, one.to_vec());
    // The two copies share the one foot's force; q̈ is the single contact's.
    for axis in 0..3 {
        let shared = lambda[axis] + lambda[3 + axis];
        assert!(
            (shared - one[axis]).abs() < 1e-4 * (1.0 + one[axis].abs()),
            "{shared} against {}",
            one[axis]
        );
        assert!((lambda[axis] - lambda[3 + axis]).abs() < 1e-6 * (1.0 + one[axis].abs()));
    }
    assert!(
        relative(&ddq, &single) < 1e-4,
        "{:e}",
        relative(&ddq, &single)
    );
}

/// Impacts against Pinocchio's `impulseDynamics` (restitution 0 and 0.5,
/// every state and contact set): v⁺ and the impulses within 1e-9; the
/// contacts leave at −e times their approach velocity; no impact gains
/// kinetic energy.
#[test]
fn impacts_match_pinocchio_and_never_gain_energy() {
    use rodyn::algorithm::constrained_dynamics::impulse_dynamics;
    use rodyn::algorithm::energy::kinetic_energy;
    let text = std::fs::read_to_string(fixtures_dir().join("contacts/solo12.json")).unwrap();
    let fixture: Value = serde_json::from_str(&text).unwrap();
    let model = model();
    let mut data = Data::new();
    let mut cdata = ConstraintData::<f64, NV, NC>::new();
    let (mut worst, mut impacts) = (0.0_f64, 0);
    for state in fixture["states"].as_array().unwrap() {
        let (q, v) = (array::<NQ>(&state["q"]), array::<NV>(&state["v"]));
        let energy_before = kinetic_energy(&model, &mut data, &q, &v).unwrap();
        for case in state["cases"].as_array().unwrap() {
            let contacts: Vec<PointContact<f64>> = case["contacts"]
                .as_array()
                .unwrap()
                .iter()
                .map(contact)
                .collect();
            for impact in case["impacts"].as_array().unwrap() {
                let e = impact["restitution"].as_f64().unwrap();
                let (v_after, impulse) =
                    impulse_dynamics(&model, &mut data, &mut cdata, &q, &v, &contacts, e, 0.0)
                        .unwrap();
                let (v_after, impulse) = (*v_after, impulse.to_vec());
                worst = worst
                    .max(relative(&v_after, &numbers(&impact["v_after"])))
                    .max(relative(&impulse, &numbers(&impact["impulse"])));
                // Contact velocities after = −e × before.
                for (r, row) in cdata.jc[..cdata.rows].iter().enumerate() {
                    let before: f64 = row.iter().zip(&v).map(|(j, x)| j * x).sum();
                    let after: f64 = row.iter().zip(&v_after).map(|(j, x)| j * x).sum();
                    assert!(
                        (after + e * before).abs() < 1e-9 * (1.0 + before.abs()),
                        "row {r}: {after} after {before}"
                    );
                }
                let energy_after = kinetic_energy(&model, &mut data, &q, &v_after).unwrap();
                assert!(
                    energy_after <= energy_before * (1.0 + 1e-12),
                    "{energy_after} > {energy_before}"
                );
                impacts += 1;
            }
        }
    }
    eprintln!("{impacts} impacts: within {worst:.1e} of Pinocchio");
    assert_eq!(impacts, 80);
    assert!(worst < 1e-9, "{worst:e}");
    let error = impulse_dynamics(
        &model,
        &mut data,
        &mut cdata,
        &[0.0; NQ],
        &[0.0; NV],
        &[],
        1.5,
        0.0,
    )
    .unwrap_err();
    assert_eq!(error, Error::InvalidGain { index: 0 });
}
