//! Planar spatial algebra: models whose joints all turn about z and move in
//! the x-y plane.
//!
//! Motion and force vectors have three components (`[ω; vx; vy]` and
//! `[n; fx; fy]`), inertias four numbers and articulated inertias a
//! symmetric 3x3 matrix, so a planar model runs the same algorithms at a
//! fraction of the 3-D cost. Gravity lies in the plane (usually `-y`).
//!
//! A planar model gives the same results as the 3-D model with every joint
//! about z ([`Axis::Z`](crate::joint::Axis::Z)), every placement a rotation
//! about z plus an x-y translation, and gravity in the x-y plane.

mod articulated;
mod force;
mod inertia;
mod joint;
mod motion;
mod transform;
mod vec2;

pub use articulated::ArticulatedInertia3;
pub use force::PlanarForce;
pub use inertia::PlanarInertia;
pub use joint::PlanarJoint;
pub use motion::PlanarMotion;
pub use transform::PlanarTransform;
pub use vec2::Vec2;

use crate::error::ModelProblem;
use crate::model::Model;
use crate::space::{RigidTransform, Space};
use crate::spatial::TurnedFrame;
use crate::topology::Topology;
use crate::Scalar;

/// The plane: 3-component motion and force vectors.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Planar;

impl Space for Planar {
    const DIM: usize = 3;
    type Motion<S: Scalar> = PlanarMotion<S>;
    type Force<S: Scalar> = PlanarForce<S>;
    type Point<S: Scalar> = Vec2<S>;
    type Transform<S: Scalar> = PlanarTransform<S>;
    type Inertia<S: Scalar> = PlanarInertia<S>;
    type Articulated<S: Scalar> = ArticulatedInertia3<S>;
    type Joint<S: Scalar> = PlanarJoint<S>;

