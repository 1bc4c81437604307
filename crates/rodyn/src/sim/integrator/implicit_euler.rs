//! Linearly implicit (backward) Euler for stiff springs, dampers and contacts.

use super::{check_time, commit, derivatives, Integrator};
use crate::algorithm::forward_dynamics::ForwardDynamics;
use crate::data::Data;
use crate::error::{Error, Quantity, Result};
use crate::model::Model;
use crate::sim::loads::AuxiliaryLoads;
use crate::sim::manifold::{displace, for_dynamics, ConfigurationRate, ConfigurationUpdate};
use crate::sim::state::State;
use crate::Scalar;

/// Backward Euler, linearised once per step (one Newton iteration, also
/// known as Rosenbrock-Euler), with the Jacobian by finite differences.
///
/// Backward Euler asks for `v₁ = v + dt a(q ⊕ v₁ dt, v₁, z₁)` and
/// `z₁ = z + dt ż(q ⊕ v₁ dt, v₁, z₁)`. Linearising `a` and `ż` about
/// `(q, v, z)` with `A_q = ∂a/∂q` (along the tangent space), `A_v = ∂a/∂v`,
/// `A_z = ∂a/∂z` and likewise `G_q`, `G_v`, `G_z` for `ż` gives one linear
/// system for `Δv = v₁ - v` and `Δz = z₁ - z`:
///
/// ```text
/// [ I - dt A_v - dt² A_q   -dt A_z     ] [Δv]   [dt (a₀ + dt A_q v)]
/// [ -dt G_v - dt² G_q      I - dt G_z  ] [Δz] = [dt (ż₀ + dt G_q v)]
/// ```
///
/// then `q₁ = q ⊕ v₁ dt`. For a linear system this is exactly backward
/// Euler: A-stable (and L-stable), so a stiff spring, contact or fast
/// auxiliary state (a muscle activation) does not limit the step; it damps
/// what it cannot resolve (energy is lost, not gained). First order.
///
/// The system is solved by blocks: `Δz` is eliminated through
/// `I - dt G_z` (the Schur complement), leaving an `NV x NV` system for
/// `Δv`. Without auxiliary states (`NZ = 0`) that is the whole system.
///
/// Cost per step: `2 NV + NZ + 1` evaluations of loads plus forward
/// dynamics (forward differences, step `√ε` in each coordinate, scaled to
/// `|v|` and `|z|`), an `NZ x NZ` elimination with `NV + 1` right-hand
/// sides and an `NV x NV` one (NV² scalars on the stack: 2.6 KB for
/// NV = 18 in f64). The loads are evaluated at time `t + dt`.
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
        let t1 = t + dt;
        let q_dyn = for_dynamics(model, self.update, &q);
        let (a0, zr0) = derivatives(&method, model, data, loads, t1, &q_dyn, &v, &z)?;
        let h_base = S::from_f64(S::EPSILON).sqrt();
        let dt2 = dt * dt;
        // The iteration matrix in four blocks (k_vv = I - dt A_v - dt² A_q,
        // k_vz = -dt A_z, k_zv = -dt G_v - dt² G_q, k_zz = I - dt G_z), built
        // column by column, and the right-hand sides dt (a₀ + dt A_q v) and
        // dt (ż₀ + dt G_q v).
        let mut k_vv = [[S::ZERO; NV]; NV];
        let mut k_vz = [[S::ZERO; NZ]; NV];
        let mut k_zv = [[S::ZERO; NV]; NZ];
        let mut k_zz = [[S::ZERO; NZ]; NZ];
        let mut rhs_v: [S; NV] = core::array::from_fn(|r| a0[r] * dt);
        let mut rhs_z: [S; NZ] = core::array::from_fn(|r| zr0[r] * dt);
        for col in 0..NV {
            // ∂/∂q along tangent direction `col` (through the exponential
            // map, so a quaternion stays on its manifold).
            let mut e = [S::ZERO; NV];
            e[col] = S::ONE;
            let q_pert = model.integrate_unvalidated(&q_dyn, &e, h_base);
            let (a_q, zr_q) = derivatives(&method, model, data, loads, t1, &q_pert, &v, &z)?;
            // ∂/∂v along coordinate `col`, with a step scaled to |v|.
            let h_v = h_base * S::ONE.max(v[col].abs());
            let mut v_pert = v;
            v_pert[col] += h_v;
            let (a_v, zr_v) = derivatives(&method, model, data, loads, t1, &q_dyn, &v_pert, &z)?;
            for r in 0..NV {
                let d_aq = (a_q[r] - a0[r]) / h_base;
                let d_av = (a_v[r] - a0[r]) / h_v;
                k_vv[r][col] = -(dt * d_av + dt2 * d_aq);
                rhs_v[r] += dt2 * d_aq * v[col];
            }
            for r in 0..NZ {
                let d_gq = (zr_q[r] - zr0[r]) / h_base;
                let d_gv = (zr_v[r] - zr0[r]) / h_v;
                k_zv[r][col] = -(dt * d_gv + dt2 * d_gq);
                rhs_z[r] += dt2 * d_gq * v[col];
            }
            k_vv[col][col] += S::ONE;
        }
        for col in 0..NZ {
            // ∂/∂z along coordinate `col`, with a step scaled to |z|.
            let h_z = h_base * S::ONE.max(z[col].abs());
            let mut z_pert = z;
            z_pert[col] += h_z;
            let (a_z, zr_z) = derivatives(&method, model, data, loads, t1, &q_dyn, &v, &z_pert)?;
            for r in 0..NV {
                k_vz[r][col] = -dt * (a_z[r] - a0[r]) / h_z;
            }
            for r in 0..NZ {
                k_zz[r][col] = -dt * (zr_z[r] - zr0[r]) / h_z;
            }
            k_zz[col][col] += S::ONE;
        }
        let (dv, dz) = solve_by_blocks(k_vv, k_vz, k_zv, k_zz, rhs_v, rhs_z)?;
        let v_next: [S; NV] = core::array::from_fn(|k| v[k] + dv[k]);
        let next = State {
            t: t1,
            q: displace(model, self.update, &q, &v_next, dt),
            v: v_next,
            z: core::array::from_fn(|k| z[k] + dz[k]),
        };
        commit(state, next)
    }
}

