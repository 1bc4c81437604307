//! Sensor and actuator drivers, written only against embedded-hal 1.0
//! traits: the same code reads a real encoder on a board and the simulated
//! one in QEMU.

mod absolute_encoder;
mod torque_drive;

pub use absolute_encoder::{
    encode_frame, AbsoluteEncoder, EncoderError, COUNTS_PER_TURN, FRAME_BYTES, READ_POSITION,
};
pub use torque_drive::{duty_to_torque, DriveError, TorqueDrive};
