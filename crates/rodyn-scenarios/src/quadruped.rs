//! The Aibo-size quadruped of [`crate::aibo`] (`models/aibo.toml`):
//! a PD stance / open-loop trot controller, ground contact at the four
//! feet, and the one call per step that a firmware makes every tick.
//!
//! The robot is the model file's: a 1.0 kg trunk and four legs of a 20 g
//! shoulder, an 80 g thigh of 69.5 mm and a 50 g shank of 76 mm (1.6 kg in
//! all), shoulders at x = ±65 mm, y = ±62.5 mm. Each leg's joints are, in
//! coordinate order, hip pitch (about y), hip roll (about x) and knee
//! (about y); positive pitch and knee angles swing the foot backward. The
//! feet are the file's contacts: a linear spring-damper ground of 5 kN/m and
//! 50 N s/m, μ = 0.8. Frames: x forward, y left, z up, gravity -z.
//!
//! Legs are numbered front left, front right, hind left, hind right
//! ([`LEG_NAMES`]); a leg's joint angles are always `[hip pitch, hip roll,
//! knee]` (rad).

use crate::aibo;
use core::f64::consts::PI;
use rodyn::algorithm::forward_dynamics::ForwardDynamics;
use rodyn::drive::PointGeometry;
use rodyn::sim::contact::{ContactReport, GroundContact, NormalLaw};
use rodyn::sim::time_stepping::{time_step, TimeSteppingData, TimeSteppingSettings};
use rodyn::sim::{Integrator, Loads, State};
use rodyn::spatial::{Force, Spatial, Transform, Vec3};
use rodyn::{Data, Endpoint, Frame, Model, Result, Scalar};

pub use aibo::{NB, NQ, NV};

/// Number of legs.
pub const LEGS: usize = 4;
/// Names of the legs, in body order.
pub const LEG_NAMES: [&str; LEGS] = ["front-left", "front-right", "hind-left", "hind-right"];

/// The quadruped's model type.
pub type QuadrupedModel<S> = Model<S, NB, NQ, NV, Spatial>;
/// Its workspace.
pub type QuadrupedData<S> = Data<S, NB, NV, Spatial>;
/// Its state.
pub type QuadrupedState<S> = State<S, NQ, NV>;

/// Velocity index of each leg's `[hip pitch, hip roll, knee]`; the
/// configuration index is one more (the trunk's quaternion has 4 entries
/// for 3 rates).
pub const LEG_JOINTS: [[usize; 3]; LEGS] = {
    use aibo::v;
    [
        [v::FL_HIP_PITCH, v::FL_HIP_ROLL, v::FL_KNEE],
        [v::FR_HIP_PITCH, v::FR_HIP_ROLL, v::FR_KNEE],
        [v::HL_HIP_PITCH, v::HL_HIP_ROLL, v::HL_KNEE],
        [v::HR_HIP_PITCH, v::HR_HIP_ROLL, v::HR_KNEE],
    ]
};

/// The model in scalar type `S`.
///
/// # Errors
/// None for this model (its joints are all built in); the `Result` is that
/// of [`Model::cast`].
pub fn model<S: Scalar>() -> Result<QuadrupedModel<S>> {
    aibo::MODEL_F64.cast()
}

/// The four feet (the model file's contact points) in scalar type `S`.
#[must_use]
pub fn feet<S: Scalar>() -> [Endpoint<S>; LEGS] {
    aibo::CONTACT_POINTS_F64.map(|foot| {
        let position = <Spatial as PointGeometry>::cast_point(&foot.position);
        match foot.body {
            Some(body) => Endpoint::on_body(body, position),
            None => Endpoint::in_world(position),
        }
    })
}

/// The model file's ground in scalar type `S` (its four foot contacts
/// share one law; a test checks it).
#[must_use]
pub fn ground<S: Scalar>() -> GroundContact<S> {
    let c = aibo::CONTACTS_F64[aibo::contact::FL_FOOT_CONTACT];
    let f = S::from_f64;
    GroundContact {
        normal: match c.normal {
            NormalLaw::LinearSpringDamper { stiffness, damping } => NormalLaw::LinearSpringDamper {
                stiffness: f(stiffness),
                damping: f(damping),
            },
            NormalLaw::HuntCrossley { stiffness, damping } => NormalLaw::HuntCrossley {
                stiffness: f(stiffness),
                damping: f(damping),
            },
        },
        friction: f(c.friction),
        slip_scale: f(c.slip_scale),
    }
}

