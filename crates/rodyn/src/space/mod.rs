//! The vector spaces an algorithm runs in: full 3-D space or a plane.
//!
//! Every algorithm in [`crate::algorithm`] is written once against the traits
//! of this module. [`Spatial`] supplies Featherstone's 6-D motion and force
//! vectors; [`Planar`] supplies their 3-D planar counterparts (one angular
//! and two linear components), so a planar model pays for a plane, not for
//! space.
//!
//! | trait              | book symbol | 3-D type                              | planar type |
//! |--------------------|-------------|---------------------------------------|-------------|
//! | [`MotionVector`]   | v, a, S     | [`Motion`](crate::spatial::Motion)     | [`PlanarMotion`](crate::planar::PlanarMotion) |
//! | [`ForceVector`]    | f           | [`Force`](crate::spatial::Force)       | [`PlanarForce`](crate::planar::PlanarForce) |
//! | [`RigidTransform`] | X           | [`Transform`](crate::spatial::Transform) | [`PlanarTransform`](crate::planar::PlanarTransform) |
//! | [`BodyInertia`]    | I           | [`Inertia`](crate::spatial::Inertia)   | [`PlanarInertia`](crate::planar::PlanarInertia) |
//! | [`ArticulatedInertia`] | I^A     | [`ArticulatedInertia6`](crate::spatial::ArticulatedInertia6) | [`ArticulatedInertia3`](crate::planar::ArticulatedInertia3) |
//!
//! A geometry is split in two: [`Geometry`], the algebra every algorithm
//! reads (the types above, casts, validators, composing a body's pose),
//! and the hooks of the one algorithm that needs more, [`CrbaSpace`]
//! (`crba.rs`, with the [`TurnedFrame`](crate::algorithm::crba::TurnedFrame)s
//! it takes; implemented beside CRBA). [`Space`] is both: forward dynamics
//! puts ABA and CRBA behind one interface, so generic code that can reach
//! forward dynamics needs CRBA's hooks, and a geometry provides both to
//! run every algorithm.
//!
//! This module stands below the joints and the algorithms and imports
//! nothing from them: the interface a geometry names its joints by,
//! [`JointModel`], is defined here (`joint_model.rs`) and the joints
//! implement it; 3-D space's [`Geometry`] impl, which names the 3-D
//! joints, stands with them (`joint/spatial_geometry.rs`).
//!
//! [`Spatial`]: crate::spatial::Spatial
//! [`Planar`]: crate::planar::Planar

pub(crate) mod crba;
pub(crate) mod joint_model;
mod planar;
mod spatial;
pub(crate) mod turned_frame;

use crate::error::ModelProblem;
use crate::Scalar;
use core::fmt::Debug;
use core::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};
use crba::CrbaSpace;
use joint_model::JointModel;

/// Arithmetic shared by motion and force vectors.
pub trait VectorOps<S: Scalar>:
    Copy
    + Debug
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Neg<Output = Self>
    + Mul<S, Output = Self>
    + AddAssign
    + SubAssign
{
    /// The zero vector.
    const ZERO: Self;
    /// `true` when every component is finite.
    fn is_finite(&self) -> bool;
    /// Component `k` in rodyn's order (angular first, then linear).
    fn component(&self, k: usize) -> S;
}

/// A spatial motion vector (velocity, acceleration, a column of S).
pub trait MotionVector<S: Scalar>: VectorOps<S> {
    /// The dual force vector type.
    type Force: ForceVector<S>;
    /// The motion cross product `self × m` (the book's `crm(self) m`).
    fn cross_motion(&self, m: &Self) -> Self;
    /// The force cross product `self ×* f` (the book's `crf(self) f`).
    fn cross_force(&self, f: &Self::Force) -> Self::Force;
    /// The scalar product `self · f` (power).
    fn dot(&self, f: &Self::Force) -> S;
}

/// A spatial force vector (force, momentum).
pub trait ForceVector<S: Scalar>: VectorOps<S> {}

/// A rigid coordinate transform `aMb` from frame b to frame a (Plücker `ᵃX_b`).
pub trait RigidTransform<S: Scalar>: Copy + Debug + PartialEq {
    /// Motion vectors it acts on.
    type Motion: MotionVector<S, Force = Self::Force>;
    /// Force vectors it acts on.
    type Force: ForceVector<S>;
    /// Position of a point, as stored by the transform's translation.
    type Point: Copy + Debug;
    /// The identity transform.
    const IDENTITY: Self;
    /// `self * o`: `aMb * bMc = aMc`.
    fn compose(&self, o: &Self) -> Self;
    /// `bMa` from `aMb`.
    fn inverse(&self) -> Self;
    /// Motion in b to motion in a: `ᵃX_b m`.
    fn act_motion(&self, m: &Self::Motion) -> Self::Motion;
    /// Motion in a to motion in b: `ᵇX_a m`.
    fn act_inv_motion(&self, m: &Self::Motion) -> Self::Motion;
    /// Force in b to force in a: `ᵃX_b* f`.
    fn act_force(&self, f: &Self::Force) -> Self::Force;
    /// Force in a to force in b: `ᵇX_a* f`.
    fn act_inv_force(&self, f: &Self::Force) -> Self::Force;
    /// A point given in b, expressed in a.
    fn act_point(&self, p: &Self::Point) -> Self::Point;
    /// The origin of b, expressed in a.
    fn translation(&self) -> Self::Point;
    /// `true` when every entry is finite.
    fn is_finite(&self) -> bool;
}

