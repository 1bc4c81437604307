//! rodyn on a Cortex-M4F: the pieces the firmware examples share.
//!
//! The examples in `src/bin/` run under QEMU's `mps2-an386` board (Cortex-M4
//! with FPU) and end the emulator with an exit code: 0 on success, 1 when a
//! check fails, 101 on a panic. They log through defmt over semihosting;
//! `cargo xtask run` and `cargo xtask test` decode the log on the host.
//!
//! | module        | what it holds                                                |
//! |---------------|--------------------------------------------------------------|
//! | [`models`]    | the example models as `const` values (f32)                   |
//! | [`drivers`]   | an SPI absolute encoder and a PWM torque drive (embedded-hal)|
//! | [`control`]   | computed-torque and task-space controllers, their references |
//! | [`simulated`] | the plant and the fake SPI / PWM peripherals standing for it |
//! | [`measure`]   | instruction counts (SysTick under `-icount`) and stack use   |
//! | [`rng`]       | a seeded xorshift generator for reproducible random states  |
//! | [`exit`]      | leaving QEMU with an exit code; the panic handler            |
//! | [`pose_log`]  | the configuration every 20 ms, for the viewer (feature)      |
#![no_std]
#![warn(missing_docs)]

// The global defmt logger: frames go to the host through semihosting.
use defmt_semihosting as _;

pub mod control;
pub mod drivers;
pub mod exit;
pub mod measure;
pub mod models;
pub mod pose_log;
pub mod rng;
pub mod simulated;
