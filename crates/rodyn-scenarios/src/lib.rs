//! rodyn's example scenes, one source for the host and the firmware.
//!
//! The robots are the model files shipped in `models/`, compiled into
//! `const` Rust by `build.rs` with `rodyn_model::build::compile`, exactly as
//! a user's firmware would compile its own. What is not a model (a gait
//! controller, a scene's call per tick) lives beside them here, so the core
//! crate `rodyn` holds mechanisms only and every tool, test and firmware
//! image simulates the same robot.
//!
//! | module               | from                          | what it is                                                        |
//! |----------------------|-------------------------------|-------------------------------------------------------------------|
//! | [`pendulum`]         | `models/pendulum.toml`        | a pendulum and its return spring                                  |
//! | [`panda`]            | `models/panda.toml`           | the Franka Panda arm (7 DoF) with joint motors                    |
//! | [`aibo`]             | `models/aibo.toml`            | an Aibo-size quadruped: floating trunk, 3 joints per leg, contacts |
//! | [`two_link_muscles`] | `models/two_link_muscles.toml`| a two-link robot with four Thelen muscles (planar)                |
//! | [`gait_planar`]      | `models/gait_planar.toml`     | a planar gait model (8 segments, Winter's table)                  |
//! | [`quadruped`]        | [`aibo`]                      | stance / trot PD controller, ground contact, one call per step     |
//! | [`quadruped_balance`] | [`quadruped`]                | a trot that holds the trunk's height and attitude by inverse dynamics with contacts |
//! | [`muscle_robot`]     | [`two_link_muscles`]          | forward dynamics with the muscles, its sensitivity `∂q̈/∂a`, loads with the activations as auxiliary states |
//! | [`ilqr`]             |                               | iterative LQR with constant work per call, for MPC                |
//! | [`driven_system`]    |                               | a model with drives as a discrete system, analytic linearisation  |
//! | [`pendulum_mpc`]     | [`pendulum`]                  | model-predictive control of the pendulum by iLQR                  |
//! | [`panda_tracking`]   | [`panda`]                     | computed torque (RNEA) tracking a trajectory against a plant stepped by ABA, one tick per call: the boards' loop |
//!
//! Every generated module holds `MODEL_F64` and `MODEL_F32`, the sizes
//! `NB`, `NQ`, `NV`, `NE`, named indices (`body::`, `joint::`, `q::`, `v::`,
//! `endpoint::`), and its drives and contacts as values of `rodyn::drive`
//! and `rodyn::sim::contact` types. Everything is `no_std` and
//! allocation-free; a firmware pays only for the constants it uses.
#![no_std]

include!(concat!(env!("OUT_DIR"), "/pendulum.rs"));
include!(concat!(env!("OUT_DIR"), "/panda.rs"));
include!(concat!(env!("OUT_DIR"), "/aibo.rs"));
include!(concat!(env!("OUT_DIR"), "/two_link_muscles.rs"));
include!(concat!(env!("OUT_DIR"), "/gait_planar.rs"));

// The generated modules document their items but not each coordinate index
// (`q::`, `v::`); the hand-written ones document everything.
#[warn(missing_docs)]
pub mod driven_system;
#[warn(missing_docs)]
pub mod ilqr;
#[warn(missing_docs)]
pub mod muscle_robot;
#[warn(missing_docs)]
pub mod panda_tracking;
#[warn(missing_docs)]
pub mod payload_estimate;
#[warn(missing_docs)]
pub mod payload_scene;
#[warn(missing_docs)]
pub mod pendulum_mpc;
#[warn(missing_docs)]
pub mod quadruped;
#[warn(missing_docs)]
pub mod quadruped_balance;
