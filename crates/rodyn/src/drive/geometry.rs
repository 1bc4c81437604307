//! Points and directions in a model's geometry, as drive paths need them.
//!
//! A path works with world-frame points (positions, point velocities, unit
//! directions) and turns a force at a point into a spatial force. Those few
//! operations differ between 3-D space and the plane; [`PointGeometry`]
//! supplies them for [`Spatial`] and [`Planar`], so every path and force
//! element is written once.

use crate::planar::{Planar, PlanarForce, Vec2};
use crate::space::Space;
use crate::spatial::{Force, Spatial, Vec3};
use crate::Scalar;

/// Euclidean operations on a geometry's points (3-D or 2-D vectors).
pub trait PointGeometry: Space {
    /// The zero vector.
    fn point_zero<S: Scalar>() -> Self::Point<S>;
    /// `a + b`.
    fn point_add<S: Scalar>(a: &Self::Point<S>, b: &Self::Point<S>) -> Self::Point<S>;
    /// `a - b`.
    fn point_sub<S: Scalar>(a: &Self::Point<S>, b: &Self::Point<S>) -> Self::Point<S>;
    /// `s a`.
    fn point_scale<S: Scalar>(a: &Self::Point<S>, s: S) -> Self::Point<S>;
    /// The dot product `a · b`.
    fn point_dot<S: Scalar>(a: &Self::Point<S>, b: &Self::Point<S>) -> S;
    /// Velocity of the point at `p` moving with the spatial velocity `v`
    /// (`v` and `p` in the same frame): `v_lin + ω × p`.
    fn point_velocity<S: Scalar>(v: &Self::Motion<S>, p: &Self::Point<S>) -> Self::Point<S>;
    /// The spatial force of a pure force `f` acting at point `p` (same frame):
    /// moment `p × f` about the origin, linear part `f`.
    fn force_at_point<S: Scalar>(f: &Self::Point<S>, p: &Self::Point<S>) -> Self::Force<S>;
    /// Converts a point's scalar type.
    fn cast_point<S: Scalar, T: Scalar>(p: &Self::Point<S>) -> Self::Point<T>;
}

impl PointGeometry for Spatial {
    #[inline]
    fn point_zero<S: Scalar>() -> Vec3<S> {
        Vec3::ZERO
    }
    #[inline]
    fn point_add<S: Scalar>(a: &Vec3<S>, b: &Vec3<S>) -> Vec3<S> {
        *a + *b
    }
    #[inline]
    fn point_sub<S: Scalar>(a: &Vec3<S>, b: &Vec3<S>) -> Vec3<S> {
        *a - *b
    }
    #[inline]
    fn point_scale<S: Scalar>(a: &Vec3<S>, s: S) -> Vec3<S> {
        a.scale(s)
    }
    #[inline]
    fn point_dot<S: Scalar>(a: &Vec3<S>, b: &Vec3<S>) -> S {
        a.dot(b)
    }
    #[inline]
    fn point_velocity<S: Scalar>(v: &crate::spatial::Motion<S>, p: &Vec3<S>) -> Vec3<S> {
        v.lin + v.ang.cross(p)
    }
    #[inline]
    fn force_at_point<S: Scalar>(f: &Vec3<S>, p: &Vec3<S>) -> Force<S> {
        Force::at_point(*f, p)
    }
    #[inline]
    fn cast_point<S: Scalar, T: Scalar>(p: &Vec3<S>) -> Vec3<T> {
        p.cast()
    }
}

impl PointGeometry for Planar {
    #[inline]
    fn point_zero<S: Scalar>() -> Vec2<S> {
        Vec2::ZERO
    }
    #[inline]
    fn point_add<S: Scalar>(a: &Vec2<S>, b: &Vec2<S>) -> Vec2<S> {
        *a + *b
    }
    #[inline]
    fn point_sub<S: Scalar>(a: &Vec2<S>, b: &Vec2<S>) -> Vec2<S> {
        *a - *b
    }
    #[inline]
    fn point_scale<S: Scalar>(a: &Vec2<S>, s: S) -> Vec2<S> {
        a.scale(s)
    }
    #[inline]
    fn point_dot<S: Scalar>(a: &Vec2<S>, b: &Vec2<S>) -> S {
        a.dot(b)
    }
    #[inline]
    fn point_velocity<S: Scalar>(v: &crate::planar::PlanarMotion<S>, p: &Vec2<S>) -> Vec2<S> {
        v.lin + p.perp_scaled(v.ang)
    }
    #[inline]
    fn force_at_point<S: Scalar>(f: &Vec2<S>, p: &Vec2<S>) -> PlanarForce<S> {
        PlanarForce::at_point(*f, p)
    }
    #[inline]
    fn cast_point<S: Scalar, T: Scalar>(p: &Vec2<S>) -> Vec2<T> {
        p.cast()
    }
}
