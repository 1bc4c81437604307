//! [`Vec3`] ↔ `Vector3`.

use ::nalgebra::Vector3;

use crate::spatial::Vec3;
use crate::Scalar;

impl<S: Scalar> From<Vec3<S>> for Vector3<S> {
    /// `(x, y, z)` in the same order.
    ///
    /// ```
    /// use nalgebra::Vector3;
    /// use rodyn::prelude::Vec3;
    ///
    /// let v: Vector3<f64> = Vec3::new(1.0, 2.0, 3.0).into();
    /// assert_eq!(v, Vector3::new(1.0, 2.0, 3.0));
    /// ```
    fn from(v: Vec3<S>) -> Self {
        Vector3::new(v.x, v.y, v.z)
    }
}

impl<S: Scalar> From<Vector3<S>> for Vec3<S> {
    /// `(x, y, z)` in the same order.
    ///
    /// ```
    /// use nalgebra::Vector3;
    /// use rodyn::prelude::Vec3;
    ///
    /// assert_eq!(Vec3::from(Vector3::new(1.0_f32, 2.0, 3.0)), Vec3::new(1.0, 2.0, 3.0));
    /// ```
    fn from(v: Vector3<S>) -> Self {
        Vec3::new(v.x, v.y, v.z)
    }
}