/// The spatial inertia of one rigid body (mass, centre of mass, rotational inertia).
pub trait BodyInertia<S: Scalar>: Copy + Debug + PartialEq {
    /// Motion vectors it maps from.
    type Motion: MotionVector<S, Force = Self::Force>;
    /// Force vectors it maps to.
    type Force: ForceVector<S>;
    /// Transforms that re-express it.
    type Transform: RigidTransform<S, Motion = Self::Motion, Force = Self::Force>;
    /// The zero (massless) inertia.
    const ZERO: Self;
    /// Mass in kg.
    fn mass(&self) -> S;
    /// Centre of mass in the frame the inertia is expressed in.
    fn com(&self) -> <Self::Transform as RigidTransform<S>>::Point;
    /// Momentum `I v`.
    fn mul_motion(&self, v: &Self::Motion) -> Self::Force;
    /// The net force `I a + v ×* I v` that gives the body the acceleration
    /// `a` at the velocity `v` (the Newton-Euler equations).
    #[inline]
    fn net_force(&self, v: &Self::Motion, a: &Self::Motion) -> Self::Force {
        self.mul_motion(a) + v.cross_force(&self.mul_motion(v))
    }
    /// The velocity-product force `v ×* I v` (the net force at zero acceleration).
    #[inline]
    fn velocity_product_force(&self, v: &Self::Motion) -> Self::Force {
        v.cross_force(&self.mul_motion(v))
    }
    /// The same inertia expressed in frame a, given `aMb` with `self` in b.
    fn act(&self, x: &Self::Transform) -> Self;
    /// The inertia of the two bodies rigidly joined (both in the same frame).
    fn combine(&self, o: &Self) -> Self;
    /// Potential energy `-m g·c` in the gravity field `g` (a motion whose
    /// linear part is the gravity acceleration, same frame as `self`).
    fn potential_energy(&self, gravity: &Self::Motion) -> S;
    /// `true` when every entry is finite.
    fn is_finite(&self) -> bool;
}

/// An articulated-body inertia `I^A`: a symmetric positive semi-definite map
/// from motion to force.
pub trait ArticulatedInertia<S: Scalar>: Copy + Debug {
    /// Motion vectors it maps from.
    type Motion: MotionVector<S, Force = Self::Force>;
    /// Force vectors it maps to.
    type Force: ForceVector<S>;
    /// Transforms that re-express it.
    type Transform: RigidTransform<S, Motion = Self::Motion, Force = Self::Force>;
    /// The rigid-body inertias it is built from.
    type Inertia: BodyInertia<S, Motion = Self::Motion, Force = Self::Force>;
    /// The zero matrix.
    const ZERO: Self;
    /// The rigid-body inertia as an articulated inertia.
    fn from_rigid(i: &Self::Inertia) -> Self;
    /// `I^A m`.
    fn mul_motion(&self, m: &Self::Motion) -> Self::Force;
    /// `self += o`.
    fn add_assign(&mut self, o: &Self);
    /// `self -= s a aᵀ`.
    fn sub_outer(&mut self, a: &Self::Force, s: S);
    /// Projects a one-DoF joint out of `self` (`self -= d⁻¹ U Uᵀ`, `U` the
    /// joint's column `u = self S`) and returns `self m` with the projected
    /// inertia. `revolute_axis` is `Some(k)` for a revolute joint about
    /// coordinate axis k without armature: the projection then zeroes the
    /// angular row and column k exactly, and a geometry may set them to
    /// zero rather than compute rounding residue.
    #[inline]
    fn project_mul_motion(
        &mut self,
        u: &Self::Force,
        d_inv: S,
        m: &Self::Motion,
        revolute_axis: Option<usize>,
    ) -> Self::Force {
        let _ = revolute_axis;
        self.sub_outer(u, d_inv);
        self.mul_motion(m)
    }
    /// `self -= s (a bᵀ + b aᵀ)`.
    fn sub_outer_sym(&mut self, a: &Self::Force, b: &Self::Force, s: S);
    /// `ᵃX_b* self ᵇX_a`: the same inertia seen from frame a, given `aMb`.
    fn act(&self, x: &Self::Transform) -> Self;
    /// `self += ᵃX_b* o ᵇX_a`: adds `o`, given in frame b, to this inertia of
    /// frame a. A geometry overrides it to avoid forming the intermediate.
    #[inline]
    fn add_act(&mut self, o: &Self, x: &Self::Transform) {
        self.add_assign(&o.act(x));
    }
    /// [`add_act`](Self::add_act) for an `o` from which a one-DoF joint was
    /// just projected out without armature (`o S = 0`): `revolute_axis` is
    /// `Some(k)` for a revolute joint about coordinate axis k, whose
    /// angular row and column k of `o` then vanish, and a geometry may skip
    /// them. The default ignores the hint.
    #[inline]
    fn add_act_projected(&mut self, o: &Self, x: &Self::Transform, revolute_axis: Option<usize>) {
        let _ = revolute_axis;
        self.add_act(o, x);
    }
    /// The trace, a scale for the positivity tests of ABA.
    fn trace(&self) -> S;
}

