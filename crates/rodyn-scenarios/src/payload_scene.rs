//! The Panda carries a payload its controller does not know; the
//! controller identifies it from the torque residual while the arm moves
//! and swaps the updated model in between two ticks.
//!
//! * Plant: the Panda ([`panda::MODEL_F32`]) with [`TRUE_PAYLOAD`] at its
//!   flange, stepped by ABA and semi-implicit Euler, [`SUBSTEPS`] steps per
//!   control tick, the torques held over the tick.
//! * Controller: computed torque at 1 kHz,
//!   `τ = RNEA(q, v, q̈_d + K_d (v_d - v) + K_p (q_d - q))` (ωₙ = 40 rad/s,
//!   critically damped) on the model it reads from a
//!   [`DoubleBuffered`]; at first the Panda without payload.
//! * Identification: from tick [`IDENTIFY_FROM`] to [`SWAP_AT`] every tick
//!   gives a sample to a [`PayloadEstimator`]: the mid-tick angles and
//!   rates, the tick's mean acceleration `Δv / Δt` and the torques held over
//!   it. At [`SWAP_AT`] the least-squares payload (mass and centre of mass,
//!   a point mass) is staged as a [`ModelUpdate`] at the flange frame and
//!   published; the next tick reads the new model.
//! * Measure: the tracking error over [`BEFORE`] and over [`AFTER`].
//!
//! On a board the tick would run in a timer interrupt (the [`Reader`]) and
//! the estimator and staging in the main loop (the [`Writer`]); here both
//! run in turn, one tick after another, so the host and the firmware give
//! the same numbers.

use crate::panda;
use crate::payload_estimate::{IdentifiedPayload, PayloadEstimator};
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::algorithm::rnea::rnea;
use rodyn::frame::Frame;
use rodyn::sim::{Integrator, SemiImplicitEuler, State};
use rodyn::space::RigidTransform;
use rodyn::spatial::{Force, Inertia, Sym3, Vec3};
use rodyn::update::{DoubleBuffered, ModelUpdate, ParameterChange, Reader, Writer};
use rodyn::{Data, Model, Result, Scalar};

/// The Panda in f32.
pub type PandaModel = Model<f32, { panda::NB }, { panda::NQ }, { panda::NV }>;
const N: usize = panda::NV;

/// Control period (s): 1 kHz.
pub const DT: f32 = 1.0e-3;
/// Plant steps per control tick.
pub const SUBSTEPS: u32 = 4;
/// Control ticks in the scene: 3 s.
pub const TICKS: u32 = 3_000;
/// The first tick whose motion feeds the estimator (the start's transient
/// over).
pub const IDENTIFY_FROM: u32 = 100;
/// The tick before which the identified model is published.
pub const SWAP_AT: u32 = 1_500;
/// Ticks over which the tracking error is measured before the swap.
pub const BEFORE: core::ops::Range<u32> = 500..SWAP_AT;
/// Ticks over which the tracking error is measured after the swap (the
/// half second after it left for the transient).
pub const AFTER: core::ops::Range<u32> = 2_000..TICKS;

/// The flange frame (`panda_link8`), where the payload is held.
pub const FLANGE: Frame<f32> = panda::FRAMES_F32[panda::frame::PANDA_LINK8];

/// The payload the plant carries and the controller must find: 2 kg, its
/// centre of mass 2 cm, −3 cm and 7 cm from the flange, a 10 cm box's
/// rotational inertia (in the flange frame).
pub const TRUE_PAYLOAD: Inertia<f32> = Inertia::new(
    2.0,
    Vec3::new(0.02, -0.03, 0.07),
    Sym3::diagonal(3.3e-3, 3.3e-3, 3.3e-3),
);

/// Ready pose (rad), as the firmware's arm example.
const READY: [f32; N] = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];
const AMPLITUDE: [f32; N] = [0.4, 0.3, 0.3, 0.3, 0.5, 0.4, 0.6];
const OMEGA: [f32; N] = [3.0, 2.5, 3.5, 2.0, 4.0, 3.0, 5.0];
/// ωₙ = 40 rad/s, ζ = 1.
const KP: f32 = 1_600.0;
const KD: f32 = 80.0;

