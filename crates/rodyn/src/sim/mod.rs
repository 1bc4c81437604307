//! Simulation: integrators and ground contact, all `no_std` and
//! allocation-free. Scenes built on them (the Aibo-size quadruped's gait)
//! live in the `rodyn-scenarios` crate.
//!
//! A simulation advances a [`State`] `(t, q, v)` by a step `dt`. At each
//! evaluation the integrator asks a [`Loads`] for the joint torques `τ` and
//! the external forces `f_ext` (one per body, body frame) at `(t, q, v)`,
//! and a [`ForwardDynamics`](crate::algorithm::forward_dynamics::ForwardDynamics)
//! method (ABA or CRBA) for `q̈`. Contacts and drives only produce loads;
//! they never change an integrator or an algorithm.
//!
//! Drives with first-order states of their own (muscle activations, motor
//! currents) put them in the state's `NZ` auxiliary states `z` and
//! implement [`AuxiliaryLoads`], whose forces may read `z` and which gives
//! `ż`; every integrator advances `z` with `q` and `v`. A model without
//! them keeps `NZ = 0`, the default, and pays nothing.
//!
//! | item                         | what it is                                                      |
//! |------------------------------|-----------------------------------------------------------------|
//! | [`State`]                    | time (s), configuration `q` (NQ), velocity `v` (NV), auxiliary states `z` (NZ, default 0) |
//! | [`Loads`]                    | `τ` and `f_ext` from `(t, q, v)`; a closure works               |
//! | [`AuxiliaryLoads`]           | `τ`, `f_ext` and `ż` from `(t, q, v, z)`; every `Loads` is one with `NZ = 0` |
//! | [`Integrator`]               | one step: [`ExplicitEuler`], [`SemiImplicitEuler`], [`Rk4`], [`ImplicitEuler`] |
//! | [`ConfigurationUpdate`]      | how `q` moves on its manifold: exponential map or embedded with optional renormalisation |
//! | [`contact::GroundContact`]   | compliant point contact with the plane z = 0                    |
//! | [`time_stepping::time_step`] | one step with rigid point contacts on the plane z = 0 and Coulomb friction |
//!
//! Every step either returns `Ok` with a finite state or returns the error of
//! the dynamics (or [`Error::NonFinite`](crate::Error::NonFinite)) and leaves
//! the state as it was: a simulation never continues silently from NaN.

pub mod contact;
pub mod integrator;
pub mod loads;
pub mod manifold;
pub mod state;
pub mod time_stepping;

pub use integrator::{ExplicitEuler, ImplicitEuler, Integrator, Rk4, SemiImplicitEuler};
pub use loads::{AuxiliaryLoads, Loads, NoLoads};
pub use manifold::{ConfigurationRate, ConfigurationUpdate};
pub use state::State;
