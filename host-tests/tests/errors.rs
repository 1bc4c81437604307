//! Where the mathematics breaks down, rodyn says which joint or body failed
//! instead of returning NaN.

use rodyn::algorithm::crba::crba;
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::algorithm::rnea::rnea;
use rodyn::error::{ModelProblem, Quantity};
use rodyn::joint::ConfigurationError;
use rodyn::prelude::*;

/// A two-link arm whose second link has mass `m2` at its joint axis and
/// rotational inertia `i2` about it.
fn arm(m2: f64, i2: f64) -> Model<f64, 2, 2, 2> {
    Model::new(
        [None, Some(0)],
        [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
        [
            Transform::IDENTITY,
            Transform::from_translation(Vec3::new(0.5, 0.0, 0.0)),
        ],
        [
            Inertia::new(
                1.0,
                Vec3::new(0.25, 0.0, 0.0),
                Sym3::diagonal(0.01, 0.02, 0.02),
            ),
            Inertia::new(m2, Vec3::ZERO, Sym3::diagonal(i2, i2, i2)),
        ],
        Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
    )
}

#[test]
fn massless_leaf_is_a_singular_articulated_inertia_in_aba() {
    let model = arm(0.0, 0.0);
    let mut data = Data::new();
    let err = Aba::forward_dynamics(&model, &mut data, &[0.1, 0.2], &[0.0; 2], &[0.0; 2], None)
        .unwrap_err();
    assert!(
        matches!(err, Error::SingularArticulatedInertia { joint: 1, .. }),
        "{err:?}"
    );
    assert!(err.to_string().contains("joint 1"), "{err}");
}

#[test]
fn massless_leaf_is_a_non_positive_definite_mass_matrix_in_crba() {
    let model = arm(0.0, 0.0);
    let mut data = Data::new();
    let err = Crba::forward_dynamics(&model, &mut data, &[0.1, 0.2], &[0.0; 2], &[0.0; 2], None)
        .unwrap_err();
    assert!(
        matches!(err, Error::MassMatrixNotPositiveDefinite { dof: 1, .. }),
        "{err:?}"
    );
}

#[test]
fn a_tiny_but_real_inertia_still_solves() {
    // 1e-6 of the first link's inertia is far above the reporting threshold.
    let model = arm(1e-3, 1e-8);
    let mut data = Data::new();
    let ddq =
        *Aba::forward_dynamics(&model, &mut data, &[0.1, 0.2], &[0.0; 2], &[0.0; 2], None).unwrap();
    let by_crba =
        *Crba::forward_dynamics(&model, &mut data, &[0.1, 0.2], &[0.0; 2], &[0.0; 2], None)
            .unwrap();
    for k in 0..2 {
        assert!(ddq[k].is_finite());
        assert!(
            (ddq[k] - by_crba[k]).abs() <= 1e-6 * (1.0 + ddq[k].abs()),
            "{ddq:?} vs {by_crba:?}"
        );
    }
}

#[test]
fn non_finite_inputs_are_named() {
    let model = arm(1.0, 0.01);
    let mut data = Data::new();
    let err = rnea(
        &model,
        &mut data,
        &[0.0, 0.0],
        &[0.0, f64::NAN],
        &[0.0; 2],
        None,
    )
    .unwrap_err();
    assert_eq!(
        err,
        Error::NonFinite {
            quantity: Quantity::Velocity,
            index: 1
        }
    );
    let err = rnea(
        &model,
        &mut data,
        &[0.0, 0.0],
        &[0.0; 2],
        &[f64::INFINITY, 0.0],
        None,
    )
    .unwrap_err();
    assert_eq!(
        err,
        Error::NonFinite {
            quantity: Quantity::Acceleration,
            index: 0
        }
    );
    let err = Aba::forward_dynamics(
        &model,
        &mut data,
        &[0.0, 0.0],
        &[0.0; 2],
        &[0.0, f64::NAN],
        None,
    )
    .unwrap_err();
    assert_eq!(
        err,
        Error::NonFinite {
            quantity: Quantity::Torque,
            index: 1
        }
    );
    let err = crba(&model, &mut data, &[f64::NAN, 0.0]).unwrap_err();
    assert_eq!(
        err,
        Error::InvalidConfiguration {
            joint: 0,
            reason: ConfigurationError::NonFinite
        }
    );
    let mut fext = [Force::<f64>::default(); 2];
    fext[1].lin.y = f64::NAN;
    let err = rnea(
        &model,
        &mut data,
        &[0.0; 2],
        &[0.0; 2],
        &[0.0; 2],
        Some(&fext),
    )
    .unwrap_err();
    assert_eq!(
        err,
        Error::NonFinite {
            quantity: Quantity::ExternalForce,
            index: 1
        }
    );
}

#[test]
fn a_quaternion_off_unit_length_is_rejected() {
    const FLOATING: Model<f64, 1, 7, 6> = Model::new(
        [None],
        [Joint::free_flyer()],
        [Transform::IDENTITY],
        [Inertia::new(2.0, Vec3::ZERO, Sym3::diagonal(0.1, 0.1, 0.1))],
        Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
    );
    let mut data = Data::new();
    let q = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.01];
    let err = rnea(&FLOATING, &mut data, &q, &[0.0; 6], &[0.0; 6], None).unwrap_err();
    match err {
        Error::InvalidConfiguration {
            joint: 0,
            reason: ConfigurationError::QuaternionNotUnit { norm },
        } => {
            assert!((norm - 1.01).abs() < 1e-12)
        }
        other => panic!("unexpected {other:?}"),
    }
    // A unit quaternion in free fall: the body accelerates at g, nothing else.
    let q = [0.3, -0.2, 1.0, 0.0, 0.0, 0.6, 0.8];
    let ddq = *Aba::forward_dynamics(&FLOATING, &mut data, &q, &[0.0; 6], &[0.0; 6], None).unwrap();
    // Gravity seen in the body frame: rotation about z leaves -z unchanged.
    assert!(
        (ddq[2] + 9.81).abs() < 1e-12 && ddq[0].abs() < 1e-12 && ddq[5].abs() < 1e-12,
        "{ddq:?}"
    );
}

