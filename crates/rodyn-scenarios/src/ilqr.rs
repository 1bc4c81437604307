//! Iterative LQR with a fixed amount of work per call, for model-predictive
//! control on a microcontroller.
//!
//! The method is Li & Todorov's ("Iterative linear quadratic regulator
//! design for nonlinear biological movement systems", ICINCO 2004), with
//! Tassa, Erez & Todorov's regularisation of `Q_uu` and line search ("Synthesis
//! and stabilization of complex behaviors through online trajectory
//! optimization", IROS 2012). Each iteration linearises the system along the
//! nominal trajectory, runs the Riccati-like backward pass for the
//! feedforward `k_t` and feedback `K_t`, and rolls the system forward with
//! `u_t = ū_t + α k_t + K_t (x_t − x̄_t)` for every `α` of a fixed list,
//! keeping the cheapest. No step depends on the data: the cost of a call is
//! the same every control tick. Controls are clamped to their bounds in
//! the forward pass.

// Index loops mirror the matrix equations (`Q_xx = ℓ_xx + Aᵀ V_xx A`).
#![allow(clippy::needless_range_loop)]

use rodyn::algorithm::dense::{cholesky_in_place, cholesky_solve};
use rodyn::{Result, Scalar};

/// Why [`Ilqr::solve`] stopped.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum IlqrError {
    /// The system's dynamics failed.
    Dynamics(rodyn::Error),
    /// `Q_uu` was not positive definite at this stage (a negative `R` or
    /// `μ`, or non-finite derivatives).
    NotPositiveDefinite {
        /// The stage, from 0.
        stage: usize,
    },
}

impl From<rodyn::Error> for IlqrError {
    fn from(e: rodyn::Error) -> Self {
        Self::Dynamics(e)
    }
}

/// A discrete-time system `x' = f(x, u)` and its linearisation.
pub trait DiscreteSystem<S: Scalar, const NX: usize, const NU: usize> {
    /// `f(x, u)`.
    ///
    /// # Errors
    /// When the dynamics fail at `(x, u)`.
    fn step(&mut self, x: &[S; NX], u: &[S; NU]) -> Result<[S; NX]>;
    /// `A = ∂f/∂x` and `B = ∂f/∂u` at `(x, u)` (row-major).
    ///
    /// # Errors
    /// As [`step`](Self::step).
    fn linearize(
        &mut self,
        x: &[S; NX],
        u: &[S; NU],
        a: &mut [[S; NX]; NX],
        b: &mut [[S; NU]; NX],
    ) -> Result<()>;
}

/// `Σₜ ½ (xₜ − rₜ)ᵀ Q (xₜ − rₜ) + ½ uₜᵀ R uₜ + ½ (x_N − r_N)ᵀ Q_N (x_N − r_N)`,
/// diagonal weights.
#[derive(Clone, Copy, Debug)]
pub struct TrackingCost<S, const NX: usize, const NU: usize> {
    /// `Q`'s diagonal, per stage.
    pub state: [S; NX],
    /// `R`'s diagonal, per stage.
    pub control: [S; NU],
    /// `Q_N`'s diagonal, at the end of the horizon.
    pub terminal: [S; NX],
}

impl<S: Scalar, const NX: usize, const NU: usize> TrackingCost<S, NX, NU> {
    fn stage(&self, x: &[S; NX], r: &[S; NX], u: &[S; NU]) -> S {
        let half = S::from_f64(0.5);
        let mut c = S::ZERO;
        for k in 0..NX {
            c += half * self.state[k] * (x[k] - r[k]) * (x[k] - r[k]);
        }
        for k in 0..NU {
            c += half * self.control[k] * u[k] * u[k];
        }
        c
    }
    fn last(&self, x: &[S; NX], r: &[S; NX]) -> S {
        let half = S::from_f64(0.5);
        (0..NX).fold(S::ZERO, |c, k| {
            c + half * self.terminal[k] * (x[k] - r[k]) * (x[k] - r[k])
        })
    }
}

/// The step sizes the forward pass tries, every one of them on every
/// iteration (constant work).
pub const LINE_SEARCH: [f64; 4] = [1.0, 0.5, 0.25, 0.1];

/// A rolled-out trajectory: its cost, final state, controls and states.
type Candidate<S, const NX: usize, const NU: usize, const N: usize> =
    (S, [S; NX], [[S; NU]; N], [[S; NX]; N]);

/// What one call of [`Ilqr::solve`] did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IlqrReport<S> {
    /// Cost of the nominal trajectory on entry (after re-rolling it from
    /// the new initial state).
    pub initial_cost: S,
    /// Cost of the nominal trajectory on return.
    pub cost: S,
    /// Iterations whose best step lowered the cost.
    pub improved: usize,
}

