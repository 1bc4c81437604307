//! The joints of planar models.
//!
//! | joint                      | nq | nv | q             | v                          |
//! |----------------------------|----|----|---------------|----------------------------|
//! | [`PlanarJoint::Revolute`]  | 1  | 1  | angle         | rate about z               |
//! | [`PlanarJoint::Prismatic`] | 1  | 1  | displacement  | rate along the axis        |
//! | [`PlanarJoint::Fixed`]     | 0  | 0  |               |                            |
//! | [`PlanarJoint::Floating`]  | 3  | 3  | `[x y θ]`     | `[vx vy ω]` in the body frame |
//!
//! Its motion (the `JointModel` implementation) is in `joint/planar.rs`.

use super::Vec2;
use crate::Scalar;

/// A joint of a planar model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PlanarJoint<S> {
    /// Rotation about z.
    Revolute,
    /// Translation along a unit axis in the plane.
    Prismatic(Vec2<S>),
    /// A rigid attachment.
    Fixed,
    /// A free-floating base in the plane.
    Floating,
}

impl<S: Scalar> PlanarJoint<S> {
    /// Configuration coordinates, usable in `const`.
    #[must_use]
    pub const fn const_nq(&self) -> usize {
        match self {
            Self::Revolute | Self::Prismatic(_) => 1,
            Self::Fixed => 0,
            Self::Floating => 3,
        }
    }
    /// Velocity coordinates, usable in `const`.
    #[must_use]
    pub const fn const_nv(&self) -> usize {
        self.const_nq()
    }
    /// Converts the scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> PlanarJoint<T> {
        match self {
            Self::Revolute => PlanarJoint::Revolute,
            Self::Prismatic(a) => PlanarJoint::Prismatic(a.cast()),
            Self::Fixed => PlanarJoint::Fixed,
            Self::Floating => PlanarJoint::Floating,
        }
    }
}