#[test]
fn unphysical_parameters_are_rejected_with_the_body() {
    let mut model = arm(1.0, 0.01);
    let bad_mass = Inertia::new(-1.0, Vec3::ZERO, Sym3::diagonal(0.1, 0.1, 0.1));
    assert_eq!(
        model.set_inertia(1, bad_mass),
        Err(Error::InvalidModel {
            body: 1,
            problem: ModelProblem::InvalidMass
        })
    );
    // Principal moments 1, 1, 3 break the triangle inequality.
    let bad_inertia = Inertia::new(1.0, Vec3::ZERO, Sym3::diagonal(1.0, 1.0, 3.0));
    assert_eq!(
        model.set_inertia(0, bad_inertia),
        Err(Error::InvalidModel {
            body: 0,
            problem: ModelProblem::InvalidInertia
        })
    );
    let skewed = Transform::new(
        Mat3::from_rows([[1.0, 0.1, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]),
        Vec3::ZERO,
    );
    assert_eq!(
        model.set_placement(1, skewed),
        Err(Error::InvalidModel {
            body: 1,
            problem: ModelProblem::RotationNotOrthonormal
        })
    );
    // The model is unchanged after a rejected update.
    assert_eq!(model.inertia(1).mass, 1.0);
    let long_axis = Model::<f64, 1, 1, 1>::new(
        [None],
        [Joint::revolute(Axis::Unit(Vec3::new(1.0, 1.0, 0.0)))],
        [Transform::IDENTITY],
        [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
        Motion::default(),
    );
    assert_eq!(
        long_axis.validate(),
        Err(Error::InvalidModel {
            body: 0,
            problem: ModelProblem::AxisNotUnit
        })
    );
}

#[test]
fn a_tree_built_at_run_time_reports_its_inconsistency() {
    use rodyn::topology::{Topology, TopologyError};
    let ok = Topology::<3, 3>::try_new([None, Some(0), Some(0)], [1; 3], [1; 3], 3).unwrap();
    assert_eq!(ok.lambda_v, [None, Some(0), Some(0)]);
    assert_eq!(
        Topology::<3, 3>::try_new([None, Some(2), Some(0)], [1; 3], [1; 3], 3),
        Err(TopologyError::ParentAfterChild { body: 1 })
    );
    assert_eq!(
        Topology::<2, 7>::try_new([None, Some(0)], [7, 1], [6, 1], 7),
        Err(TopologyError::ConfigurationCount {
            declared: 7,
            found: 8
        })
    );
    let too_many = Topology::<2, 6>::try_new([None, Some(0)], [7, 1], [6, 1], 8).unwrap_err();
    assert_eq!(
        too_many,
        TopologyError::VelocityCount {
            declared: 6,
            found: 7
        }
    );
    assert!(
        too_many.to_string().contains("declared 6, joints give 7"),
        "{too_many}"
    );
    assert_eq!(
        Topology::<1, 7>::try_new([None], [7], [7], 7),
        Err(TopologyError::TooManyJointDofs { body: 0 })
    );
}

/// A model's topology is always one `Topology::try_new` laid out (its
/// tables cannot be written: a doctest on `Topology` fails to compile),
/// and `Model::from_parts` refuses one laid out for another `NQ`: the
/// algorithms index the model's vectors by these tables without checks.
#[test]
#[should_panic(expected = "do not add up to NQ")]
fn from_parts_refuses_a_topology_for_another_nq() {
    use rodyn::topology::Topology;
    let topology = Topology::<2, 2>::new([None, Some(0)], [1; 2], [1; 2], 2);
    let _: Model<f64, 2, 3, 2> = Model::from_parts(
        topology,
        [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
        [Transform::IDENTITY; 2],
        [Inertia::point_mass(1.0, Vec3::new(0.5, 0.0, 0.0)); 2],
        Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
    );
}

/// The built-in joints read their coordinates from the front of the
/// slices they are given (the algorithms pass the state from a joint's
/// first coordinate on) and do not panic on a short one.
#[test]
fn joints_read_from_the_front_and_tolerate_short_slices() {
    use rodyn::joint::JointModel;
    let free = Joint::<f64>::free_flyer();
    let q = [1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 1.0, 99.0, 99.0];
    let t = free.transform(&q);
    assert_eq!(t, free.transform(&q[..7]));
    assert_eq!(t.trans, Vec3::new(1.0, 2.0, 3.0));
    assert_eq!(free.transform(&q[..3]), Transform::IDENTITY);
    let revolute = Joint::<f64>::revolute(Axis::Z);
    assert_eq!(revolute.transform(&[0.3, 7.0]), revolute.transform(&[0.3]));
    assert_eq!(revolute.transform(&[]), revolute.transform(&[0.0]));
    let mut out = [0.0; 2];
    free.integrate(&q[..3], &[0.0; 6], 0.1, &mut out);
    assert_eq!(out, [0.0; 2]);
}
