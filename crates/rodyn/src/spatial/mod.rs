//! Featherstone's 6-D spatial algebra for models in 3-D space.
//!
//! One concept per file: [`Motion`], [`Force`], [`Transform`], [`Inertia`],
//! [`ArticulatedInertia6`], [`AxisPermutation`], and the 3-D building
//! blocks [`Vec3`], [`Mat3`], [`Sym3`]. [`Spatial`] names the geometry they make;
//! `crate::space` ties them to the traits the algorithms are written
//! against ([`Geometry`](crate::space::Geometry)). The algebra imports
//! nothing above the scalar.

pub(crate) mod articulated;
pub(crate) mod axis_permutation;
mod force;
mod inertia;
mod log;
mod mat3;
mod motion;
mod parameter_problem;
mod sym3;
mod transform;
mod vec3;

pub use articulated::ArticulatedInertia6;
pub use axis_permutation::AxisPermutation;
pub use force::Force;
pub use inertia::Inertia;
pub use log::{log3, log6};
pub use mat3::Mat3;
pub use motion::Motion;
pub use parameter_problem::ParameterProblem;
pub use sym3::Sym3;
pub use transform::Transform;
pub use vec3::Vec3;

/// Full 3-D space: 6-D motion and force vectors.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Spatial;
