//! Scenarios: a model, its loads and initial state, run with a chosen
//! forward-dynamics method, scalar type, integrator and step.

use crate::models::{arm7, ARM7_RELEASE};
use crate::progress::Progress;
use crate::trajectory::Trajectory;
use clap::ValueEnum;
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::sim::{
    AuxiliaryLoads, ConfigurationRate, ExplicitEuler, ImplicitEuler, Integrator, NoLoads, Rk4,
    SemiImplicitEuler, State,
};
use rodyn::{Data, Model, Scalar};
use rodyn_scenarios::muscle_robot::{self, example_excitation, RobotLoads, INITIAL_ACTIVATION};
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
    /// The quadruped only: rigid feet with Coulomb friction, one Moreau–Jean
    /// step per step (`rodyn::sim::time_stepping`), the PD's damping
    /// implicit; the forward-dynamics method is the KKT solve on CRBA.
    RigidContact,
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
            Self::RigidContact => "rigid-contact",
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

    /// Whether the scenario has feet for [`IntegratorKind::RigidContact`].
    pub fn has_feet(self) -> bool {
        matches!(self, Self::QuadrupedStand | Self::QuadrupedTrot)
    }

    /// The step a run takes unless told otherwise (s): 0.5 ms for the
    /// quadruped, whose stiff feet make semi-implicit Euler at 1 ms bounce
    /// the robot over (it hopped at 0.8 s and flipped at 1.6 s), 1 ms for
    /// the others.
    pub fn default_step(self) -> f64 {
        match self {
            Self::QuadrupedStand | Self::QuadrupedTrot => 5e-4,
            Self::ArmSwing | Self::MuscleRobot => 1e-3,
        }
    }
}

/// A physical-state check run on every recorded sample: `Some(cause)` ends
/// the run with a failure that names the time and the cause.
pub type Guard = fn(&[f64]) -> Option<String>;

/// The quadruped's: the trunk below the ground or upside down.
fn quadruped_guard(q: &[f64]) -> Option<String> {
    let q: &[f64; quadruped::NQ] = q.try_into().ok()?;
    let trunk = quadruped::trunk_position(q);
    // The trunk's z axis in the world: the (2, 2) entry of its rotation.
    let (x, y) = (q[3], q[4]);
    let up = 1.0 - 2.0 * (x * x + y * y);
    if trunk.z < 0.0 {
        Some(format!(
            "the trunk is below the ground (z = {:.3} m)",
            trunk.z
        ))
    } else if up < 0.0 {
        Some(format!(
            "the trunk is upside down (its z axis points {:.2} of the way down)",
            -up
        ))
    } else {
        None
    }
}

/// The most steps a run may take: about ten seconds of the arm's
/// semi-implicit Euler on a desktop, minutes of the quadruped's RK4.
pub const MAX_STEPS: usize = 10_000_000;

/// The most simulated time a run may cover (s): its recorded samples, one
/// per 10 ms or per step if longer, then stay within memory.
pub const MAX_DURATION: f64 = 1000.0;

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

impl RunConfig {
    /// The dynamics method as reports name it: rigid contact always solves
    /// its contacts by the KKT method on CRBA, whatever `method` says.
    pub fn method_name(&self) -> &'static str {
        if self.integrator == IntegratorKind::RigidContact {
            "KKT"
        } else {
            self.method.name()
        }
    }
}

/// Runs a scenario; a dynamics error ends the run early and is recorded in
/// the trajectory.
pub fn run(config: &RunConfig, progress: Option<&Progress>) -> Trajectory {
    match config.scalar {
        ScalarType::F32 => run_typed::<f32>(config, progress),
        ScalarType::F64 => run_typed::<f64>(config, progress),
    }
}

fn run_typed<S: Scalar>(config: &RunConfig, progress: Option<&Progress>) -> Trajectory {
    match config.scenario {
        Scenario::ArmSwing => {
            let model = arm7::<S>();
            let state = State::new(ARM7_RELEASE.map(S::from_f64), [S::ZERO; 7]);
            by_integrator(config, &model, NoLoads, state, Vec::new(), progress, None)
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
            if config.integrator == IntegratorKind::RigidContact {
                let ground = quadruped::rigid_ground();
                let mut data = Data::new();
                let mut contact = quadruped::RigidContactData::new();
                let dt = S::from_f64(config.dt);
                return drive(
                    config,
                    state,
                    Vec::new(),
                    progress,
                    Some(quadruped_guard),
                    |state| {
                        quadruped::rigid_step(
                            &model,
                            &mut data,
                            &mut contact,
                            &loads,
                            &ground,
                            state,
                            dt,
                        )
                    },
                );
            }
            by_integrator(
                config,
                &model,
                loads,
                state,
                Vec::new(),
                progress,
                Some(quadruped_guard),
            )
        }
        Scenario::MuscleRobot => {
            // Casting fails only for custom joints, which the model file cannot have.
            let model = muscle_robot::model::<S>().expect("the muscle robot casts to any scalar");
            let muscles = muscle_robot::muscles::<S>();
            let loads = RobotLoads::new(&muscles, example_excitation::<S>);
            let state = muscle_robot::rest_state(S::from_f64(INITIAL_ACTIVATION));
            // The activations are the state's auxiliary states; the
            // trajectory records them as its internal states.
            let names = (1..=muscle_robot::NU).map(|k| format!("a{k}")).collect();
            by_integrator(config, &model, loads, state, names, progress, None)
        }
    }
}

