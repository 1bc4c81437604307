//! Frames, Jacobians and centroidal quantities against Pinocchio 4.1, in
//! f64 (1e-9 relative) and f32 (bounded per model).
//!
//! Fixtures: `python3 tools/pinocchio/make_kinematics_fixtures.py`, which
//! reads the states of `host-tests/fixtures/<model>.json` and writes
//! `host-tests/fixtures/kinematics/<model>.json` (frames with random
//! placements on three bodies of each model). Each quantity's error is
//! `‖x − x_ref‖∞ / ‖x_ref‖∞`, the worst over the states (absolute where
//! the reference is below 1e-12 everywhere, as the first body's `J̇` on a
//! fixed base, which is exactly zero).

use std::collections::BTreeMap;

use rodyn::algorithm::centroidal::{
    centroidal_map, centroidal_map_time_variation, centroidal_momentum, com_jacobian,
    com_velocity_acceleration, CentroidalData,
};
use rodyn::algorithm::frames::{
    frame_classical_acceleration, frame_placement, frame_velocity, ReferenceFrame,
};
use rodyn::algorithm::jacobian::{
    frame_jacobian, frame_jacobian_time_variation, joint_jacobians, joint_jacobians_time_variation,
    to_linear_first, JacobianData,
};
use rodyn::algorithm::kinematics::forward_kinematics_acceleration;
use rodyn::prelude::*;
use rodyn::Frame;
use rodyn_host_tests::fixture::{fixtures_dir, Fixture};
use serde_json::Value;

const F64_TOLERANCE: f64 = 1e-9;

const REFERENCES: [(&str, ReferenceFrame); 3] = [
    ("local", ReferenceFrame::Local),
    ("world", ReferenceFrame::World),
    ("local_world_aligned", ReferenceFrame::LocalWorldAligned),
];

/// Worst error per quantity name.
#[derive(Default, Debug)]
struct Errors(BTreeMap<String, f64>);

impl Errors {
    fn add(&mut self, name: &str, x: &[f64], reference: &[f64]) {
        assert_eq!(x.len(), reference.len(), "{name}: sizes");
        let scale = reference.iter().fold(0.0_f64, |m, r| m.max(r.abs()));
        let diff = x
            .iter()
            .zip(reference)
            .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        let e = if scale < 1e-12 { diff } else { diff / scale };
        let e = if e.is_nan() { f64::INFINITY } else { e };
        let slot = self.0.entry(name.to_owned()).or_insert(0.0);
        *slot = slot.max(e);
    }
    fn worst(&self) -> f64 {
        self.0.values().fold(0.0, |m, &e| m.max(e))
    }
}

fn flat(v: &Value) -> Vec<f64> {
    match v {
        Value::Array(a) => a.iter().flat_map(flat).collect(),
        Value::Number(n) => vec![n.as_f64().unwrap()],
        _ => panic!("not numbers: {v}"),
    }
}

fn mat_rows<S: Scalar, const R: usize, const C: usize>(m: &[[S; C]; R]) -> Vec<f64> {
    m.iter().flatten().map(|x| x.to_f64()).collect()
}

fn motion6<S: Scalar>(m: &Motion<S>) -> Vec<f64> {
    m.to_linear_first().iter().map(|x| x.to_f64()).collect()
}

fn force6<S: Scalar>(f: &Force<S>) -> Vec<f64> {
    f.to_linear_first().iter().map(|x| x.to_f64()).collect()
}

fn vec3<S: Scalar>(p: &Vec3<S>) -> Vec<f64> {
    p.to_array().iter().map(|x| x.to_f64()).collect()
}

/// Pinocchio's 6×6 spatial inertia matrix, [linear; angular].
fn inertia_matrix<S: Scalar>(i: &Inertia<S>) -> Vec<f64> {
    let m = i.mass.to_f64();
    let c = vec3(&i.com);
    let cx = [[0.0, -c[2], c[1]], [c[2], 0.0, -c[0]], [-c[1], c[0], 0.0]];
    let ic = i.rot_inertia.to_mat3();
    let mut out = vec![0.0; 36];
    for r in 0..3 {
        for k in 0..3 {
            out[r * 6 + k] = if r == k { m } else { 0.0 };
            out[r * 6 + 3 + k] = -m * cx[r][k];
            out[(3 + r) * 6 + k] = m * cx[r][k];
            let cxcx: f64 = (0..3).map(|l| cx[r][l] * cx[l][k]).sum();
            out[(3 + r) * 6 + 3 + k] = ic.m[r][k].to_f64() - m * cxcx;
        }
    }
    out
}

