//! The frames of the generated modules against Pinocchio 4.1's `BODY`
//! frames on the same URDFs: each link's body and placement (`iMf`, with
//! its rotation), and its world placement (`data.oMf`) at seeded random
//! configurations, from `host-tests/fixtures/frames/` (written by
//! `tools/pinocchio/make_frame_fixtures.py`); and the conversions of a
//! configuration to and from Pinocchio's layout, where a continuous joint
//! keeps `(cos θ, sin θ)`.

use rodyn::algorithm::frames::frame_placement;
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::spatial::Transform;
use rodyn::{Data, Frame, Model};
use rodyn_model_generated_tests::{
    panda, panda_with_motors, solo12, wheeled_arm, wheeled_arm_tool,
};
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
/// difference of the world placements. `to_rodyn` takes each state's `q`
/// (Pinocchio's layout) to rodyn's.
fn check<const NB: usize, const NQ: usize, const NV: usize, const NF: usize>(
    name: &str,
    model: &Model<f64, NB, NQ, NV>,
    frames: &[Frame<f64>; NF],
    frame_names: &[&str; NF],
    to_rodyn: impl Fn(&[f64]) -> [f64; NQ],
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
        let q = to_rodyn(&numbers(&state["q"]));
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
        |q| q.try_into().unwrap(),
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
        |q| q.try_into().unwrap(),
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

#[test]
fn continuous_joints_convert_to_and_from_pinocchios_layout() {
    // Three continuous joints on a free-flyer: Pinocchio's nq is 14,
    // rodyn's 11; nv is 10 in both.
    let fx = fixture("wheeled_arm");
    assert_eq!(fx["nq"].as_u64(), Some(wheeled_arm::PINOCCHIO_NQ as u64));
    assert_eq!((wheeled_arm::NQ, wheeled_arm::NV), (11, 10));
    assert_eq!(fx["nv"].as_u64(), Some(wheeled_arm::NV as u64));
    assert_eq!(
        wheeled_arm::PINOCCHIO_ANGLES,
        [
            None,
            None,
            None,
            None,
            None,
            None,
            None,
            Some(wheeled_arm::joint::A_LEFT_WHEEL),
            Some(wheeled_arm::joint::B_RIGHT_WHEEL),
            None,
            Some(wheeled_arm::joint::WRIST)
        ]
    );
    let mut worst_angle: f64 = 0.0;
    let mut worst_back: f64 = 0.0;
    for state in fx["states"].as_array().unwrap() {
        let q_pin: [f64; wheeled_arm::PINOCCHIO_NQ] = numbers(&state["q"]).try_into().unwrap();
        let q = wheeled_arm::q_from_pinocchio(&q_pin).unwrap();
        for (g, w) in q.iter().zip(numbers(&state["q_rodyn"])) {
            worst_angle = worst_angle.max((g - w).abs());
        }
        let back = wheeled_arm::q_to_pinocchio(&q).unwrap();
        for (g, w) in back.iter().zip(q_pin) {
            worst_back = worst_back.max((g - w).abs());
        }
        // f32 too.
        let q32 = wheeled_arm::q_from_pinocchio(&q_pin.map(|x| x as f32)).unwrap();
        assert!((q32[wheeled_arm::q::WRIST] - q[wheeled_arm::q::WRIST] as f32).abs() < 1e-5);
    }
    println!("wheeled_arm: angles off by {worst_angle:e}, round trip off by {worst_back:e}");
    assert!(worst_angle <= 1e-15 && worst_back <= 1e-15);
    // The converted configurations give Pinocchio's frame placements.
    let worst = check(
        "wheeled_arm",
        &wheeled_arm::MODEL_F64,
        &wheeled_arm::FRAMES_F64,
        &wheeled_arm::FRAME_NAMES,
        |q| wheeled_arm::q_from_pinocchio(&q.try_into().unwrap()).unwrap(),
    );
    println!("wheeled_arm: worst oMf difference {worst:e}");
}

#[test]
fn bad_configurations_in_pinocchios_layout_are_named() {
    use rodyn::error::{ConfigurationError, Quantity};
    use rodyn::Error;
    let mut neutral = [0.0; wheeled_arm::NQ];
    neutral[wheeled_arm::q::ROOT_JOINT + 6] = 1.0;
    let mut q = wheeled_arm::q_to_pinocchio(&neutral).unwrap();
    // Pinocchio's neutral configuration: the identity quaternion's qw,
    // then (cos, sin) = (1, 0) per wheel, the shoulder, (1, 0) at the wrist.
    assert_eq!(&q[6..], &[1.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0]);
    q[10] = 0.5; // the right wheel's (cos, sin) = (1, 0.5)
    assert_eq!(
        wheeled_arm::q_from_pinocchio(&q),
        Err(Error::InvalidConfiguration {
            joint: wheeled_arm::joint::B_RIGHT_WHEEL,
            reason: ConfigurationError::AngleNotUnit {
                norm: 1.25_f64.sqrt()
            }
        })
    );
    q[12] = f64::NAN;
    assert_eq!(
        wheeled_arm::q_from_pinocchio(&q),
        Err(Error::NonFinite {
            quantity: Quantity::Configuration,
            index: 12
        })
    );
    let mut q = [0.0; wheeled_arm::NQ];
    q[wheeled_arm::q::WRIST] = f64::INFINITY;
    assert_eq!(
        wheeled_arm::q_to_pinocchio(&q),
        Err(Error::NonFinite {
            quantity: Quantity::Configuration,
            index: wheeled_arm::q::WRIST
        })
    );
    // Models without continuous joints keep one layout.
    assert_eq!(panda::PINOCCHIO_NQ, panda::NQ);
    // A planar floating base's θ is Pinocchio's (cos θ, sin θ) too
    // (`JointModelPlanar`: q = [x y cos θ sin θ]).
    use rodyn_model_generated_tests::gait_planar;
    assert_eq!(gait_planar::PINOCCHIO_NQ, gait_planar::NQ + 1);
    let mut q = [0.1; gait_planar::NQ];
    q[2] = 2.0;
    let p = gait_planar::q_to_pinocchio(&q).unwrap();
    // rodyn's sine and cosine: the C library's or a neighbouring float.
    let expected = [0.1, 0.1, 2.0_f64.cos(), 2.0_f64.sin()];
    assert!(
        p[..4]
            .iter()
            .zip(expected)
            .all(|(a, b)| (a - b).abs() <= 1.2e-16),
        "{p:?}"
    );
    let back = gait_planar::q_from_pinocchio(&p).unwrap();
    assert!(back.iter().zip(q).all(|(b, x)| (b - x).abs() < 1e-15));
}

#[test]
fn frames_named_in_a_rodyn_file_sit_on_their_links() {
    use rodyn::space::RigidTransform;
    use rodyn::spatial::{Mat3, Vec3};
    // The URDF's frames first, then the file's, in its order.
    assert_eq!(wheeled_arm_tool::NF, wheeled_arm::NF + 2);
    assert_eq!(
        wheeled_arm_tool::FRAME_NAMES[wheeled_arm::NF..],
        ["camera", "wheel_marker"]
    );
    let tool = wheeled_arm::FRAMES_F64[wheeled_arm::frame::TOOL];
    let camera = wheeled_arm_tool::FRAMES_F64[wheeled_arm_tool::frame::CAMERA];
    assert_eq!(camera.body, tool.body);
    // 2 cm along the tool's z, turned by 90° about its y.
    let offset = Transform::new(
        Mat3::from_rows([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]),
        Vec3::new(0.0, 0.0, 0.02),
    );
    let want = tool.placement.compose(&offset);
    for r in 0..3 {
        for c in 0..3 {
            assert!((camera.placement.rot.m[r][c] - want.rot.m[r][c]).abs() < 1e-15);
        }
    }
    let d = camera.placement.trans.to_array();
    let w = want.trans.to_array();
    assert!(d.iter().zip(w).all(|(a, b)| (a - b).abs() < 1e-15));
    let marker = wheeled_arm_tool::FRAMES_F64[wheeled_arm_tool::frame::WHEEL_MARKER];
    assert_eq!(marker.body, wheeled_arm::body::LEFT_WHEEL);
    assert_eq!(
        marker.placement,
        Transform::from_translation(Vec3::new(0.05, 0.0, 0.0))
    );
}
