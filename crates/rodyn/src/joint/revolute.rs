//! The revolute joint: one rotation about a fixed axis. nq = nv = 1.
//!
//! `jMi(q)` is a rotation by `q` about the axis; `S = [axis; 0]`.

use super::Axis;
use crate::space::RigidTransform;
use crate::spatial::{ArticulatedInertia6, Force, Mat3, Motion, Transform, Vec3};
use crate::Scalar;

/// A revolute joint about [`axis`](Self::axis).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Revolute<S> {
    /// The rotation axis in the joint frame.
    pub axis: Axis<S>,
}

impl<S> Revolute<S> {
    /// Configuration coordinates: the angle.
    pub const NQ: usize = 1;
    /// Velocity coordinates.
    pub const NV: usize = 1;
    /// Every finite `q` is a valid configuration (no quaternion to keep
    /// of unit length).
    pub const CONSTRAINS_CONFIGURATION: bool = false;
}

impl<S: Scalar> Revolute<S> {
    /// `jMi(q)`.
    #[inline]
    #[must_use]
    pub fn transform(&self, q: S) -> Transform<S> {
        let (s, c) = q.sin_cos();
        self.transform_from_sin_cos(s, c)
    }
    /// `jMi(q)` given `sin q` and `cos q`.
    #[inline]
    #[must_use]
    pub fn transform_from_sin_cos(&self, s: S, c: S) -> Transform<S> {
        let rot = match self.axis.index() {
            Some(k) => Mat3::from_axis_index(k, s, c),
            None => Mat3::from_axis_sin_cos(&self.axis.vector(), s, c),
        };
        Transform::from_rotation(rot)
    }
    /// `placement · jMi(q)`: the body's frame in its parent's frame.
    ///
    /// About a coordinate axis the rotation mixes two columns of the
    /// placement's rotation; no 3x3 product is needed.
    #[cfg_attr(rodyn_tuning = "out_of_order", inline(always))]
    #[cfg_attr(rodyn_tuning = "in_order", inline)]
    #[must_use]
    pub fn placed_transform(&self, placement: &Transform<S>, q: S) -> Transform<S> {
        let (s, c) = q.sin_cos();
        self.placed_transform_from_sin_cos(placement, s, c)
    }
    /// [`placed_transform`](Self::placed_transform) given `sin q` and `cos q`.
    #[cfg_attr(rodyn_tuning = "out_of_order", inline(always))]
    #[cfg_attr(rodyn_tuning = "in_order", inline)]
    #[must_use]
    pub fn placed_transform_from_sin_cos(
        &self,
        placement: &Transform<S>,
        s: S,
        c: S,
    ) -> Transform<S> {
        match self.axis.index() {
            Some(k) => Transform::new(placement.rot.mul_axis_rotation(k, s, c), placement.trans),
            None => placement.compose(&self.transform_from_sin_cos(s, c)),
        }
    }
    /// `S qd`.
    #[inline]
    #[must_use]
    pub fn motion(&self, qd: S) -> Motion<S> {
        Motion::new(self.axis.vector() * qd, Vec3::ZERO)
    }
    /// `m + S qd`.
    #[inline]
    #[must_use]
    pub fn add_motion(&self, m: &Motion<S>, qd: S) -> Motion<S> {
        Motion::new(self.axis.add_scaled(&m.ang, qd), m.lin)
    }
    /// `v × (S qd) = [ω × a qd; v_lin × a qd]`.
    #[inline]
    #[must_use]
    pub fn cross_motion(&self, v: &Motion<S>, qd: S) -> Motion<S> {
        Motion::new(
            self.axis.cross_scaled(&v.ang, qd),
            self.axis.cross_scaled(&v.lin, qd),
        )
    }
    /// `Sᵀ f`: the moment about the axis.
    #[inline]
    #[must_use]
    pub fn project_force(&self, f: &Force<S>) -> S {
        self.axis.dot(&f.ang)
    }
    /// `U = I^A S`: for a coordinate axis, one column of the blocks.
    #[inline]
    #[must_use]
    pub fn articulated_column(&self, ia: &ArticulatedInertia6<S>) -> Force<S> {
        match self.axis.index() {
            Some(k) => Force::new(ia.a.column(k), ia.b.row(k)),
            None => {
                let a = self.axis.vector();
                Force::new(ia.a.mul_vec(&a), ia.b.tr_mul_vec(&a))
            }
        }
    }
}
