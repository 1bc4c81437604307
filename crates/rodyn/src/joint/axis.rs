//! Joint axes, with the coordinate axes as sparse fast paths.

use crate::spatial::Vec3;
use crate::Scalar;

/// The axis of a revolute or prismatic joint, in the joint frame.
///
/// The coordinate axes are their own variants so that the algorithms read a
/// single row or column instead of multiplying by a unit vector.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Axis<S> {
    /// The x axis.
    X,
    /// The y axis.
    Y,
    /// The z axis.
    Z,
    /// Any other axis; must have unit length
    /// ([`Model::validate`](crate::Model::validate) checks it).
    Unit(Vec3<S>),
}

impl<S: Scalar> Axis<S> {
    /// The axis as a vector.
    #[inline]
    #[must_use]
    pub fn vector(&self) -> Vec3<S> {
        match self {
            Self::X => Vec3::unit(0),
            Self::Y => Vec3::unit(1),
            Self::Z => Vec3::unit(2),
            Self::Unit(v) => *v,
        }
    }
    /// The coordinate index of a coordinate axis.
    #[inline]
    #[must_use]
    pub fn index(&self) -> Option<usize> {
        match self {
            Self::X => Some(0),
            Self::Y => Some(1),
            Self::Z => Some(2),
            Self::Unit(_) => None,
        }
    }
    /// The component of `v` along the axis.
    #[inline]
    #[must_use]
    pub fn dot(&self, v: &Vec3<S>) -> S {
        match self {
            Self::X => v.x,
            Self::Y => v.y,
            Self::Z => v.z,
            Self::Unit(a) => a.dot(v),
        }
    }
    /// `v + s axis`: one component for a coordinate axis.
    #[inline]
    #[must_use]
    pub fn add_scaled(&self, v: &Vec3<S>, s: S) -> Vec3<S> {
        let mut out = *v;
        match self {
            Self::X => out.x += s,
            Self::Y => out.y += s,
            Self::Z => out.z += s,
            Self::Unit(a) => out += *a * s,
        }
        out
    }
    /// `w × (s axis)`: two products for a coordinate axis.
    #[inline]
    #[must_use]
    pub fn cross_scaled(&self, w: &Vec3<S>, s: S) -> Vec3<S> {
        match self {
            Self::X => Vec3::new(S::ZERO, w.z * s, -(w.y * s)),
            Self::Y => Vec3::new(-(w.z * s), S::ZERO, w.x * s),
            Self::Z => Vec3::new(w.y * s, -(w.x * s), S::ZERO),
            Self::Unit(a) => w.cross(&(*a * s)),
        }
    }
    /// Converts the scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> Axis<T> {
        match self {
            Self::X => Axis::X,
            Self::Y => Axis::Y,
            Self::Z => Axis::Z,
            Self::Unit(v) => Axis::Unit(v.cast()),
        }
    }
}
