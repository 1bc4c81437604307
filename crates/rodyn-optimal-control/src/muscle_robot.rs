//! The optimal-control problem of Friedmann, Wojtusch & von Stryk (PAMM):
//! the two-link, four-muscle robot ([`rodyn_scenarios::muscle_robot`])
//! follows desired joint trajectories with the least muscle effort. This
//! module holds the task, its transcription and the robot on its Thelen
//! muscles; [`crate::smooth_muscle_robot`] the robot on smooth ones.
//!
//! State `x = (q₁, q₂, q̇₁, q̇₂, a₁ … a₄)` (rad, rad/s, activations in
//! `[0, 1]`), control `u = (u₁ … u₄)`, the muscle excitations in `[0, 1]`:
//!
//! ```text
//! ẋ = f(x, u) = (q̇,  q̈(q, q̇, a),  ȧ(u, a)),
//! ```
//!
//! `q̈` from rodyn's articulated-body forward dynamics with the muscle
//! forces, `ȧ` Thelen's (2003) first-order activation dynamics. The joint
//! angles are held to the desired trajectory at every node (equality
//! bounds), the robot starts at rest, and the objective is the muscle
//! effort measured by the activations, with a small penalty on how fast
//! the excitations change:
//!
//! ```text
//! J = ∫ Σᵢ aᵢ² dt + r Σᵢ ∫ u̇ᵢ² dt,   r = 10⁻³ s².
//! ```
//!
//! The paper asks for "energy-minimal" controls without a formula. Squared
//! activations are a common effort measure of muscle optimal control
//! (Crowninshield & Brand 1981 sum squared stresses; activations squared
//! or cubed are used by e.g. Anderson & Pandy 2001). The obvious
//! alternative, `∫ Σ uᵢ² dt` on the excitations, has no smooth minimiser
//! with Thelen's activation dynamics: activation is about four times
//! faster than deactivation, so switching an excitation between 0 and a
//! little above the activation holds the same activation for about 0.6 of
//! the cost of a steady excitation, and the solver chatters between nodes
//! (seen with this model: excitations alternating node by node at every
//! grid tried). The rate penalty `r` rules that out at a few per cent of
//! the objective. It also fixes the trapezoidal rule's one free direction
//! per muscle: each interval's activation defect involves the excitations
//! at both its ends, so an excitation alternating node by node is
//! invisible to the activation term.
//!
//! The state Jacobians `A = ∂f/∂x`, `B = ∂f/∂u` come by one of three
//! routes ([`Derivatives`]), compared by the example in one run.

use crate::collocation::{Dynamics, Hessian, Node, NodeBounds, Trapezoidal, Weights};
use rodyn::algorithm::derivatives::DerivativeData;
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::algorithm::jacobian::JacobianData;
use rodyn::drive::{aba_derivatives_with_drives, DriveDerivatives};
use rodyn::planar::Planar;
use rodyn::sim::{AuxiliaryLoads, Integrator, Rk4};
use rodyn::{Data, Dual, Scalar};
use rodyn_scenarios::muscle_robot::{
    self as robot, activation_rates, RobotData, RobotForces, RobotLoads, RobotModel, RobotMuscles,
    NB, NU, NV,
};

/// Size of the state: joint angles, joint rates, activations.
pub const NX: usize = 2 * NV + NU;

/// How the state Jacobians `A = ∂f/∂x` and `B = ∂f/∂u` are computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Derivatives {
    /// rodyn's analytic derivatives: `∂q̈/∂(q, q̇)` of forward dynamics
    /// with the muscles (Carpentier & Mansard's for the rigid body, the
    /// paths' gradients and Hessians and the muscles' tension partials for
    /// the drives), the paper's sensitivity `∂q̈/∂a` (one extra
    /// articulated-body pass per muscle) and `∂ȧ/∂(u, a)` in closed form.
    Analytic,
    /// Forward-mode dual numbers through the whole of `f`: one pass per
    /// state and control, exact to rounding.
    Dual,
    /// Central finite differences of `f`, steps `10⁻⁶ max(1, |xⱼ|)`.
    FiniteDifference,
}