/// The algebra a geometry provides: 3-D space
/// ([`Spatial`](crate::spatial::Spatial)) or the plane
/// ([`Planar`](crate::planar::Planar)).
pub trait Geometry: Copy + Debug + PartialEq + 'static {
    /// Dimension of motion and force vectors (6 or 3).
    const DIM: usize;
    /// Motion vectors.
    type Motion<S: Scalar>: MotionVector<S, Force = Self::Force<S>>;
    /// Force vectors.
    type Force<S: Scalar>: ForceVector<S>;
    /// Positions of points (3-D or 2-D).
    type Point<S: Scalar>: Copy + Debug + Add<Output = Self::Point<S>>;
    /// Rigid transforms.
    type Transform<S: Scalar>: RigidTransform<
        S,
        Motion = Self::Motion<S>,
        Force = Self::Force<S>,
        Point = Self::Point<S>,
    >;
    /// Rigid-body inertias.
    type Inertia<S: Scalar>: BodyInertia<
        S,
        Motion = Self::Motion<S>,
        Force = Self::Force<S>,
        Transform = Self::Transform<S>,
    >;
    /// Articulated-body inertias.
    type Articulated<S: Scalar>: ArticulatedInertia<
        S,
        Motion = Self::Motion<S>,
        Force = Self::Force<S>,
        Transform = Self::Transform<S>,
        Inertia = Self::Inertia<S>,
    >;
    /// The closed set of built-in joints for this geometry.
    type Joint<S: Scalar>: JointModel<S, Self>;

    /// A placeholder joint (used while converting models).
    fn default_joint<S: Scalar>() -> Self::Joint<S>;
    /// Converts a joint's scalar type; `None` when the joint cannot be converted.
    fn cast_joint<S: Scalar, T: Scalar>(j: &Self::Joint<S>) -> Option<Self::Joint<T>>;
    /// Converts a transform's scalar type.
    fn cast_transform<S: Scalar, T: Scalar>(x: &Self::Transform<S>) -> Self::Transform<T>;
    /// `true` when every coordinate of the point is finite.
    fn point_is_finite<S: Scalar>(p: &Self::Point<S>) -> bool;
    /// Converts an inertia's scalar type.
    fn cast_inertia<S: Scalar, T: Scalar>(i: &Self::Inertia<S>) -> Self::Inertia<T>;
    /// Converts a motion's scalar type.
    fn cast_motion<S: Scalar, T: Scalar>(m: &Self::Motion<S>) -> Self::Motion<T>;
    /// Checks that an inertia is physical.
    fn validate_inertia<S: Scalar>(i: &Self::Inertia<S>) -> Result<(), ModelProblem>;
    /// Checks that a placement is finite with an orthonormal rotation.
    fn validate_transform<S: Scalar>(x: &Self::Transform<S>) -> Result<(), ModelProblem>;
    /// Checks a joint's own parameters (unit axes).
    fn validate_joint<S: Scalar>(j: &Self::Joint<S>) -> Result<(), ModelProblem>;

    /// `parent x`: body i's pose from its parent's (`parent`) and its
    /// joint transform `x = ˡⁱMᵢ` ([`RigidTransform::compose`]) of
    /// `joint`; a geometry may skip products that the joint and `x` tell
    /// are with zeros (giving the same result, bit for bit).
    #[inline(always)]
    fn then_joint<S: Scalar>(
        parent: &Self::Transform<S>,
        x: &Self::Transform<S>,
        _joint: &Self::Joint<S>,
    ) -> Self::Transform<S> {
        parent.compose(x)
    }
    /// [`then_joint`](Self::then_joint), where a geometry may also skip
    /// the products with the zeros of `x` behind a quarter-turn placement.
    /// Its own hook because the tests for that form pay only where the
    /// chain's products have the registers to themselves (the poses of the
    /// centroidal map and of the joint Jacobians, out of order, whose joint
    /// transforms are formed first); where each pose is composed beside
    /// other work they cost more than they save.
    #[inline(always)]
    fn then_turned_joint<S: Scalar>(
        parent: &Self::Transform<S>,
        x: &Self::Transform<S>,
        joint: &Self::Joint<S>,
    ) -> Self::Transform<S> {
        Self::then_joint(parent, x, joint)
    }
}

/// A geometry every algorithm of the crate runs in: its algebra
/// ([`Geometry`]) and CRBA's hooks
/// ([`CrbaSpace`]); implemented for
/// every type that has both.
pub trait Space: Geometry + CrbaSpace {}

impl<G: Geometry + CrbaSpace> Space for G {}