/// The solver's state over a horizon of `N` stages: the nominal controls
/// (the warm start), the nominal states and the per-stage work arrays.
#[derive(Clone, Debug)]
pub struct Ilqr<S: Scalar, const NX: usize, const NU: usize, const N: usize> {
    /// Nominal controls `ū₀ … ū_{N−1}`; `ū₀` is the one to apply.
    pub controls: [[S; NU]; N],
    /// Nominal states `x̄₀ … x̄_{N−1}` and the final one.
    pub states: [[S; NX]; N],
    /// `x̄_N`.
    pub final_state: [S; NX],
    /// Lower control bounds.
    pub u_min: [S; NU],
    /// Upper control bounds.
    pub u_max: [S; NU],
    /// `μ`, added to `Q_uu`'s diagonal (units of `R`).
    pub regularization: S,
    a: [[[S; NX]; NX]; N],
    b: [[[S; NU]; NX]; N],
    feedforward: [[S; NU]; N],
    feedback: [[[S; NX]; NU]; N],
    trial: [[S; NU]; N],
    trial_states: [[S; NX]; N],
}

impl<S: Scalar, const NX: usize, const NU: usize, const N: usize> Ilqr<S, NX, NU, N> {
    /// Zero controls within `[u_min, u_max]`, regularisation `μ`.
    #[must_use]
    pub fn new(u_min: [S; NU], u_max: [S; NU], regularization: S) -> Self {
        Self {
            controls: [[S::ZERO; NU]; N],
            states: [[S::ZERO; NX]; N],
            final_state: [S::ZERO; NX],
            u_min,
            u_max,
            regularization,
            a: [[[S::ZERO; NX]; NX]; N],
            b: [[[S::ZERO; NU]; NX]; N],
            feedforward: [[S::ZERO; NU]; N],
            feedback: [[[S::ZERO; NX]; NU]; N],
            trial: [[S::ZERO; NU]; N],
            trial_states: [[S::ZERO; NX]; N],
        }
    }

    /// Moves the warm start one stage on: `ūₜ ← ūₜ₊₁`, the last repeated.
    pub fn shift(&mut self) {
        self.controls.rotate_left(1);
        if N > 1 {
            self.controls[N - 1] = self.controls[N - 2];
        }
    }

    /// `iterations` iterations from the current state `x0` toward the
    /// references `r₀ … r_{N−1}` and `r_N`.
    ///
    /// # Errors
    /// [`IlqrError`].
    #[allow(clippy::too_many_arguments)]
    pub fn solve<D: DiscreteSystem<S, NX, NU>>(
        &mut self,
        system: &mut D,
        cost: &TrackingCost<S, NX, NU>,
        x0: &[S; NX],
        references: &[[S; NX]; N],
        final_reference: &[S; NX],
        iterations: usize,
    ) -> core::result::Result<IlqrReport<S>, IlqrError> {
        // The nominal trajectory from the new initial state, open loop.
        let mut nominal = self.rollout(system, cost, x0, references, final_reference, None)?;
        self.states = self.trial_states;
        self.final_state = nominal.1;
        self.controls = self.trial;
        let initial_cost = nominal.0;
        let mut improved = 0;
        for _ in 0..iterations {
            for t in 0..N {
                let (x, u) = (self.states[t], self.controls[t]);
                system.linearize(&x, &u, &mut self.a[t], &mut self.b[t])?;
            }
            self.backward_pass(cost, references, final_reference)?;
            let mut best: Option<Candidate<S, NX, NU, N>> = None;
            for alpha in LINE_SEARCH {
                let alpha = S::from_f64(alpha);
                let (c, last) =
                    self.rollout(system, cost, x0, references, final_reference, Some(alpha))?;
                if best.as_ref().is_none_or(|b| c < b.0) {
                    best = Some((c, last, self.trial, self.trial_states));
                }
            }
            if let Some((c, last, controls, states)) = best {
                if c < nominal.0 {
                    nominal = (c, last);
                    self.controls = controls;
                    self.states = states;
                    self.final_state = last;
                    improved += 1;
                }
            }
        }
        Ok(IlqrReport {
            initial_cost,
            cost: nominal.0,
            improved,
        })
    }

    /// Rolls the system from `x0` into `trial` / `trial_states`: with
    /// `alpha`, `u = ū + α k + K (x − x̄)`; without, the nominal controls.
    /// Returns the cost and the final state.
    fn rollout<D: DiscreteSystem<S, NX, NU>>(
        &mut self,
        system: &mut D,
        cost: &TrackingCost<S, NX, NU>,
        x0: &[S; NX],
        references: &[[S; NX]; N],
        final_reference: &[S; NX],
        alpha: Option<S>,
    ) -> Result<(S, [S; NX])> {
        let mut x = *x0;
        let mut total = S::ZERO;
        for t in 0..N {
            let mut u = self.controls[t];
            if let Some(alpha) = alpha {
                for (i, ui) in u.iter_mut().enumerate() {
                    *ui += alpha * self.feedforward[t][i];
                    for j in 0..NX {
                        *ui += self.feedback[t][i][j] * (x[j] - self.states[t][j]);
                    }
                }
            }
            for ((ui, lo), hi) in u.iter_mut().zip(&self.u_min).zip(&self.u_max) {
                *ui = ui.max(*lo).min(*hi);
            }
            total += cost.stage(&x, &references[t], &u);
            self.trial[t] = u;
            self.trial_states[t] = x;
            x = system.step(&x, &u)?;
        }
        total += cost.last(&x, final_reference);
        Ok((total, x))
    }