impl Derivatives {
    /// All three routes.
    pub const ALL: [Self; 3] = [Self::Analytic, Self::Dual, Self::FiniteDifference];

    /// A short name for tables and files.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Analytic => "analytic",
            Self::Dual => "dual",
            Self::FiniteDifference => "finite-difference",
        }
    }
}

/// The robot as a controlled system for [`Trapezoidal`].
pub struct MuscleRobot {
    route: Derivatives,
    model: RobotModel<f64>,
    muscles: RobotMuscles<f64>,
    data: RobotData<f64>,
    forces: RobotForces<f64>,
    derivatives: Box<DerivativeData<f64, NB, NV, Planar>>,
    jacobians: Box<JacobianData<f64, NV, Planar>>,
    drive: Box<DriveDerivatives<f64, NV>>,
    model_dual: RobotModel<Dual>,
    muscles_dual: RobotMuscles<Dual>,
    data_dual: RobotData<Dual>,
    forces_dual: RobotForces<Dual>,
    /// Evaluations of `f` and of its Jacobians so far.
    pub evaluations: usize,
}

impl MuscleRobot {
    /// The robot with its Jacobians by `route`.
    ///
    /// # Errors
    /// None for this model; the `Result` is that of casting it to [`Dual`].
    pub fn new(route: Derivatives) -> rodyn::Result<Self> {
        Ok(Self {
            route,
            model: robot::MODEL_F64,
            muscles: robot::MUSCLES_F64,
            data: Data::new(),
            forces: RobotForces::new(),
            derivatives: Box::default(),
            jacobians: Box::default(),
            drive: Box::default(),
            model_dual: robot::model()?,
            muscles_dual: robot::muscles(),
            data_dual: Data::new(),
            forces_dual: RobotForces::new(),
            evaluations: 0,
        })
    }

    /// `f(x, u)` in `f64`.
    fn f64_rate(&mut self, x: &[f64; NX], u: &[f64; NU]) -> rodyn::Result<[f64; NX]> {
        let (q, v, a) = split(x);
        let q_ddot = *robot::forward_dynamics(
            &self.model,
            &self.muscles,
            &mut self.data,
            &q,
            &v,
            &a,
            &mut self.forces,
        )?;
        Ok(join(&v, &q_ddot, &activation_rates(&self.muscles, u, &a)?))
    }

    /// `f` and its derivative along the direction `(dx, du)`, by one pass
    /// on dual numbers.
    fn dual_rate(
        &mut self,
        x: &[f64; NX],
        u: &[f64; NU],
        dx: &[f64; NX],
        du: &[f64; NU],
    ) -> rodyn::Result<[Dual; NX]> {
        let xd: [Dual; NX] = core::array::from_fn(|i| Dual {
            re: x[i],
            du: dx[i],
        });
        let ud: [Dual; NU] = core::array::from_fn(|i| Dual {
            re: u[i],
            du: du[i],
        });
        let (q, v, a) = split(&xd);
        let q_ddot = *robot::forward_dynamics(
            &self.model_dual,
            &self.muscles_dual,
            &mut self.data_dual,
            &q,
            &v,
            &a,
            &mut self.forces_dual,
        )?;
        Ok(join(
            &v,
            &q_ddot,
            &activation_rates(&self.muscles_dual, &ud, &a)?,
        ))
    }

