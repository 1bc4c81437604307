//! What stands in for the robot in QEMU: a plant simulated with rodyn's ABA
//! and fake peripherals that implement the embedded-hal traits on top of it.
//!
//! The controller and its drivers cannot tell these from real hardware: the
//! fake SPI encoder quantises the plant's joint angle to 18 bits and frames
//! it as the sensor would, the fake PWM holds a duty cycle that the plant
//! reads back as a torque.

mod arm_plant;
mod encoder_spi;
mod pwm;
mod signals;
mod wiring;

pub use arm_plant::ArmPlant;
pub use encoder_spi::SimulatedEncoderSpi;
pub use pwm::{SimulatedPwm, PWM_PERIOD};
pub use signals::Signals;
pub use wiring::{wire, Wiring};
