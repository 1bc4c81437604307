//! Inverse dynamics with contacts (`rodyn::algorithm::contact_inverse_dynamics`)
//! checked against constrained forward dynamics: the torques it returns,
//! applied with the same contacts, give back its acceleration and its
//! contact forces. Also the standing quadruped's forces, the residual of an
//! impossible motion, and bad input.

use rodyn::algorithm::constrained_dynamics::{
    constrained_forward_dynamics, ConstraintData, ConstraintSettings, Contact,
};
use rodyn::algorithm::contact_inverse_dynamics::{
    contact_inverse_dynamics, ContactInverseDynamicsData, ContactInverseDynamicsSettings,
};
use rodyn::error::Setting;
use rodyn::prelude::*;
use rodyn::Error;
use rodyn_host_tests::contact_fixture::{
    array, contacts, relative, solo12, solo12_contacts, talos, SOLO_NB, SOLO_NQ, SOLO_NV,
};
use serde_json::Value;

/// Over the cases of `states` whose contacts can push the base every way
/// (three or four point feet, or a frame among them): the
/// inverse dynamics of a wanted acceleration (the state's own `tau`
/// through ABA, so a different motion in each case), then forward
/// dynamics with its torques: the same q̈ and λ within `1e-9`, the
/// unactuated rows' residual within `1e-9` of the forces, the torques zero
/// on the base. Returns the worst differences and the number of cases.
fn round_trip<const B: usize, const Q: usize, const V: usize, const C: usize>(
    model: &Model<f64, B, Q, V>,
    states: &Value,
    settings: &ConstraintSettings<f64>,
) -> (f64, f64, f64, usize) {
    let mut data = Data::new();
    let mut id = ContactInverseDynamicsData::<f64, V, C>::new();
    let mut cdata = ConstraintData::<f64, V, C>::new();
    let id_settings = ContactInverseDynamicsSettings::floating_base(0.8);
    let (mut worst_ddq, mut worst_lambda, mut worst_residual, mut cases) = (0.0, 0.0, 0.0_f64, 0);
    for state in states.as_array().unwrap() {
        let (q, v, tau) = (
            array::<Q>(&state["q"]),
            array::<V>(&state["v"]),
            array::<V>(&state["tau"]),
        );
        let wanted = *rodyn::algorithm::aba::aba(model, &mut data, &q, &v, &tau, None).unwrap();
        for case in state["cases"].as_array().unwrap() {
            let contacts = contacts(case);
            let has_frame = contacts.iter().any(|c| matches!(c, Contact::Frame { .. }));
            if !has_frame && contacts.len() < 3 {
                continue;
            }
            let tau_id = *contact_inverse_dynamics(
                model,
                &mut data,
                &mut id,
                &q,
                &v,
                &wanted,
                &contacts,
                settings,
                &id_settings,
            )
            .unwrap();
            assert!(tau_id[..6].iter().all(|t| *t == 0.0));
            let scale = tau_id.iter().fold(1.0_f64, |m, t| m.max(t.abs()));
            worst_residual = worst_residual.max(id.residual_norm() / scale);
            let lambda_id = id.constraint.lambda[..id.constraint.rows].to_vec();
            let (ddq, lambda) = constrained_forward_dynamics(
                model, &mut data, &mut cdata, &q, &v, &tau_id, &contacts, settings,
            )
            .unwrap();
            worst_ddq = f64::max(worst_ddq, relative(ddq, &id.ddq));
            worst_lambda = f64::max(worst_lambda, relative(lambda, &lambda_id));
            cases += 1;
        }
    }
    (worst_ddq, worst_lambda, worst_residual, cases)
}

#[test]
fn torques_give_back_the_motion_solo12() {
    let model = solo12();
    for settings in [
        ConstraintSettings::default(),
        ConstraintSettings::baumgarte(40.0, 9.0),
    ] {
        let (ddq, lambda, residual, cases) = round_trip::<SOLO_NB, SOLO_NQ, SOLO_NV, 12>(
            &model,
            &solo12_contacts()["states"],
            &settings,
        );
        eprintln!(
            "Solo12, {cases} cases: q̈ within {ddq:.1e}, λ within {lambda:.1e}, residual {residual:.1e}"
        );
        assert_eq!(cases, 32);
        assert!(ddq < 1e-9 && lambda < 1e-9 && residual < 1e-9);
    }
}

#[test]
fn torques_give_back_the_motion_talos() {
    let (model, fixture) = talos();
    let (ddq, lambda, residual, cases) = round_trip::<33, 39, 38, 12>(
        &model,
        &fixture["contact_states"],
        &ConstraintSettings::default(),
    );
    eprintln!(
        "Talos, {cases} cases: q̈ within {ddq:.1e}, λ within {lambda:.1e}, residual {residual:.1e}"
    );
    assert_eq!(cases, 24);
    assert!(ddq < 1e-9 && lambda < 1e-9 && residual < 1e-9);
}