    fn jacobians(
        &mut self,
        x: &[f64; NX],
        u: &[f64; NU],
        a_out: &mut [[f64; NX]; NX],
        b_out: &mut [[f64; NU]; NX],
    ) -> rodyn::Result<[f64; NX]> {
        let unit = |j: usize| -> ([f64; NX], [f64; NU]) {
            let dx = core::array::from_fn(|i| f64::from(u8::from(i == j)));
            let du = core::array::from_fn(|i| f64::from(u8::from(i + NX == j)));
            (dx, du)
        };
        let set_column =
            |a: &mut [[f64; NX]; NX], b: &mut [[f64; NU]; NX], j: usize, d: &[f64; NX]| {
                for (i, value) in d.iter().enumerate() {
                    if j < NX {
                        a[i][j] = *value;
                    } else {
                        b[i][j - NX] = *value;
                    }
                }
            };
        match self.route {
            Derivatives::Dual => {
                let mut f = [0.0; NX];
                for j in 0..NX + NU {
                    let (dx, du) = unit(j);
                    let rate = self.dual_rate(x, u, &dx, &du)?;
                    f = rate.map(|r| r.re);
                    set_column(a_out, b_out, j, &rate.map(|r| r.du));
                }
                Ok(f)
            }
            Derivatives::FiniteDifference => {
                let f = self.f64_rate(x, u)?;
                for j in 0..NX + NU {
                    let (mut xp, mut up, mut xm, mut um) = (*x, *u, *x, *u);
                    let value = if j < NX { x[j] } else { u[j - NX] };
                    let h = 1e-6 * value.abs().max(1.0);
                    if j < NX {
                        xp[j] += h;
                        xm[j] -= h;
                    } else {
                        up[j - NX] += h;
                        um[j - NX] -= h;
                    }
                    let (plus, minus) = (self.f64_rate(&xp, &up)?, self.f64_rate(&xm, &um)?);
                    let d: [f64; NX] = core::array::from_fn(|i| (plus[i] - minus[i]) / (2.0 * h));
                    set_column(a_out, b_out, j, &d);
                }
                Ok(f)
            }
            Derivatives::Analytic => {
                let (q, v, act) = split(x);
                aba_derivatives_with_drives(
                    &self.model,
                    &mut self.data,
                    &mut self.derivatives,
                    &mut self.jacobians,
                    &mut self.drive,
                    &q,
                    &v,
                    &[0.0; NV],
                    &self.muscles,
                    &act,
                )?;
                let mut dq_ddot_da = [[0.0; NU]; NV];
                let q_ddot = *robot::sensitivity(
                    &self.model,
                    &self.muscles,
                    &mut self.data,
                    &q,
                    &v,
                    &act,
                    &mut self.forces,
                    &mut dq_ddot_da,
                )?;
                *b_out = [[0.0; NU]; NX];
                // q̈ along q and q̇: the muscles' paths move with them.
                rigid_body_rows(a_out, &self.derivatives, &dq_ddot_da);
                let mut a_dot = [0.0; NU];
                for k in 0..NU {
                    let (rate, d_du, d_da) =
                        activation_rate_derivatives(&self.muscles[k].params, u[k], act[k]);
                    a_dot[k] = rate;
                    b_out[2 * NV + k][k] = d_du;
                    a_out[2 * NV + k][2 * NV + k] = d_da;
                }
                Ok(join(&v, &q_ddot, &a_dot))
            }
        }
    }
}

/// The state Jacobian `A = ∂f/∂x`, `x = (q, q̇, a)`, zeroed and given its
/// rigid-body rows: `∂q/∂q̇ = I`, `q̈` along `q` and `q̇` (`derivatives`)
/// and along the activations (`dq_ddot_da`, the sensitivities). The
/// activation rows are the muscle model's own.
pub(crate) fn rigid_body_rows<S: Scalar>(
    a_out: &mut [[S; NX]; NX],
    derivatives: &DerivativeData<S, NB, NV, Planar>,
    dq_ddot_da: &[[S; NU]; NV],
) {
    *a_out = [[S::ZERO; NX]; NX];
    for (row, (dq, dv)) in a_out[NV..2 * NV]
        .iter_mut()
        .zip(derivatives.ddq_dq.iter().zip(&derivatives.ddq_dv))
    {
        row[..NV].copy_from_slice(dq);
        row[NV..2 * NV].copy_from_slice(dv);
    }
    for (i, sensitivity) in dq_ddot_da.iter().enumerate() {
        a_out[i][NV + i] = S::ONE;
        a_out[NV + i][2 * NV..].copy_from_slice(sensitivity);
    }
}

impl Dynamics<NX, NU> for MuscleRobot {
    fn rate(&mut self, _t: f64, x: &[f64; NX], u: &[f64; NU]) -> Option<[f64; NX]> {
        self.evaluations += 1;
        self.f64_rate(x, u).ok()
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
        self.jacobians(x, u, a, b).ok()
    }
}

