//! rodyn's types through nalgebra's and back (feature `nalgebra`): every
//! conversion that copies entries round-trips exactly; the quaternion's
//! rounds once each way; the order of a spatial vector is Pinocchio's,
//! linear part first.

use approx::{assert_relative_eq, assert_ulps_eq};
use nalgebra::{
    Isometry3, IsometryMatrix3, Matrix3, Point3, Rotation3, SMatrix, SVector, UnitQuaternion,
    Vector3, Vector6,
};
use rodyn::algorithm::jacobian::to_linear_first;
use rodyn::interop::nalgebra::{jacobian_matrix, matrix_from_rows, rows_from_matrix};
use rodyn::prelude::*;

/// A rotation about an oblique axis, no entry a round number.
fn oblique_rotation() -> Mat3<f64> {
    let axis = Vec3::new(0.3, -0.5, 0.8);
    Mat3::from_axis_angle(&axis.scale(1.0 / axis.norm()), 1.234)
}

fn oblique_transform() -> Transform<f64> {
    Transform::new(oblique_rotation(), Vec3::new(0.125, -2.5, 3.0e-3))
}

#[test]
fn vectors_and_matrices_round_trip_exactly() {
    let v = Vec3::new(0.1, -2.0e10, 3.5e-12);
    let n: Vector3<f64> = v.into();
    assert_eq!((n.x, n.y, n.z), (v.x, v.y, v.z));
    assert_eq!(Vec3::from(n), v);

    let m = Mat3::from_rows([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0], [7.0, 8.0, 9.5]]);
    let n: Matrix3<f64> = m.into();
    assert_eq!(n, Matrix3::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.5));
    assert_eq!(Mat3::from(n), m);

    let inertia = Sym3::new(1.0, 0.1, 0.2, 2.0, 0.3, 3.0);
    let n: Matrix3<f64> = inertia.into();
    assert_eq!(n, inertia.to_mat3().into());
    assert_eq!(n, n.transpose());
}

#[test]
fn joint_space_arrays_round_trip_exactly() {
    let q = [0.1, -0.2, 0.3, 1.0e-9];
    let n: SVector<f64, 4> = q.into();
    assert_eq!(n[3], 1.0e-9);
    let back: [f64; 4] = n.into();
    assert_eq!(back, q);

    // Row r of rodyn's array is row r of the matrix, for a matrix that is
    // not symmetric (nalgebra's own `From` would read columns).
    let rows = [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]];
    let m: SMatrix<f64, 2, 3> = matrix_from_rows(&rows);
    assert_eq!((m[(0, 1)], m[(1, 0)]), (2.0, 4.0));
    assert_eq!(rows_from_matrix(&m), rows);
}

#[test]
fn spatial_vectors_are_linear_first_and_round_trip_exactly() {
    let twist = Motion::new(Vec3::new(1.0, 2.0, 3.0), Vec3::new(4.0, 5.0, 6.0));
    let n: Vector6<f64> = twist.into();
    assert_eq!(n, Vector6::new(4.0, 5.0, 6.0, 1.0, 2.0, 3.0));
    assert_eq!(Motion::from(n), twist);

    let wrench = Force::new(Vec3::new(-1.0, 0.5, 0.25), Vec3::new(0.0, 0.0, -9.81));
    let n: Vector6<f64> = wrench.into();
    assert_eq!(n, Vector6::new(0.0, 0.0, -9.81, -1.0, 0.5, 0.25));
    assert_eq!(Force::from(n), wrench);
}

#[test]
fn rotations_and_matrix_isometries_round_trip_exactly() {
    let r = oblique_rotation();
    let n: Rotation3<f64> = r.into();
    assert_eq!(Mat3::from(n), r);
    // nalgebra's angle of the rotation is the one it was built with.
    assert_relative_eq!(n.angle(), 1.234, max_relative = 1e-14);

    let t = oblique_transform();
    let iso: IsometryMatrix3<f64> = t.into();
    assert_eq!(Transform::from(iso), t);
    // The same map of points: p_a = rot p_b + trans.
    let p = Vec3::new(0.7, -0.1, 2.0);
    let mapped = iso * Point3::new(p.x, p.y, p.z);
    let expected = t.rot.mul_vec(&p) + t.trans;
    assert_ulps_eq!(
        Vec3::new(mapped.x, mapped.y, mapped.z),
        expected,
        max_ulps = 4
    );
}

#[test]
fn quaternion_isometries_round_trip_to_rounding() {
    let t = oblique_transform();
    let iso: Isometry3<f64> = t.into();
    let back = Transform::from(iso);
    // The translation is copied; the rotation goes through a quaternion.
    assert_eq!(back.trans, t.trans);
    assert_relative_eq!(back, t, epsilon = 4.0 * f64::EPSILON);
    // And nalgebra's quaternion is the rotation's: the same axis and angle.
    let q: UnitQuaternion<f64> = t.rot.into();
    assert_relative_eq!(q.angle(), 1.234, max_relative = 1e-14);
    let expected = Vector3::new(0.3, -0.5, 0.8).normalize();
    assert_relative_eq!(q.axis().unwrap().into_inner(), expected, epsilon = 1e-14);
    // A quaternion from nalgebra through rodyn and back.
    let q = UnitQuaternion::from_euler_angles(0.1, -0.4, 2.0);
    let again: UnitQuaternion<f64> = Mat3::from(q).into();
    assert!(q.angle_to(&again) < 1e-15, "{}", q.angle_to(&again));
}

#[test]
fn jacobian_matrix_is_the_linear_first_array() {
    let columns = [
        Motion::new(Vec3::new(0.0, 0.0, 1.0), Vec3::new(-0.5, 1.5, 0.0)),
        Motion::new(Vec3::new(0.1, 0.2, 0.3), Vec3::new(0.4, 0.5, 0.6)),
        Motion::ZERO,
    ];
    let j = jacobian_matrix(&columns);
    assert_eq!(rows_from_matrix(&j), to_linear_first(&columns));
    for (k, column) in columns.iter().enumerate() {
        assert_eq!(Motion::from(j.column(k).into_owned()), *column);
    }
}

#[test]
fn f32_converts_like_f64() {
    let t = Transform::<f32>::new(
        Mat3::from_axis_angle(&Vec3::new(0.0, 1.0, 0.0), 0.5),
        Vec3::new(1.0, 2.0, 3.0),
    );
    let iso: IsometryMatrix3<f32> = t.into();
    assert_eq!(Transform::from(iso), t);
    let back = Transform::from(Isometry3::from(t));
    assert_relative_eq!(back, t, epsilon = 4.0 * f32::EPSILON);
}