/// The gait the joint controller follows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Gait<S> {
    /// Hold the stance pose.
    Stand,
    /// An open-loop trot: diagonal legs in phase, the two pairs half a
    /// period apart; the hip pitches sinusoidally and the knee folds during
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
/// trunk is unactuated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadrupedLoads<S: Scalar> {
    /// Proportional gain (N m/rad).
    pub kp: S,
    /// Derivative gain (N m s/rad).
    pub kd: S,
    /// Stance joint angles `[hip pitch, hip roll, knee]` (rad), the same for every leg.
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
    /// hip pitched 0.6 rad and the knee at -1.2 rad (feet 4 mm ahead of the
    /// shoulders, shoulder height 0.120 m), on the model file's [`ground`].
    #[must_use]
    pub fn standing() -> Self {
        Self {
            kp: S::from_f64(8.0),
            kd: S::from_f64(0.05),
            stance: [S::from_f64(0.6), S::ZERO, S::from_f64(-1.2)],
            gait: Gait::Stand,
            ground: ground(),
            feet: feet(),
            reports: [ContactReport {
                position: Vec3::ZERO,
                penetration: S::ZERO,
                force: Vec3::ZERO,
            }; LEGS],
        }
    }

    /// A trot at 3 Hz, hip amplitude 0.2 rad, knee lift 0.4 rad (open loop:
    /// it drifts in yaw).
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

    /// Joint targets `[hip pitch, hip roll, knee]` of `leg` at time `t` (s).
    #[must_use]
    pub fn targets(&self, leg: usize, t: S) -> [S; 3] {
        let [hip, roll, knee] = self.stance;
        match self.gait {
            Gait::Stand => self.stance,
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
                    hip + ramp * hip_amplitude * sin,
                    roll,
                    knee - ramp * knee_lift * lift,
                ]
            }
        }
    }

    /// A state with the trunk's origin at world height `height` (m) above
    /// the world origin, level and at rest, and the joints in the stance
    /// pose.
    ///
    /// The model file places the floating joint 0.2 m above the world
    /// origin (so that `q = 0` stands the legs straight), and the trunk's
    /// position coordinates are measured from there: see [`trunk_position`].
    #[must_use]
    pub fn initial_state(&self, height: S) -> QuadrupedState<S> {
        let root = root_offset();
        let mut q = [S::ZERO; NQ];
        q[0] = S::from_f64(-root.x);
        q[1] = S::from_f64(-root.y);
        q[2] = height - S::from_f64(root.z);
        q[6] = S::ONE;
        for joints in LEG_JOINTS {
            for (iv, angle) in joints.into_iter().zip(self.stance) {
                q[iv + 1] = angle;
            }
        }
        State::new(q, [S::ZERO; NV])
    }

    /// The trunk height (m) at which the stance feet just touch the ground.
    #[must_use]
    pub fn stance_height(&self) -> S {
        let [hip, _, knee] = self.stance;
        let (thigh, shank) = leg_lengths();
        // Foot below the shoulder in the sagittal plane; the shoulders sit
        // at the trunk origin's height.
        S::from_f64(thigh) * hip.cos() + S::from_f64(shank) * (hip + knee).cos()
    }
}

/// The world position (m) of the trunk's origin in configuration `q`: the
/// floating joint's translation plus its placement in the world.
#[must_use]
pub fn trunk_position<S: Scalar>(q: &[S; NQ]) -> Vec3<S> {
    let root = root_offset();
    Vec3::new(
        q[0] + S::from_f64(root.x),
        q[1] + S::from_f64(root.y),
        q[2] + S::from_f64(root.z),
    )
}

/// Where the model file places the floating joint in the world (m); its
/// placement has no rotation (a test checks it), so the trunk's position
/// coordinates are world coordinates shifted by this offset.
fn root_offset() -> Vec3<f64> {
    aibo::MODEL_F64.placement(aibo::body::TRUNK).trans
}

/// Thigh (shoulder to knee) and shank (knee to foot) lengths (m), read from
/// the model file.
fn leg_lengths() -> (f64, f64) {
    let knee = aibo::MODEL_F64.placement(aibo::body::FL_SHANK).trans;
    let foot = aibo::ENDPOINTS_F64[aibo::endpoint::FL_FOOT].position;
    (knee.norm(), foot.norm())
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
        for (tau, joint) in tau.iter_mut().zip(self.joint_torques(t, q, v)) {
            *tau += joint;
        }
        Ok(())
    }
}

