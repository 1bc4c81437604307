//! The benchmark models.
//!
//! * [`urdf_models`]: the Panda arm (7 DoF), the UR5 arm (6 DoF) and the
//!   Solo12 quadruped (free flyer + 4 legs x 3 revolute), compiled from
//!   `models/urdf` by rodyn's model compiler in `build.rs`.
//! * [`chains`]: planar revolute chains of any length, as planar models and
//!   as their 3-D equivalents, with the link parameters of
//!   `models/urdf/planar_chain_N.urdf`.

pub mod chains;
pub mod urdf_models;

pub use chains::{planar_chain, planar_chain_3d};
pub use urdf_models::{PANDA, PANDA_URDF, SOLO12, SOLO12_URDF, UR5, UR5_URDF};
