//! The two first-order Euler schemes.

use super::{check_time, commit, derivatives, Integrator};
use crate::algorithm::forward_dynamics::ForwardDynamics;
use crate::data::Data;
use crate::error::Result;
use crate::model::Model;
use crate::sim::loads::AuxiliaryLoads;
use crate::sim::manifold::{
    add_scaled, displace, for_dynamics, ConfigurationRate, ConfigurationUpdate,
};
use crate::sim::state::State;
use crate::Scalar;

/// Explicit (forward) Euler: `q₁ = q ⊕ v dt`, `v₁ = v + a(q, v, z) dt`,
/// `z₁ = z + ż(q, v, z) dt`.
///
/// First order. On an undamped oscillator it multiplies the energy by
/// `1 + (ω dt)²` every step, so it is unstable at any step size there; it
/// is here as the baseline the others are measured against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ExplicitEuler {
    /// How `q` moves (default: the exponential map).
    pub update: ConfigurationUpdate,
}

impl Default for ExplicitEuler {
    fn default() -> Self {
        Self {
            update: ConfigurationUpdate::ExponentialMap,
        }
    }
}

impl Integrator for ExplicitEuler {
    const NAME: &'static str = "explicit-euler";

    fn step<F, L, S, const NB: usize, const NQ: usize, const NV: usize, const NZ: usize, G>(
        &mut self,
        method: F,
        model: &Model<S, NB, NQ, NV, G>,
        data: &mut Data<S, NB, NV, G>,
        state: &mut State<S, NQ, NV, NZ>,
        dt: S,
        loads: &mut L,
    ) -> Result<()>
    where
        F: ForwardDynamics,
        L: AuxiliaryLoads<S, NB, NQ, NV, NZ, G>,
        S: Scalar,
        G: ConfigurationRate,
    {
        let State { t, q, v, z } = *state;
        check_time(t, dt)?;
        let q_dyn = for_dynamics(model, self.update, &q);
        let (a, z_rate) = derivatives(&method, model, data, loads, t, &q_dyn, &v, &z)?;
        let next = State {
            t: t + dt,
            q: displace(model, self.update, &q, &v, dt),
            v: core::array::from_fn(|k| v[k] + a[k] * dt),
            z: add_scaled(&z, &z_rate, dt),
        };
        commit(state, next)
    }
}

/// Semi-implicit (symplectic) Euler: `v₁ = v + a(q, v, z) dt` and
/// `z₁ = z + ż(q, v, z) dt`, then `q₁ = q ⊕ v₁ dt`.
///
/// First order, same cost as [`ExplicitEuler`], but symplectic for
/// conservative systems: the energy error stays bounded instead of growing,
/// and an oscillator of frequency ω is stable for `ω dt < 2`. The usual
/// choice for a real-time loop.
///
/// # Example
///
/// ```
/// use rodyn::algorithm::forward_dynamics::Aba;
/// use rodyn::sim::{Integrator, NoLoads, SemiImplicitEuler, State};
/// # use rodyn::prelude::*;
/// # // A 1 kg point mass on a massless 1 m link, pivot about z, gravity -y.
/// # const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
/// #     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
/// #     [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
/// #     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// # );
/// let mut data = Data::new();
/// let (q0, dt) = (0.3, 1e-3);
/// let mut state = State::new([q0], [0.0]);
/// SemiImplicitEuler::default().step(Aba, &PENDULUM, &mut data, &mut state, dt, &mut NoLoads)?;
/// // v₁ = v + q̈ dt with q̈ = -(g / l) cos q, then q₁ = q + v₁ dt.
/// let v1 = -9.81 * f64::cos(q0) * dt;
/// assert!((state.v[0] - v1).abs() < 1e-15 && (state.q[0] - (q0 + v1 * dt)).abs() < 1e-15);
/// assert!((state.t - dt).abs() < 1e-18);
/// # Ok::<(), rodyn::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SemiImplicitEuler {
    /// How `q` moves (default: the exponential map).
    pub update: ConfigurationUpdate,
}

impl Default for SemiImplicitEuler {
    fn default() -> Self {
        Self {
            update: ConfigurationUpdate::ExponentialMap,
        }
    }
}

impl Integrator for SemiImplicitEuler {
    const NAME: &'static str = "semi-implicit-euler";

    fn step<F, L, S, const NB: usize, const NQ: usize, const NV: usize, const NZ: usize, G>(
        &mut self,
        method: F,
        model: &Model<S, NB, NQ, NV, G>,
        data: &mut Data<S, NB, NV, G>,
        state: &mut State<S, NQ, NV, NZ>,
        dt: S,
        loads: &mut L,
    ) -> Result<()>
    where
        F: ForwardDynamics,
        L: AuxiliaryLoads<S, NB, NQ, NV, NZ, G>,
        S: Scalar,
        G: ConfigurationRate,
    {
        let State { t, q, v, z } = *state;
        check_time(t, dt)?;
        let q_dyn = for_dynamics(model, self.update, &q);
        let (a, z_rate) = derivatives(&method, model, data, loads, t, &q_dyn, &v, &z)?;
        let v_next: [S; NV] = core::array::from_fn(|k| v[k] + a[k] * dt);
        let next = State {
            t: t + dt,
            q: displace(model, self.update, &q, &v_next, dt),
            v: v_next,
            // The auxiliary states move with `v`, from the rates at the
            // start of the step: only `q` sees the new velocity, so the
            // scheme still needs one evaluation per step.
            z: add_scaled(&z, &z_rate, dt),
        };
        commit(state, next)
    }
}
