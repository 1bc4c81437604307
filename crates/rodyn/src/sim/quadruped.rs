//! An Aibo-size quadruped: floating torso, four legs of three joints, feet
//! in compliant contact with the ground, and a PD stance / open-loop trot
//! controller. Everything here is `no_std`, so the same step runs in the
//! firmware.
//!
//! ## The model (numbers chosen, not measured)
//! The numbers are chosen in the range of a Sony Aibo ERS-7 (about 1.6-1.7
//! kg, legs of two segments of roughly 7-8 cm); they are not a measured
//! Aibo. The x axis points forward, y to the left, z up.
//!
//! | body            | joint                  | mass (kg) | inertia                                    |
//! |-----------------|------------------------|-----------|--------------------------------------------|
//! | torso           | free flyer             | 1.40      | box 0.20 x 0.10 x 0.07 m                   |
//! | hip (x4)        | abduction about x      | 0.020     | sphere of radius 1.5 cm                    |
//! | thigh (x4)      | hip pitch about y      | 0.070     | rod 0.075 m along -z, centre at mid-length |
//! | shin (x4)       | knee pitch about y     | 0.040     | rod 0.075 m along -z, centre at mid-length |
//!
//! Total 1.92 kg (a little heavier than an ERS-7, whose legs carry motors we
//! do not model separately; no rotor inertia). Hips sit at x = ±0.07 m, y = ±0.05 m in the torso frame;
//! the knee is 0.075 m below the hip pitch axis, the foot (the contact
//! point, an [`Endpoint`]) 0.075 m below the knee. Bodies are numbered torso
//! 0, then per leg (front left, front right, hind left, hind right) hip,
//! thigh, shin; velocity coordinates are the torso's six
//! (`[vx vy vz ωx ωy ωz]`, body frame) then `[abduction, hip, knee]` per leg.

use super::contact::{ContactReport, GroundContact, NormalLaw};
use super::integrator::Integrator;
use super::loads::Loads;
use super::state::State;
use crate::algorithm::forward_dynamics::ForwardDynamics;
use crate::data::Data;
use crate::endpoint::Endpoint;
use crate::error::Result;
use crate::joint::{Axis, Joint};
use crate::model::Model;
use crate::spatial::{Force, Inertia, Motion, Spatial, Sym3, Transform, Vec3};
use crate::Scalar;
use core::f64::consts::PI;

/// Number of bodies: torso and 4 x (hip, thigh, shin).
pub const NB: usize = 13;
/// Configuration coordinates: 7 for the torso, 12 joint angles.
pub const NQ: usize = 19;
/// Velocity coordinates: 6 for the torso, 12 joint rates.
pub const NV: usize = 18;
/// Number of legs.
pub const LEGS: usize = 4;

/// The quadruped's model type.
pub type QuadrupedModel<S> = Model<S, NB, NQ, NV, Spatial>;
/// Its workspace.
pub type QuadrupedData<S> = Data<S, NB, NV, Spatial>;
/// Its state.
pub type QuadrupedState<S> = State<S, NQ, NV>;

/// Thigh length, hip pitch axis to knee (m).
pub const THIGH_LENGTH: f64 = 0.075;
/// Shin length, knee to foot (m).
pub const SHIN_LENGTH: f64 = 0.075;
/// Hip positions in the torso frame (m), legs in the order FL, FR, HL, HR.
pub const HIP_POSITIONS: [[f64; 3]; LEGS] = [
    [0.07, 0.05, 0.0],
    [0.07, -0.05, 0.0],
    [-0.07, 0.05, 0.0],
    [-0.07, -0.05, 0.0],
];
/// Names of the legs, in body order.
pub const LEG_NAMES: [&str; LEGS] = ["front-left", "front-right", "hind-left", "hind-right"];

/// Body index of leg `leg`'s shin (the body that carries the foot).
#[must_use]
pub const fn shin_body(leg: usize) -> usize {
    3 + 3 * leg
}

/// Velocity index of leg `leg`'s joint `joint` (0 abduction, 1 hip, 2 knee);
/// the configuration index is one more (the quaternion has 4 entries).
#[must_use]
pub const fn joint_velocity_index(leg: usize, joint: usize) -> usize {
    6 + 3 * leg + joint
}

fn rod<S: Scalar>(mass: f64, length: f64) -> Inertia<S> {
    let across = mass * length * length / 12.0;
    Inertia::new(
        S::from_f64(mass),
        Vec3::new(S::ZERO, S::ZERO, S::from_f64(-length / 2.0)),
        Sym3::diagonal(
            S::from_f64(across),
            S::from_f64(across),
            S::from_f64(across * 1e-2),
        ),
    )
}

