//! Optimal control with rodyn, as the first seed does it: the two-link,
//! four-muscle robot (`models/two_link_muscles.toml`) follows desired joint
//! trajectories with the least muscle effort, found by direct collocation
//! and solved by IPOPT with the constraint Jacobian built from rodyn's
//! derivatives.
//!
//! - [`ipopt`]: a safe interface to IPOPT's C API (the system library;
//!   Debian's `coinor-libipopt-dev`).
//! - [`collocation`]: trapezoidal direct collocation of `ẋ = f(t, x, u)`
//!   with an effort objective, as a sparse nonlinear program.
//! - [`muscle_robot`]: the seed's robot as such a system, with its state
//!   Jacobians by three routes (rodyn's analytic derivatives, dual
//!   numbers, finite differences).
//!
//! The example `muscle_robot_optimal_control` runs the seed's problem end
//! to end and writes the controls, a summary and the figure.

pub mod collocation;
pub mod ipopt;
pub mod muscle_robot;
pub mod smooth_muscle_robot;
