//! The public formulas that return `Result`: each names the input that is
//! bad (which one, at which index), tells an overflow of finite inputs
//! apart from a bad input, and answers good inputs with the numbers the
//! formula gives. (The probe, probe_public_api.rs, checks only "finite or
//! a named error"; here the names themselves.)

use rodyn::algorithm::dense::cholesky_solve;
use rodyn::algorithm::inverse_kinematics::pose_error;
use rodyn::algorithm::jacobian::mul_rates;
use rodyn::error::{Error, ModelProblem, Quantity};
use rodyn::prelude::*;
use rodyn::sim::manifold::configuration_rate;
use rodyn::spatial::Mat3;
use rodyn::Endpoint;
use rodyn_host_tests::contact_fixture::{solo12, SOLO_NQ, SOLO_NV};

/// The factor of `[[4, 2], [2, 3]]`.
fn factor() -> [[f64; 2]; 2] {
    [[2.0, 0.0], [1.0, 2f64.sqrt()]]
}

#[test]
fn cholesky_solve_names_the_row_or_the_overflow() {
    let mut b = [2.0, 1.0];
    cholesky_solve(&factor(), 2, &mut b).unwrap();
    // A = [[4, 2], [2, 3]], b = [2, 1]: x = [0.5, 0].
    assert!((b[0] - 0.5).abs() < 1e-15 && b[1].abs() < 1e-15, "{b:?}");

    let row = |index| Error::NonFinite {
        quantity: Quantity::LinearSystem,
        index,
    };
    let mut b = [2.0, f64::NAN];
    assert_eq!(cholesky_solve(&factor(), 2, &mut b), Err(row(1)));
    let mut l = factor();
    l[1][0] = f64::INFINITY;
    assert_eq!(cholesky_solve(&l, 2, &mut [2.0, 1.0]), Err(row(1)));
    // A zero pivot: finite inputs, an infinite solution.
    let mut l = factor();
    l[1][1] = 0.0;
    assert!(matches!(
        cholesky_solve(&l, 2, &mut [2.0, 1.0]),
        Err(Error::NonFiniteResult {
            quantity: Quantity::LinearSystem,
            ..
        })
    ));
    assert_eq!(
        cholesky_solve(&factor(), 3, &mut [2.0, 1.0]),
        Err(Error::TooManyConstraints {
            rows: 3,
            capacity: 2
        })
    );
}

#[test]
fn mul_rates_names_the_rate_or_the_column() {
    let columns = [
        Motion::new(Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0)),
        Motion::new(Vec3::new(0.0, 0.0, 3.0), Vec3::new(4.0, 0.0, 0.0)),
    ];
    let jv = mul_rates::<f64, 2, Spatial>(&columns, &[0.5, 2.0]).unwrap();
    assert_eq!(
        jv,
        Motion::new(Vec3::new(0.5, 0.0, 6.0), Vec3::new(8.0, 1.0, 0.0))
    );
    assert_eq!(
        mul_rates::<f64, 2, Spatial>(&columns, &[0.5, f64::NAN]),
        Err(Error::NonFinite {
            quantity: Quantity::Velocity,
            index: 1
        })
    );
    let mut bad = columns;
    bad[1].ang.z = f64::NEG_INFINITY;
    assert_eq!(
        mul_rates::<f64, 2, Spatial>(&bad, &[0.5, 2.0]),
        Err(Error::NonFinite {
            quantity: Quantity::Jacobian,
            index: 1
        })
    );
    assert_eq!(
        mul_rates::<f64, 2, Spatial>(&columns, &[1e308, 1e308]),
        Err(Error::NonFiniteResult {
            quantity: Quantity::Jacobian,
            index: 0
        })
    );
}

#[test]
fn pose_error_names_the_pose_that_is_not_a_rigid_motion() {
    let frame = Transform::from_translation(Vec3::new(0.25, 0.2, 0.3));
    let target = Transform::from_translation(Vec3::new(0.5, 0.2, 0.3));
    // The same axes, 0.25 m along x.
    let e = pose_error(&frame, &target).unwrap();
    assert_eq!(e, Motion::new(Vec3::ZERO, Vec3::new(0.25, 0.0, 0.0)));

    let mut flat = target;
    flat.rot = Mat3 { m: [[0.0; 3]; 3] };
    assert_eq!(
        pose_error(&frame, &flat),
        Err(Error::InvalidPose {
            quantity: Quantity::Target,
            index: 0,
            problem: ModelProblem::RotationNotOrthonormal
        })
    );
    let mut lost = frame;
    lost.trans.y = f64::NAN;
    assert_eq!(
        pose_error(&lost, &target),
        Err(Error::InvalidPose {
            quantity: Quantity::WorldPose,
            index: 0,
            problem: ModelProblem::NonFiniteParameter
        })
    );
}

#[test]
fn world_position_names_the_point_the_pose_or_the_body() {
    let poses = [
        Transform::IDENTITY,
        Transform::from_translation(Vec3::new(1.0, 0.0, 0.0)),
    ];
    let point = Vec3::new(0.0, 0.5, 0.0);
    let on_body = Endpoint::<f64>::on_body(1, point);
    assert_eq!(on_body.world_position(&poses), Ok(Vec3::new(1.0, 0.5, 0.0)));
    assert_eq!(
        Endpoint::<f64>::on_body(2, point).world_position(&poses),
        Err(Error::BodyOutOfRange { body: 2 })
    );
    let nowhere = Vec3::new(f64::NAN, 0.0, 0.0);
    let path_point = Error::NonFinite {
        quantity: Quantity::PathPoint,
        index: 0,
    };
    assert_eq!(
        Endpoint::<f64>::on_body(1, nowhere).world_position(&poses),
        Err(path_point)
    );
    assert_eq!(
        Endpoint::<f64>::in_world(nowhere).world_position(&poses),
        Err(path_point)
    );
    let mut lost = poses;
    lost[1].trans.z = f64::INFINITY;
    assert_eq!(
        on_body.world_position(&lost),
        Err(Error::NonFinite {
            quantity: Quantity::WorldPose,
            index: 1
        })
    );
}

#[test]
fn configuration_rate_names_the_coordinate() {
    let model = solo12();
    let mut q = [0.0; SOLO_NQ];
    q[6] = 1.0;
    let mut v = [0.0; SOLO_NV];
    v[0] = 0.7;
    v[7] = -0.2;
    // At the identity orientation the base's rates are its velocity; a
    // hinge's rate is its velocity.
    let q_dot = configuration_rate(&model, &q, &v).unwrap();
    assert_eq!(q_dot[0], 0.7);
    assert_eq!(q_dot[8], -0.2);

    let mut bad_q = q;
    bad_q[4] = f64::NAN;
    assert_eq!(
        configuration_rate(&model, &bad_q, &v),
        Err(Error::NonFinite {
            quantity: Quantity::Configuration,
            index: 4
        })
    );
    let mut bad_v = v;
    bad_v[3] = f64::INFINITY;
    assert_eq!(
        configuration_rate(&model, &q, &bad_v),
        Err(Error::NonFinite {
            quantity: Quantity::Velocity,
            index: 3
        })
    );
}
