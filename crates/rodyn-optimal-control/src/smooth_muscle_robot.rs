//! The muscle robot with smooth muscles: the same two links, paths and
//! muscle strengths as [`crate::muscle_robot`], each Thelen (2003) muscle
//! replaced by a [`DeGrooteMuscle`] (De Groote et al. 2016) with the same
//! maximum force, optimal fibre length and tendon slack length. Its
//! dynamics are infinitely differentiable in the state and the controls,
//! so IPOPT's Newton steps see a Hessian that does not jump.
//!
//! Derivatives:
//! * `A = ∂f/∂x`, `B = ∂f/∂u` analytically, as the Thelen robot's analytic
//!   route: `∂q̈/∂(q, q̇)` by [`aba_derivatives_with_drives`] (Carpentier
//!   & Mansard's rigid-body derivatives, the paths' gradients and
//!   Hessians, the muscles' tension partials), `∂q̈/∂a` by one extra
//!   articulated-body pass per muscle (the sensitivity of
//!   [`rodyn::sensitivity`]), `∂ȧ/∂(u, a)` in closed form
//!   ([`DeGrooteParameters::activation_rate_partials`]);
//! * the second derivatives `∇²(μᵀ f)` for the exact Hessian of the
//!   Lagrangian by running that same analytic code on dual numbers: one
//!   pass per state direction `(q, q̇, a)` differentiates every entry of
//!   `A` and `B` exactly (forward mode over exact first derivatives), and
//!   the controls, which enter only the activation dynamics, by dual
//!   numbers through those alone.

use crate::collocation::{Dynamics, Node, Trapezoidal};
use crate::ipopt::{solve, Options, Solution};
use crate::muscle_robot::{
    excitation_of, join, replay, rigid_body_rows, split, Derivatives, Replay, Task, NX,
};
use rodyn::algorithm::derivatives::DerivativeData;
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::algorithm::jacobian::JacobianData;
use rodyn::drive::{
    aba_derivatives_with_drives, drive_forces, forward_dynamics_with_drives, DeGrooteMuscle,
    DeGrooteParameters, DriveDerivatives,
};
use rodyn::planar::Planar;
use rodyn::sensitivity::forward_dynamics_and_sensitivity;
use rodyn::sim::AuxiliaryLoads;
use rodyn::space::Geometry;
use rodyn::{Data, Dual, Scalar};
use rodyn_scenarios::muscle_robot::{
    self as robot, RobotData, RobotForces, RobotLoads, RobotModel, NB, NU, NV,
};

/// The robot's four smooth muscles, in input order.
pub type SmoothMuscles<S> = [DeGrooteMuscle<S, Planar, 3>; NU];

/// The robot's muscles as De Groote (2016) muscles: each Thelen muscle's
/// path, maximum isometric force, optimal fibre length, tendon slack
/// length and pennation with De Groote's curves and time constants.
#[must_use]
pub fn smooth_muscles<S: Scalar>() -> SmoothMuscles<S> {
    robot::MUSCLES_F64.map(|m| {
        let p = m.params;
        let params = DeGrooteParameters::<f64>::de_groote_2016(
            p.max_isometric_force,
            p.optimal_fiber_length,
            p.tendon_slack_length,
            p.pennation_angle_at_optimal,
        );
        DeGrooteMuscle::new(m.path, params, m.input).cast()
    })
}

/// Activation rates `ȧ` (1/s) of the four smooth muscles.
///
/// # Errors
/// The first muscle's error from
/// [`DeGrooteParameters::activation_rate`](rodyn::drive::DeGrooteParameters::activation_rate)
/// (a non-finite excitation or activation).
pub fn activation_rates<S: Scalar>(
    muscles: &SmoothMuscles<S>,
    excitation: &[S; NU],
    activation: &[S; NU],
) -> rodyn::Result<[S; NU]> {
    let mut rates = [S::ZERO; NU];
    for (k, rate) in rates.iter_mut().enumerate() {
        *rate = muscles[k].activation_rate(excitation[k], activation[k])?;
    }
    Ok(rates)
}