/// `q(t) = q₀ + A (1 - cos ωt)`, its rate and acceleration.
#[inline]
fn reference(t: f32) -> ([f32; N], [f32; N], [f32; N]) {
    let mut r = ([0.0; N], [0.0; N], [0.0; N]);
    for k in 0..N {
        let (a, w) = (AMPLITUDE[k], OMEGA[k]);
        let (s, c) = Scalar::sin_cos(w * t);
        r.0[k] = READY[k] + a * (1.0 - c);
        r.1[k] = a * w * s;
        r.2[k] = a * w * w * c;
    }
    r
}

/// Root-mean-square and largest tracking error over a window (rad).
#[derive(Clone, Copy, Default)]
pub struct TrackingError {
    squares: f32,
    samples: u32,
    /// Largest error on any joint (rad).
    pub max: f32,
}

impl TrackingError {
    #[inline]
    fn add(&mut self, error: &[f32; N]) {
        for e in error {
            self.squares += e * e;
            self.max = self.max.max(e.abs());
        }
        self.samples += N as u32;
    }
    /// The root-mean-square error over every joint and tick (rad).
    #[must_use]
    #[inline]
    pub fn rms(&self) -> f32 {
        Scalar::sqrt(self.squares / (self.samples.max(1) as f32))
    }
}

/// What one tick did.
#[derive(Clone, Copy)]
pub struct TickOutcome {
    /// The tick's index.
    pub tick: u32,
    /// Joint angle minus reference at the tick (rad).
    pub error: [f32; N],
    /// The payload identified and published before this tick, once.
    pub swapped: Option<IdentifiedPayload>,
}

/// The scene's state; the models live in the [`DoubleBuffered`] it was
/// given.
pub struct PayloadScene<'a> {
    plant: PandaModel,
    plant_data: Data<f32, { panda::NB }, N>,
    /// The plant's time, angles and rates.
    pub state: State<f32, N, N>,
    integrator: SemiImplicitEuler,
    tick_model: Reader<'a, PandaModel>,
    updates: Writer<'a, PandaModel>,
    controller_data: Data<f32, { panda::NB }, N>,
    estimator: PayloadEstimator,
    estimator_data: Data<f32, { panda::NB }, N>,
    tick: u32,
    /// Tracking error over [`BEFORE`].
    pub before: TrackingError,
    /// Tracking error over [`AFTER`].
    pub after: TrackingError,
}

// `Debug` by hand and inlined, as every function of this module (see
// `payload_estimate`): nothing of it is compiled into the crate itself.
impl core::fmt::Debug for TrackingError {
    #[inline]
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("TrackingError")
            .field("rms", &self.rms())
            .field("max", &self.max)
            .finish()
    }
}

impl core::fmt::Debug for TickOutcome {
    #[inline]
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("TickOutcome")
            .field("tick", &self.tick)
            .field("error", &self.error)
            .field("swapped", &self.swapped)
            .finish()
    }
}

impl core::fmt::Debug for PayloadScene<'_> {
    #[inline]
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("PayloadScene")
            .field("tick", &self.tick)
            .field("state", &self.state)
            .field("before", &self.before)
            .field("after", &self.after)
            .finish_non_exhaustive()
    }
}

impl<'a> PayloadScene<'a> {
    /// The scene at rest at the ready pose; `models` should hold the
    /// Panda without payload ([`panda::MODEL_F32`]).
    ///
    /// # Errors
    /// None for the shipped Panda; a payload the model refuses.
    #[inline]
    pub fn new(models: &'a mut DoubleBuffered<PandaModel>) -> Result<Self> {
        let mut plant = panda::MODEL_F32;
        ModelUpdate::new([ParameterChange::Payload {
            frame: FLANGE,
            inertia: TRUE_PAYLOAD,
        }])
        .apply(&mut plant)?;
        let (tick_model, updates) = models.split();
        Ok(Self {
            plant,
            plant_data: Data::new(),
            state: State::new(READY, [0.0; N]),
            integrator: SemiImplicitEuler::default(),
            tick_model,
            updates,
            controller_data: Data::new(),
            estimator: PayloadEstimator::new(FLANGE.body),
            estimator_data: Data::new(),
            tick: 0,
            before: TrackingError::default(),
            after: TrackingError::default(),
        })
    }

