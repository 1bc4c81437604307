//! The prismatic joint: one translation along a fixed axis. nq = nv = 1.
//!
//! `jMi(q)` is a translation by `q` along the axis; `S = [0; axis]`.

use super::Axis;
use crate::spatial::{ArticulatedInertia6, Force, Motion, Transform, Vec3};
use crate::Scalar;

/// A prismatic joint along [`axis`](Self::axis).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Prismatic<S> {
    /// The translation axis in the joint frame.
    pub axis: Axis<S>,
}

impl<S> Prismatic<S> {
    /// Configuration coordinates: the displacement.
    pub const NQ: usize = 1;
    /// Velocity coordinates.
    pub const NV: usize = 1;
    /// Every finite `q` is a valid configuration (no quaternion to keep
    /// of unit length).
    pub const CONSTRAINS_CONFIGURATION: bool = false;
}

impl<S: Scalar> Prismatic<S> {
    /// `jMi(q)`.
    #[inline]
    #[must_use]
    pub fn transform(&self, q: S) -> Transform<S> {
        Transform::from_translation(self.axis.vector() * q)
    }
    /// `S qd`.
    #[inline]
    #[must_use]
    pub fn motion(&self, qd: S) -> Motion<S> {
        Motion::new(Vec3::ZERO, self.axis.vector() * qd)
    }
    /// `m + S qd`.
    #[inline]
    #[must_use]
    pub fn add_motion(&self, m: &Motion<S>, qd: S) -> Motion<S> {
        Motion::new(m.ang, self.axis.add_scaled(&m.lin, qd))
    }
    /// `v × (S qd) = [0; ω × a qd]`.
    #[inline]
    #[must_use]
    pub fn cross_motion(&self, v: &Motion<S>, qd: S) -> Motion<S> {
        Motion::new(Vec3::ZERO, self.axis.cross_scaled(&v.ang, qd))
    }
    /// `Sᵀ f`: the force along the axis.
    #[inline]
    #[must_use]
    pub fn project_force(&self, f: &Force<S>) -> S {
        self.axis.dot(&f.lin)
    }
    /// `U = I^A S`.
    #[inline]
    #[must_use]
    pub fn articulated_column(&self, ia: &ArticulatedInertia6<S>) -> Force<S> {
        match self.axis.index() {
            Some(k) => Force::new(ia.b.column(k), ia.c.column(k)),
            None => {
                let a = self.axis.vector();
                Force::new(ia.b.mul_vec(&a), ia.c.mul_vec(&a))
            }
        }
    }
}
