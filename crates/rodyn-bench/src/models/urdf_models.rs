//! The benchmark robots, compiled from `models/urdf/` by `build.rs` with
//! rodyn's model compiler (the files Pinocchio reads in the comparison).

use rodyn::Model;

include!(concat!(env!("OUT_DIR"), "/panda.rs"));
include!(concat!(env!("OUT_DIR"), "/ur5.rs"));
include!(concat!(env!("OUT_DIR"), "/solo12.rs"));

/// `models/urdf/panda.urdf`: 7 bodies, nq = 7, nv = 7.
pub const PANDA: Model<f64, 7, 7, 7> = panda::MODEL_F64;
/// Path of the Panda's URDF, relative to the workspace root.
pub const PANDA_URDF: &str = "models/urdf/panda.urdf";

/// `models/urdf/ur5.urdf`: 6 bodies, nq = 6, nv = 6.
pub const UR5: Model<f64, 6, 6, 6> = ur5::MODEL_F64;
/// Path of the UR5's URDF, relative to the workspace root.
pub const UR5_URDF: &str = "models/urdf/ur5.urdf";

/// `models/urdf/solo12.urdf` on a free-flyer root: 13 bodies, nq = 19, nv = 18.
pub const SOLO12: Model<f64, 13, 19, 18> = solo12::MODEL_F64;
/// Path of Solo12's URDF, relative to the workspace root.
pub const SOLO12_URDF: &str = "models/urdf/solo12.urdf";
