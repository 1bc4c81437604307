//! Optimal control with rodyn, as Friedmann, Wojtusch & von Stryk (PAMM,
//! "A modular and efficient approach to computational modeling and
//! sensitivity analysis of robot and human motion dynamics") do it: the
//! two-link, four-muscle robot (`models/two_link_muscles.toml`) follows
//! desired joint trajectories with the least muscle effort, found by
//! direct collocation and solved by IPOPT with derivatives from rodyn.
//!
//! - [`ipopt`]: a safe interface to IPOPT's C API (the system library;
//!   Debian's `coinor-libipopt-dev`).
//! - [`collocation`]: trapezoidal direct collocation of `ẋ = f(t, x, u)`
//!   with an effort objective, as a sparse nonlinear program, with the
//!   Hessian of the Lagrangian exact, from differences of the Jacobians,
//!   or left to IPOPT's quasi-Newton approximation.
//! - [`muscle_robot`]: the robot on its Thelen (2003) muscles, with its
//!   state Jacobians by three routes (rodyn's analytic derivatives, dual
//!   numbers, finite differences), the task and the replay of controls.
//! - [`smooth_muscle_robot`]: the robot on smooth De Groote et al. (2016)
//!   muscles, with analytic Jacobians and exact second derivatives, which
//!   IPOPT solves to its default tolerance.
//!
//! The example `muscle_robot_optimal_control` runs the problem end to end
//! and writes the controls, the results and the figure.

pub mod collocation;
pub mod ipopt;
pub mod muscle_robot;
pub mod smooth_muscle_robot;
