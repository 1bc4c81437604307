//! [`Motion`] and [`Force`] ↔ `Vector6`, **linear part first**.
//!
//! rodyn stores a spatial vector angular part first (Featherstone's
//! `[ω; v]`, `[n; f]`); the `Vector6` holds `[v; ω]` and `[f; n]`, as
//! Pinocchio's `toVector()` does (see the [module](super)).

use ::nalgebra::Vector6;

use crate::spatial::{Force, Motion};
use crate::Scalar;

impl<S: Scalar> From<Motion<S>> for Vector6<S> {
    /// `[vx vy vz ωx ωy ωz]`: linear part first, as Pinocchio.
    ///
    /// ```
    /// use nalgebra::Vector6;
    /// use rodyn::prelude::*;
    ///
    /// let twist = Motion::new(Vec3::new(0.0, 0.0, 2.0), Vec3::new(1.0, 0.0, 0.0));
    /// let v: Vector6<f64> = twist.into();
    /// assert_eq!(v, Vector6::new(1.0, 0.0, 0.0, 0.0, 0.0, 2.0));
    /// ```
    fn from(m: Motion<S>) -> Self {
        Vector6::from(m.to_linear_first())
    }
}

impl<S: Scalar> From<Vector6<S>> for Motion<S> {
    /// From `[vx vy vz ωx ωy ωz]`: linear part first, as Pinocchio.
    ///
    /// ```
    /// use nalgebra::Vector6;
    /// use rodyn::prelude::*;
    ///
    /// let twist = Motion::from(Vector6::new(1.0, 0.0, 0.0, 0.0, 0.0, 2.0));
    /// assert_eq!((twist.lin.x, twist.ang.z), (1.0, 2.0));
    /// ```
    fn from(v: Vector6<S>) -> Self {
        Motion::from_linear_first(&v.into())
    }
}

impl<S: Scalar> From<Force<S>> for Vector6<S> {
    /// `[fx fy fz nx ny nz]`: force first, then moment, as Pinocchio.
    ///
    /// ```
    /// use nalgebra::Vector6;
    /// use rodyn::prelude::*;
    ///
    /// let wrench = Force::new(Vec3::new(0.0, 0.5, 0.0), Vec3::new(0.0, 0.0, -9.81));
    /// let w: Vector6<f64> = wrench.into();
    /// assert_eq!(w, Vector6::new(0.0, 0.0, -9.81, 0.0, 0.5, 0.0));
    /// ```
    fn from(f: Force<S>) -> Self {
        Vector6::from(f.to_linear_first())
    }
}

impl<S: Scalar> From<Vector6<S>> for Force<S> {
    /// From `[fx fy fz nx ny nz]`: force first, then moment, as Pinocchio.
    ///
    /// ```
    /// use nalgebra::Vector6;
    /// use rodyn::prelude::*;
    ///
    /// let wrench = Force::from(Vector6::new(0.0, 0.0, -9.81, 0.0, 0.5, 0.0));
    /// assert_eq!((wrench.lin.z, wrench.ang.y), (-9.81, 0.5));
    /// ```
    fn from(v: Vector6<S>) -> Self {
        Force::from_linear_first(&v.into())
    }
}
