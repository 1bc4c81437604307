//! The URDF models compiled by `rodyn-model` against Pinocchio 4.1 on the
//! same files: body order, joint placements, inertias, and RNEA torques with
//! and without external forces, from `host-tests/fixtures/` (written by
//! `tools/pinocchio/make_fixtures.py`).

use rodyn::algorithm::rnea::{gravity_torques, rnea};
use rodyn::spatial::{Force, Motion, Vec3};
use rodyn::{Data, Model};
use rodyn_model_generated_tests as generated;
use serde_json::Value;
use std::path::Path;

/// Pinocchio writes six significant digits into no file here, so the
/// parameters agree to rounding; torques are sums of a few dozen products.
const PARAMETER_TOLERANCE: f64 = 1e-12;
/// The compiler keeps a file's rotations (only the rounding of exact
/// quarter turns, 4 ε, is removed): the UR5's `rpy` of 1.57079632679, 4.9e-12
/// from a quarter turn, is compiled as written, as Pinocchio reads it.
const ROTATION_TOLERANCE: f64 = 1e-12;
const TORQUE_TOLERANCE: f64 = 1e-9;

fn fixture(name: &str) -> Value {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(format!("../../../host-tests/fixtures/{name}.json"));
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

fn close(what: &str, got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "{what}: length");
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        let scale = 1.0_f64.max(w.abs());
        assert!(
            (g - w).abs() <= tol * scale,
            "{what}[{k}]: rodyn {g}, Pinocchio {w}"
        );
    }
}

fn check<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model: &Model<f64, NB, NQ, NV>,
    joint_names: &[&str],
) {
    let fx = fixture(name);
    model.validate().unwrap();
    // URDF has no gravity; the fixtures of planar chains put it in the plane.
    let g = numbers(&fx["model"]["gravity"]);
    let mut model = *model;
    model
        .set_gravity(Motion::new(Vec3::ZERO, Vec3::new(g[0], g[1], g[2])))
        .unwrap();
    let model = &model;
    let joints = fx["model"]["joints"].as_array().unwrap();
    assert_eq!(joints.len(), NB, "{name}: number of bodies");
    for (i, j) in joints.iter().enumerate() {
        assert_eq!(
            j["name"].as_str().unwrap(),
            joint_names[i],
            "{name}: body order"
        );
        let parent = j["parent"].as_u64().map(|p| p as usize);
        assert_eq!(model.parent(i), parent, "{name}: parent of body {i}");
        let x = model.placement(i);
        let rot = j["placement"]["rotation"].as_array().unwrap();
        for (r, row) in rot.iter().enumerate() {
            close(
                &format!("{name} placement {i} row {r}"),
                &x.rot.m[r],
                &numbers(row),
                ROTATION_TOLERANCE,
            );
        }
        close(
            &format!("{name} placement {i}"),
            &x.trans.to_array(),
            &numbers(&j["placement"]["translation"]),
            PARAMETER_TOLERANCE,
        );
        let inertia = model.inertia(i);
        let y = &j["inertia"];
        close(
            &format!("{name} mass {i}"),
            &[inertia.mass],
            &[y["mass"].as_f64().unwrap()],
            PARAMETER_TOLERANCE,
        );
        close(
            &format!("{name} com {i}"),
            &inertia.com.to_array(),
            &numbers(&y["lever"]),
            PARAMETER_TOLERANCE,
        );
        let rows = y["inertia"].as_array().unwrap();
        let ic = inertia.rot_inertia.to_mat3();
        for (r, row) in rows.iter().enumerate() {
            close(
                &format!("{name} inertia {i} row {r}"),
                &ic.m[r],
                &numbers(row),
                PARAMETER_TOLERANCE,
            );
        }
    }
    let mut data = Data::new();
    for (s, state) in fx["states"].as_array().unwrap().iter().enumerate() {
        let q: [f64; NQ] = numbers(&state["q"]).try_into().unwrap();
        let v: [f64; NV] = numbers(&state["v"]).try_into().unwrap();
        let a: [f64; NV] = numbers(&state["a"]).try_into().unwrap();
        let tau = *rnea(model, &mut data, &q, &v, &a, None).unwrap();
        close(
            &format!("{name} state {s} rnea"),
            &tau,
            &numbers(&state["rnea"]),
            TORQUE_TOLERANCE,
        );
        let fext: [Force<f64>; NB] = core::array::from_fn(|i| {
            let f = numbers(&state["fext"][i]);
            Force::new(Vec3::new(f[3], f[4], f[5]), Vec3::new(f[0], f[1], f[2]))
        });
        let tau = *rnea(model, &mut data, &q, &v, &a, Some(&fext)).unwrap();
        close(
            &format!("{name} state {s} rnea with fext"),
            &tau,
            &numbers(&state["rnea_fext"]),
            TORQUE_TOLERANCE,
        );
        let g = *gravity_torques(model, &mut data, &q).unwrap();
        close(
            &format!("{name} state {s} gravity"),
            &g,
            &numbers(&state["gravity_torques"]),
            TORQUE_TOLERANCE,
        );
    }
}