/// What one evaluation of the analytic Jacobians needs, in one scalar type.
struct Workspace<S: Scalar> {
    model: RobotModel<S>,
    muscles: SmoothMuscles<S>,
    data: RobotData<S>,
    forces: RobotForces<S>,
    derivatives: Box<DerivativeData<S, NB, NV, Planar>>,
    jacobians: Box<JacobianData<S, NV, Planar>>,
    drive: Box<DriveDerivatives<S, NV>>,
}

impl<S: Scalar> Workspace<S> {
    fn new() -> rodyn::Result<Self> {
        Ok(Self {
            model: robot::model()?,
            muscles: smooth_muscles(),
            data: Data::new(),
            forces: RobotForces::new(),
            derivatives: Box::default(),
            jacobians: Box::default(),
            drive: Box::default(),
        })
    }

    /// `f(x, u)`.
    fn rate(&mut self, x: &[S; NX], u: &[S; NU]) -> rodyn::Result<[S; NX]> {
        let (q, v, a) = split(x);
        let q_ddot = *forward_dynamics_with_drives::<Aba, _, _, _, NB, NV, NV>(
            &self.model,
            &mut self.data,
            &q,
            &v,
            &[S::ZERO; NV],
            &self.muscles,
            &a,
            &mut self.forces,
        )?;
        Ok(join(&v, &q_ddot, &activation_rates(&self.muscles, u, &a)?))
    }

    /// `f`, `A = ∂f/∂x` and `B = ∂f/∂u` from rodyn's analytic derivatives.
    fn rate_and_jacobians(
        &mut self,
        x: &[S; NX],
        u: &[S; NU],
        a_out: &mut [[S; NX]; NX],
        b_out: &mut [[S; NU]; NX],
    ) -> rodyn::Result<[S; NX]> {
        let (q, v, act) = split(x);
        aba_derivatives_with_drives(
            &self.model,
            &mut self.data,
            &mut self.derivatives,
            &mut self.jacobians,
            &mut self.drive,
            &q,
            &v,
            &[S::ZERO; NV],
            &self.muscles,
            &act,
        )?;
        let mut dq_ddot_da = [[S::ZERO; NU]; NV];
        let q_ddot = *forward_dynamics_and_sensitivity(
            &self.model,
            &mut self.data,
            &q,
            &v,
            &[S::ZERO; NV],
            &self.muscles,
            &act,
            &mut self.forces,
            &mut dq_ddot_da,
        )?;
        *b_out = [[S::ZERO; NU]; NX];
        rigid_body_rows(a_out, &self.derivatives, &dq_ddot_da);
        let mut a_dot = [S::ZERO; NU];
        for k in 0..NU {
            let (rate, d_du, d_da) = self.muscles[k]
                .params
                .activation_rate_partials(u[k], act[k])?;
            a_dot[k] = rate;
            b_out[2 * NV + k][k] = d_du;
            a_out[2 * NV + k][2 * NV + k] = d_da;
        }
        Ok(join(&v, &q_ddot, &a_dot))
    }
}

/// The smooth-muscle robot as a controlled system for [`Trapezoidal`],
/// with analytic Jacobians and exact second derivatives.
pub struct SmoothMuscleRobot {
    real: Workspace<f64>,
    dual: Workspace<Dual>,
    /// Evaluations of `f`, of its Jacobians and of its second derivatives
    /// so far.
    pub evaluations: usize,
}

impl SmoothMuscleRobot {
    /// The robot.
    ///
    /// # Errors
    /// None for this model; the `Result` is that of casting it to [`Dual`].
    pub fn new() -> rodyn::Result<Self> {
        Ok(Self {
            real: Workspace::new()?,
            dual: Workspace::new()?,
            evaluations: 0,
        })
    }

