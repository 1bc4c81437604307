//! Planar articulated-body inertia: a symmetric 3x3 matrix over `(ω, vx, vy)`.

use super::{PlanarForce, PlanarMotion};
use crate::spatial::{Sym3, Vec3};
use crate::Scalar;

/// A symmetric 3x3 articulated-body inertia; index 0 is angular, 1 and 2 linear.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArticulatedInertia3<S> {
    /// The matrix.
    pub m: Sym3<S>,
}

pub(crate) fn motion_vec<S: Scalar>(m: &PlanarMotion<S>) -> Vec3<S> {
    Vec3::new(m.ang, m.lin.x, m.lin.y)
}
pub(crate) fn force_vec<S: Scalar>(f: &PlanarForce<S>) -> Vec3<S> {
    Vec3::new(f.ang, f.lin.x, f.lin.y)
}
