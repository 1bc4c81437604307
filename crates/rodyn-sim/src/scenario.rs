//! Scenarios: a model, its loads and initial state, run with a chosen
//! forward-dynamics method, scalar type, integrator and step.

use crate::models::{arm7, ARM7_RELEASE};
use crate::trajectory::Trajectory;
use clap::ValueEnum;
use indicatif::ProgressBar;
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::sim::{
    ExplicitEuler, ImplicitEuler, Integrator, Loads, NoLoads, Rk4, SemiImplicitEuler, State,
};
use rodyn::spatial::Spatial;
use rodyn::{Data, Model, Scalar};
use rodyn_scenarios::muscle_robot::{self, example_excitation, INITIAL_ACTIVATION};
use rodyn_scenarios::quadruped::{self, QuadrupedLoads};
use std::time::Instant;

/// What is simulated.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Scenario {
    /// The 7-DoF Panda-like arm released from a bent pose, swinging under gravity.
    ArmSwing,
    /// The quadruped dropped from 3 cm above its stance height, PD-holding its stance.
    QuadrupedStand,
    /// The quadruped trotting open-loop from standing.
    QuadrupedTrot,
    /// The two-link, four-muscle robot from rest under the example
    /// excitations, its activations integrated with the joints.
    MuscleRobot,
}

/// Forward-dynamics method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Method {
    /// Articulated-body algorithm.
    Aba,
    /// Composite-rigid-body algorithm with a sparse LTDL solve.
    Crba,
}

/// Scalar type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ScalarType {
    /// Single precision.
    F32,
    /// Double precision.
    F64,
}

/// Time-stepping scheme.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum IntegratorKind {
    /// Explicit Euler.
    ExplicitEuler,
    /// Semi-implicit (symplectic) Euler.
    SemiImplicitEuler,
    /// Classical RK4.
    Rk4,
    /// Linearly implicit Euler with a finite-difference Jacobian.
    ImplicitEuler,
}

impl IntegratorKind {
    /// Every integrator.
    pub const ALL: [Self; 4] = [
        Self::ExplicitEuler,
        Self::SemiImplicitEuler,
        Self::Rk4,
        Self::ImplicitEuler,
    ];
    /// The name used on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            Self::ExplicitEuler => ExplicitEuler::NAME,
            Self::SemiImplicitEuler => SemiImplicitEuler::NAME,
            Self::Rk4 => Rk4::NAME,
            Self::ImplicitEuler => ImplicitEuler::NAME,
        }
    }
}

impl Method {
    /// The name used in reports.
    pub fn name(self) -> &'static str {
        match self {
            Self::Aba => Aba::NAME,
            Self::Crba => Crba::NAME,
        }
    }
}

impl ScalarType {
    /// The name used in reports.
    pub fn name(self) -> &'static str {
        match self {
            Self::F32 => "f32",
            Self::F64 => "f64",
        }
    }
}

impl Scenario {
    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Self::ArmSwing => "arm-swing",
            Self::QuadrupedStand => "quadruped-stand",
            Self::QuadrupedTrot => "quadruped-trot",
            Self::MuscleRobot => "muscle-robot",
        }
    }
}

/// One run's settings.
#[derive(Clone, Copy, Debug)]
pub struct RunConfig {
    /// What.
    pub scenario: Scenario,
    /// Simulated time (s).
    pub duration: f64,
    /// Step (s).
    pub dt: f64,
    /// Forward dynamics.
    pub method: Method,
    /// Scalar.
    pub scalar: ScalarType,
    /// Integrator.
    pub integrator: IntegratorKind,
    /// Interval between recorded samples (s); rounded to a whole number of steps.
    pub sample_interval: f64,
}

/// Runs a scenario; a dynamics error ends the run early and is recorded in
/// the trajectory.
pub fn run(config: &RunConfig, progress: Option<&ProgressBar>) -> Trajectory {
    match config.scalar {
        ScalarType::F32 => run_typed::<f32>(config, progress),
        ScalarType::F64 => run_typed::<f64>(config, progress),
    }
}

fn run_typed<S: Scalar>(config: &RunConfig, progress: Option<&ProgressBar>) -> Trajectory {
    match config.scenario {
        Scenario::ArmSwing => {
            let model = arm7::<S>();
            let state = State::new(ARM7_RELEASE.map(S::from_f64), [S::ZERO; 7]);
            by_integrator(config, &model, NoLoads, state, progress)
        }
        Scenario::QuadrupedStand | Scenario::QuadrupedTrot => {
            // Casting fails only for custom joints, which the model file cannot have.
            let model = quadruped::model::<S>().expect("the Aibo model casts to any scalar");
            let loads = if config.scenario == Scenario::QuadrupedTrot {
                QuadrupedLoads::trotting()
            } else {
                QuadrupedLoads::standing()
            };
            // The stand scenario drops from 3 cm; the trot starts with the
            // feet just touching.
            let drop = if config.scenario == Scenario::QuadrupedStand {
                0.03
            } else {
                0.0
            };
            let state = loads.initial_state(loads.stance_height() + S::from_f64(drop));
            by_integrator(config, &model, loads, state, progress)
        }
        Scenario::MuscleRobot => match config.method {
            Method::Aba => simulate_muscle_robot::<Aba, S>(config, progress),
            Method::Crba => simulate_muscle_robot::<Crba, S>(config, progress),
        },
    }
}

impl IntegratorKind {
    /// The same scheme for the muscle robot's joints-and-activations state.
    fn muscle_robot_scheme(self) -> muscle_robot::Scheme {
        match self {
            Self::ExplicitEuler => muscle_robot::Scheme::ExplicitEuler,
            Self::SemiImplicitEuler => muscle_robot::Scheme::SemiImplicitEuler,
            Self::Rk4 => muscle_robot::Scheme::Rk4,
            Self::ImplicitEuler => muscle_robot::Scheme::ImplicitEuler,
        }
    }
}