/// Thelen's activation rate `ȧ = (u − a)/τ(u, a)` and its partial
/// derivatives `∂ȧ/∂u`, `∂ȧ/∂a`, with `τ = τ_act (0.5 + 1.5a)` while
/// activating (`u > a`) and `τ_deact / (0.5 + 1.5a)` while deactivating;
/// `u` and `a` clamped to `[0, 1]` as [`rodyn::drive::ThelenParameters`]
/// does (zero derivative outside).
#[must_use]
pub fn activation_rate_derivatives(
    params: &rodyn::drive::ThelenParameters<f64>,
    excitation: f64,
    activation: f64,
) -> (f64, f64, f64) {
    let u = excitation.clamp(0.0, 1.0);
    let a = activation.clamp(0.0, 1.0);
    let inside = |v: f64| f64::from(u8::from((0.0..=1.0).contains(&v)));
    let (du_inside, da_inside) = (inside(excitation), inside(activation));
    let shape = 0.5 + 1.5 * a;
    let gap = u - activation;
    if u > a {
        // ȧ = gap / (τ_act s): ∂/∂a = −1/(τ_act s) − gap 1.5/(τ_act s²).
        let tau = params.activation_time_constant * shape;
        let d_da =
            -1.0 / tau - da_inside * gap * 1.5 / (params.activation_time_constant * shape * shape);
        (gap / tau, du_inside / tau, d_da)
    } else {
        // ȧ = gap s / τ_deact: ∂/∂a = (−s + 1.5 gap)/τ_deact.
        let tau_d = params.deactivation_time_constant;
        let d_da = (-shape + da_inside * 1.5 * gap) / tau_d;
        (gap * shape / tau_d, du_inside * shape / tau_d, d_da)
    }
}

pub(crate) fn split<S: Copy>(x: &[S; NX]) -> ([S; NV], [S; NV], [S; NU]) {
    (
        core::array::from_fn(|i| x[i]),
        core::array::from_fn(|i| x[NV + i]),
        core::array::from_fn(|i| x[2 * NV + i]),
    )
}

pub(crate) fn join<S: Copy>(a: &[S; NV], b: &[S; NV], c: &[S; NU]) -> [S; NX] {
    core::array::from_fn(|i| {
        if i < NV {
            a[i]
        } else if i < 2 * NV {
            b[i - NV]
        } else {
            c[i - 2 * NV]
        }
    })
}

/// Weight `r` of the excitation-rate penalty `r Σᵢ ∫ u̇ᵢ² dt`, s².
pub const EXCITATION_RATE_WEIGHT: f64 = 1e-3;

/// The task: duration, grid and desired motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Task {
    /// Duration, s.
    pub duration: f64,
    /// Collocation nodes.
    pub nodes: usize,
    /// Peak angles of shoulder and elbow, rad: each joint swings from 0
    /// (hanging) to its peak and back, `q_d(t) = peak (1 − cos 2πt/T)/2`.
    /// The default 0.5 and 0.75 rad are within the smooth muscles' reach;
    /// at 0.6 and 0.9 rad m1 saturates over the peak and IPOPT reports
    /// local infeasibility.
    pub peak: [f64; NV],
    /// How the solver gets the Hessian of the Lagrangian.
    pub hessian: Hessian,
}

impl Default for Task {
    fn default() -> Self {
        Self {
            duration: 2.0,
            nodes: 101,
            peak: [0.5, 0.75],
            hessian: Hessian::QuasiNewton,
        }
    }
}

impl Task {
    /// The objective's weights: squared activations, and the excitation
    /// rates at [`EXCITATION_RATE_WEIGHT`].
    #[must_use]
    pub fn weights(&self) -> Weights<NX, NU> {
        let mut state = [0.0; NX];
        state[2 * NV..].fill(1.0);
        Weights {
            state,
            control: [0.0; NU],
            control_rate: [EXCITATION_RATE_WEIGHT; NU],
        }
    }

