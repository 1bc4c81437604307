//! Sensitivities of the joint accelerations.
//!
//! **With respect to drive inputs** ([`input_sensitivity`]). At a fixed
//! state `(q, v)` the accelerations are
//! `q̈ = M⁻¹ (τ(w) - h + Jᵀ f(w))`, so for each drive input `w_k`
//!
//! `∂q̈/∂w_k = M⁻¹ (∂τ/∂w_k + Jᵀ ∂f/∂w_k)`,
//!
//! the accelerations that the input's force derivative alone would cause
//! with zero velocity and no gravity (the bias terms `h` do not depend on
//! `w`). ABA computes that in O(n) reusing the articulated quantities of
//! the main pass (`aba_response`): the whole `NV × NU` matrix costs one
//! extra pass per input, O(n·m), as in the first seed paper.
//!
//! Which derivative: `w` is the drive-input vector of [`crate::drive`]:
//! motor currents, and muscle *activations*. A muscle's excitation `u`
//! reaches the accelerations only through its activation dynamics, so at an
//! instant `∂q̈/∂u = 0`; an optimal-control transcription combines
//! `∂q̈/∂a` from here with `∂ȧ/∂u` from
//! [`ThelenMuscle::activation_rate`](crate::drive::ThelenMuscle::activation_rate).
//! The derivative is exact for any element, affine in `w` or not (a Thelen
//! muscle's force is not affine in activation: its velocity scale depends
//! on it).
//!
//! **With respect to model parameters** (a mass, a length, a muscle
//! constant): run the same generic dynamics on [`Dual`](crate::Dual) with
//! that parameter's derivative part set to one; see the crate's host tests.

mod inputs;
mod response;

pub use inputs::{forward_dynamics_and_sensitivity, input_sensitivity};
pub(crate) use response::aba_response;