/// Solo12 at rest on four feet, wanted q̈ = 0: the feet carry the weight
/// (Σ λ_z = m g to 1e-9), every force inside a μ = 0.8 cone, the base rows
/// fully supplied. With one foot only the base cannot be held: the
/// residual shows it. Pushed forward on ice, every foot is flagged as
/// outside its cone.
#[test]
fn standing_on_four_feet_and_on_one() {
    let model = solo12();
    let fixture = solo12_contacts();
    let mut data = Data::new();
    let mut id = ContactInverseDynamicsData::<f64, SOLO_NV, 12>::new();
    let settings = ContactInverseDynamicsSettings::floating_base(0.8);
    // A standing pose: level trunk, legs bent, feet below the hips.
    let mut q = [0.0; SOLO_NQ];
    q[2] = 0.25;
    q[6] = 1.0;
    for leg in 0..4 {
        q[7 + 3 * leg + 1] = if leg < 2 { 0.8 } else { -0.8 };
        q[7 + 3 * leg + 2] = if leg < 2 { -1.6 } else { 1.6 };
    }
    let v = [0.0; SOLO_NV];
    rodyn::algorithm::kinematics::forward_kinematics(&model, &mut data, &q).unwrap();
    let feet: Vec<Contact<f64>> = contacts(&fixture["states"][0]["cases"][3])
        .iter()
        .map(|c| {
            let frame = *c.held_frame();
            let at = rodyn::algorithm::frames::frame_placement(&data, &frame)
                .unwrap()
                .trans;
            Contact::point(frame, at)
        })
        .collect();
    contact_inverse_dynamics(
        &model,
        &mut data,
        &mut id,
        &q,
        &v,
        &[0.0; SOLO_NV],
        &feet,
        &ConstraintSettings::default(),
        &settings,
    )
    .unwrap();
    let weight = model.total_mass() * 9.81;
    let lambda = &id.constraint.lambda;
    let support: f64 = (0..4).map(|c| lambda[3 * c + 2]).sum();
    assert!(
        (support - weight).abs() < 1e-9 * weight,
        "{support} N vs {weight} N"
    );
    assert!(!id.outside_cone.contains(&true), "{:?}", &lambda[..12]);
    assert!(id.residual_norm() < 1e-9 * weight);
    assert!(id.ddq.iter().all(|a| a.abs() < 1e-9), "{:?}", id.ddq);

    contact_inverse_dynamics(
        &model,
        &mut data,
        &mut id,
        &q,
        &v,
        &[0.0; SOLO_NV],
        &feet[..1],
        &ConstraintSettings::default(),
        &settings,
    )
    .unwrap();
    assert!(id.residual_norm() > 0.1 * weight, "{:?}", id.residual);

    // Pushing the trunk forward at 2 m/s² on ice (μ = 0.05): the feet need
    // 0.2 g of traction against a cone of 0.05: every foot is flagged.
    let mut forward = [0.0; SOLO_NV];
    forward[0] = 2.0;
    let ice = ContactInverseDynamicsSettings::floating_base(0.05);
    contact_inverse_dynamics(
        &model,
        &mut data,
        &mut id,
        &q,
        &v,
        &forward,
        &feet,
        &ConstraintSettings::default(),
        &ice,
    )
    .unwrap();
    assert_eq!(
        id.outside_cone[..4],
        [true; 4],
        "{:?}",
        &id.constraint.lambda[..12]
    );
}

#[test]
fn bad_input_is_an_error() {
    let model = solo12();
    let mut data = Data::new();
    let mut id = ContactInverseDynamicsData::<f64, SOLO_NV, 12>::new();
    let mut q = [0.0; SOLO_NQ];
    q[6] = 1.0;
    let v = [0.0; SOLO_NV];
    let good = ContactInverseDynamicsSettings::floating_base(0.8);
    let constraint = ConstraintSettings::default();
    let mut call = |wanted: &[f64; SOLO_NV], settings: &ContactInverseDynamicsSettings<f64>| {
        contact_inverse_dynamics(
            &model,
            &mut data,
            &mut id,
            &q,
            &v,
            wanted,
            &[],
            &constraint,
            settings,
        )
        .copied()
    };
    let zero = [0.0; SOLO_NV];
    assert!(call(&zero, &good).is_ok());
    for (settings, setting) in [
        (good.with_unactuated(19), Setting::Unactuated),
        (good.with_regularisation(0.0), Setting::Regularisation),
        (good.with_friction(f64::NAN), Setting::Friction),
    ] {
        assert_eq!(
            call(&zero, &settings),
            Err(Error::InvalidSetting { setting })
        );
    }
    let mut nan = zero;
    nan[4] = f64::NAN;
    assert!(matches!(
        call(&nan, &good),
        Err(Error::NonFinite { index: 4, .. })
    ));
}
