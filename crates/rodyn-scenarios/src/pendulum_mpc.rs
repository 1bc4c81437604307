//! Model-predictive control of the seed pendulum with its return spring:
//! iterative LQR over a short horizon, warm-started every tick, on rodyn's
//! analytic derivatives (see [`ilqr`](crate::ilqr) and
//! [`driven_system`](crate::driven_system)).
//!
//! The pendulum (`models/pendulum.toml`: 1 m, 1 kg rod, spring of 20 N/m
//! from its tip to an anchor beside the pivot) follows a reference angle
//! that rests hanging, swings to 0.8 rad, then back to 0.2 rad, each move a
//! half-cosine of 1 s, under a torque limit. (Holding it hanging takes
//! 4 N m against the spring, at 0.8 rad 5 N m against gravity.) The controller plans
//! [`HORIZON`] stages of [`STEP`] seconds (0.5 s ahead) and applies the
//! first control until the next tick; each tick costs the same:
//! [`ITERATIONS_PER_TICK`] iLQR iterations, each linearising every stage
//! and rolling the system out once per line-search step.

use crate::driven_system::DrivenModel;
use crate::ilqr::{Ilqr, IlqrError, IlqrReport, TrackingCost};
use rodyn::drive::LinearSpring;
use rodyn::spatial::Spatial;
use rodyn::{Model, Scalar};

/// Stages planned ahead.
pub const HORIZON: usize = 25;
/// Length of a stage and period of the controller (s).
pub const STEP: f64 = 0.02;
/// iLQR iterations per control tick.
pub const ITERATIONS_PER_TICK: usize = 1;
/// iLQR iterations before the first tick, from zero torques.
pub const WARM_UP_ITERATIONS: usize = 10;
/// The motor's torque limit (N m): above the 5 N m that holding the
/// reference's angles takes, with room for the swings.
pub const TORQUE_LIMIT: f64 = 8.0;

/// The pendulum's state and control sizes: `x = (q, q̇)`, `u = τ`.
pub const NX: usize = 2;
/// See [`NX`].
pub const NU: usize = 1;

/// Reference angle and rate at time `t` (s): at rest until 0.5 s, a
/// half-cosine to 0.8 rad over 1 s, rest, a half-cosine to 0.2 rad from
/// 2.5 s to 3.5 s, rest.
#[must_use]
pub fn reference<S: Scalar>(t: S) -> [S; NX] {
    let c = S::from_f64;
    // In S, not f64: a Cortex-M4F has no double-precision unit.
    let moves = [(c(0.5), c(0.0), c(0.8)), (c(2.5), c(0.8), c(0.2))];
    let pi = c(core::f64::consts::PI);
    let mut state = [S::ZERO, S::ZERO];
    for (start, from, to) in moves {
        if t >= start + S::ONE {
            state = [to, S::ZERO];
        } else if t > start {
            let (sin, cos) = (pi * (t - start)).sin_cos();
            let half = c(0.5) * (to - from);
            state = [from + half * (S::ONE - cos), half * pi * sin];
        }
    }
    state
}

/// The tracking cost: angle error 400 per rad², rate error 1 per
/// (rad/s)², torque 0.01 per (N m)², the end of the horizon weighted 10x.
#[must_use]
pub fn cost<S: Scalar>() -> TrackingCost<S, NX, NU> {
    let c = S::from_f64;
    TrackingCost {
        state: [c(400.0), c(1.0)],
        control: [c(0.01)],
        terminal: [c(4000.0), c(10.0)],
    }
}

/// The pendulum's model-predictive controller in scalar `S`.
pub struct PendulumMpc<'m, S: Scalar> {
    system: DrivenModel<'m, S, Spatial, LinearSpring<S, Spatial, 2>, 1, 1, NX, NU>,
    /// The solver, with its warm start.
    pub solver: Ilqr<S, NX, NU, HORIZON>,
    cost: TrackingCost<S, NX, NU>,
    started: bool,
}

impl<'m, S: Scalar> PendulumMpc<'m, S> {
    /// A controller for `model` with its return `spring`.
    #[must_use]
    pub fn new(model: &'m Model<S, 1, 1, 1>, spring: &'m LinearSpring<S, Spatial, 2>) -> Self {
        let limit = S::from_f64(TORQUE_LIMIT);
        Self {
            system: DrivenModel::new(model, spring, &[], S::from_f64(STEP)),
            solver: Ilqr::new([-limit], [limit], S::from_f64(1e-6)),
            cost: cost(),
            started: false,
        }
    }

    /// One control tick at time `t` (s) from the measured state `x`: the
    /// torque to apply until the next tick (N m), within the limit, and
    /// what the solver did. The first tick warms up with
    /// [`WARM_UP_ITERATIONS`]; every later one shifts the plan one stage
    /// and runs [`ITERATIONS_PER_TICK`].
    ///
    /// # Errors
    /// [`IlqrError`] when the dynamics fail.
    pub fn tick(&mut self, t: S, x: &[S; NX]) -> Result<(S, IlqrReport<S>), IlqrError> {
        let iterations = if self.started {
            self.solver.shift();
            ITERATIONS_PER_TICK
        } else {
            self.started = true;
            WARM_UP_ITERATIONS
        };
        let h = S::from_f64(STEP);
        let references: [[S; NX]; HORIZON] =
            core::array::from_fn(|k| reference(t + h * S::from_f64(k as f64)));
        let last = reference(t + h * S::from_f64(HORIZON as f64));
        let report = self.solver.solve(
            &mut self.system,
            &self.cost,
            x,
            &references,
            &last,
            iterations,
        )?;
        Ok((self.solver.controls[0][0], report))
    }
}