    fn default_joint<S: Scalar>() -> PlanarJoint<S> {
        PlanarJoint::Fixed
    }
    fn cast_joint<S: Scalar, T: Scalar>(j: &PlanarJoint<S>) -> Option<PlanarJoint<T>> {
        Some(j.cast())
    }
    fn cast_transform<S: Scalar, T: Scalar>(x: &PlanarTransform<S>) -> PlanarTransform<T> {
        x.cast()
    }
    fn cast_inertia<S: Scalar, T: Scalar>(i: &PlanarInertia<S>) -> PlanarInertia<T> {
        i.cast()
    }
    fn cast_motion<S: Scalar, T: Scalar>(m: &PlanarMotion<S>) -> PlanarMotion<T> {
        PlanarMotion::new(T::from_f64(m.ang.to_f64()), m.lin.cast())
    }
    fn validate_inertia<S: Scalar>(i: &PlanarInertia<S>) -> Result<(), ModelProblem> {
        let ok = |x: S| x.is_finite() && x.to_f64() >= 0.0;
        if !(i.mass.is_finite() && i.com.is_finite() && i.izz.is_finite()) {
            Err(ModelProblem::NonFiniteParameter)
        } else if !ok(i.mass) {
            Err(ModelProblem::InvalidMass)
        } else if !(i.mass * i.com.norm_squared() + i.izz).is_finite()
            || !(i.mass * i.mass).is_finite()
            || !((i.mass * i.com.norm_squared() + i.izz).squared()).is_finite()
        {
            // Also the products of two entries ABA forms (U Uᵀ).
            Err(ModelProblem::Overflow)
        } else if !ok(i.izz) {
            Err(ModelProblem::InvalidInertia)
        } else {
            Ok(())
        }
    }
    fn validate_transform<S: Scalar>(x: &PlanarTransform<S>) -> Result<(), ModelProblem> {
        let n = (x.cos * x.cos + x.sin * x.sin).to_f64();
        if !x.is_finite() {
            Err(ModelProblem::NonFiniteParameter)
        } else if !x.trans.norm_squared().squared().is_finite() {
            // As the 3-D placements: ABA multiplies two m |p|² entries.
            Err(ModelProblem::Overflow)
        } else if (n - 1.0).abs() <= 1e3 * S::EPSILON {
            Ok(())
        } else {
            Err(ModelProblem::RotationNotOrthonormal)
        }
    }
    fn validate_joint<S: Scalar>(j: &PlanarJoint<S>) -> Result<(), ModelProblem> {
        match j {
            PlanarJoint::Prismatic(a)
                if (a.norm_squared().to_f64() - 1.0).abs() > 1e3 * S::EPSILON =>
            {
                Err(ModelProblem::AxisNotUnit)
            }
            _ => Ok(()),
        }
    }
    // A plane rotation is already two products per vector: nothing to prepare.
    type Step<S: Scalar> = PlanarTransform<S>;
    #[inline(always)]
    fn step<S: Scalar>(x: &PlanarTransform<S>) -> PlanarTransform<S> {
        *x
    }
    #[inline(always)]
    fn joint_step<S: Scalar>(
        j: &PlanarJoint<S>,
        placement: &PlanarTransform<S>,
        q: &[S],
    ) -> PlanarTransform<S> {
        use crate::joint::JointModel;
        j.placed_transform(placement, q)
    }
    /// A revolute joint: its angle.
    #[inline(always)]
    fn step_angle<S: Scalar>(_frame: &TurnedFrame, j: &PlanarJoint<S>, q: &[S]) -> Option<S> {
        matches!(j, PlanarJoint::Revolute).then(|| q[0])
    }
    // Only the out-of-order profile forms the angles first
    // (`crate::tuning::ANGLES_FIRST`); on the Cortex-M4 the extra call site
    // of `compose` cost the muscle robot's forward dynamics instructions
    // through other inlining (see the performance notebook, "Sine and
    // cosine").
    #[cfg(rodyn_tuning = "out_of_order")]
    #[inline(always)]
    fn turned_joint_step<S: Scalar>(
        _frame: &TurnedFrame,
        j: &PlanarJoint<S>,
        placement: &PlanarTransform<S>,
        q: &[S],
        sin_cos: Option<(S, S)>,
    ) -> PlanarTransform<S> {
        match (j, sin_cos) {
            (PlanarJoint::Revolute, Some((sin, cos))) => {
                placement.compose(&PlanarTransform::from_cos_sin(cos, sin, Vec2::ZERO))
            }
            _ => Self::joint_step(j, placement, q),
        }
    }
    #[inline(always)]
    fn then_step<S: Scalar>(
        x: &PlanarTransform<S>,
        step: &PlanarTransform<S>,
    ) -> PlanarTransform<S> {
        x.compose(step)
    }
    #[inline(always)]
    fn step_forces<S: Scalar>(x: &PlanarTransform<S>, forces: &mut [PlanarForce<S>]) {
        for f in forces {
            *f = x.act_force(f);
        }
    }
    #[inline(always)]
    fn add_stepped_inertia<S: Scalar>(
        acc: &mut PlanarInertia<S>,
        x: &PlanarTransform<S>,
        i: &PlanarInertia<S>,
    ) {
        // As `PlanarInertia::combine` with `x.act(i)`: its centre of mass
        // moved, `izz` unchanged by a rotation about z.
        let com_i = x.act_point(&i.com);
        let mass = acc.mass + i.mass;
        let inv = S::ONE / mass.max(S::from_f64(S::EPSILON));
        let d = acc.com - com_i;
        acc.izz = acc.izz + i.izz + acc.mass * i.mass * inv * d.norm_squared();
        acc.com = (acc.com * acc.mass + com_i * i.mass) * inv;
        acc.mass = mass;
    }
    #[inline(always)]
    fn inertia_column<S: Scalar>(
        i: &PlanarInertia<S>,
        j: &PlanarJoint<S>,
        k: usize,
    ) -> PlanarForce<S> {
        use crate::joint::JointModel;
        use crate::space::BodyInertia;
        i.mul_motion(&j.subspace_column(k))
    }
}

impl<S: Scalar, const NB: usize, const NQ: usize, const NV: usize> Model<S, NB, NQ, NV, Planar> {
    /// A planar model, checked at compile time when evaluated in a `const`;
    /// arguments as for the 3-D [`Model::new`](crate::Model::new).
    ///
    /// # Panics
    /// When the topology is inconsistent; in a `const` a compile error.
    #[must_use]
    pub const fn new_planar(
        parents: [Option<usize>; NB],
        joints: [PlanarJoint<S>; NB],
        placements: [PlanarTransform<S>; NB],
        inertias: [PlanarInertia<S>; NB],
        gravity: PlanarMotion<S>,
    ) -> Self {
        let mut nq = [0; NB];
        let mut nv = [0; NB];
        let mut i = 0;
        while i < NB {
            nq[i] = joints[i].const_nq();
            nv[i] = joints[i].const_nv();
            i += 1;
        }
        // Planar joints are angles and displacements: any finite q is valid.
        Self::from_parts(
            Topology::new(parents, nq, nv, NQ),
            joints,
            placements,
            inertias,
            gravity,
        )
        .with_unconstrained_configuration()
    }
}