    /// Desired angles (rad) and rates (rad/s) at `t`.
    #[must_use]
    pub fn desired(&self, t: f64) -> ([f64; NV], [f64; NV]) {
        let w = 2.0 * core::f64::consts::PI / self.duration;
        (
            self.peak.map(|p| p * 0.5 * (1.0 - (w * t).cos())),
            self.peak.map(|p| p * 0.5 * w * (w * t).sin()),
        )
    }

    /// The collocation problem with derivatives by `route`: angles fixed
    /// to the desired ones at every node, at rest at `t = 0`, activations
    /// and excitations in `[0, 1]`; the guess is the desired motion with
    /// every muscle at 0.1.
    ///
    /// # Errors
    /// As [`MuscleRobot::new`].
    pub fn transcribe(
        &self,
        route: Derivatives,
    ) -> rodyn::Result<Trapezoidal<MuscleRobot, NX, NU>> {
        Ok(self.transcribe_with(MuscleRobot::new(route)?))
    }

    /// The collocation problem of [`transcribe`](Self::transcribe) for
    /// any model of the robot's dynamics with the same state and control.
    pub fn transcribe_with<D: Dynamics<NX, NU>>(&self, dynamics: D) -> Trapezoidal<D, NX, NU> {
        let task = *self;
        let bounds = move |t: f64| {
            let (q, _) = task.desired(t);
            let mut x_lower = [f64::NEG_INFINITY; NX];
            let mut x_upper = [f64::INFINITY; NX];
            x_lower[..NV].copy_from_slice(&q);
            x_upper[..NV].copy_from_slice(&q);
            if t == 0.0 {
                x_lower[NV..2 * NV].fill(0.0);
                x_upper[NV..2 * NV].fill(0.0);
            }
            x_lower[2 * NV..].fill(0.0);
            x_upper[2 * NV..].fill(1.0);
            NodeBounds {
                x_lower,
                x_upper,
                u_lower: [0.0; NU],
                u_upper: [1.0; NU],
            }
        };
        let guess = move |t: f64| {
            let (q, v) = task.desired(t);
            Node {
                t,
                x: join(&q, &v, &[0.1; NU]),
                u: [0.1; NU],
            }
        };
        let mut problem = Trapezoidal::new(
            dynamics,
            0.0,
            self.duration,
            self.nodes,
            bounds,
            guess,
            self.weights(),
        );
        problem.hessian = self.hessian;
        problem
    }
}

/// The excitations of `nodes` as a function of time, linear between
/// nodes (as the collocation assumes) and held at the ends.
pub fn excitation_of(nodes: &[Node<NX, NU>]) -> impl FnMut(f64) -> [f64; NU] + '_ {
    move |t: f64| {
        let h = nodes[1].t - nodes[0].t;
        let position = ((t - nodes[0].t) / h).clamp(0.0, (nodes.len() - 1) as f64);
        // In range by the clamp; the cast truncates toward zero.
        let k = (position.floor() as usize).min(nodes.len() - 2);
        let s = position - k as f64;
        core::array::from_fn(|i| (1.0 - s) * nodes[k].u[i] + s * nodes[k + 1].u[i])
    }
}

/// The optimal controls replayed: RK4 from the first node's state with the
/// excitations interpolated linearly between nodes (as the collocation
/// assumes), step `dt`, the Thelen muscles; returns the RMS over the run
/// of the angle error against the desired trajectory (rad) and the
/// largest error (rad).
///
/// # Errors
/// When the simulation fails (a rodyn error).
pub fn resimulate(task: &Task, nodes: &[Node<NX, NU>], dt: f64) -> rodyn::Result<(f64, f64)> {
    let muscles = robot::MUSCLES_F64;
    let mut loads = RobotLoads::new(&muscles, excitation_of(nodes));
    let run = replay(task, nodes, dt, &mut loads)?;
    Ok((run.rms, run.max))
}

/// A replay of optimal controls: the angle error against the desired
/// trajectory and the angles along the way.
#[derive(Clone, Debug, PartialEq)]
pub struct Replay {
    /// RMS over the run and both joints of the angle error, rad.
    pub rms: f64,
    /// Largest angle error, rad.
    pub max: f64,
    /// `(t, q)` after every step, s and rad.
    pub samples: Vec<(f64, [f64; NV])>,
}

