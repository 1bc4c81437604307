//! The model compiler (`rodyn-model`) reads every URDF of `models/urdf/` into
//! the same model that the Pinocchio fixture describes: same bodies in the
//! same order, same parents, joints, placements and inertias (after both
//! merged the fixed joints). The fixture-built model is the one that
//! `pinocchio_reference` holds to Pinocchio's results, so the two tests
//! together carry Pinocchio's results over to the compiled models. The
//! generated source rounds quarter turns written to a few digits (the
//! UR5's `rpy` of 1.57079632679) to exact ones; the model with those
//! placements is held to Pinocchio's results here, to the same 1e-9.
//!
//! Gravity is not compared: URDF has none. The compiler uses Pinocchio's
//! default, (0, 0, -9.81); the planar chains' fixtures use (0, -9.81, 0).

use rodyn::joint::Joint;
use rodyn::spatial::{Mat3, Transform};
use rodyn::Model;
use rodyn_host_tests::fixture::compare::{compare_model, Check};
use rodyn_host_tests::fixture::Fixture;
use rodyn_host_tests::for_each_fixture;
use rodyn_model::description::JointType;
use rodyn_model::geometry::snap_signed_permutation;
use rodyn_model::LoadOptions;
use std::path::Path;

/// URDF angles become rotation matrices through different formulas in
/// Pinocchio and in the compiler, and merged inertias are summed in a
/// different order; both round at the last few bits, nothing more.
const PARAMETER_TOLERANCE: f64 = 1e-12;

/// What `pinocchio_reference` asks of the fixture's own model.
const REFERENCE_TOLERANCE: f64 = 1e-9;

fn close(what: &str, compiled: &[f64], fixture: &[f64]) {
    let scale = fixture.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
    for (k, (c, f)) in compiled.iter().zip(fixture).enumerate() {
        assert!(
            (c - f).abs() <= PARAMETER_TOLERANCE * scale,
            "{what}[{k}]: compiler {c}, fixture {f}"
        );
    }
}

/// `("revolute" | "prismatic" | "free-flyer", axis)` of a rodyn joint.
fn joint_of_fixture(joint: &Joint<f64>) -> (&'static str, [f64; 3]) {
    match joint {
        Joint::Revolute(r) => ("revolute", r.axis.vector().to_array()),
        Joint::Prismatic(p) => ("prismatic", p.axis.vector().to_array()),
        Joint::FreeFlyer(_) => ("free-flyer", [0.0; 3]),
        other => panic!("the fixtures hold no {other:?} joint"),
    }
}

fn joint_of_compiler(joint: &JointType) -> (&'static str, [f64; 3]) {
    match joint {
        JointType::Revolute { axis } => ("revolute", *axis),
        JointType::Prismatic { axis } => ("prismatic", *axis),
        JointType::FreeFlyer => ("free-flyer", [0.0; 3]),
        JointType::PlanarFloating => panic!("no URDF here has a planar floating base"),
    }
}

fn compare<const NB: usize, const NQ: usize, const NV: usize>(name: &str) {
    let fixture = Fixture::load_named(name).unwrap_or_else(|e| panic!("{e}"));
    let model: Model<f64, NB, NQ, NV> = fixture.model().unwrap_or_else(|e| panic!("{e}"));
    let urdf = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../models/urdf/{name}.urdf"));
    let options = LoadOptions::new().with_floating_base(name == "solo12");
    let compiled = rodyn_model::load(&urdf, options).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(compiled.bodies.len(), NB, "{name}: number of bodies");
    let mut compiled_model = model;
    for (i, (body, described)) in compiled
        .bodies
        .iter()
        .zip(&fixture.model.joints)
        .enumerate()
    {
        let what = |part: &str| format!("{name} body {i} ({}) {part}", described.name);
        // The free-flyer is Pinocchio's root joint, which it names itself.
        if described.kind != "FreeFlyer" {
            assert_eq!(body.joint_name, described.name, "{}", what("joint name"));
        }
        assert_eq!(body.parent, model.parent(i), "{}", what("parent"));
        let (kind, axis) = joint_of_compiler(&body.joint);
        let (fixture_kind, fixture_axis) = joint_of_fixture(model.joint(i));
        assert_eq!(kind, fixture_kind, "{}", what("joint type"));
        close(&what("axis"), &axis, &fixture_axis);

        let x = model.placement(i);
        close(
            &what("placement rotation"),
            body.placement.rot.as_flattened(),
            x.rot.m.as_flattened(),
        );
        close(
            &what("placement translation"),
            &body.placement.trans,
            &x.trans.to_array(),
        );

        // What the generated source holds: a quarter turn within the
        // compiled model's tolerance (the rounding of an exact one by
        // default) taken as the exact one.
        if let Some(rot) = snap_signed_permutation(&x.rot.m, compiled.snap_tolerance()) {
            compiled_model
                .set_placement(i, Transform::new(Mat3::from_rows(rot), x.trans))
                .unwrap();
        }

        let inertia = model.inertia(i);
        close(&what("mass"), &[body.inertia.mass], &[inertia.mass]);
        close(
            &what("centre of mass"),
            &body.inertia.com,
            &inertia.com.to_array(),
        );
        close(
            &what("rotational inertia"),
            body.inertia.inertia.as_flattened(),
            inertia.rot_inertia.to_mat3().m.as_flattened(),
        );
    }

    // The rounded quarter turns (the UR5's π/2 written to 12 digits moves
    // entries by 4.9e-12) keep the compiled model within the tolerance
    // that `pinocchio_reference` holds the fixture's model to.
    let errors = compare_model(&fixture, &compiled_model).unwrap_or_else(|e| panic!("{e}"));
    for check in Check::ALL {
        let e = errors.get(check);
        assert!(
            e <= REFERENCE_TOLERANCE,
            "{name} with rounded quarter turns: {} {e:.2e}",
            check.name()
        );
    }
}

macro_rules! compiler_tests {
    ($(($id:ident, $name:literal, $nb:literal, $nq:literal, $nv:literal)),* $(,)?) => {
        $(
            #[test]
            fn $id() {
                compare::<$nb, $nq, $nv>($name);
            }
        )*
    };
}

for_each_fixture!(compiler_tests);
