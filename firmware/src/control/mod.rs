//! Model-based joint control. The controller knows the robot only through
//! the embedded-hal drivers and a rodyn model.

mod computed_torque;
mod trajectory;

pub use computed_torque::{ComputedTorque, ControlError, Gains, TickReport};
pub use trajectory::{CosineTrajectory, Reference};
