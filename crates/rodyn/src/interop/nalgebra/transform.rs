//! [`Transform`] ↔ `IsometryMatrix3` and `Isometry3`.
//!
//! Both sides map a point as `p_a = rot p_b + trans`: a transform `aMb`
//! becomes the isometry with rotation `rot` and translation `trans`.

use ::nalgebra::{Isometry3, IsometryMatrix3, RealField, Translation3, UnitQuaternion};

use crate::spatial::{Mat3, Transform};
use crate::Scalar;

impl<S: Scalar + RealField> From<Transform<S>> for IsometryMatrix3<S> {
    /// Rotation matrix and translation as they are (exact).
    ///
    /// ```
    /// use nalgebra::{IsometryMatrix3, Point3};
    /// use rodyn::prelude::*;
    ///
    /// let t = Transform::new(
    ///     Mat3::from_axis_angle(&Vec3::new(0.0, 0.0, 1.0), 0.3),
    ///     Vec3::new(1.0, 2.0, 3.0),
    /// );
    /// let iso: IsometryMatrix3<f64> = t.into();
    /// let p = iso * Point3::new(0.5, 0.0, 0.0);
    /// let expected = t.rot.mul_vec(&Vec3::new(0.5, 0.0, 0.0)) + t.trans;
    /// assert_eq!((p.x, p.y, p.z), (expected.x, expected.y, expected.z));
    /// assert_eq!(Transform::from(iso), t);
    /// ```
    fn from(t: Transform<S>) -> Self {
        IsometryMatrix3::from_parts(Translation3::from(t.trans.to_array()), t.rot.into())
    }
}

impl<S: Scalar + RealField> From<IsometryMatrix3<S>> for Transform<S> {
    /// Rotation matrix and translation as they are (exact).
    ///
    /// ```
    /// use nalgebra::{IsometryMatrix3, Vector3};
    /// use rodyn::prelude::*;
    ///
    /// let iso = IsometryMatrix3::translation(1.0, 2.0, 3.0);
    /// assert_eq!(Transform::from(iso), Transform::from_translation(Vec3::new(1.0, 2.0, 3.0)));
    /// ```
    fn from(iso: IsometryMatrix3<S>) -> Self {
        Transform::new(iso.rotation.into(), iso.translation.vector.into())
    }
}

impl<S: Scalar + RealField> From<Transform<S>> for Isometry3<S> {
    /// The rotation as a unit quaternion (rounded once), the translation
    /// as it is.
    ///
    /// ```
    /// use nalgebra::{Isometry3, Point3};
    /// use rodyn::prelude::*;
    ///
    /// let t = Transform::new(
    ///     Mat3::from_axis_angle(&Vec3::new(0.0, 1.0, 0.0), -0.7),
    ///     Vec3::new(0.1, 0.2, 0.3),
    /// );
    /// let iso: Isometry3<f64> = t.into();
    /// let p = iso * Point3::new(1.0, 0.0, 0.0);
    /// let expected = t.rot.mul_vec(&Vec3::new(1.0, 0.0, 0.0)) + t.trans;
    /// assert!((p.x - expected.x).abs() < 1e-15 && (p.z - expected.z).abs() < 1e-15);
    /// ```
    fn from(t: Transform<S>) -> Self {
        Isometry3::from_parts(
            Translation3::from(t.trans.to_array()),
            UnitQuaternion::from(t.rot),
        )
    }
}

impl<S: Scalar + RealField> From<Isometry3<S>> for Transform<S> {
    /// The unit quaternion as a rotation matrix (rodyn's
    /// [`Mat3::from_quaternion`]), the translation as it is.
    ///
    /// ```
    /// use nalgebra::{Isometry3, Vector3};
    /// use rodyn::prelude::*;
    ///
    /// let iso = Isometry3::new(Vector3::new(1.0, 0.0, 0.0), Vector3::new(0.0, 0.0, 0.4));
    /// let t = Transform::from(iso);
    /// assert_eq!(t.trans, Vec3::new(1.0, 0.0, 0.0));
    /// assert!((t.rot.m[1][0] - 0.4_f64.sin()).abs() < 1e-15);
    /// ```
    fn from(iso: Isometry3<S>) -> Self {
        Transform::new(Mat3::from(iso.rotation), iso.translation.vector.into())
    }
}