fn placement<S: Scalar>(v: &Value) -> Transform<S> {
    let r = flat(&v["rotation"]);
    let t = flat(&v["translation"]);
    let s = |x: f64| S::from_f64(x);
    Transform::new(
        Mat3::from_rows([
            [s(r[0]), s(r[1]), s(r[2])],
            [s(r[3]), s(r[4]), s(r[5])],
            [s(r[6]), s(r[7]), s(r[8])],
        ]),
        Vec3::new(s(t[0]), s(t[1]), s(t[2])),
    )
}

fn compare<S: Scalar, const NB: usize, const NQ: usize, const NV: usize>(name: &str) -> Errors {
    let base = Fixture::load_named(name).unwrap();
    let model = base.model::<NB, NQ, NV>().unwrap().cast::<S>().unwrap();
    let path = fixtures_dir()
        .join("kinematics")
        .join(format!("{name}.json"));
    let kin: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let frames: Vec<Frame<S>> = kin["frames"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            Frame::new(
                f["body"].as_u64().unwrap() as usize,
                placement(&f["placement"]),
            )
        })
        .collect();
    let states = kin["states"].as_array().unwrap();
    assert_eq!(states.len(), base.states.len());

    let mut errors = Errors::default();
    let mut data = Data::<S, NB, NV>::new();
    let mut jac = JacobianData::<S, NV>::new();
    let mut cd = CentroidalData::<S, NB, NV>::new();
    let mut cols = [Motion::<S>::ZERO; NV];
    for (state, r) in base.states.iter().zip(states) {
        let s = state.arrays::<S, NB, NQ, NV>().unwrap();
        let zero = [S::ZERO; NV];

        joint_jacobians(&model, &mut data, &mut jac, &s.q).unwrap();
        errors.add(
            "joint_jacobians",
            &mat_rows(&to_linear_first(&jac.j)),
            &flat(&r["joint_jacobians"]),
        );
        for (f, rf) in frames.iter().zip(r["frames"].as_array().unwrap()) {
            let o_m_f = frame_placement(&data, f).unwrap();
            let mut p = mat_rows(&o_m_f.rot.m);
            p.extend(vec3(&o_m_f.trans));
            let mut p_ref = flat(&rf["placement"]["rotation"]);
            p_ref.extend(flat(&rf["placement"]["translation"]));
            errors.add("frame_placement", &p, &p_ref);
            for (key, reference) in REFERENCES {
                frame_jacobian(&model, &data, &jac, f, reference, &mut cols).unwrap();
                errors.add(
                    &format!("frame_jacobian_{key}"),
                    &mat_rows(&to_linear_first(&cols)),
                    &flat(&rf[format!("jacobian_{key}")]),
                );
            }
        }

        joint_jacobians_time_variation(&model, &mut data, &mut jac, &s.q, &s.v).unwrap();
        errors.add(
            "joint_jacobians_dot",
            &mat_rows(&to_linear_first(&jac.dj)),
            &flat(&r["joint_jacobians_dot"]),
        );
        for (f, rf) in frames.iter().zip(r["frames"].as_array().unwrap()) {
            for (key, reference) in REFERENCES {
                frame_jacobian_time_variation(&model, &data, &jac, f, reference, &mut cols)
                    .unwrap();
                errors.add(
                    &format!("frame_jacobian_dot_{key}"),
                    &mat_rows(&to_linear_first(&cols)),
                    &flat(&rf[format!("jacobian_dot_{key}")]),
                );
            }
        }

        forward_kinematics_acceleration(&model, &mut data, &s.q, &s.v, &s.a).unwrap();
        for (f, rf) in frames.iter().zip(r["frames"].as_array().unwrap()) {
            for (key, reference) in REFERENCES {
                let v = frame_velocity(&data, f, reference).unwrap();
                errors.add(
                    &format!("frame_velocity_{key}"),
                    &motion6(&v),
                    &flat(&rf[format!("velocity_{key}")]),
                );
                let a = frame_classical_acceleration(&data, f, reference).unwrap();
                errors.add(
                    &format!("frame_classical_acceleration_{key}"),
                    &motion6(&a),
                    &flat(&rf[format!("classical_acceleration_{key}")]),
                );
            }
        }
        forward_kinematics_acceleration(&model, &mut data, &s.q, &s.v, &zero).unwrap();
        for (f, rf) in frames.iter().zip(r["frames"].as_array().unwrap()) {
            for (key, reference) in REFERENCES {
                let a = frame_classical_acceleration(&data, f, reference).unwrap();
                errors.add(
                    &format!("jdot_v_{key}"),
                    &motion6(&a),
                    &flat(&rf[format!("jdot_v_{key}")]),
                );
            }
        }

        centroidal_map(&model, &mut data, &mut cd, &s.q).unwrap();
        let ag: Vec<[S; 6]> = cd.ag.iter().map(|c| c.to_linear_first()).collect();
        let mut ag_rows = vec![0.0; 6 * NV];
        for (k, c) in ag.iter().enumerate() {
            for row in 0..6 {
                ag_rows[row * NV + k] = c[row].to_f64();
            }
        }
        errors.add("centroidal_map", &ag_rows, &flat(&r["ag"]));
        errors.add("ccrba_ig", &inertia_matrix(&cd.ig), &flat(&r["ig"]));
        let mut jcom = [Vec3::<S>::ZERO; NV];
        com_jacobian(&cd, &mut jcom);
        let mut jcom_rows = vec![0.0; 3 * NV];
        for (k, c) in jcom.iter().enumerate() {
            for (row, x) in vec3(c).into_iter().enumerate() {
                jcom_rows[row * NV + k] = x;
            }
        }
        errors.add("com_jacobian", &jcom_rows, &flat(&r["com_jacobian"]));
        errors.add("com", &vec3(&cd.com()), &flat(&r["com"]));

        centroidal_momentum(&model, &mut data, &mut cd, &s.q, &s.v, &s.a).unwrap();
        errors.add("ccrba_hg", &force6(&cd.hg), &flat(&r["hg"]));
        errors.add(
            "centroidal_momentum_rate",
            &force6(&cd.dhg),
            &flat(&r["dhg"]),
        );
        let (vcom, acom) = com_velocity_acceleration(&cd);
        errors.add("com_velocity", &vec3(&vcom), &flat(&r["com_velocity"]));
        errors.add(
            "com_acceleration",
            &vec3(&acom),
            &flat(&r["com_acceleration"]),
        );
        centroidal_momentum(&model, &mut data, &mut cd, &s.q, &s.v, &zero).unwrap();
        errors.add("dccrba_dag_v", &force6(&cd.dhg), &flat(&r["dag_v"]));
        let mut dag = [Force::<S>::ZERO; NV];
        centroidal_map_time_variation(&model, &mut data, &mut cd, &s.q, &s.v, &mut dag).unwrap();
        let mut dag_rows = vec![0.0; 6 * NV];
        for (k, c) in dag.iter().enumerate() {
            for (row, x) in force6(c).into_iter().enumerate() {
                dag_rows[row * NV + k] = x;
            }
        }
        errors.add("dccrba_dag", &dag_rows, &flat(&r["dag"]));
    }
    errors
}

