//! Featherstone's 6-D spatial algebra for models in 3-D space.
//!
//! One concept per file: [`Motion`], [`Force`], [`Transform`], [`Inertia`],
//! [`ArticulatedInertia6`], and the 3-D building blocks [`Vec3`], [`Mat3`],
//! [`Sym3`]. [`Spatial`] ties them together as a [`Space`].

mod articulated;
mod force;
mod inertia;
mod mat3;
mod motion;
mod sym3;
mod transform;
mod vec3;

pub use articulated::ArticulatedInertia6;
pub use force::Force;
pub use inertia::Inertia;
pub use mat3::Mat3;
pub use motion::Motion;
pub use sym3::Sym3;
pub use transform::Transform;
pub use vec3::Vec3;

use crate::error::ModelProblem;
use crate::joint::Joint;
use crate::space::Space;
use crate::Scalar;

/// Full 3-D space: 6-D motion and force vectors.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Spatial;

impl Space for Spatial {
    const DIM: usize = 6;
    type Motion<S: Scalar> = Motion<S>;
    type Force<S: Scalar> = Force<S>;
    type Point<S: Scalar> = Vec3<S>;
    type Transform<S: Scalar> = Transform<S>;
    type Inertia<S: Scalar> = Inertia<S>;
    type Articulated<S: Scalar> = ArticulatedInertia6<S>;
    type Joint<S: Scalar> = Joint<S>;

    fn default_joint<S: Scalar>() -> Joint<S> {
        Joint::Fixed
    }
    fn cast_joint<S: Scalar, T: Scalar>(j: &Joint<S>) -> Option<Joint<T>> {
        j.cast()
    }
    fn cast_transform<S: Scalar, T: Scalar>(x: &Transform<S>) -> Transform<T> {
        x.cast()
    }
    fn cast_inertia<S: Scalar, T: Scalar>(i: &Inertia<S>) -> Inertia<T> {
        i.cast()
    }
    fn cast_motion<S: Scalar, T: Scalar>(m: &Motion<S>) -> Motion<T> {
        Motion::new(m.ang.cast(), m.lin.cast())
    }
    fn validate_inertia<S: Scalar>(i: &Inertia<S>) -> Result<(), ModelProblem> {
        crate::model::validate_inertia_3d(i)
    }
    fn validate_transform<S: Scalar>(x: &Transform<S>) -> Result<(), ModelProblem> {
        crate::model::validate_transform_3d(x)
    }
    fn validate_joint<S: Scalar>(j: &Joint<S>) -> Result<(), ModelProblem> {
        let axis = match j {
            Joint::Revolute(r) => r.axis,
            Joint::Prismatic(p) => p.axis,
            _ => return Ok(()),
        };
        let n = axis.vector().norm_squared().to_f64();
        if (n - 1.0).abs() > 1e3 * S::EPSILON {
            Err(ModelProblem::AxisNotUnit)
        } else {
            Ok(())
        }
    }
}
