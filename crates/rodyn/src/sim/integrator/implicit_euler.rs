//! Linearly implicit (backward) Euler for stiff springs, dampers and contacts.

use super::{acceleration, commit, Integrator};
use crate::algorithm::forward_dynamics::ForwardDynamics;
use crate::data::Data;
use crate::error::{Error, Quantity, Result};
use crate::model::Model;
use crate::sim::loads::Loads;
use crate::sim::manifold::{displace, for_dynamics, ConfigurationRate, ConfigurationUpdate};
use crate::sim::state::State;
use crate::Scalar;

/// Backward Euler, linearised once per step (one Newton iteration, also
/// known as Rosenbrock-Euler), with the Jacobian by finite differences.
///
/// Backward Euler asks for `v₁ = v + dt a(q ⊕ v₁ dt, v₁)`. Linearising `a`
/// about `(q, v)` with `A_q = ∂a/∂q` (along the tangent space) and
/// `A_v = ∂a/∂v` gives one linear system for `Δv = v₁ - v`:
///
/// `(I - dt A_v - dt² A_q) Δv = dt (a₀ + dt A_q v)`,
///
/// then `q₁ = q ⊕ v₁ dt`. For a linear system this is exactly backward
/// Euler: A-stable (and L-stable), so a stiff spring or contact does not
/// limit the step; it damps what it cannot resolve (energy is lost, not
/// gained). First order.
///
/// Cost per step: `2 NV + 1` evaluations of loads plus forward dynamics
/// (forward differences, step `√ε` in each coordinate) and an `NV x NV`
/// Gaussian elimination (NV² scalars on the stack: 2.6 KB for NV = 18 in
/// f64). The loads are evaluated at time `t + dt`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImplicitEuler {
    /// How `q` moves (default: the exponential map).
    pub update: ConfigurationUpdate,
}

impl Default for ImplicitEuler {
    fn default() -> Self {
        Self {
            update: ConfigurationUpdate::ExponentialMap,
        }
    }
}

impl Integrator for ImplicitEuler {
    const NAME: &'static str = "implicit-euler";

    fn step<F, L, S, const NB: usize, const NQ: usize, const NV: usize, G>(
        &mut self,
        method: F,
        model: &Model<S, NB, NQ, NV, G>,
        data: &mut Data<S, NB, NV, G>,
        state: &mut State<S, NQ, NV>,
        dt: S,
        loads: &mut L,
    ) -> Result<()>
    where
        F: ForwardDynamics,
        L: Loads<S, NB, NQ, NV, G>,
        S: Scalar,
        G: ConfigurationRate,
    {
        let State { t, q, v } = *state;
        let t1 = t + dt;
        let q_dyn = for_dynamics(model, self.update, &q);
        let a0 = acceleration(&method, model, data, loads, t1, &q_dyn, &v)?;
        let h_base = S::from_f64(S::EPSILON).sqrt();
        let dt2 = dt * dt;
        // Iteration matrix K = I - dt A_v - dt² A_q, built column by column,
        // and the right-hand side dt (a₀ + dt A_q v).
        let mut k_mat = [[S::ZERO; NV]; NV];
        let mut rhs: [S; NV] = core::array::from_fn(|r| a0[r] * dt);
        for col in 0..NV {
            // ∂a/∂q along tangent direction `col` (through the exponential
            // map, so a quaternion stays on its manifold).
            let mut e = [S::ZERO; NV];
            e[col] = S::ONE;
            let q_pert = model.integrate(&q_dyn, &e, h_base);
            let a_q = acceleration(&method, model, data, loads, t1, &q_pert, &v)?;
            // ∂a/∂v along coordinate `col`, with a step scaled to |v|.
            let h_v = h_base * S::ONE.max(v[col].abs());
            let mut v_pert = v;
            v_pert[col] += h_v;
            let a_v = acceleration(&method, model, data, loads, t1, &q_dyn, &v_pert)?;
            for r in 0..NV {
                let d_aq = (a_q[r] - a0[r]) / h_base;
                let d_av = (a_v[r] - a0[r]) / h_v;
                k_mat[r][col] = -(dt * d_av + dt2 * d_aq);
                rhs[r] += dt2 * d_aq * v[col];
            }
            k_mat[col][col] += S::ONE;
        }
        let dv = solve_in_place(&mut k_mat, rhs)?;
        let v_next: [S; NV] = core::array::from_fn(|k| v[k] + dv[k]);
        let next = State {
            t: t1,
            q: displace(model, self.update, &q, &v_next, dt),
            v: v_next,
        };
        commit(state, next)
    }
}

/// Solves `K x = b` by Gaussian elimination with partial pivoting,
/// destroying `K`.
///
/// # Errors
/// [`Error::NonFinite`] for the acceleration coordinate whose pivot is zero
/// or not finite: the solution would be infinite there. This happens only
/// when `dt` times an unstable eigenvalue of the dynamics equals one.
fn solve_in_place<S: Scalar, const N: usize>(k: &mut [[S; N]; N], mut b: [S; N]) -> Result<[S; N]> {
    let mut scale = 0.0f64;
    for row in k.iter() {
        for x in row {
            scale = scale.max(x.to_f64().abs());
        }
    }
    let tiny = scale * S::EPSILON;
    for c in 0..N {
        let mut pivot_row = c;
        for r in c + 1..N {
            if k[r][c].abs() > k[pivot_row][c].abs() {
                pivot_row = r;
            }
        }
        let pivot = k[pivot_row][c];
        if !pivot.is_finite() || pivot.abs().to_f64() <= tiny {
            return Err(Error::NonFinite {
                quantity: Quantity::Acceleration,
                index: c,
            });
        }
        k.swap(c, pivot_row);
        b.swap(c, pivot_row);
        let inv = S::ONE / pivot;
        for r in c + 1..N {
            let factor = k[r][c] * inv;
            if factor != S::ZERO {
                for j in c..N {
                    let kcj = k[c][j];
                    k[r][j] -= factor * kcj;
                }
                let bc = b[c];
                b[r] -= factor * bc;
            }
        }
    }
    for r in (0..N).rev() {
        let mut s = b[r];
        for j in r + 1..N {
            s -= k[r][j] * b[j];
        }
        b[r] = s / k[r][r];
    }
    Ok(b)
}
