//! A rotation [`Mat3`] ↔ `Rotation3` and `UnitQuaternion`.
//!
//! rodyn keeps rotations as matrices; a `Mat3` given to these conversions
//! must be one (orthonormal, determinant 1), as a [`Transform`](crate::spatial::Transform)'s
//! `rot` is.

use ::nalgebra::{Quaternion, RealField, Rotation3, Unit, UnitQuaternion};

use crate::spatial::Mat3;
use crate::Scalar;

impl<S: Scalar> From<Mat3<S>> for Rotation3<S> {
    /// The same matrix, taken as a rotation without a check.
    ///
    /// ```
    /// use nalgebra::{Rotation3, Vector3};
    /// use rodyn::prelude::*;
    ///
    /// let r: Rotation3<f64> = Mat3::from_axis_angle(&Vec3::new(0.0, 0.0, 1.0), 0.5).into();
    /// assert!((r.angle() - 0.5).abs() < 1e-15);
    /// ```
    fn from(m: Mat3<S>) -> Self {
        Rotation3::from_matrix_unchecked(m.into())
    }
}

impl<S: Scalar> From<Rotation3<S>> for Mat3<S> {
    /// The rotation's matrix, entry for entry.
    ///
    /// ```
    /// use nalgebra::{Rotation3, Vector3};
    /// use rodyn::prelude::*;
    ///
    /// let m = Mat3::from(Rotation3::from_axis_angle(&Vector3::z_axis(), 0.5));
    /// let expected = Mat3::from_axis_angle(&Vec3::new(0.0, 0.0, 1.0), 0.5);
    /// assert!((m.m[0][1] - expected.m[0][1]).abs() < 1e-15);
    /// ```
    fn from(r: Rotation3<S>) -> Self {
        r.into_inner().into()
    }
}

impl<S: Scalar + RealField> From<Mat3<S>> for UnitQuaternion<S> {
    /// The unit quaternion of the rotation (nalgebra's conversion from a
    /// rotation matrix; rounded once).
    ///
    /// ```
    /// use nalgebra::UnitQuaternion;
    /// use rodyn::prelude::*;
    ///
    /// let q: UnitQuaternion<f64> = Mat3::from_axis_angle(&Vec3::new(1.0, 0.0, 0.0), 0.25).into();
    /// assert!((q.angle() - 0.25).abs() < 1e-15);
    /// ```
    fn from(m: Mat3<S>) -> Self {
        UnitQuaternion::from_rotation_matrix(&m.into())
    }
}

impl<S: Scalar> From<Unit<Quaternion<S>>> for Mat3<S> {
    /// The rotation matrix of the unit quaternion, by rodyn's
    /// [`Mat3::from_quaternion`] (as the model compiler forms a URDF's).
    ///
    /// ```
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// use rodyn::prelude::*;
    ///
    /// let m = Mat3::from(UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 0.25));
    /// let expected = Mat3::from_axis_angle(&Vec3::new(0.0, 1.0, 0.0), 0.25);
    /// assert!((m.m[0][2] - expected.m[0][2]).abs() < 1e-15);
    /// ```
    fn from(q: Unit<Quaternion<S>>) -> Self {
        // nalgebra stores a quaternion as `[i, j, k, w]`.
        let c = q.into_inner().coords;
        Mat3::from_quaternion(c[0], c[1], c[2], c[3])
    }
}
