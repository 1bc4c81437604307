//! The contact Jacobians `J_c` the constrained dynamics form along the
//! contacts' support paths (`frame_chain`) against the all-joints path
//! (`joint_jacobians` for every joint, then `frame_jacobian` at each
//! contact in its reference frame: LOCAL_WORLD_ALIGNED for a point,
//! LOCAL for a frame), bit for bit: in `constrained_forward_dynamics`
//! (both methods' KKT pieces), `impulse_dynamics`,
//! `contact_inverse_dynamics` and the quadruped's trunk controller, on
//! the Pinocchio fixtures' Solo12 (one to four feet as points, a foot as a
//! frame) and Talos (its soles as frames) states and cases.

use rodyn::algorithm::constrained_dynamics::{
    constrained_forward_dynamics, impulse_dynamics, ConstraintData, ConstraintSettings, Contact,
};
use rodyn::algorithm::contact_inverse_dynamics::{
    contact_inverse_dynamics, ContactInverseDynamicsData, ContactInverseDynamicsSettings,
};
use rodyn::algorithm::frames::ReferenceFrame;
use rodyn::algorithm::jacobian::{frame_jacobian, joint_jacobians, JacobianData};
use rodyn::prelude::*;
use rodyn_host_tests::contact_fixture::{
    array, contacts, solo12, solo12_contacts, talos, SOLO_NB, SOLO_NQ, SOLO_NV, TALOS_NB, TALOS_NQ,
    TALOS_NV,
};
use rodyn_scenarios::quadruped::{self, QuadrupedData, QuadrupedLoads, LEGS};
use rodyn_scenarios::quadruped_balance::{TrunkController, TrunkControllerData};
use serde_json::Value;

/// Rows of the workspaces: four feet as points, or two soles as frames.
const NC: usize = 12;

/// `J_c` by the all-joints path: every joint's columns, then each
/// contact's frame Jacobian in its reference frame, rows linear first.
fn all_joints_rows<const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<f64, NB, NQ, NV>,
    q: &[f64; NQ],
    contacts: &[Contact<f64>],
) -> Vec<[f64; NV]> {
    let mut data = Data::new();
    let mut jac = JacobianData::new();
    joint_jacobians(model, &mut data, &mut jac, q).unwrap();
    let mut rows = Vec::new();
    for contact in contacts {
        let (reference, n) = match contact {
            Contact::Point { .. } => (ReferenceFrame::LocalWorldAligned, 3),
            Contact::Frame { .. } => (ReferenceFrame::Local, 6),
        };
        let mut columns = [Motion::ZERO; NV];
        frame_jacobian(
            model,
            &data,
            &jac,
            contact.held_frame(),
            reference,
            &mut columns,
        )
        .unwrap();
        for r in 0..n {
            rows.push(core::array::from_fn(|k| {
                let c = &columns[k];
                if r < 3 {
                    c.lin.to_array()[r]
                } else {
                    c.ang.to_array()[r - 3]
                }
            }));
        }
    }
    rows
}

/// Asserts that `jc`'s first rows are the all-joints path's, exactly.
fn assert_rows<const NV: usize>(jc: &[[f64; NV]], reference: &[[f64; NV]], at: &str) {
    assert_eq!(jc.len(), reference.len(), "{at}: rows");
    for (r, (row, expected)) in jc.iter().zip(reference).enumerate() {
        assert_eq!(row, expected, "{at}: row {r}");
    }
}

