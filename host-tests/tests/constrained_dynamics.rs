//! Forward dynamics with rigid contacts against Pinocchio 4.1's
//! `constraintDynamics` and `impulseDynamics` (Solo12 with 1 to 4 feet as
//! points and a foot as a frame; Talos with its soles as frames, with and
//! without Baumgarte stabilisation), identities that hold whatever the
//! reference, and bad input.

use rodyn::algorithm::constrained_dynamics::{
    constrained_forward_dynamics, constrained_forward_dynamics_with, impulse_dynamics,
    ConstraintData, ConstraintMethod, ConstraintSettings, Contact,
};
use rodyn::algorithm::energy::kinetic_energy;
use rodyn::algorithm::forward_dynamics::{Aba, ForwardDynamics};
use rodyn::algorithm::frames::{
    frame_acceleration, frame_classical_acceleration, frame_placement, frame_velocity,
    ReferenceFrame,
};
use rodyn::algorithm::kinematics::{forward_kinematics, forward_kinematics_acceleration};
use rodyn::algorithm::rnea::rnea;
use rodyn::error::Setting;
use rodyn::prelude::*;
use rodyn::space::RigidTransform;
use rodyn::spatial::log6;
use rodyn::Frame;
use rodyn_host_tests::contact_fixture::{
    array, contact, contacts, numbers, relative, solo12, solo12_contacts, talos, SOLO_NB, SOLO_NQ,
    SOLO_NV, TALOS_NB, TALOS_NQ, TALOS_NV,
};
use rodyn_host_tests::fixture::Fixture;
use serde_json::Value;

const NB: usize = SOLO_NB;
const NQ: usize = SOLO_NQ;
const NV: usize = SOLO_NV;
const NC: usize = 12;
const TALOS_NC: usize = 12;

fn model() -> Model<f64, NB, NQ, NV> {
    solo12()
}

fn solo12_fixture() -> Value {
    solo12_contacts()
}

/// The worst relative differences of q̈ and λ from Pinocchio's over the
/// states and cases of `states`, and the number of cases.
fn against_constraint_dynamics<const B: usize, const Q: usize, const V: usize, const C: usize>(
    method: ConstraintMethod,
    model: &Model<f64, B, Q, V>,
    states: &Value,
) -> (f64, f64, usize) {
    let mut data = Data::new();
    let mut cdata = ConstraintData::<f64, V, C>::new();
    let (mut worst_ddq, mut worst_lambda, mut cases) = (0.0_f64, 0.0_f64, 0);
    for state in states.as_array().unwrap() {
        let (q, v, tau) = (
            array::<Q>(&state["q"]),
            array::<V>(&state["v"]),
            array::<V>(&state["tau"]),
        );
        for case in state["cases"].as_array().unwrap() {
            let settings = ConstraintSettings::baumgarte(
                case["kp"].as_f64().unwrap(),
                case["kd"].as_f64().unwrap(),
            );
            let (ddq, lambda) = constrained_forward_dynamics_with(
                method,
                model,
                &mut data,
                &mut cdata,
                &q,
                &v,
                &tau,
                &contacts(case),
                &settings,
            )
            .unwrap();
            worst_ddq = worst_ddq.max(relative(ddq, &numbers(&case["ddq"])));
            worst_lambda = worst_lambda.max(relative(lambda, &numbers(&case["lambda"])));
            cases += 1;
        }
    }
    (worst_ddq, worst_lambda, cases)
}

const METHODS: [ConstraintMethod; 2] = [ConstraintMethod::Kkt, ConstraintMethod::ArticulatedBody];

/// q̈ and λ within 1e-9 relative of Pinocchio's on every Solo12 state and
/// case (points, a frame, a frame with a point, with and without gains),
/// by both methods.
#[test]
fn matches_pinocchio_constraint_dynamics_solo12() {
    for method in METHODS {
        let (ddq, lambda, cases) = against_constraint_dynamics::<NB, NQ, NV, NC>(
            method,
            &model(),
            &solo12_fixture()["states"],
        );
        eprintln!(
            "Solo12, {method:?}, {cases} cases: q̈ within {ddq:.1e}, λ within {lambda:.1e} of Pinocchio"
        );
        assert_eq!(cases, 56);
        assert!(ddq < 1e-9 && lambda < 1e-9, "q̈ {ddq:e}, λ {lambda:e}");
    }
}