/// The quadruped model, gravity 9.81 m/s² along -z.
#[must_use]
pub fn model<S: Scalar>() -> QuadrupedModel<S> {
    let f = S::from_f64;
    let (m_torso, a, b, c) = (1.40, 0.20, 0.10, 0.07);
    let torso = Inertia::new(
        f(m_torso),
        Vec3::ZERO,
        Sym3::diagonal(
            f(m_torso / 12.0 * (b * b + c * c)),
            f(m_torso / 12.0 * (a * a + c * c)),
            f(m_torso / 12.0 * (a * a + b * b)),
        ),
    );
    let hip = Inertia::new(
        f(0.02),
        Vec3::ZERO,
        Sym3::identity_scaled(f(0.4 * 0.02 * 0.015 * 0.015)),
    );
    let mut parents = [None; NB];
    let mut joints = [Joint::free_flyer(); NB];
    let mut placements = [Transform::IDENTITY; NB];
    let mut inertias = [torso; NB];
    for leg in 0..LEGS {
        let (h, t, s) = (1 + 3 * leg, 2 + 3 * leg, 3 + 3 * leg);
        let [x, y, z] = HIP_POSITIONS[leg];
        parents[h] = Some(0);
        parents[t] = Some(h);
        parents[s] = Some(t);
        joints[h] = Joint::revolute(Axis::X);
        joints[t] = Joint::revolute(Axis::Y);
        joints[s] = Joint::revolute(Axis::Y);
        placements[h] = Transform::from_translation(Vec3::new(f(x), f(y), f(z)));
        placements[s] = Transform::from_translation(Vec3::new(S::ZERO, S::ZERO, f(-THIGH_LENGTH)));
        inertias[h] = hip;
        inertias[t] = rod(0.07, THIGH_LENGTH);
        inertias[s] = rod(0.04, SHIN_LENGTH);
    }
    Model::new(
        parents,
        joints,
        placements,
        inertias,
        Motion::new(Vec3::ZERO, Vec3::new(S::ZERO, S::ZERO, f(-9.81))),
    )
}

/// The four feet, as points at the end of each shin.
#[must_use]
pub fn feet<S: Scalar>() -> [Endpoint<S>; LEGS] {
    core::array::from_fn(|leg| {
        Endpoint::on_body(
            shin_body(leg),
            Vec3::new(S::ZERO, S::ZERO, S::from_f64(-SHIN_LENGTH)),
        )
    })
}

/// A ground for the quadruped: linear spring-damper of 5 kN/m and 10 N s/m,
/// μ = 0.8, slip scale 0.2 m/s. A standing foot sinks by about 1 mm.
///
/// The damping and the slip scale are chosen so that a 1 kHz explicit
/// loop stays stable: with legs of a few tens of grams, the friction's
/// viscous slope `μ λ / s₀` and the normal damping are the stiffest terms
/// of the whole system (`rodyn-sim failures contact` maps this).
#[must_use]
pub fn default_ground<S: Scalar>() -> GroundContact<S> {
    GroundContact {
        normal: NormalLaw::LinearSpringDamper {
            stiffness: S::from_f64(5.0e3),
            damping: S::from_f64(10.0),
        },
        friction: S::from_f64(0.8),
        slip_scale: S::from_f64(0.2),
    }
}

/// The gait the joint controller follows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Gait<S> {
    /// Hold the stance pose.
    Stand,
    /// An open-loop trot: diagonal legs in phase, the two pairs half a
    /// period apart; the hip swings sinusoidally and the knee folds during
    /// the forward swing. The amplitudes ramp up over the first period.
    Trot {
        /// Stride frequency (Hz).
        frequency: S,
        /// Hip pitch amplitude (rad).
        hip_amplitude: S,
        /// Extra knee flexion at mid-swing (rad).
        knee_lift: S,
    },
}

/// PD joint control towards a stance pose or a trot, plus ground contact:
/// the [`Loads`] of a quadruped simulation.
///
/// Torques `τ = kp (q* - q) - kd q̇` on the twelve leg joints (N m); the
/// torso is unactuated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadrupedLoads<S: Scalar> {
    /// Proportional gain (N m/rad).
    pub kp: S,
    /// Derivative gain (N m s/rad).
    pub kd: S,
    /// Stance joint angles `[abduction, hip, knee]` (rad), the same for every leg.
    pub stance: [S; 3],
    /// What the legs do.
    pub gait: Gait<S>,
    /// The ground.
    pub ground: GroundContact<S>,
    /// The contact points.
    pub feet: [Endpoint<S>; LEGS],
    /// What each foot did at the last evaluation.
    pub reports: [ContactReport<S>; LEGS],
}

