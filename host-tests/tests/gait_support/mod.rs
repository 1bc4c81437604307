//! Shared by the gait example (`examples/gait_*.rs`) and its tests: the
//! compiled gait model, the input files and the inverse dynamics at the
//! prosthesis interface.

include!(concat!(env!("OUT_DIR"), "/gait_planar.rs"));

pub mod data;
pub mod fourier;
pub mod inverse_dynamics;