impl<S: Scalar> QuadrupedLoads<S> {
    /// The PD torques `kp (q* − q) − kd q̇` on the leg joints at time `t`
    /// (N m; zero on the trunk's six coordinates).
    #[must_use]
    pub fn joint_torques(&self, t: S, q: &[S; NQ], v: &[S; NV]) -> [S; NV] {
        let mut tau = [S::ZERO; NV];
        for (leg, joints) in LEG_JOINTS.into_iter().enumerate() {
            for (iv, target) in joints.into_iter().zip(self.targets(leg, t)) {
                tau[iv] = self.kp * (target - q[iv + 1]) - self.kd * v[iv];
            }
        }
        tau
    }
}

/// The feet as frames (their points, no rotation) for rigid contact.
#[must_use]
pub fn foot_frames<S: Scalar>() -> [Frame<S, Spatial>; LEGS] {
    feet::<S>().map(|foot| {
        // The model file puts every foot on a shank (a test checks).
        let body = foot.body.unwrap_or(0);
        Frame::new(body, Transform::from_translation(foot.position))
    })
}

/// Rigid ground contact for [`rigid_step`]: the model file's friction
/// coefficient and [`TimeSteppingSettings::with_friction`]'s defaults.
#[must_use]
pub fn rigid_ground<S: Scalar>() -> TimeSteppingSettings<S> {
    TimeSteppingSettings::with_friction(ground::<S>().friction)
}

/// The workspace of [`rigid_step`]: three rows per foot.
pub type RigidContactData<S> = TimeSteppingData<S, NV, { 3 * LEGS }, LEGS>;

/// One step of the quadruped with rigid feet on the ground and Coulomb
/// friction ([`rodyn::sim::time_stepping`]): the controller's stiffness
/// torques `kp (q* − q)` at the step's start and its damping `kd`
/// implicitly, then one time step. Unlike [`step`]'s spring-damper ground
/// it stays stable at 5 ms steps.
///
/// # Errors
/// As [`time_step`]; the state is unchanged on error.
#[allow(clippy::too_many_arguments)]
pub fn rigid_step<S: Scalar>(
    model: &QuadrupedModel<S>,
    data: &mut QuadrupedData<S>,
    contact: &mut RigidContactData<S>,
    loads: &QuadrupedLoads<S>,
    ground: &TimeSteppingSettings<S>,
    state: &mut QuadrupedState<S>,
    dt: S,
) -> Result<()> {
    // The PD torques at v = 0 are the stiffness part; kd goes implicit.
    let tau = loads.joint_torques(state.t, &state.q, &[S::ZERO; NV]);
    let mut damping = [S::ZERO; NV];
    for iv in LEG_JOINTS.into_iter().flatten() {
        damping[iv] = loads.kd;
    }
    time_step(
        model,
        data,
        contact,
        state,
        &tau,
        &damping,
        &foot_frames(),
        ground,
        dt,
    )
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_model_files_feet_share_one_ground_and_the_root_is_not_rotated() {
        for c in aibo::CONTACTS_F64 {
            assert_eq!(c, aibo::CONTACTS_F64[0]);
        }
        let root = aibo::MODEL_F64.placement(aibo::body::TRUNK);
        assert_eq!(root.rot, rodyn::spatial::Mat3::IDENTITY);
        assert!((root.trans.z - 0.2).abs() < 1e-15);
    }

    #[test]
    fn every_foot_is_on_a_body() {
        for foot in feet::<f64>() {
            assert!(foot.body.is_some_and(|b| b > 0), "{foot:?}");
        }
    }

    #[test]
    fn stance_puts_the_feet_on_the_ground_at_the_stance_height() {
        let loads = QuadrupedLoads::<f64>::standing();
        let height = loads.stance_height();
        // 69.5 mm and 76 mm segments at 0.6 rad from the vertical.
        assert!((height - 0.1455 * 0.6f64.cos()).abs() < 1e-12, "{height}");
        let state = loads.initial_state(height);
        assert!((trunk_position(&state.q).z - height).abs() < 1e-15);
        let model = model::<f64>().unwrap();
        let mut data = QuadrupedData::new();
        rodyn::algorithm::kinematics::forward_kinematics(&model, &mut data, &state.q).unwrap();
        for foot in feet::<f64>() {
            let p = foot.world_position(&data.o_m_i).unwrap();
            assert!(p.z.abs() < 1e-12, "foot at z = {}", p.z);
        }
    }
}
