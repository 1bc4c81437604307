//! The run-time model behind `tree` and `render`: padding must not change
//! the dynamics, and the pictures and listings show what the file says.

use rodyn::algorithm::rnea::gravity_torques;
use rodyn::Data;
use rodyn_model::render::{render_svg, View};
use rodyn_model::runtime::{PaddedRuntimeModel, RuntimeModel, MAX_BODIES, MAX_NV};
use rodyn_model::tree::render_tree;
use rodyn_model::{load, LoadOptions};
use std::path::Path;

fn model(file: &str) -> rodyn_model::ModelDescription {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../models")
        .join(file);
    load(&path, LoadOptions::default()).unwrap()
}

#[test]
fn padded_panda_has_the_gravity_torques_of_a_hand_computation() {
    let runtime = PaddedRuntimeModel::new(model("panda.toml")).unwrap();
    runtime.model.validate().unwrap();
    let mut data: Box<Data<f64, MAX_BODIES, MAX_NV>> = Box::default();
    // At q = 0 the Panda stands upright: joints 1, 3, 5, 7 turn about the
    // vertical and feel no gravity; joint 2 carries the offsets of the
    // links' centres of mass.
    let q = runtime.configuration(&[0.0; 7]);
    let g = gravity_torques(&runtime.model, &mut data, &q).unwrap();
    for j in [0, 2, 4, 6] {
        assert!(g[j].abs() < 1e-12, "joint {j}: {}", g[j]);
    }
    // The padding coordinates carry no torque.
    assert!(g[7..].iter().all(|t| *t == 0.0));
}

#[test]
fn tree_lists_bodies_coordinates_and_drives() {
    let text = render_tree(&model("gait_planar.toml"));
    assert!(
        text.starts_with("model `gait_planar` (planar): 8 bodies, nq = 10, nv = 10"),
        "{text}"
    );
    assert!(
        text.contains("r_knee: revolute about z  q[8] v[8]"),
        "{text}"
    );
    assert!(text.contains("socket on r_thigh"), "{text}");
    let text = render_tree(&model("two_link_muscles.toml"));
    assert!(
        text.contains("muscle m3: m3_origin -> m3_via -> m3_insertion (F_max = 300 N"),
        "{text}"
    );
}

#[test]
fn render_puts_the_pendulum_tip_where_forward_kinematics_says() {
    let runtime = RuntimeModel::new(model("pendulum.toml")).unwrap();
    let q = [std::f64::consts::FRAC_PI_2];
    let poses = runtime.body_poses(&q).unwrap();
    let tip = runtime.endpoint_positions(&poses)[0];
    // Turned by +90° about z, the tip at (0, -1) goes to (1, 0).
    assert!((tip.x - 1.0).abs() < 1e-12 && tip.y.abs() < 1e-12);
    let svg = render_svg(&runtime, &q, View::Xy, 400.0).unwrap();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert_eq!(svg.matches("<polyline").count(), 1, "one spring");
    assert_eq!(svg.matches("<title>tip</title>").count(), 1);
}