impl<S: Scalar> QuadrupedLoads<S> {
    /// Standing control: kp = 8 N m/rad, kd = 0.05 N m s/rad, stance with the
    /// hip at 0.6 rad and the knee at -1.2 rad (feet under the hips, hip
    /// height 0.124 m), on [`default_ground`].
    #[must_use]
    pub fn standing() -> Self {
        Self {
            kp: S::from_f64(8.0),
            kd: S::from_f64(0.05),
            stance: [S::ZERO, S::from_f64(0.6), S::from_f64(-1.2)],
            gait: Gait::Stand,
            ground: default_ground(),
            feet: feet(),
            reports: [ContactReport {
                position: Vec3::ZERO,
                penetration: S::ZERO,
                force: Vec3::ZERO,
            }; LEGS],
        }
    }

    /// A trot at 3 Hz, hip amplitude 0.2 rad, knee lift 0.4 rad (about
    /// 0.2 m/s forward, with a slow yaw drift: it is open loop).
    #[must_use]
    pub fn trotting() -> Self {
        Self {
            gait: Gait::Trot {
                frequency: S::from_f64(3.0),
                hip_amplitude: S::from_f64(0.2),
                knee_lift: S::from_f64(0.4),
            },
            ..Self::standing()
        }
    }

    /// Joint targets `[abduction, hip, knee]` of `leg` at time `t`.
    #[must_use]
    pub fn targets(&self, leg: usize, t: S) -> [S; 3] {
        let [abduction, hip, knee] = self.stance;
        match self.gait {
            Gait::Stand => [abduction, hip, knee],
            Gait::Trot {
                frequency,
                hip_amplitude,
                knee_lift,
            } => {
                // Front-left with hind-right, front-right with hind-left.
                let pair_phase = if leg == 0 || leg == 3 { 0.0 } else { PI };
                let phase = S::from_f64(2.0 * PI) * frequency * t + S::from_f64(pair_phase);
                let ramp = (frequency * t).min(S::ONE);
                let (sin, cos) = phase.sin_cos();
                // The hip angle grows (foot moves back: stance, pushing the
                // body forward) while cos > 0 and shrinks (swing) while cos < 0;
                // the knee folds during the swing to lift the foot.
                let lift = (-cos).max(S::ZERO);
                [
                    abduction,
                    hip + ramp * hip_amplitude * sin,
                    knee - ramp * knee_lift * lift,
                ]
            }
        }
    }

    /// A state with the torso at height `height` (m), level and at rest, and
    /// the joints in the stance pose.
    #[must_use]
    pub fn initial_state(&self, height: S) -> QuadrupedState<S> {
        let mut q = [S::ZERO; NQ];
        q[2] = height;
        q[6] = S::ONE;
        for leg in 0..LEGS {
            for joint in 0..3 {
                q[joint_velocity_index(leg, joint) + 1] = self.stance[joint];
            }
        }
        State::new(q, [S::ZERO; NV])
    }

    /// The torso height (m) at which the stance feet just touch the ground.
    #[must_use]
    pub fn stance_height(&self) -> S {
        let [_, hip, knee] = self.stance;
        // Foot height below the hip in the sagittal plane.
        let (thigh, shin) = (S::from_f64(THIGH_LENGTH), S::from_f64(SHIN_LENGTH));
        thigh * hip.cos() + shin * (hip + knee).cos()
    }
}

impl<S: Scalar> Loads<S, NB, NQ, NV, Spatial> for QuadrupedLoads<S> {
    fn loads(
        &mut self,
        model: &QuadrupedModel<S>,
        data: &mut QuadrupedData<S>,
        t: S,
        q: &[S; NQ],
        v: &[S; NV],
        tau: &mut [S; NV],
        f_ext: &mut [Force<S>; NB],
    ) -> Result<()> {
        self.ground.add_forces(
            model,
            data,
            q,
            v,
            &self.feet,
            f_ext,
            Some(&mut self.reports),
        )?;
        for leg in 0..LEGS {
            let targets = self.targets(leg, t);
            for (joint, target) in targets.into_iter().enumerate() {
                let iv = joint_velocity_index(leg, joint);
                tau[iv] += self.kp * (target - q[iv + 1]) - self.kd * v[iv];
            }
        }
        Ok(())
    }
}

/// One simulation step of the quadruped with contact: the call a firmware
/// makes every tick. `method` is `Aba` or `Crba`, `integrator` any
/// [`Integrator`] (semi-implicit Euler at 1 kHz is the cheap choice, see the
/// workspace's simulation chart).
///
/// # Errors
/// As [`Integrator::step`]; the state is unchanged on error.
pub fn step<I: Integrator, F: ForwardDynamics, S: Scalar>(
    integrator: &mut I,
    method: F,
    model: &QuadrupedModel<S>,
    data: &mut QuadrupedData<S>,
    loads: &mut QuadrupedLoads<S>,
    state: &mut QuadrupedState<S>,
    dt: S,
) -> Result<()> {
    integrator.step(method, model, data, state, dt, loads)
}