    /// `true` once every tick has run.
    #[must_use]
    #[inline]
    pub const fn done(&self) -> bool {
        self.tick >= TICKS
    }

    /// One control tick: publish the identified model when it is time,
    /// compute and apply the torques, advance the plant, feed the
    /// estimator.
    ///
    /// # Errors
    /// The dynamics' (a diverging plant), or the staged update's.
    #[inline]
    pub fn step(&mut self) -> Result<TickOutcome> {
        let swapped = if self.tick == SWAP_AT {
            self.swap_in_identified()?
        } else {
            None
        };
        let t = self.tick as f32 * DT;
        let (q_d, v_d, a_d) = reference(t);
        let (q0, v0) = (self.state.q, self.state.v);
        let error = core::array::from_fn(|k| q0[k] - q_d[k]);
        let a_cmd =
            core::array::from_fn(|k| a_d[k] + KD * (v_d[k] - v0[k]) + KP * (q_d[k] - q0[k]));
        let data = &mut self.controller_data;
        let tau = self
            .tick_model
            .read(|model| rnea(model, data, &q0, &v0, &a_cmd, None).copied())?;
        self.advance(&tau)?;
        if (IDENTIFY_FROM..SWAP_AT).contains(&self.tick) {
            let (q1, v1) = (self.state.q, self.state.v);
            let q_mid = core::array::from_fn(|k| 0.5 * (q0[k] + q1[k]));
            let v_mid = core::array::from_fn(|k| 0.5 * (v0[k] + v1[k]));
            let a_mean = core::array::from_fn(|k| (v1[k] - v0[k]) / DT);
            self.estimator.add_sample(
                &panda::MODEL_F32,
                &mut self.estimator_data,
                &q_mid,
                &v_mid,
                &a_mean,
                &tau,
            )?;
        }
        if BEFORE.contains(&self.tick) {
            self.before.add(&error);
        }
        if AFTER.contains(&self.tick) {
            self.after.add(&error);
        }
        let outcome = TickOutcome {
            tick: self.tick,
            error,
            swapped,
        };
        self.tick += 1;
        Ok(outcome)
    }

    /// Solves for the payload, stages it at the flange and publishes it.
    #[inline]
    fn swap_in_identified(&mut self) -> Result<Option<IdentifiedPayload>> {
        let Some(found) = self.estimator.solve() else {
            return Ok(None);
        };
        // The centre of mass from the body's frame into the flange's.
        let com = FLANGE.placement.inverse().act_point(&found.com);
        let update = ModelUpdate::new([ParameterChange::Payload {
            frame: FLANGE,
            inertia: Inertia::point_mass(found.mass, com),
        }]);
        self.updates.stage_update(&update)?;
        self.updates.publish();
        Ok(Some(IdentifiedPayload { com, ..found }))
    }

    /// Advances the plant one tick under `tau`, held over the tick.
    #[inline]
    fn advance(&mut self, tau: &[f32; N]) -> Result<()> {
        let tau = *tau;
        let mut loads = |_: &PandaModel,
                         _: &mut Data<f32, { panda::NB }, N>,
                         _: f32,
                         _: &[f32; N],
                         _: &[f32; N],
                         tau_out: &mut [f32; N],
                         _: &mut [Force<f32>; panda::NB]|
         -> Result<()> {
            *tau_out = tau;
            Ok(())
        };
        let h = DT / SUBSTEPS as f32;
        for _ in 0..SUBSTEPS {
            self.integrator.step(
                Aba,
                &self.plant,
                &mut self.plant_data,
                &mut self.state,
                h,
                &mut loads,
            )?;
        }
        Ok(())
    }
}
