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
use crate::space::Geometry;
use crate::topology::Topology;
use crate::Scalar;

/// The plane: 3-component motion and force vectors.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Planar;

impl Geometry for Planar {
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
        i.validate().map_err(ModelProblem::from)
    }
    fn validate_transform<S: Scalar>(x: &PlanarTransform<S>) -> Result<(), ModelProblem> {
        x.validate().map_err(ModelProblem::from)
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