/// Solves the block system `[k_vv k_vz; k_zv k_zz] [x_v; x_z] = [b_v; b_z]`
/// by eliminating `x_z`: with `W = k_zz⁻¹ k_zv` (`big_w`) and
/// `w = k_zz⁻¹ b_z`, `(k_vv - k_vz W) x_v = b_v - k_vz w`, then
/// `x_z = w - W x_v`.
///
/// `k_zz = I - dt G_z` is the auxiliary states' own iteration matrix, well
/// conditioned whenever their dynamics are stable, so eliminating through
/// it first loses little to the missing cross-block pivoting. With
/// `NZ = 0` every `z` loop is empty and this is one `NV x NV` solve.
///
/// # Errors
/// As [`solve_in_place`]: a zero pivot of `k_zz` names index `NV + k`,
/// after the accelerations.
fn solve_by_blocks<S: Scalar, const NV: usize, const NZ: usize>(
    mut k_vv: [[S; NV]; NV],
    k_vz: [[S; NZ]; NV],
    k_zv: [[S; NV]; NZ],
    mut k_zz: [[S; NZ]; NZ],
    b_v: [S; NV],
    b_z: [S; NZ],
) -> Result<([S; NV], [S; NZ])> {
    // Eliminate x_z: k_zz W = k_zv and k_zz w = b_z in one factorisation.
    let mut big_w = k_zv;
    let mut w = b_z;
    solve_in_place(&mut k_zz, &mut big_w, &mut w, NV)?;
    let mut x_v = b_v;
    for r in 0..NV {
        for k in 0..NZ {
            x_v[r] -= k_vz[r][k] * w[k];
            for c in 0..NV {
                k_vv[r][c] -= k_vz[r][k] * big_w[k][c];
            }
        }
    }
    solve_in_place(&mut k_vv, &mut [[S::ZERO; 0]; NV], &mut x_v, 0)?;
    let x_z: [S; NZ] = core::array::from_fn(|r| {
        let mut x = w[r];
        for c in 0..NV {
            x -= big_w[r][c] * x_v[c];
        }
        x
    });
    Ok((x_v, x_z))
}

/// Solves `K X = C` (`M` columns) and `K x = b` together by Gaussian
/// elimination with partial pivoting, destroying `K` and leaving `X` in
/// `columns` and `x` in `b`.
///
/// # Errors
/// [`Error::NonFinite`] for the acceleration coordinate (`first_index` plus
/// the column) whose pivot is zero or not finite: the solution would be
/// infinite there. This happens only when `dt` times an unstable eigenvalue
/// of the dynamics equals one.
fn solve_in_place<S: Scalar, const N: usize, const M: usize>(
    k: &mut [[S; N]; N],
    columns: &mut [[S; M]; N],
    b: &mut [S; N],
    first_index: usize,
) -> Result<()> {
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
                index: first_index + c,
            });
        }
        k.swap(c, pivot_row);
        columns.swap(c, pivot_row);
        b.swap(c, pivot_row);
        let inv = S::ONE / pivot;
        for r in c + 1..N {
            let factor = k[r][c] * inv;
            if factor != S::ZERO {
                for j in c..N {
                    let kcj = k[c][j];
                    k[r][j] -= factor * kcj;
                }
                for m in 0..M {
                    let ccm = columns[c][m];
                    columns[r][m] -= factor * ccm;
                }
                let bc = b[c];
                b[r] -= factor * bc;
            }
        }
    }
    for r in (0..N).rev() {
        for m in 0..M {
            let mut s = columns[r][m];
            for j in r + 1..N {
                s -= k[r][j] * columns[j][m];
            }
            columns[r][m] = s / k[r][r];
        }
        let mut s = b[r];
        for j in r + 1..N {
            s -= k[r][j] * b[j];
        }
        b[r] = s / k[r][r];
    }
    Ok(())
}