    /// `∇²(μᵀ f)` at `(x, u)` (side `NX + NU`, rows and columns in
    /// `(x, u)` order), exact to rounding.
    ///
    /// # Errors
    /// As the dynamics (a rodyn error).
    pub fn second_derivatives(
        &mut self,
        x: &[f64; NX],
        u: &[f64; NU],
        mu: &[f64; NX],
    ) -> rodyn::Result<Vec<Vec<f64>>> {
        let n = NX + NU;
        let mut hessian = vec![vec![0.0; n]; n];
        // Along each state direction m: d/dz_m of every entry of [A B],
        // weighted by μ, is row m of the Hessian.
        for (m, row) in hessian.iter_mut().enumerate().take(NX) {
            let xd: [Dual; NX] = core::array::from_fn(|i| Dual {
                re: x[i],
                du: f64::from(u8::from(i == m)),
            });
            let ud: [Dual; NU] = u.map(Dual::constant);
            let (mut a, mut b) = ([[Dual::ZERO; NX]; NX], [[Dual::ZERO; NU]; NX]);
            self.dual.rate_and_jacobians(&xd, &ud, &mut a, &mut b)?;
            for (i, weight) in mu.iter().enumerate() {
                let entries = a[i].iter().chain(&b[i]);
                for (slot, entry) in row.iter_mut().zip(entries) {
                    *slot += weight * entry.du;
                }
            }
        }
        // The controls enter only the activation dynamics: ∂²ȧ_k/∂u_k∂(u_k, a_k).
        for k in 0..NU {
            let params = &self.dual.muscles[k].params;
            let a_k = Dual::constant(x[2 * NV + k]);
            let u_k = Dual { re: u[k], du: 1.0 };
            let (_, d_du, d_da) = params.activation_rate_partials(u_k, a_k)?;
            let weight = mu[2 * NV + k];
            hessian[NX + k][NX + k] += weight * d_du.du;
            hessian[NX + k][2 * NV + k] += weight * d_da.du;
        }
        Ok(hessian)
    }
}

impl Dynamics<NX, NU> for SmoothMuscleRobot {
    fn rate(&mut self, _t: f64, x: &[f64; NX], u: &[f64; NU]) -> Option<[f64; NX]> {
        self.evaluations += 1;
        self.real.rate(x, u).ok()
    }

    fn rate_and_jacobians(
        &mut self,
        _t: f64,
        x: &[f64; NX],
        u: &[f64; NU],
        a: &mut [[f64; NX]; NX],
        b: &mut [[f64; NU]; NX],
    ) -> Option<[f64; NX]> {
        self.evaluations += 1;
        self.real.rate_and_jacobians(x, u, a, b).ok()
    }

    fn weighted_second_derivatives(
        &mut self,
        _t: f64,
        x: &[f64; NX],
        u: &[f64; NU],
        mu: &[f64; NX],
    ) -> Option<Vec<Vec<f64>>> {
        self.evaluations += 1;
        self.second_derivatives(x, u, mu).ok()
    }
}

impl Task {
    /// The collocation problem of [`Task::transcribe`] on the smooth-muscle
    /// robot.
    ///
    /// # Errors
    /// As [`SmoothMuscleRobot::new`].
    pub fn transcribe_smooth(&self) -> rodyn::Result<Trapezoidal<SmoothMuscleRobot, NX, NU>> {
        Ok(self.transcribe_with(SmoothMuscleRobot::new()?))
    }
}

/// The smooth muscles under an excitation pattern, as loads with the
/// activations as auxiliary states for `rodyn::sim`'s integrators.
pub struct SmoothLoads<E> {
    muscles: SmoothMuscles<f64>,
    excitation: E,
    forces: RobotForces<f64>,
}

impl<E: FnMut(f64) -> [f64; NU]> SmoothLoads<E> {
    /// The robot's smooth muscles driven by `excitation(t)`.
    pub fn new(excitation: E) -> Self {
        Self {
            muscles: smooth_muscles(),
            excitation,
            forces: RobotForces::new(),
        }
    }
}