/// RK4 at step `dt` under `loads` (the muscles driven by the excitations
/// of `nodes`) from the first node's state.
///
/// # Errors
/// When the simulation fails (a rodyn error).
pub fn replay<L: AuxiliaryLoads<f64, NB, NV, NV, NU, Planar>>(
    task: &Task,
    nodes: &[Node<NX, NU>],
    dt: f64,
    loads: &mut L,
) -> rodyn::Result<Replay> {
    let (q, v, a) = split(&nodes[0].x);
    let mut state = robot::RobotState::with_auxiliary(q, v, a);
    let mut data = Data::new();
    let mut rk4 = Rk4::default();
    let end = nodes[nodes.len() - 1].t;
    let steps = ((end - nodes[0].t) / dt).round() as usize;
    let (mut sum, mut worst) = (0.0, 0.0_f64);
    let mut samples = Vec::with_capacity(steps + 1);
    samples.push((state.t, state.q));
    for _ in 0..steps {
        rk4.step(Aba, &robot::MODEL_F64, &mut data, &mut state, dt, loads)?;
        let (desired, _) = task.desired(state.t);
        for (q, d) in state.q.iter().zip(desired) {
            sum += (q - d) * (q - d);
            worst = worst.max((q - d).abs());
        }
        samples.push((state.t, state.q));
    }
    Ok(Replay {
        rms: (sum / (steps * NV) as f64).sqrt(),
        max: worst,
        samples,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The three routes give the same Jacobians at states inside the bounds
    /// (IPOPT's iterates are) and away from the activation dynamics' switch
    /// `u = a` and the force-velocity curve's change of slope at zero fibre
    /// velocity, where one-sided derivatives differ: the analytic parts and dual numbers to rounding, central
    /// differences to their truncation.
    #[test]
    fn routes_agree() {
        let states: [([f64; NX], [f64; NU]); 3] = [
            (
                [0.1, 0.3, 0.2, -0.5, 0.2, 0.3, 0.4, 0.5],
                [0.6, 0.1, 0.9, 0.2],
            ),
            (
                [0.5, 0.9, -1.0, 0.4, 0.05, 0.6, 0.1, 0.3],
                [0.3, 0.2, 0.5, 0.02],
            ),
            (
                [-0.2, 0.4, 0.3, 0.1, 0.5, 0.5, 0.5, 0.5],
                [0.97, 0.03, 0.7, 0.2],
            ),
        ];
        let jacobians = |route| {
            let mut robot = MuscleRobot::new(route).unwrap();
            states.map(|(x, u)| {
                let (mut a, mut b) = ([[0.0; NX]; NX], [[0.0; NU]; NX]);
                let f = robot.jacobians(&x, &u, &mut a, &mut b).unwrap();
                (f, a, b)
            })
        };
        let dual = jacobians(Derivatives::Dual);
        for (route, tolerance) in [
            (Derivatives::Analytic, 1e-10),
            (Derivatives::FiniteDifference, 1e-6),
        ] {
            for (n, ((f, a, b), (f_ref, a_ref, b_ref))) in
                jacobians(route).iter().zip(&dual).enumerate()
            {
                let scale = a_ref
                    .iter()
                    .flatten()
                    .chain(b_ref.iter().flatten())
                    .fold(1.0_f64, |m, v| m.max(v.abs()));
                for (x, y) in f.iter().zip(f_ref) {
                    assert!(
                        (x - y).abs() <= 1e-12 * scale,
                        "{route:?}: f {x} against {y}"
                    );
                }
                let entries = a.iter().flatten().zip(a_ref.iter().flatten());
                for (e, (x, y)) in entries
                    .chain(b.iter().flatten().zip(b_ref.iter().flatten()))
                    .enumerate()
                {
                    assert!(
                        (x - y).abs() <= tolerance * scale,
                        "{route:?} state {n} entry {e}: {x} against {y} (scale {scale})"
                    );
                }
            }
        }
    }
}