/// The same on Talos with its soles held as 6-D frame contacts.
#[test]
fn matches_pinocchio_constraint_dynamics_talos() {
    let (model, fixture) = talos();
    for method in METHODS {
        let (ddq, lambda, cases) = against_constraint_dynamics::<
            TALOS_NB,
            TALOS_NQ,
            TALOS_NV,
            TALOS_NC,
        >(method, &model, &fixture["contact_states"]);
        eprintln!(
            "Talos, {method:?}, {cases} cases: q̈ within {ddq:.1e}, λ within {lambda:.1e} of Pinocchio"
        );
        assert_eq!(cases, 24);
        assert!(ddq < 1e-9 && lambda < 1e-9, "q̈ {ddq:e}, λ {lambda:e}");
    }
}

/// The four feet of one fixture state as point contacts, anchored where
/// they are and raised by `lift` (m).
fn feet(model: &Model<f64, NB, NQ, NV>, q: &[f64; NQ], lift: f64) -> Vec<Contact<f64>> {
    let fixture = solo12_fixture();
    let mut data = Data::new();
    forward_kinematics(model, &mut data, q).unwrap();
    fixture["states"][0]["cases"][3]["contacts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            let frame = *contact(c).held_frame();
            let mut anchor = frame_placement(&data, &frame).unwrap().trans;
            anchor.z += lift;
            Contact::point(frame, anchor)
        })
        .collect()
}

/// The equations themselves at one state: M q̈ + h = τ + J_cᵀ λ (through
/// RNEA with the contact forces as external forces), each contact's
/// acceleration is the Baumgarte term, and with no contact the result is
/// ABA's.
fn check_equations<const B: usize, const Q: usize, const V: usize, const C: usize>(
    model: &Model<f64, B, Q, V>,
    (q, v, tau): (&[f64; Q], &[f64; V], &[f64; V]),
    contacts: &[Contact<f64>],
    settings: &ConstraintSettings<f64>,
) {
    let mut data = Data::new();
    let mut cdata = ConstraintData::<f64, V, C>::new();
    let (ddq, lambda) =
        constrained_forward_dynamics(model, &mut data, &mut cdata, q, v, tau, contacts, settings)
            .unwrap();
    let (ddq, lambda) = (*ddq, lambda.to_vec());

    // Contact forces as external forces on their bodies (body frame, about
    // its origin): RNEA must then return τ.
    forward_kinematics(model, &mut data, q).unwrap();
    let mut f_ext = [Force::ZERO; B];
    let mut row = 0;
    for contact in contacts {
        let frame = contact.held_frame();
        let l = &lambda[row..row + contact.rows()];
        f_ext[frame.body] += match contact {
            Contact::Point { .. } => {
                let f_world = Vec3::new(l[0], l[1], l[2]);
                let o_m_b = data.o_m_i[frame.body];
                Force::at_point(o_m_b.rot.tr_mul_vec(&f_world), &frame.placement.trans)
            }
            Contact::Frame { .. } => frame.placement.act_force(&Force::new(
                Vec3::new(l[3], l[4], l[5]),
                Vec3::new(l[0], l[1], l[2]),
            )),
        };
        row += contact.rows();
    }
    let tau_back = *rnea(model, &mut data, q, v, &ddq, Some(&f_ext)).unwrap();
    let miss = relative(&tau_back, tau);
    assert!(miss < 1e-10, "RNEA with the contact forces: {miss:e}");

    forward_kinematics_acceleration(model, &mut data, q, v, &ddq).unwrap();
    for contact in contacts {
        let frame = contact.held_frame();
        let placement = frame_placement(&data, frame).unwrap();
        let (acc, vel, err) = match contact {
            Contact::Point { anchor, .. } => {
                let world = ReferenceFrame::LocalWorldAligned;
                let acc = frame_classical_acceleration(&data, frame, world).unwrap();
                let vel = frame_velocity(&data, frame, world).unwrap();
                let err = Motion::new(Vec3::ZERO, placement.trans - *anchor);
                (
                    Motion::new(Vec3::ZERO, acc.lin),
                    Motion::new(Vec3::ZERO, vel.lin),
                    err,
                )
            }
            Contact::Frame { anchor, .. } => (
                frame_acceleration(&data, frame, ReferenceFrame::Local).unwrap(),
                frame_velocity(&data, frame, ReferenceFrame::Local).unwrap(),
                -log6(&placement.inverse().compose(anchor)),
            ),
        };
        let want = -(err * settings.kp) - vel * settings.kd;
        let miss = (acc.lin - want.lin).norm() + (acc.ang - want.ang).norm();
        let scale = 1.0 + want.lin.norm() + want.ang.norm();
        assert!(miss < 1e-9 * scale, "contact acceleration off by {miss:e}");
    }

    let (none, _) =
        constrained_forward_dynamics(model, &mut data, &mut cdata, q, v, tau, &[], settings)
            .unwrap();
    let none = *none;
    let aba = *Aba::forward_dynamics(model, &mut data, q, v, tau, None).unwrap();
    assert!(relative(&none, &aba) < 1e-11);
}