fn check(name: &str, errors: &Errors, bound: f64) {
    let failed: Vec<String> = errors
        .0
        .iter()
        .filter(|(_, &e)| e > bound)
        .map(|(k, e)| format!("{k} {e:.2e}"))
        .collect();
    assert!(
        failed.is_empty(),
        "{name}: above {bound:e}: {}",
        failed.join(", ")
    );
}

macro_rules! kinematics_tests {
    ($(($id:ident, $name:literal, $nb:literal, $nq:literal, $nv:literal, $f32_bound:literal)),* $(,)?) => {
        mod f64_reference {
            use super::*;
            $(
                #[test]
                fn $id() {
                    let errors = compare::<f64, $nb, $nq, $nv>($name);
                    println!("{} f64 worst {:.2e}: {:?}", $name, errors.worst(), errors.0);
                    check($name, &errors, F64_TOLERANCE);
                }
            )*
        }
        mod f32_bounded {
            use super::*;
            $(
                #[test]
                fn $id() {
                    let errors = compare::<f32, $nb, $nq, $nv>($name);
                    println!("{} f32 worst {:.2e}: {:?}", $name, errors.worst(), errors.0);
                    check($name, &errors, $f32_bound);
                }
            )*
        }
    };
}

// f32 bounds: 4x the worst error measured over every quantity (x86-64,
// Rust 1.95, Pinocchio 4.1 fixtures; printed by these tests with
// `--nocapture`), rounded up. The branched tree's worst is J̇ v in
// LOCAL_WORLD_ALIGNED, a small vector formed as a difference of larger ones.
kinematics_tests! {
    (ur5, "ur5", 6, 6, 6, 2e-6),
    (panda, "panda", 7, 7, 7, 2e-6),
    (solo12, "solo12", 13, 19, 18, 3e-6),
    (branched_tree, "branched_tree", 13, 13, 13, 3e-5),
}