/// The muscle robot's stepping loop. Its activations are states beside
/// `(q, v)`, which `rodyn::sim`'s integrators do not carry, so it steps with
/// `muscle_robot::step` (the same four schemes) and records the activations
/// as the trajectory's internal states. Times the steps and the recording,
/// as [`simulate`] does.
fn simulate_muscle_robot<M: ForwardDynamics, S: Scalar>(
    config: &RunConfig,
    progress: Option<&ProgressBar>,
) -> Trajectory {
    // Casting fails only for custom joints, which the model file cannot have.
    let model = muscle_robot::model::<S>().expect("the muscle robot casts to any scalar");
    let muscles = muscle_robot::muscles::<S>();
    let scheme = config.integrator.muscle_robot_scheme();
    let steps = (config.duration / config.dt).round() as usize;
    let every = ((config.sample_interval / config.dt).round() as usize).max(1);
    let dt = S::from_f64(config.dt);
    let mut work = muscle_robot::RobotWorkspace::new();
    let mut state = muscle_robot::RobotState::at_rest(S::from_f64(INITIAL_ACTIVATION));
    let names = (1..=muscle_robot::NU).map(|k| format!("a{k}")).collect();
    let mut trajectory =
        Trajectory::with_internal_states(muscle_robot::NV, muscle_robot::NV, names);
    let record = |trajectory: &mut Trajectory, s: &muscle_robot::RobotState<S>| {
        let widen = |x: &S| x.to_f64();
        trajectory.record_with_internal(
            &State {
                t: s.t.to_f64(),
                q: s.q.each_ref().map(widen),
                v: s.v.each_ref().map(widen),
            },
            &s.activation.map(|x| x.to_f64()),
        );
    };
    record(&mut trajectory, &state);
    let start = Instant::now();
    for n in 1..=steps {
        if let Err(e) = muscle_robot::step::<M, S>(
            scheme,
            &model,
            &muscles,
            &mut work,
            &mut state,
            dt,
            &example_excitation,
        ) {
            trajectory.failure = Some(format!("t = {:.4} s: {e}", state.t.to_f64()));
            break;
        }
        if n % every == 0 || n == steps {
            record(&mut trajectory, &state);
        }
        if let Some(bar) = progress {
            if n % 1000 == 0 {
                bar.set_position(n as u64);
            }
        }
    }
    trajectory.wall_time = start.elapsed();
    trajectory.steps = steps;
    trajectory
}

fn by_integrator<S, L, const NB: usize, const NQ: usize, const NV: usize>(
    config: &RunConfig,
    model: &Model<S, NB, NQ, NV, Spatial>,
    loads: L,
    state: State<S, NQ, NV>,
    progress: Option<&ProgressBar>,
) -> Trajectory
where
    S: Scalar,
    L: Loads<S, NB, NQ, NV, Spatial>,
{
    match config.integrator {
        IntegratorKind::ExplicitEuler => by_method(
            config,
            model,
            loads,
            state,
            ExplicitEuler::default(),
            progress,
        ),
        IntegratorKind::SemiImplicitEuler => by_method(
            config,
            model,
            loads,
            state,
            SemiImplicitEuler::default(),
            progress,
        ),
        IntegratorKind::Rk4 => by_method(config, model, loads, state, Rk4::default(), progress),
        IntegratorKind::ImplicitEuler => by_method(
            config,
            model,
            loads,
            state,
            ImplicitEuler::default(),
            progress,
        ),
    }
}

fn by_method<S, L, I, const NB: usize, const NQ: usize, const NV: usize>(
    config: &RunConfig,
    model: &Model<S, NB, NQ, NV, Spatial>,
    loads: L,
    state: State<S, NQ, NV>,
    integrator: I,
    progress: Option<&ProgressBar>,
) -> Trajectory
where
    S: Scalar,
    L: Loads<S, NB, NQ, NV, Spatial>,
    I: Integrator,
{
    match config.method {
        Method::Aba => simulate(Aba, integrator, model, loads, state, config, progress),
        Method::Crba => simulate(Crba, integrator, model, loads, state, config, progress),
    }
}

/// The stepping loop: times only the steps and the recording of samples.
pub fn simulate<F, I, L, S, const NB: usize, const NQ: usize, const NV: usize>(
    method: F,
    mut integrator: I,
    model: &Model<S, NB, NQ, NV, Spatial>,
    mut loads: L,
    mut state: State<S, NQ, NV>,
    config: &RunConfig,
    progress: Option<&ProgressBar>,
) -> Trajectory
where
    F: ForwardDynamics + Copy,
    I: Integrator,
    L: Loads<S, NB, NQ, NV, Spatial>,
    S: Scalar,
{
    let steps = (config.duration / config.dt).round() as usize;
    let every = ((config.sample_interval / config.dt).round() as usize).max(1);
    let dt = S::from_f64(config.dt);
    let mut data = Data::new();
    let mut trajectory = Trajectory::new(NQ, NV);
    trajectory.record(&state.cast::<f64>());
    let start = Instant::now();
    for n in 1..=steps {
        if let Err(e) = integrator.step(method, model, &mut data, &mut state, dt, &mut loads) {
            trajectory.failure = Some(format!("t = {:.4} s: {e}", state.t.to_f64()));
            break;
        }
        if n % every == 0 || n == steps {
            trajectory.record(&state.cast::<f64>());
        }
        if let Some(bar) = progress {
            if n % 1000 == 0 {
                bar.set_position(n as u64);
            }
        }
    }
    trajectory.wall_time = start.elapsed();
    trajectory.steps = steps;
    trajectory
}
