//! A trotting controller for the [`quadruped`](crate::quadruped) that holds the trunk's
//! height and attitude with inverse dynamics with contacts
//! ([`rodyn::algorithm::contact_inverse_dynamics`]).
//!
//! Each tick it writes a wanted acceleration for every coordinate, then
//! asks the inverse dynamics for the torques that produce it with the
//! stance feet held:
//!
//! - **trunk** (the free flyer's six): a PD on the height of the trunk's
//!   origin and on its attitude (level, heading 0: `−K_R log3(R)` and
//!   `−D_R ω` in world axes), and a damping of the horizontal velocity
//!   towards a forward speed that ramps up over the first second;
//! - **legs**: a PD towards the trot's joint trajectory ([`QuadrupedLoads::targets`]),
//!   which only the swing legs can follow: a stance foot's acceleration
//!   is held at zero by the contact, and the inverse dynamics moves the
//!   wanted acceleration onto what the contacts allow.
//!
//! The torques are the inverse dynamics' plus the trot's joint stiffness
//! `kp (q* − q)`, whose compliance carries the gait through touch-downs
//! that come early or late; the trot's joint damping is left to the drives
//! ([`TrunkController::joint_damping`]). A foot is a contact when the
//! simulation (or a foot switch) says it touches the ground. The trunk and
//! swing gains are in acceleration units (1/s², 1/s), so they do not
//! depend on the masses.
//! In a trot only two feet stand: they cannot turn the trunk about the
//! line between them, and that share of the wanted trunk motion is left
//! out (the inverse dynamics' residual); the next pair catches it.

use crate::quadruped::{
    foot_frames, trunk_position, QuadrupedData, QuadrupedLoads, QuadrupedModel, LEGS, LEG_JOINTS,
    NV,
};
use rodyn::algorithm::constrained_dynamics::{ConstraintSettings, Contact};
use rodyn::algorithm::contact_inverse_dynamics::{
    contact_inverse_dynamics, ContactInverseDynamicsData, ContactInverseDynamicsSettings,
};
use rodyn::spatial::{log3, Mat3, Vec3};
use rodyn::{Result, Scalar};

/// Rows of the contact workspace: three per foot.
pub const CONTACT_ROWS: usize = 3 * LEGS;

/// The workspace of [`TrunkController::torques`].
pub type TrunkControllerData<S> = ContactInverseDynamicsData<S, NV, CONTACT_ROWS>;

/// The controller's targets and gains.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrunkController<S: Scalar> {
    /// The trot: its joint trajectory and stance pose.
    pub gait: QuadrupedLoads<S>,
    /// Wanted height of the trunk's origin above the ground (m).
    pub height: S,
    /// Forward speed to reach after the first second (m/s).
    pub speed: S,
    /// Height stiffness (1/s²) and damping (1/s).
    pub height_gains: [S; 2],
    /// Attitude stiffness (1/s²) and damping (1/s).
    pub attitude_gains: [S; 2],
    /// Horizontal velocity damping (1/s).
    pub velocity_gain: S,
    /// Joint stiffness (1/s²) and damping (1/s) of the swing legs.
    pub joint_gains: [S; 2],
    /// The inverse dynamics' settings (friction of the cone check).
    pub settings: ContactInverseDynamicsSettings<S>,
}

impl<S: Scalar> TrunkController<S> {
    /// The trot of [`QuadrupedLoads::trotting`] at the stance height,
    /// 0.2 m/s forward; trunk gains 400 1/s² and 40 1/s, joints 900 1/s²
    /// and 60 1/s, friction 0.8.
    #[must_use]
    pub fn trotting() -> Self {
        let gait = QuadrupedLoads::trotting();
        let f = S::from_f64;
        Self {
            height: gait.stance_height(),
            gait,
            speed: f(0.2),
            height_gains: [f(400.0), f(40.0)],
            attitude_gains: [f(400.0), f(40.0)],
            velocity_gain: f(10.0),
            joint_gains: [f(900.0), f(60.0)],
            settings: ContactInverseDynamicsSettings::floating_base(f(0.8)),
        }
    }