/// Picks the integrator. `internal_names` name the state's auxiliary
/// states `z` (NZ of them) in the trajectory.
fn by_integrator<S, G, L, const NB: usize, const NQ: usize, const NV: usize, const NZ: usize>(
    config: &RunConfig,
    model: &Model<S, NB, NQ, NV, G>,
    loads: L,
    state: State<S, NQ, NV, NZ>,
    internal_names: Vec<String>,
    progress: Option<&Progress>,
    guard: Option<Guard>,
) -> Trajectory
where
    S: Scalar,
    G: ConfigurationRate,
    L: AuxiliaryLoads<S, NB, NQ, NV, NZ, G>,
{
    let run = Run {
        config,
        model,
        loads,
        state,
        internal_names,
        progress,
        guard,
    };
    match config.integrator {
        IntegratorKind::ExplicitEuler => run.by_method(ExplicitEuler::default()),
        IntegratorKind::SemiImplicitEuler => run.by_method(SemiImplicitEuler::default()),
        IntegratorKind::Rk4 => run.by_method(Rk4::default()),
        IntegratorKind::ImplicitEuler => run.by_method(ImplicitEuler::default()),
        IntegratorKind::RigidContact => Trajectory::failed(
            NQ,
            NV,
            format!("{}: no feet for rigid contact", config.scenario.name()),
        ),
    }
}

/// Everything a run needs but the integrator and the method.
struct Run<
    'a,
    S: Scalar,
    G: ConfigurationRate,
    L,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NZ: usize,
> {
    config: &'a RunConfig,
    model: &'a Model<S, NB, NQ, NV, G>,
    loads: L,
    state: State<S, NQ, NV, NZ>,
    internal_names: Vec<String>,
    progress: Option<&'a Progress>,
    guard: Option<Guard>,
}

impl<S, G, L, const NB: usize, const NQ: usize, const NV: usize, const NZ: usize>
    Run<'_, S, G, L, NB, NQ, NV, NZ>
where
    S: Scalar,
    G: ConfigurationRate,
    L: AuxiliaryLoads<S, NB, NQ, NV, NZ, G>,
{
    fn by_method<I: Integrator>(self, integrator: I) -> Trajectory {
        match self.config.method {
            Method::Aba => self.simulate(Aba, integrator),
            Method::Crba => self.simulate(Crba, integrator),
        }
    }

    /// The stepping loop: times only the steps and the recording of samples.
    fn simulate<F, I>(self, method: F, mut integrator: I) -> Trajectory
    where
        F: ForwardDynamics + Copy,
        I: Integrator,
    {
        let Self {
            config,
            model,
            mut loads,
            state,
            internal_names,
            progress,
            guard,
        } = self;
        let dt = S::from_f64(config.dt);
        let mut data = Data::new();
        drive(config, state, internal_names, progress, guard, |state| {
            integrator.step(method, model, &mut data, state, dt, &mut loads)
        })
    }
}

/// The stepping loop: `step` advances the state by one step; times only
/// the steps and the recording of samples.
fn drive<S: Scalar, const NQ: usize, const NV: usize, const NZ: usize>(
    config: &RunConfig,
    mut state: State<S, NQ, NV, NZ>,
    internal_names: Vec<String>,
    progress: Option<&Progress>,
    guard: Option<Guard>,
    mut step: impl FnMut(&mut State<S, NQ, NV, NZ>) -> rodyn::Result<()>,
) -> Trajectory {
    let steps = (config.duration / config.dt).round() as usize;
    let every = ((config.sample_interval / config.dt).round() as usize).max(1);
    let mut trajectory = Trajectory::with_internal_states(NQ, NV, internal_names);
    trajectory.record(&state.cast::<f64>());
    let start = Instant::now();
    for n in 1..=steps {
        if let Err(e) = step(&mut state) {
            trajectory.failure = Some(format!("t = {:.4} s: {e}", state.t.to_f64()));
            break;
        }
        if n % every == 0 || n == steps {
            let sample = state.cast::<f64>();
            trajectory.record(&sample);
            if let Some(cause) = guard.and_then(|g| g(&sample.q)) {
                trajectory.failure = Some(format!("t = {:.4} s: {cause}", state.t.to_f64()));
                break;
            }
        }
        if let Some(progress) = progress {
            if n % 1000 == 0 {
                progress.at(n as u64);
            }
        }
    }
    trajectory.wall_time = start.elapsed();
    trajectory.steps = steps;
    trajectory
}
