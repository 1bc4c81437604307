//! Mimic joints: the generated `*_mimic` maps around rodyn's model (which
//! keeps every follower as a joint of its own) against Pinocchio 4.1's
//! `buildModelFromUrdf(..., mimic=True)` on `urdf/gripper.urdf` (a finger
//! mimicking the other, a thumb mimicking the wrist, with multipliers and
//! offsets): RNEA (`Gᵀ τ`), the mass matrix (`Gᵀ M G`) and the frames,
//! from `host-tests/fixtures/mimic/gripper.json`
//! (`tools/pinocchio/make_mimic_fixtures.py`).

use rodyn::algorithm::crba::crba;
use rodyn::algorithm::frames::frame_placement;
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::algorithm::rnea::rnea;
use rodyn::Data;
use rodyn_model_generated_tests::gripper;
use serde_json::Value;
use std::path::Path;

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

#[test]
fn mimic_maps_reproduce_pinocchios_mimic_model() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../host-tests/fixtures/mimic/gripper.json");
    let fx: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    assert_eq!((gripper::NQ, gripper::NM), (4, 2));
    assert_eq!(fx["nq"].as_u64(), Some(gripper::MIMIC_NQ as u64));
    assert_eq!(fx["nv"].as_u64(), Some(gripper::MIMIC_NV as u64));
    assert_eq!(
        gripper::MIMICS[0],
        gripper::Mimic {
            follower: gripper::joint::FINGER_B_JOINT,
            leader: gripper::joint::FINGER_A_JOINT,
            multiplier: 0.8,
            offset: 0.005
        }
    );
    let names: Vec<&str> = fx["frames"]
        .as_array()
        .unwrap()
        .iter()
        .map(|n| n.as_str().unwrap())
        .collect();
    assert_eq!(names, gripper::FRAME_NAMES);
    let model = &gripper::MODEL_F64;
    let mut data = Data::new();
    let (mut worst_tau, mut worst_m, mut worst_frame) = (0.0_f64, 0.0_f64, 0.0_f64);
    for state in fx["states"].as_array().unwrap() {
        let q_m: [f64; gripper::MIMIC_NQ] = numbers(&state["q"]).try_into().unwrap();
        let v_m: [f64; gripper::MIMIC_NV] = numbers(&state["v"]).try_into().unwrap();
        let a_m: [f64; gripper::MIMIC_NV] = numbers(&state["a"]).try_into().unwrap();
        let q = gripper::q_from_mimic(&q_m).unwrap();
        assert_eq!(gripper::q_to_mimic(&q).unwrap(), q_m);
        let v = gripper::v_from_mimic(&v_m).unwrap();
        let a = gripper::v_from_mimic(&a_m).unwrap();
        let tau = *rnea(model, &mut data, &q, &v, &a, None).unwrap();
        let tau_m = gripper::tau_to_mimic(&tau).unwrap();
        for (g, w) in tau_m.iter().zip(numbers(&state["rnea"])) {
            worst_tau = worst_tau.max((g - w).abs());
        }
        // Gᵀ M G, column by column.
        let m = *crba(model, &mut data, &q).unwrap();
        let want = state["mass_matrix"].as_array().unwrap();
        for j in 0..gripper::MIMIC_NV {
            let mut e = [0.0; gripper::MIMIC_NV];
            e[j] = 1.0;
            let g = gripper::v_from_mimic(&e).unwrap();
            let mut mg = [0.0; gripper::NV];
            for (r, row) in mg.iter_mut().enumerate() {
                *row = (0..gripper::NV).map(|c| m[r][c] * g[c]).sum();
            }
            let column = gripper::tau_to_mimic(&mg).unwrap();
            for (i, x) in column.iter().enumerate() {
                worst_m = worst_m.max((x - want[i][j].as_f64().unwrap()).abs());
            }
        }
        // Followers where Pinocchio puts them (offsets included).
        forward_kinematics(model, &mut data, &q).unwrap();
        for (k, o_m_f) in state["o_m_f"].as_array().unwrap().iter().enumerate() {
            let got = frame_placement(&data, &gripper::FRAMES_F64[k]).unwrap();
            for (r, row) in o_m_f["rotation"].as_array().unwrap().iter().enumerate() {
                for (g, w) in got.rot.m[r].iter().zip(numbers(row)) {
                    worst_frame = worst_frame.max((g - w).abs());
                }
            }
            for (g, w) in got
                .trans
                .to_array()
                .iter()
                .zip(numbers(&o_m_f["translation"]))
            {
                worst_frame = worst_frame.max((g - w).abs());
            }
        }
    }
    println!("gripper: rnea {worst_tau:e}, mass matrix {worst_m:e}, oMf {worst_frame:e}");
    assert!(worst_tau <= 1e-12 && worst_m <= 1e-12 && worst_frame <= 1e-12);
}

#[test]
fn mimic_maps_refuse_non_finite_numbers() {
    use rodyn::error::Quantity;
    use rodyn::Error;
    assert_eq!(
        gripper::q_from_mimic(&[0.0, f64::NAN]),
        Err(Error::NonFinite {
            quantity: Quantity::Configuration,
            index: 1
        })
    );
    assert_eq!(
        gripper::v_from_mimic(&[1.5e308, 0.0]),
        Err(Error::NonFiniteResult {
            quantity: Quantity::Velocity,
            index: gripper::v::THUMB_JOINT
        })
    );
    assert!(gripper::tau_to_mimic(&[0.0, 0.0, f64::INFINITY, 0.0]).is_err());
    // A model without mimic joints maps one to one.
    use rodyn_model_generated_tests::panda;
    assert_eq!((panda::NM, panda::MIMIC_NQ), (0, panda::NQ));
}