/// Every state and contact case of a fixture through the three solvers;
/// returns the number of cases.
fn check_fixture<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model: &Model<f64, NB, NQ, NV>,
    states: &Value,
) -> usize {
    let mut data = Data::new();
    let mut cdata = ConstraintData::<f64, NV, NC>::new();
    let mut iddata = ContactInverseDynamicsData::<f64, NV, NC>::new();
    let mut cases = 0;
    // The workspaces are reused from case to case, as a controller's are:
    // what one case leaves must not leak into the next one's rows.
    for (s, state) in states.as_array().unwrap().iter().enumerate() {
        let (q, v, tau) = (
            array::<NQ>(&state["q"]),
            array::<NV>(&state["v"]),
            array::<NV>(&state["tau"]),
        );
        for (c, case) in state["cases"].as_array().unwrap().iter().enumerate() {
            let held = contacts(case);
            let reference = all_joints_rows(model, &q, &held);
            let at = |solver: &str| format!("{name} state {s} case {c} {solver}");
            let settings = ConstraintSettings::baumgarte(10.0, 2.0);
            constrained_forward_dynamics(
                model, &mut data, &mut cdata, &q, &v, &tau, &held, &settings,
            )
            .unwrap();
            assert_rows(&cdata.jc[..cdata.rows], &reference, &at("forward dynamics"));
            impulse_dynamics(model, &mut data, &mut cdata, &q, &v, &held, 0.5, 1e-9).unwrap();
            assert_rows(&cdata.jc[..cdata.rows], &reference, &at("impulse"));
            contact_inverse_dynamics(
                model,
                &mut data,
                &mut iddata,
                &q,
                &v,
                &[0.0; NV],
                &held,
                &ConstraintSettings::default(),
                &ContactInverseDynamicsSettings::floating_base(0.8),
            )
            .unwrap();
            let jc = &iddata.constraint.jc[..iddata.constraint.rows];
            assert_rows(jc, &reference, &at("inverse dynamics"));
            cases += 1;
        }
    }
    cases
}

#[test]
fn solo12_contact_rows_are_the_all_joints_paths() {
    let cases = check_fixture::<SOLO_NB, SOLO_NQ, SOLO_NV>(
        "solo12",
        &solo12(),
        &solo12_contacts()["states"],
    );
    assert_eq!(cases, 56);
}

#[test]
fn talos_contact_rows_are_the_all_joints_paths() {
    let (model, fixture) = talos();
    let cases =
        check_fixture::<TALOS_NB, TALOS_NQ, TALOS_NV>("talos", &model, &fixture["contact_states"]);
    assert_eq!(cases, 24);
}

/// The quadruped's trunk controller in a trot, each pair of feet and all
/// four touching: its contact rows are the all-joints path's.
#[test]
fn the_trunk_controllers_contact_rows_are_the_all_joints_paths() {
    let model = quadruped::model::<f64>().unwrap();
    let controller = TrunkController::<f64>::trotting();
    let mut state = QuadrupedLoads::<f64>::trotting().initial_state(controller.height);
    // A state off the stance: the trunk tilted and moving, the legs apart.
    for (k, q) in state.q.iter_mut().enumerate().skip(7) {
        *q += 0.05 * (k as f64).sin();
    }
    state.q[3] = 0.05;
    state.q[6] = (1.0_f64 - 0.05 * 0.05).sqrt();
    for (k, v) in state.v.iter_mut().enumerate() {
        *v = 0.3 * (1.7 * k as f64).cos();
    }
    let frames = quadruped::foot_frames::<f64>();
    let mut data = QuadrupedData::new();
    let mut cdata = TrunkControllerData::new();
    for touching in [
        [true, false, false, true],
        [false, true, true, false],
        [true; LEGS],
    ] {
        controller
            .torques(
                &model, &mut data, &mut cdata, 0.1, &state.q, &state.v, &touching,
            )
            .unwrap();
        let held: Vec<_> = (0..LEGS)
            .filter(|&leg| touching[leg])
            .map(|leg| Contact::point(frames[leg], Vec3::ZERO))
            .collect();
        let reference = all_joints_rows(&model, &state.q, &held);
        let jc = &cdata.constraint.jc[..cdata.constraint.rows];
        assert_rows(jc, &reference, &format!("trunk controller {touching:?}"));
    }
}