/// The equations on every Solo12 fixture state with the four feet held
/// 3 mm below their anchors and Baumgarte gains.
#[test]
fn satisfies_the_equations_of_motion_and_the_constraints() {
    let model = model();
    let settings = ConstraintSettings::baumgarte(25.0, 7.0);
    for state in &Fixture::load_named("solo12").unwrap().states {
        let (q, v, tau): ([f64; NQ], [f64; NV], [f64; NV]) = (
            state.q.clone().try_into().unwrap(),
            state.v.clone().try_into().unwrap(),
            state.tau.clone().try_into().unwrap(),
        );
        // A drift for the position feedback to act on.
        let contacts = feet(&model, &q, 0.003);
        check_equations::<NB, NQ, NV, NC>(&model, (&q, &v, &tau), &contacts, &settings);
    }
}

/// The same on Talos with both soles held as frames (anchors moved and
/// turned) and with one sole as a frame and the other as a point.
#[test]
fn satisfies_the_equations_with_frame_contacts() {
    let (model, fixture) = talos();
    let settings = ConstraintSettings::baumgarte(30.0, 8.0);
    for state in fixture["contact_states"].as_array().unwrap() {
        let (q, v, tau) = (
            array::<TALOS_NQ>(&state["q"]),
            array::<TALOS_NV>(&state["v"]),
            array::<TALOS_NV>(&state["tau"]),
        );
        for case in [1, 3] {
            let contacts = contacts(&state["cases"][case]);
            check_equations::<TALOS_NB, TALOS_NQ, TALOS_NV, TALOS_NC>(
                &model,
                (&q, &v, &tau),
                &contacts,
                &settings,
            );
        }
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
    let contacts = feet(&model, &q, 0.0);
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
    for (settings, setting) in [
        (
            ConstraintSettings::new().with_kp(-1.0),
            Setting::PositionGain,
        ),
        (
            ConstraintSettings::new().with_kd(f64::NAN),
            Setting::VelocityGain,
        ),
        (
            ConstraintSettings::new().with_damping(f64::INFINITY),
            Setting::ContactDamping,
        ),
    ] {
        let error = constrained_forward_dynamics(
            &model, &mut data, &mut cdata, &q, &v, &tau, &contacts, &settings,
        )
        .unwrap_err();
        assert_eq!(error, Error::InvalidSetting { setting });
    }
    let foot = *contacts[0].held_frame();
    let missing = Contact::point(Frame::new(NB, foot.placement), Vec3::ZERO);
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
    let nan = Contact::point(*contacts[1].held_frame(), Vec3::new(0.0, f64::NAN, 0.0));
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
        matches!(
            error,
            Error::RedundantConstraints {
                row: 3..=5,
                contact: 1
            }
        ),
        "{error:?}"
    );
    let error = constrained_forward_dynamics_with(
        ConstraintMethod::ArticulatedBody,
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
        matches!(error, Error::RedundantConstraints { contact: 1, .. }),
        "{error:?}"
    );
    let damped = ConstraintSettings::new().with_damping(1e-6);
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

/// The worst relative difference of v⁺ and the impulses from Pinocchio's
/// `impulseDynamics` over `states`, and the number of impacts; checks on
/// the way that the contacts leave at −e times their approach velocity
/// and that no impact gains kinetic energy.
fn against_impulse_dynamics<const B: usize, const Q: usize, const V: usize, const C: usize>(
    model: &Model<f64, B, Q, V>,
    states: &Value,
) -> (f64, usize) {
    let mut data = Data::new();
    let mut cdata = ConstraintData::<f64, V, C>::new();
    let (mut worst, mut impacts) = (0.0_f64, 0);
    for state in states.as_array().unwrap() {
        let (q, v) = (array::<Q>(&state["q"]), array::<V>(&state["v"]));
        let energy_before = kinetic_energy(model, &mut data, &q, &v).unwrap();
        for case in state["cases"].as_array().unwrap() {
            let contacts = contacts(case);
            for impact in case["impacts"].as_array().unwrap() {
                let e = impact["restitution"].as_f64().unwrap();
                let (v_after, impulse) =
                    impulse_dynamics(model, &mut data, &mut cdata, &q, &v, &contacts, e, 0.0)
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
                let energy_after = kinetic_energy(model, &mut data, &q, &v_after).unwrap();
                assert!(
                    energy_after <= energy_before * (1.0 + 1e-12),
                    "{energy_after} > {energy_before}"
                );
                impacts += 1;
            }
        }
    }
    (worst, impacts)
}

/// Impacts against Pinocchio's `impulseDynamics` (restitution 0 and 0.5,
/// every state and contact set of Solo12 and Talos): v⁺ and the impulses
/// within 1e-9 relative.
#[test]
fn impacts_match_pinocchio_and_never_gain_energy() {
    let (worst, impacts) =
        against_impulse_dynamics::<NB, NQ, NV, NC>(&model(), &solo12_fixture()["states"]);
    eprintln!("Solo12, {impacts} impacts: within {worst:.1e} of Pinocchio");
    assert_eq!(impacts, 112);
    assert!(worst < 1e-9, "{worst:e}");
    let (talos, fixture) = talos();
    let (worst, impacts) = against_impulse_dynamics::<TALOS_NB, TALOS_NQ, TALOS_NV, TALOS_NC>(
        &talos,
        &fixture["contact_states"],
    );
    eprintln!("Talos, {impacts} impacts: within {worst:.1e} of Pinocchio");
    assert_eq!(impacts, 48);
    assert!(worst < 1e-9, "{worst:e}");

    let model = model();
    let mut data = Data::new();
    let mut cdata = ConstraintData::<f64, NV, NC>::new();
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
    assert_eq!(
        error,
        Error::InvalidSetting {
            setting: Setting::Restitution
        }
    );
}

/// The f32 solves (both methods) against Pinocchio's f64 results on every
/// Solo12 and Talos case: the worst relative differences of q̈ and λ,
/// bounded by what f32
/// rounding gives through CRBA, the factorisation and the Delassus solve
/// (measured 2.5e-5 and 2.0e-5 on Solo12, 2.0e-5 and 2.1e-5 on Talos;
/// bound 1e-4).
#[test]
fn f32_stays_near_pinocchio() {
    fn worst<const B: usize, const Q: usize, const V: usize>(
        model: &Model<f64, B, Q, V>,
        states: &Value,
    ) -> (f64, f64) {
        let model = model.cast::<f32>().unwrap();
        let mut data = Data::new();
        let mut cdata = ConstraintData::<f32, V, 12>::new();
        let (mut worst_ddq, mut worst_lambda) = (0.0_f64, 0.0_f64);
        for state in states.as_array().unwrap() {
            let q = array::<Q>(&state["q"]).map(|x| x as f32);
            let v = array::<V>(&state["v"]).map(|x| x as f32);
            let tau = array::<V>(&state["tau"]).map(|x| x as f32);
            for case in state["cases"].as_array().unwrap() {
                let contacts: Vec<Contact<f32>> =
                    contacts(case).iter().map(Contact::cast).collect();
                let settings = ConstraintSettings::baumgarte(
                    case["kp"].as_f64().unwrap() as f32,
                    case["kd"].as_f64().unwrap() as f32,
                );
                for method in METHODS {
                    let (ddq, lambda) = constrained_forward_dynamics_with(
                        method, &model, &mut data, &mut cdata, &q, &v, &tau, &contacts, &settings,
                    )
                    .unwrap();
                    let ddq: Vec<f64> = ddq.iter().map(|x| f64::from(*x)).collect();
                    let lambda: Vec<f64> = lambda.iter().map(|x| f64::from(*x)).collect();
                    worst_ddq = worst_ddq.max(relative(&ddq, &numbers(&case["ddq"])));
                    worst_lambda = worst_lambda.max(relative(&lambda, &numbers(&case["lambda"])));
                }
            }
        }
        (worst_ddq, worst_lambda)
    }
    let (ddq, lambda) = worst(&model(), &solo12_fixture()["states"]);
    eprintln!("Solo12 in f32: q̈ within {ddq:.1e}, λ within {lambda:.1e} of Pinocchio's f64");
    assert!(ddq < 1e-4 && lambda < 1e-4, "{ddq:e} {lambda:e}");
    let (talos, fixture) = talos();
    let (ddq, lambda) = worst(&talos, &fixture["contact_states"]);
    eprintln!("Talos in f32: q̈ within {ddq:.1e}, λ within {lambda:.1e} of Pinocchio's f64");
    assert!(ddq < 1e-4 && lambda < 1e-4, "{ddq:e} {lambda:e}");
}

/// Redundant contacts (a foot held twice beside another, on Solo12)
/// against Pinocchio's proximal solver (μ 1e-4, 200 iterations): with a
/// damping of 1e-10 both methods give Pinocchio's q̈ within 1e-9 relative
/// (measured 7e-11), and the forces, which both split between the two
/// copies of the foot by least norm, within 2e-5 (measured 1e-5, where
/// Pinocchio's iterations stop).
#[test]
fn redundant_contacts_match_pinocchios_proximal_solver() {
    let model = model();
    let fixture = solo12_fixture();
    let mut data = Data::new();
    let mut cdata = ConstraintData::<f64, NV, NC>::new();
    let settings = ConstraintSettings::new().with_damping(1e-10);
    for method in METHODS {
        let (mut worst_ddq, mut worst_lambda, mut cases) = (0.0_f64, 0.0_f64, 0);
        for state in fixture["states"].as_array().unwrap() {
            let (q, v, tau) = (
                array::<NQ>(&state["q"]),
                array::<NV>(&state["v"]),
                array::<NV>(&state["tau"]),
            );
            for case in state["redundant"].as_array().unwrap() {
                let (ddq, lambda) = constrained_forward_dynamics_with(
                    method,
                    &model,
                    &mut data,
                    &mut cdata,
                    &q,
                    &v,
                    &tau,
                    &contacts(case),
                    &settings,
                )
                .unwrap();
                worst_ddq = worst_ddq.max(relative(ddq, &numbers(&case["ddq"])));
                worst_lambda = worst_lambda.max(relative(lambda, &numbers(&case["lambda"])));
                cases += 1;
            }
        }
        eprintln!(
            "Solo12, {method:?}, {cases} redundant sets: q̈ within {worst_ddq:.1e}, λ within {worst_lambda:.1e} of Pinocchio's proximal solve"
        );
        assert_eq!(cases, 8);
        assert!(
            worst_ddq < 1e-9 && worst_lambda < 2e-5,
            "q̈ {worst_ddq:e}, λ {worst_lambda:e}"
        );
    }
}
