//! The frames of the generated modules against Pinocchio 4.1's `BODY`
//! frames on the same URDFs: each link's body and placement (`iMf`, with
//! its rotation), and its world placement (`data.oMf`) at seeded random
//! configurations, from `host-tests/fixtures/frames/` (written by
//! `tools/pinocchio/make_frame_fixtures.py`).

use rodyn::algorithm::frames::frame_placement;
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::spatial::Transform;
use rodyn::{Data, Frame, Model};
use rodyn_model_generated_tests::{panda, panda_with_motors, solo12};
use serde_json::Value;
use std::path::Path;

const TOLERANCE: f64 = 1e-12;

fn fixture(name: &str) -> Value {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(format!("../../../host-tests/fixtures/frames/{name}.json"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap()
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

/// The largest entry difference between `got` and Pinocchio's SE3 `want`.
fn difference(got: &Transform<f64>, want: &Value) -> f64 {
    let mut worst: f64 = 0.0;
    for (r, row) in want["rotation"].as_array().unwrap().iter().enumerate() {
        for (g, w) in got.rot.m[r].iter().zip(numbers(row)) {
            worst = worst.max((g - w).abs());
        }
    }
    for (g, w) in got
        .trans
        .to_array()
        .iter()
        .zip(numbers(&want["translation"]))
    {
        worst = worst.max((g - w).abs());
    }
    worst
}

/// Every generated frame is one of Pinocchio's, on the same body at the
/// same placement, and lands where Pinocchio's does; returns the worst
/// difference of the world placements.
fn check<const NB: usize, const NQ: usize, const NV: usize, const NF: usize>(
    name: &str,
    model: &Model<f64, NB, NQ, NV>,
    frames: &[Frame<f64>; NF],
    frame_names: &[&str; NF],
) -> f64 {
    let fx = fixture(name);
    let want = fx["frames"].as_array().unwrap();
    assert_eq!(
        want.iter()
            .map(|f| f["name"].as_str().unwrap())
            .collect::<Vec<_>>(),
        frame_names.to_vec(),
        "{name}: the generated frames are Pinocchio's BODY frames on moving joints, in its order"
    );
    for (k, f) in want.iter().enumerate() {
        assert_eq!(
            frames[k].body,
            f["body"].as_u64().unwrap() as usize,
            "{name}: body of frame {}",
            frame_names[k]
        );
        let d = difference(&frames[k].placement, &f["placement"]);
        assert!(
            d <= TOLERANCE,
            "{name}: placement of {} off by {d:e}",
            frame_names[k]
        );
    }
    let mut data = Data::new();
    let mut worst: f64 = 0.0;
    for (s, state) in fx["states"].as_array().unwrap().iter().enumerate() {
        let q: [f64; NQ] = numbers(&state["q"]).try_into().unwrap();
        forward_kinematics(model, &mut data, &q).unwrap();
        for (k, o_m_f) in state["o_m_f"].as_array().unwrap().iter().enumerate() {
            let got = frame_placement(&data, &frames[k]).unwrap();
            let d = difference(&got, o_m_f);
            assert!(
                d <= TOLERANCE,
                "{name} state {s}: oMf of {} off by {d:e}",
                frame_names[k]
            );
            worst = worst.max(d);
        }
    }
    worst
}

#[test]
fn panda_frames_match_pinocchio_omf() {
    let worst = check(
        "panda",
        &panda::MODEL_F64,
        &panda::FRAMES_F64,
        &panda::FRAME_NAMES,
    );
    println!("panda: worst oMf difference {worst:e}");
    // The flange, the hand turned by -45° about z and the tool centre
    // point, all merged into panda_link7.
    for f in [
        panda::frame::PANDA_LINK8,
        panda::frame::PANDA_HAND,
        panda::frame::PANDA_HAND_TCP,
    ] {
        assert_eq!(panda::FRAMES_F64[f].body, panda::body::PANDA_LINK7);
    }
    let hand = panda::FRAMES_F64[panda::frame::PANDA_HAND].placement;
    let c = core::f64::consts::FRAC_1_SQRT_2;
    assert!((hand.rot.m[0][0] - c).abs() < 1e-15 && (hand.rot.m[0][1] - c).abs() < 1e-15);
}

#[test]
fn solo12_feet_match_pinocchio_omf() {
    let worst = check(
        "solo12",
        &solo12::MODEL_F64,
        &solo12::FRAMES_F64,
        &solo12::FRAME_NAMES,
    );
    println!("solo12: worst oMf difference {worst:e}");
    assert_eq!(
        solo12::FRAMES_F64[solo12::frame::HR_FOOT].body,
        solo12::body::HR_LOWER_LEG
    );
}

#[test]
fn f32_frames_are_the_f64_frames_rounded() {
    for (f64_frame, f32_frame) in panda::FRAMES_F64.iter().zip(panda::FRAMES_F32) {
        assert_eq!(f64_frame.cast::<f32>(), f32_frame);
    }
    // A rodyn file that includes the URDF keeps its frames.
    assert_eq!(panda_with_motors::FRAME_NAMES, panda::FRAME_NAMES);
    assert_eq!(panda_with_motors::FRAMES_F32, panda::FRAMES_F32);
}
