//! Every way to build a model checks what the algorithms' unchecked
//! indexing assumes: parents before children, coordinate counts that add
//! up to `NQ` and `NV`, and joints whose `nq`/`nv` are the ones the
//! topology lays out for their bodies. A bad tree is refused, never built.

use rodyn::error::{ModelProblem, TopologyProblem};
use rodyn::planar::{Planar, PlanarInertia, PlanarJoint, PlanarMotion, PlanarTransform, Vec2};
use rodyn::prelude::*;
use rodyn::topology::Topology;
use rodyn::Error;

const BODY: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(0.5, 0.0, 0.0));
const GRAVITY: Motion<f64> = Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81));

/// A free-flyer carrying a revolute joint, with the topology laid out for
/// the joints in the other order: the counts add up (8 and 7), body 0's
/// do not match (1 laid out, 7 and 6 in its joint).
fn swapped_layout() -> Topology<2, 7> {
    Topology::new([None, Some(0)], [1, 7], [1, 6], 8)
}

#[test]
fn try_from_parts_names_the_body_whose_joint_does_not_match() {
    let result = Model::<f64, 2, 8, 7>::try_from_parts(
        swapped_layout(),
        [Joint::free_flyer(), Joint::revolute(Axis::Z)],
        [Transform::IDENTITY; 2],
        [BODY; 2],
        GRAVITY,
    );
    assert_eq!(
        result.err(),
        Some(Error::InvalidModel {
            body: 0,
            problem: ModelProblem::JointCoordinateMismatch,
        })
    );
}

#[test]
fn try_from_parts_names_a_later_body_when_only_its_nv_differs() {
    // Same counts in q, not in v: a prismatic joint is laid out with no
    // velocity coordinate at body 1 and a second one at body 2.
    let topology = Topology::<3, 3>::new([None, Some(0), Some(1)], [1, 1, 1], [1, 0, 2], 3);
    let result = Model::<f64, 3, 3, 3>::try_from_parts(
        topology,
        [Joint::revolute(Axis::Z); 3],
        [Transform::IDENTITY; 3],
        [BODY; 3],
        GRAVITY,
    );
    assert_eq!(
        result.err(),
        Some(Error::InvalidModel {
            body: 1,
            problem: ModelProblem::JointCoordinateMismatch,
        })
    );
}

#[test]
fn try_from_parts_refuses_a_topology_for_another_nq() {
    let topology = Topology::<2, 2>::new([None, Some(0)], [1; 2], [1; 2], 2);
    let result = Model::<f64, 2, 3, 2>::try_from_parts(
        topology,
        [Joint::revolute(Axis::Z); 2],
        [Transform::IDENTITY; 2],
        [BODY; 2],
        GRAVITY,
    );
    assert_eq!(
        result.err(),
        Some(Error::InvalidModel {
            body: 0,
            problem: ModelProblem::Topology(TopologyProblem::ConfigurationCount),
        })
    );
}

#[test]
fn try_from_parts_accepts_matching_joints_as_new_builds_them() {
    let built = Model::<f64, 2, 8, 7>::try_from_parts(
        Topology::new([None, Some(0)], [7, 1], [6, 1], 8),
        [Joint::free_flyer(), Joint::revolute(Axis::Z)],
        [Transform::IDENTITY; 2],
        [BODY; 2],
        GRAVITY,
    )
    .expect("the joints match the layout");
    let reference = Model::<f64, 2, 8, 7>::new(
        [None, Some(0)],
        [Joint::free_flyer(), Joint::revolute(Axis::Z)],
        [Transform::IDENTITY; 2],
        [BODY; 2],
        GRAVITY,
    );
    assert_eq!(built.topology().idx_q, reference.topology().idx_q);
    assert_eq!(built.topology().idx_v, reference.topology().idx_v);
    assert_eq!(built.configuration_range(1), (7, 1));
}

#[test]
#[should_panic(expected = "body 0: its joint's coordinate counts (nq, nv) differ")]
fn from_parts_panics_on_a_joint_that_does_not_match() {
    let _ = Model::<f64, 2, 8, 7>::from_parts(
        swapped_layout(),
        [Joint::free_flyer(), Joint::revolute(Axis::Z)],
        [Transform::IDENTITY; 2],
        [BODY; 2],
        GRAVITY,
    );
}

