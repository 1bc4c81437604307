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
//! [`Spatial`]: crate::spatial::Spatial
//! [`Planar`]: crate::planar::Planar

use crate::error::ModelProblem;
use crate::joint::JointModel;
use crate::spatial::{AxisPermutation, TurnedFrame};
use crate::Scalar;
use core::fmt::Debug;
use core::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

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

/// A choice of geometry: 3-D space ([`Spatial`](crate::spatial::Spatial)) or the
/// plane ([`Planar`](crate::planar::Planar)).
pub trait Space: Copy + Debug + PartialEq + 'static {
    /// Dimension of motion and force vectors (6 or 3).
    const DIM: usize;
    /// Whether the geometry has fused CRBA steps ([`Self::crba_axis_body`],
    /// [`Self::crba_free_root`]): without them CRBA does not look for
    /// them, and carries no code for the test.
    const FUSES_CRBA_STEPS: bool = false;
    /// Whether CRBA can turn this geometry's body frames (whether its
    /// placements can be quarter turns, [`Self::axis_permutation`]):
    /// without, a CRBA plan holds nothing the model does not, and the
    /// planned entries read the model instead.
    const TURNS_FRAMES: bool = false;
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

    // CRBA's backward pass: each joint transform moves every column of
    // its body's subtree and the body's composite inertia into the
    // parent's frame.

    /// A joint transform `ˡⁱXᵢ` prepared to act many times.
    type Step<S: Scalar>: Copy;
    /// Prepares `x` ([`Self::Step`]).
    fn step<S: Scalar>(x: &Self::Transform<S>) -> Self::Step<S>;
    /// The step of joint `j` at `q` behind `placement`: `step(&j
    /// .placed_transform(placement, q))`, without forming the transform
    /// where the step does not need it.
    fn joint_step<S: Scalar>(
        j: &Self::Joint<S>,
        placement: &Self::Transform<S>,
        q: &[S],
    ) -> Self::Step<S>;
    /// `x.act_force(f)` through a prepared step, for every force of `forces`.
    fn step_forces<S: Scalar>(step: &Self::Step<S>, forces: &mut [Self::Force<S>]);
    /// CRBA's whole step at a body with one coordinate, fused, when its
    /// joint turns about coordinate axis `axis.0` of the columns' frame
    /// (the opposite way when `axis.1`) and `step` turns about that same
    /// axis: the body's column `Iᶜ S` into `columns[0]`; for each column
    /// `F_d` of `columns` (the body's subtree, its own first) the entry
    /// `rows[d][iv] = Sᵀ F_d` (with `upper`, also `rows[0][iv + d]`, its
    /// mirror above the diagonal) and `F_d` moved through the step; then
    /// `ic` moved and added to `parent_ic`. Returns `false`, having done
    /// nothing, where it does not apply (the default: always).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn crba_axis_body<S: Scalar, const NV: usize>(
        _step: &Self::Step<S>,
        _axis: (usize, bool),
        _ic: &Self::Inertia<S>,
        _parent_ic: &mut Self::Inertia<S>,
        _columns: &mut [Self::Force<S>],
        _rows: &mut [[S; NV]],
        _iv: usize,
        _upper: bool,
    ) -> bool {
        false
    }
    /// CRBA's step at a root body whose joint's motion subspace is the
    /// identity (a free flyer, linear coordinates first), fused: its own
    /// block of `M`, the composite inertia `ic` itself, into the lower
    /// triangle of `rows[..6]`, and its entries against the rest of its
    /// subtree, `rows[6 + d][iv..iv + 6]` = `columns[d]` reordered; with
    /// `upper`, their mirrors above the diagonal too. Nothing moves from a
    /// root. Returns `false`, having done nothing, for any other joint (the
    /// default: always).
    #[inline(always)]
    fn crba_free_root<S: Scalar, const NV: usize>(
        _joint: &Self::Joint<S>,
        _ic: &Self::Inertia<S>,
        _columns: &[Self::Force<S>],
        _rows: &mut [[S; NV]],
        _iv: usize,
        _upper: bool,
    ) -> bool {
        false
    }
    /// `acc` plus `i` moved through the step (`x.act(i)`): the composite of
    /// a parent and its child, in the parent's frame.
    fn add_stepped_inertia<S: Scalar>(
        acc: &mut Self::Inertia<S>,
        step: &Self::Step<S>,
        i: &Self::Inertia<S>,
    );
    /// `x` followed by the step: the transform `x ˡⁱXᵢ`, as from a root
    /// frame to body i's when `x` is from the root frame to its parent's.
    fn then_step<S: Scalar>(x: &Self::Transform<S>, step: &Self::Step<S>) -> Self::Transform<S>;
    /// `i Sₖ`: the inertia times column k of joint `j`'s motion subspace,
    /// both in the joint's body frame.
    fn inertia_column<S: Scalar>(
        i: &Self::Inertia<S>,
        j: &Self::Joint<S>,
        k: usize,
    ) -> Self::Force<S>;

    // Turned frames ([`TurnedFrame`]): CRBA may express a body in its
    // frame turned by the quarter turns of the placements above it. Only
    // 3-D placements are recognised as quarter turns; the defaults, for
    // geometries without them, ignore the frames.

    /// `Some` when placement `x`'s rotation is exactly an
    /// [`AxisPermutation`].
    fn axis_permutation<S: Scalar>(_x: &Self::Transform<S>) -> Option<AxisPermutation> {
        None
    }
    /// The angle of body i's joint whose sine and cosine
    /// [`Self::turned_joint_step`] takes when given them (`None`: it takes
    /// none), so that a caller can form many at once
    /// ([`Scalar::sin_cos_array`]).
    #[inline(always)]
    fn step_angle<S: Scalar>(_frame: &TurnedFrame, _j: &Self::Joint<S>, _q: &[S]) -> Option<S> {
        None
    }
    /// [`Self::joint_step`] from body i's turned frame to its parent's,
    /// given its placement seen from the parent's turned frame
    /// ([`CrbaPlan::placement`](crate::algorithm::crba::CrbaPlan::placement)).
    /// `sin_cos`, when the caller has formed it, is the sine and cosine of
    /// [`Self::step_angle`].
    #[inline(always)]
    fn turned_joint_step<S: Scalar>(
        _frame: &TurnedFrame,
        j: &Self::Joint<S>,
        turned_placement: &Self::Transform<S>,
        q: &[S],
        _sin_cos: Option<(S, S)>,
    ) -> Self::Step<S> {
        Self::joint_step(j, turned_placement, q)
    }
    /// [`Self::step`] from body i's turned frame to its parent's, given
    /// `x = ˡⁱXᵢ` between their own frames (as RNEA leaves it) and the
    /// placement seen from the parent's turned frame.
    #[inline(always)]
    fn turned_step<S: Scalar>(
        _frame: &TurnedFrame,
        x: &Self::Transform<S>,
        _turned_placement: &Self::Transform<S>,
    ) -> Self::Step<S> {
        Self::step(x)
    }
    /// `parent x`: body i's pose from its parent's (`parent`) and its
    /// joint transform `x = ˡⁱMᵢ` ([`RigidTransform::compose`]), `x` formed
    /// from `joint` behind `placement`; a geometry may skip products that
    /// the joint and placement tell are with zeros (giving the same
    /// result, bit for bit).
    #[inline(always)]
    fn then_joint<S: Scalar>(
        parent: &Self::Transform<S>,
        x: &Self::Transform<S>,
        _joint: &Self::Joint<S>,
        _placement: &Self::Transform<S>,
    ) -> Self::Transform<S> {
        parent.compose(x)
    }
    /// `i` expressed in the frame turned by `turn` (`turn` applied to its
    /// centre of mass, `turn I turnᵀ` to its rotational inertia).
    #[inline(always)]
    fn turn_inertia<S: Scalar>(_turn: &AxisPermutation, i: &Self::Inertia<S>) -> Self::Inertia<S> {
        *i
    }
    /// `turn` then `x` (`x` seen from the frame turned by `turn`).
    #[inline(always)]
    fn turn_transform<S: Scalar>(
        _turn: &AxisPermutation,
        x: &Self::Transform<S>,
    ) -> Self::Transform<S> {
        *x
    }
    /// `x Sₖ`: column k of joint `j`'s motion subspace, in body i's
    /// turned frame, moved by `x` (as into a root frame).
    #[inline(always)]
    fn act_turned_subspace_column<S: Scalar>(
        x: &Self::Transform<S>,
        _frame: &TurnedFrame,
        j: &Self::Joint<S>,
        k: usize,
    ) -> Self::Motion<S> {
        x.act_motion(&j.subspace_column(k))
    }
    /// [`Self::inertia_column`] in body i's turned frame.
    #[inline(always)]
    fn turned_inertia_column<S: Scalar>(
        _frame: &TurnedFrame,
        i: &Self::Inertia<S>,
        j: &Self::Joint<S>,
        k: usize,
    ) -> Self::Force<S> {
        Self::inertia_column(i, j, k)
    }
}