impl<E: FnMut(f64) -> [f64; NU]> AuxiliaryLoads<f64, NB, NV, NV, NU, Planar> for SmoothLoads<E> {
    fn loads_and_rates(
        &mut self,
        model: &RobotModel<f64>,
        data: &mut RobotData<f64>,
        t: f64,
        q: &[f64; NV],
        v: &[f64; NV],
        activation: &[f64; NU],
        tau: &mut [f64; NV],
        f_ext: &mut [<Planar as Geometry>::Force<f64>; NB],
        activation_rate: &mut [f64; NU],
    ) -> rodyn::Result<()> {
        drive_forces(
            model,
            data,
            q,
            v,
            &self.muscles,
            activation,
            &mut self.forces,
        )?;
        for (total, muscle) in tau.iter_mut().zip(&self.forces.tau) {
            *total += *muscle;
        }
        for (total, muscle) in f_ext.iter_mut().zip(&self.forces.f_ext) {
            *total += *muscle;
        }
        *activation_rate = activation_rates(&self.muscles, &(self.excitation)(t), activation)?;
        Ok(())
    }
}

/// [`crate::muscle_robot::resimulate`] for the smooth muscles: RK4 at
/// step `dt` from the first node's state under the excitations of `nodes`
/// (linear between nodes).
///
/// # Errors
/// When the simulation fails (a rodyn error).
pub fn resimulate_smooth(task: &Task, nodes: &[Node<NX, NU>], dt: f64) -> rodyn::Result<Replay> {
    let mut loads = SmoothLoads::new(excitation_of(nodes));
    replay(task, nodes, dt, &mut loads)
}

/// Largest defect a certified solution may leave (IPOPT's
/// `constr_viol_tol`).
pub const MAX_DEFECT: f64 = 1e-8;
/// Largest RMS angle error (rad) of a certified solution's controls
/// replayed by RK4.
pub const MAX_TRACKING_RMS: f64 = 1e-2;

/// One solve of the task and what it is worth.
#[derive(Clone, Debug)]
pub struct Solved {
    /// IPOPT's result.
    pub solution: Solution,
    /// The nodes of the final iterate.
    pub nodes: Vec<Node<NX, NU>>,
    /// The largest absolute defect.
    pub max_defect: f64,
    /// The RMS angle error of the controls replayed by RK4, rad.
    pub tracking_rms: f64,
    /// The largest angle error of that replay, rad.
    pub tracking_max: f64,
    /// The replay's `(t, q)`.
    pub resimulated: Vec<(f64, [f64; NV])>,
    /// Evaluations of the dynamics and their derivatives.
    pub evaluations: usize,
    /// How the constraint Jacobian was formed.
    pub jacobian: &'static str,
}

/// The error of a solve: IPOPT refused the problem, or the dynamics or
/// the replay failed at the solution.
pub type SolveError = Box<dyn std::error::Error>;

fn finish<D: Dynamics<NX, NU>>(
    problem: &mut Trapezoidal<D, NX, NU>,
    solution: Solution,
    replay: impl FnOnce(&[Node<NX, NU>]) -> rodyn::Result<Replay>,
    evaluations: impl FnOnce(&D) -> usize,
    jacobian: &'static str,
) -> Result<Solved, SolveError> {
    let max_defect = problem
        .max_defect(&solution.x)
        .ok_or("the dynamics cannot be evaluated at the solution")?;
    let nodes = problem.unpack(&solution.x);
    let run = replay(&nodes)?;
    Ok(Solved {
        solution,
        nodes,
        max_defect,
        tracking_rms: run.rms,
        tracking_max: run.max,
        resimulated: run.samples,
        evaluations: evaluations(&problem.dynamics),
        jacobian,
    })
}

/// Solves `task` on the smooth muscles (analytic Jacobians; the Hessian as
/// `task.hessian` says) and replays the controls by RK4 at step `dt`.
///
/// # Errors
/// As [`SolveError`].
pub fn solve_smooth(task: &Task, options: &Options, dt: f64) -> Result<Solved, SolveError> {
    let mut problem = task.transcribe_smooth()?;
    let solution = solve(&mut problem, options)?;
    finish(
        &mut problem,
        solution,
        |nodes| resimulate_smooth(task, nodes, dt),
        |d| d.evaluations,
        "analytic (rodyn's derivatives and sensitivities)",
    )
}