    /// The feedforward and feedback gains from the quadratic model of the
    /// cost-to-go, last stage first.
    fn backward_pass(
        &mut self,
        cost: &TrackingCost<S, NX, NU>,
        references: &[[S; NX]; N],
        final_reference: &[S; NX],
    ) -> core::result::Result<(), IlqrError> {
        // V_x and V_xx at the end of the horizon.
        let mut v_x: [S; NX] =
            core::array::from_fn(|k| cost.terminal[k] * (self.final_state[k] - final_reference[k]));
        let mut v_xx = [[S::ZERO; NX]; NX];
        for k in 0..NX {
            v_xx[k][k] = cost.terminal[k];
        }
        for t in (0..N).rev() {
            let (a, b) = (&self.a[t], &self.b[t]);
            let (x, u) = (&self.states[t], &self.controls[t]);
            // V_xx A and V_xx B, then the Q function's derivatives.
            let va: [[S; NX]; NX] = core::array::from_fn(|i| {
                core::array::from_fn(|j| (0..NX).fold(S::ZERO, |s, k| s + v_xx[i][k] * a[k][j]))
            });
            let vb: [[S; NU]; NX] = core::array::from_fn(|i| {
                core::array::from_fn(|j| (0..NX).fold(S::ZERO, |s, k| s + v_xx[i][k] * b[k][j]))
            });
            let q_x: [S; NX] = core::array::from_fn(|j| {
                cost.state[j] * (x[j] - references[t][j])
                    + (0..NX).fold(S::ZERO, |s, k| s + a[k][j] * v_x[k])
            });
            let q_u: [S; NU] = core::array::from_fn(|j| {
                cost.control[j] * u[j] + (0..NX).fold(S::ZERO, |s, k| s + b[k][j] * v_x[k])
            });
            let mut q_xx: [[S; NX]; NX] = core::array::from_fn(|i| {
                core::array::from_fn(|j| (0..NX).fold(S::ZERO, |s, k| s + a[k][i] * va[k][j]))
            });
            for k in 0..NX {
                q_xx[k][k] += cost.state[k];
            }
            let mut q_uu: [[S; NU]; NU] = core::array::from_fn(|i| {
                core::array::from_fn(|j| (0..NX).fold(S::ZERO, |s, k| s + b[k][i] * vb[k][j]))
            });
            for k in 0..NU {
                q_uu[k][k] += cost.control[k] + self.regularization;
            }
            let q_ux: [[S; NX]; NU] = core::array::from_fn(|i| {
                core::array::from_fn(|j| (0..NX).fold(S::ZERO, |s, k| s + b[k][i] * va[k][j]))
            });
            // k = −Q_uu⁻¹ Q_u, K = −Q_uu⁻¹ Q_ux.
            let q_uu_plain = q_uu;
            cholesky_in_place(&mut q_uu, NU, 0.0)
                .map_err(|_| IlqrError::NotPositiveDefinite { stage: t })?;
            let mut k = q_u.map(|x| -x);
            cholesky_solve(&q_uu, NU, &mut k)?;
            let mut gain = [[S::ZERO; NX]; NU];
            for j in 0..NX {
                let mut column: [S; NU] = core::array::from_fn(|i| -q_ux[i][j]);
                cholesky_solve(&q_uu, NU, &mut column)?;
                for i in 0..NU {
                    gain[i][j] = column[i];
                }
            }
            // V_x = Q_x + Kᵀ Q_uu k + Kᵀ Q_u + Q_uxᵀ k, V_xx likewise.
            for i in 0..NX {
                let mut s = q_x[i];
                for r in 0..NU {
                    let quu_k = (0..NU).fold(S::ZERO, |acc, c| acc + q_uu_plain[r][c] * k[c]);
                    s += gain[r][i] * (quu_k + q_u[r]) + q_ux[r][i] * k[r];
                }
                v_x[i] = s;
            }
            for i in 0..NX {
                for j in 0..NX {
                    let mut s = q_xx[i][j];
                    for r in 0..NU {
                        let quu_k =
                            (0..NU).fold(S::ZERO, |acc, c| acc + q_uu_plain[r][c] * gain[c][j]);
                        s += gain[r][i] * (quu_k + q_ux[r][j]) + q_ux[r][i] * gain[r][j];
                    }
                    v_xx[i][j] = s;
                }
            }
            // Keep V_xx symmetric against rounding.
            for i in 0..NX {
                for j in 0..i {
                    let m = S::from_f64(0.5) * (v_xx[i][j] + v_xx[j][i]);
                    v_xx[i][j] = m;
                    v_xx[j][i] = m;
                }
            }
            self.feedforward[t] = k;
            self.feedback[t] = gain;
        }
        Ok(())
    }
}
