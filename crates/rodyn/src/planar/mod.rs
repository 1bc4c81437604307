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
//!
//! The algebra imports the scalar and the 3-D building blocks it reuses
//! (`Vec3`, `Sym3`, `ParameterProblem`) only; `crate::space::planar` ties
//! it to the traits, `joint/planar.rs` gives [`PlanarJoint`] its motion and
//! [`Model::new_planar`](crate::Model::new_planar) builds planar models.

pub(crate) mod articulated;
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

/// The plane: 3-component motion and force vectors.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Planar;