/// Solves `task` on the Thelen muscles with derivatives by `route` and
/// replays the controls by RK4 at step `dt`.
///
/// # Errors
/// As [`SolveError`].
pub fn solve_thelen(
    task: &Task,
    route: Derivatives,
    options: &Options,
    dt: f64,
) -> Result<Solved, SolveError> {
    let mut problem = task.transcribe(route)?;
    let solution = solve(&mut problem, options)?;
    let muscles = robot::MUSCLES_F64;
    finish(
        &mut problem,
        solution,
        |nodes| {
            let mut loads = RobotLoads::new(&muscles, excitation_of(nodes));
            replay(task, nodes, dt, &mut loads)
        },
        |d| d.evaluations,
        route.name(),
    )
}

/// Each muscle's share of the activation effort `∫ Σᵢ aᵢ² dt`
/// (trapezoidal, as the objective).
#[must_use]
pub fn effort_shares(nodes: &[Node<NX, NU>]) -> [f64; NU] {
    let h = nodes[1].t - nodes[0].t;
    let integrals: [f64; NU] = core::array::from_fn(|i| {
        nodes
            .iter()
            .enumerate()
            .map(|(k, n)| {
                let ends = k == 0 || k + 1 == nodes.len();
                let w = if ends { 0.5 } else { 1.0 };
                w * h * n.x[2 * NV + i] * n.x[2 * NV + i]
            })
            .sum()
    });
    let total: f64 = integrals.iter().sum();
    integrals.map(|i| i / total)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// States inside the bounds, away from nothing in particular: the
    /// smooth model has no switch to avoid.
    const STATES: [([f64; NX], [f64; NU]); 3] = [
        (
            [0.1, 0.3, 0.2, -0.5, 0.2, 0.3, 0.4, 0.5],
            [0.6, 0.1, 0.9, 0.2],
        ),
        (
            [0.5, 0.9, -1.0, 0.4, 0.05, 0.6, 0.1, 0.3],
            [0.3, 0.2, 0.5, 0.02],
        ),
        (
            [-0.2, 0.4, 0.0, 0.0, 0.5, 0.5, 0.5, 0.5],
            [0.5, 0.03, 0.7, 0.5],
        ),
    ];

    /// The analytic `A`, `B` against dual numbers through `f` (to
    /// rounding) and central differences of `f` (to their truncation).
    #[test]
    fn analytic_jacobians_match_dual_numbers_and_differences() {
        let mut robot = SmoothMuscleRobot::new().unwrap();
        for (n, (x, u)) in STATES.iter().enumerate() {
            let (mut a, mut b) = ([[0.0; NX]; NX], [[0.0; NU]; NX]);
            let f = robot.real.rate_and_jacobians(x, u, &mut a, &mut b).unwrap();
            let scale = a
                .iter()
                .flatten()
                .chain(b.iter().flatten())
                .fold(1.0_f64, |m, v| m.max(v.abs()));
            for j in 0..NX + NU {
                let unit = |i: usize| f64::from(u8::from(i == j));
                let xd: [Dual; NX] = core::array::from_fn(|i| Dual {
                    re: x[i],
                    du: unit(i),
                });
                let ud: [Dual; NU] = core::array::from_fn(|i| Dual {
                    re: u[i],
                    du: unit(NX + i),
                });
                let column = robot.dual.rate(&xd, &ud).unwrap();
                let h = 1e-6;
                let (mut xp, mut up, mut xm, mut um) = (*x, *u, *x, *u);
                if j < NX {
                    xp[j] += h;
                    xm[j] -= h;
                } else {
                    up[j - NX] += h;
                    um[j - NX] -= h;
                }
                let plus = robot.real.rate(&xp, &up).unwrap();
                let minus = robot.real.rate(&xm, &um).unwrap();
                for i in 0..NX {
                    let analytic = if j < NX { a[i][j] } else { b[i][j - NX] };
                    let dual = column[i].du;
                    let difference = (plus[i] - minus[i]) / (2.0 * h);
                    assert!((f[i] - column[i].re).abs() <= 1e-12 * scale);
                    assert!(
                        (analytic - dual).abs() <= 1e-11 * scale,
                        "state {n} ({i}, {j}): analytic {analytic} dual {dual}"
                    );
                    assert!(
                        (analytic - difference).abs() <= 1e-6 * scale,
                        "state {n} ({i}, {j}): analytic {analytic} difference {difference}"
                    );
                }
            }
        }
    }

    /// `∇²(μᵀ f)` against central differences of the analytic `μᵀ[A B]`,
    /// and symmetric.
    #[test]
    fn second_derivatives_match_differences_of_the_jacobians() {
        let mut robot = SmoothMuscleRobot::new().unwrap();
        let mu = [0.3, -1.2, 0.7, 0.4, -0.9, 1.1, 0.5, -0.6];
        for (n, (x, u)) in STATES.iter().enumerate() {
            let hessian = robot.second_derivatives(x, u, &mu).unwrap();
            let mut gradient = |x: &[f64; NX], u: &[f64; NU]| -> Vec<f64> {
                let (mut a, mut b) = ([[0.0; NX]; NX], [[0.0; NU]; NX]);
                robot.real.rate_and_jacobians(x, u, &mut a, &mut b).unwrap();
                (0..NX + NU)
                    .map(|j| {
                        (0..NX)
                            .map(|i| mu[i] * if j < NX { a[i][j] } else { b[i][j - NX] })
                            .sum()
                    })
                    .collect()
            };
            let scale = hessian
                .iter()
                .flatten()
                .fold(1.0_f64, |m, v| m.max(v.abs()));
            for m in 0..NX + NU {
                let h = 1e-6;
                let (mut xp, mut up, mut xm, mut um) = (*x, *u, *x, *u);
                if m < NX {
                    xp[m] += h;
                    xm[m] -= h;
                } else {
                    up[m - NX] += h;
                    um[m - NX] -= h;
                }
                let (plus, minus) = (gradient(&xp, &up), gradient(&xm, &um));
                for j in 0..NX + NU {
                    let difference = (plus[j] - minus[j]) / (2.0 * h);
                    assert!(
                        (hessian[m][j] - difference).abs() <= 1e-6 * scale,
                        "state {n} ({m}, {j}): {} against {difference}",
                        hessian[m][j]
                    );
                    assert!(
                        (hessian[m][j] - hessian[j][m]).abs() <= 1e-9 * scale,
                        "state {n}: not symmetric at ({m}, {j})"
                    );
                }
            }
        }
    }

    /// The transcription's exact Hessian of the Lagrangian against the one
    /// from central differences of the analytic Jacobians, on a short grid
    /// at a point and multipliers off the optimum.
    #[test]
    fn exact_hessian_of_the_lagrangian_matches_jacobian_differences() {
        use crate::collocation::Hessian;
        use crate::ipopt::Nlp;
        let task = Task {
            nodes: 5,
            ..Task::default()
        };
        let mut exact = task.transcribe_smooth().unwrap();
        exact.hessian = Hessian::Exact;
        let mut differences = task.transcribe_smooth().unwrap();
        differences.hessian = Hessian::JacobianDifferences;
        let (n, m) = (exact.variables(), exact.constraints());
        let mut z = vec![0.0; n];
        exact.initial_point(&mut z);
        for (i, value) in z.iter_mut().enumerate() {
            *value += 0.05 * (i as f64 * 0.7).sin();
        }
        let lambda: Vec<f64> = (0..m).map(|i| (i as f64 * 1.3).cos()).collect();
        let entries = exact.hessian_structure().unwrap();
        assert_eq!(Some(&entries), differences.hessian_structure().as_ref());
        let (mut a, mut b) = (vec![0.0; entries.len()], vec![0.0; entries.len()]);
        assert!(exact.hessian_values(&z, 0.8, &lambda, &mut a));
        assert!(differences.hessian_values(&z, 0.8, &lambda, &mut b));
        let scale = b.iter().fold(1.0_f64, |m, v| m.max(v.abs()));
        for (k, (x, y)) in a.iter().zip(&b).enumerate() {
            assert!(
                (x - y).abs() <= 1e-6 * scale,
                "entry {k} {:?}: exact {x} against differences {y} (scale {scale})",
                entries[k]
            );
        }
    }
}
