//! Model-based control. The controllers know the robot only through the
//! embedded-hal drivers and a rodyn model.

mod computed_torque;
mod pose_trajectory;
mod rate_estimate;
mod task_space;
mod trajectory;

pub use computed_torque::{ComputedTorque, ControlError, Gains, TickReport};
pub use pose_trajectory::{CirclePoseTrajectory, PoseReference};
pub use rate_estimate::RateEstimate;
pub use task_space::{TaskGains, TaskSpaceImpedance};
pub use trajectory::{CosineTrajectory, Reference};