/// The joint names in body order, from the generated `joint` module's
/// constants (so a renamed or reordered joint fails here).
macro_rules! joint_names {
    ($module:ident: $($joint:ident = $name:literal),* $(,)?) => {{
        let mut names = [""; generated::$module::NB];
        $( names[generated::$module::joint::$joint] = $name; )*
        names
    }};
}

#[test]
fn urdf_gravity_is_pinocchios_default() {
    let g = generated::panda::MODEL_F64.gravity().lin;
    assert_eq!(g.to_array(), [0.0, 0.0, -9.81]);
    assert_eq!(
        numbers(&fixture("panda")["model"]["gravity"]),
        [0.0, 0.0, -9.81]
    );
}

#[test]
fn panda_matches_pinocchio() {
    let names = joint_names!(panda: PANDA_JOINT1 = "panda_joint1", PANDA_JOINT2 = "panda_joint2",
        PANDA_JOINT3 = "panda_joint3", PANDA_JOINT4 = "panda_joint4", PANDA_JOINT5 = "panda_joint5",
        PANDA_JOINT6 = "panda_joint6", PANDA_JOINT7 = "panda_joint7");
    check("panda", &generated::panda::MODEL_F64, &names);
}

#[test]
fn ur5_matches_pinocchio() {
    let names = joint_names!(ur5: SHOULDER_PAN_JOINT = "shoulder_pan_joint",
        SHOULDER_LIFT_JOINT = "shoulder_lift_joint", ELBOW_JOINT = "elbow_joint",
        WRIST_1_JOINT = "wrist_1_joint", WRIST_2_JOINT = "wrist_2_joint", WRIST_3_JOINT = "wrist_3_joint");
    check("ur5", &generated::ur5::MODEL_F64, &names);
}

#[test]
fn solo12_with_a_floating_base_matches_pinocchio() {
    let fx = fixture("solo12");
    let names: Vec<String> = fx["model"]["joints"]
        .as_array()
        .unwrap()
        .iter()
        .map(|j| j["name"].as_str().unwrap().to_string())
        .collect();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    assert_eq!(generated::solo12::joint::ROOT_JOINT, 0);
    assert_eq!(
        generated::solo12::joint::FL_HFE,
        names.iter().position(|n| *n == "FL_HFE").unwrap()
    );
    check("solo12", &generated::solo12::MODEL_F64, &names);
}

#[test]
fn synthetic_trees_match_pinocchio() {
    for (name, check_one) in [
        (
            "branched_tree",
            (|n: &[&str]| check("branched_tree", &generated::branched_tree::MODEL_F64, n))
                as fn(&[&str]),
        ),
        ("planar_chain_5", |n: &[&str]| {
            check("planar_chain_5", &generated::planar_chain_5::MODEL_F64, n)
        }),
        ("spatial_chain_12", |n: &[&str]| {
            check(
                "spatial_chain_12",
                &generated::spatial_chain_12::MODEL_F64,
                n,
            )
        }),
    ] {
        let fx = fixture(name);
        let names: Vec<String> = fx["model"]["joints"]
            .as_array()
            .unwrap()
            .iter()
            .map(|j| j["name"].as_str().unwrap().to_string())
            .collect();
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        check_one(&names);
    }
}