    /// The joint torques (N m; zero on the trunk) at time `t` and state
    /// `(q, v)`, with `touching[leg]` telling which feet touch the ground.
    /// Also leaves the contact forces and the residual in `cdata`.
    ///
    /// # Errors
    /// Those of [`contact_inverse_dynamics`].
    #[allow(clippy::too_many_arguments)]
    pub fn torques<'d>(
        &self,
        model: &QuadrupedModel<S>,
        data: &mut QuadrupedData<S>,
        cdata: &'d mut TrunkControllerData<S>,
        t: S,
        q: &[S; crate::quadruped::NQ],
        v: &[S; NV],
        touching: &[bool; LEGS],
    ) -> Result<&'d [S; NV]> {
        let wanted = self.wanted_acceleration(t, q, v);

        // The touching feet as contacts. Their anchors are not used: without
        // Baumgarte gains the inverse dynamics keeps the feet's
        // accelerations at zero, wherever they stand.
        let frames = foot_frames::<S>();
        let mut contacts = [Contact::point(frames[0], Vec3::ZERO); LEGS];
        let mut n = 0;
        for (leg, frame) in frames.iter().enumerate() {
            if touching[leg] {
                contacts[n] = Contact::point(*frame, Vec3::ZERO);
                n += 1;
            }
        }
        contact_inverse_dynamics(
            model,
            data,
            cdata,
            q,
            v,
            &wanted,
            &contacts[..n],
            &ConstraintSettings::default(),
            &self.settings,
        )?;
        // The trot's joint stiffness on top: the stance legs' compliance,
        // which carries the gait through touch-downs the schedule does not
        // foresee. Its damping is the drives' (see `joint_damping`).
        let stiffness = self.gait.joint_torques(t, q, &[S::ZERO; NV]);
        for (tau, k) in cdata.tau.iter_mut().zip(stiffness) {
            *tau += k;
        }
        Ok(&cdata.tau)
    }

    /// The joint damping the drives apply (N m s/rad, the trot's `kd` on
    /// every leg joint): a current loop far faster than the controller,
    /// which a simulation takes implicitly
    /// ([`time_step`](rodyn::sim::time_stepping::time_step)'s `damping`).
    #[must_use]
    pub fn joint_damping(&self) -> [S; NV] {
        let mut damping = [S::ZERO; NV];
        for iv in LEG_JOINTS.into_iter().flatten() {
            damping[iv] = self.gait.kd;
        }
        damping
    }

    /// The wanted `q̈`: trunk PDs in world axes turned into the free
    /// flyer's body-axis coordinates, joint PDs towards the trot.
    fn wanted_acceleration(&self, t: S, q: &[S; crate::quadruped::NQ], v: &[S; NV]) -> [S; NV] {
        let mut wanted = [S::ZERO; NV];
        // The trunk: q = [x y z qx qy qz qw], v = [v_body; ω_body].
        let r = Mat3::from_quaternion(q[3], q[4], q[5], q[6]);
        let v_body = Vec3::new(v[0], v[1], v[2]);
        let w_body = Vec3::new(v[3], v[4], v[5]);
        let v_world = r.mul_vec(&v_body);
        let w_world = r.mul_vec(&w_body);
        let ramp = t.min(S::ONE).max(S::ZERO);
        let [kh, dh] = self.height_gains;
        let z = trunk_position(q).z;
        let a_world = Vec3::new(
            self.velocity_gain * (self.speed * ramp - v_world.x),
            -self.velocity_gain * v_world.y,
            kh * (self.height - z) - dh * v_world.z,
        );
        // Level with heading 0: the rotation error is R itself.
        let [kr, dr] = self.attitude_gains;
        let alpha_world = -(log3(&r) * kr) - w_world * dr;
        // v̇_body = Rᵀ a − ω_body × v_body; ω̇_body = Rᵀ α.
        let lin = r.tr_mul_vec(&a_world) - w_body.cross(&v_body);
        let ang = r.tr_mul_vec(&alpha_world);
        wanted[..3].copy_from_slice(&lin.to_array());
        wanted[3..6].copy_from_slice(&ang.to_array());

        // The legs: PD towards the trot, its rate by a central difference.
        let [kj, dj] = self.joint_gains;
        let h = S::from_f64(1e-3);
        for (leg, joints) in LEG_JOINTS.into_iter().enumerate() {
            let now = self.gait.targets(leg, t);
            let ahead = self.gait.targets(leg, t + h);
            let behind = self.gait.targets(leg, t - h);
            for (k, iv) in joints.into_iter().enumerate() {
                let rate = (ahead[k] - behind[k]) / (h + h);
                wanted[iv] = kj * (now[k] - q[iv + 1]) + dj * (rate - v[iv]);
            }
        }
        wanted
    }
}