#[test]
fn planar_try_from_parts_names_the_body_whose_joint_does_not_match() {
    let body = PlanarInertia::new(1.0, Vec2::new(0.5, 0.0), 0.01);
    let result = Model::<f64, 2, 4, 4, Planar>::try_from_parts(
        Topology::new([None, Some(0)], [3, 1], [3, 1], 4),
        [PlanarJoint::Revolute, PlanarJoint::Floating],
        [PlanarTransform::from_translation(Vec2::ZERO); 2],
        [body; 2],
        PlanarMotion::new(0.0, Vec2::new(0.0, -9.81)),
    );
    assert_eq!(
        result.err(),
        Some(Error::InvalidModel {
            body: 0,
            problem: ModelProblem::JointCoordinateMismatch,
        })
    );
}

#[test]
fn try_new_names_the_body_whose_parent_comes_after_it() {
    let result = Model::<f64, 3, 3, 3>::try_new(
        [None, Some(2), Some(0)],
        [Joint::revolute(Axis::Z); 3],
        [Transform::IDENTITY; 3],
        [BODY; 3],
        GRAVITY,
    );
    assert_eq!(
        result.err(),
        Some(Error::InvalidModel {
            body: 1,
            problem: ModelProblem::Topology(TopologyProblem::ParentAfterChild),
        })
    );
}

#[test]
fn try_new_refuses_counts_that_do_not_add_up() {
    // 7 + 1 configuration coordinates declared as 7 (the compile-fail
    // test `dof_count_mismatch` is the same tree in a `const`).
    let result = Model::<f64, 2, 7, 7>::try_new(
        [None, Some(0)],
        [Joint::free_flyer(), Joint::revolute(Axis::X)],
        [Transform::IDENTITY; 2],
        [BODY; 2],
        GRAVITY,
    );
    assert_eq!(
        result.err(),
        Some(Error::InvalidModel {
            body: 0,
            problem: ModelProblem::Topology(TopologyProblem::ConfigurationCount),
        })
    );
    let result = Model::<f64, 2, 8, 6>::try_new(
        [None, Some(0)],
        [Joint::free_flyer(), Joint::revolute(Axis::X)],
        [Transform::IDENTITY; 2],
        [BODY; 2],
        GRAVITY,
    );
    assert_eq!(
        result.err(),
        Some(Error::InvalidModel {
            body: 0,
            problem: ModelProblem::Topology(TopologyProblem::VelocityCount),
        })
    );
}

#[test]
fn try_new_builds_what_new_builds() {
    let parents = [None, Some(0), Some(0)];
    let joints = [
        Joint::free_flyer(),
        Joint::revolute(Axis::X),
        Joint::prismatic(Axis::Y),
    ];
    let built = Model::<f64, 3, 9, 8>::try_new(
        parents,
        joints,
        [Transform::IDENTITY; 3],
        [BODY; 3],
        GRAVITY,
    )
    .expect("a consistent tree");
    let reference = Model::<f64, 3, 9, 8>::new(
        parents,
        joints,
        [Transform::IDENTITY; 3],
        [BODY; 3],
        GRAVITY,
    );
    assert_eq!(built.topology().idx_q, [0, 7, 8]);
    assert_eq!(built.topology().idx_v, reference.topology().idx_v);
    assert_eq!(built.topology().lambda_v, reference.topology().lambda_v);
    // The free-flyer's quaternion restricts q in both.
    let mut q = built.neutral_configuration();
    q[3] = 2.0;
    assert!(built.check_configuration(&q).is_err());
    assert!(reference.check_configuration(&q).is_err());
}

#[test]
fn try_new_planar_names_the_body_whose_parent_comes_after_it() {
    let body = PlanarInertia::new(1.0, Vec2::new(0.5, 0.0), 0.01);
    let joints = [PlanarJoint::Floating, PlanarJoint::Revolute];
    let placements = [PlanarTransform::from_translation(Vec2::ZERO); 2];
    let gravity = PlanarMotion::new(0.0, Vec2::new(0.0, -9.81));
    let result = Model::<f64, 2, 4, 4, Planar>::try_new_planar(
        [Some(1), None],
        joints,
        placements,
        [body; 2],
        gravity,
    );
    assert_eq!(
        result.err(),
        Some(Error::InvalidModel {
            body: 0,
            problem: ModelProblem::Topology(TopologyProblem::ParentAfterChild),
        })
    );
    let built = Model::<f64, 2, 4, 4, Planar>::try_new_planar(
        [None, Some(0)],
        joints,
        placements,
        [body; 2],
        gravity,
    )
    .expect("a consistent tree");
    assert_eq!(built.configuration_range(1), (3, 1));
    assert_eq!(built.topology().idx_v, [0, 3]);
}
