//! Task-space impedance control of one frame of a redundant arm (its flange).
//!
//! The frame is pulled toward a moving pose by a spring and a damper in the
//! task space, whose wrench reaches the joints through the frame's Jacobian
//! transpose; one RNEA call supplies gravity, the Coriolis and centrifugal
//! torques and the torques that give the reference's own acceleration; a
//! posture spring acts only in the Jacobian's null space:
//!
//! ```text
//! τ = RNEA(q, q̇, J⁺ (ẍ_d − J̇ q̇))                       gravity, Coriolis, feedforward
//!   + Jᵀ (K e + D (ẋ_d − J q̇))                          the task-space impedance
//!   + (I − Jᵀ J⁺ᵀ) (K_n (q_n − q) − D_n q̇)             the posture, in the null space
//! ```
//!
//! `J` is the frame's Jacobian in the world's axes at its origin (rodyn's
//! `LocalWorldAligned`, rows angular then linear), so that `J q̇` is the
//! frame's angular velocity and the velocity of its origin; `J̇ q̇` is its
//! classical acceleration at rest joints. `e` is the pose error in the same
//! axes: the rotation vector `log₃(R_d Rᵀ)` that carries the frame's axes
//! onto the desired ones (rad), and `p_d − p` (m). `J⁺ = Jᵀ (J Jᵀ + λ² I)⁻¹`
//! is the damped pseudo-inverse, one 6×6 Cholesky factor per tick shared by
//! the feedforward and the null-space projector.
//!
//! With an exact model the closed loop in the task space is
//! `ë + Λ⁻¹ (K e + D ė) = J M⁻¹ τ_n`, `Λ⁻¹ = J M⁻¹ Jᵀ`: an impedance whose
//! inertia is the arm's own at the frame. The right side is what the
//! posture term disturbs the task by: the projector is the static one (it
//! keeps the posture torque from doing work against a task force), not the
//! dynamically consistent one, which would need `M⁻¹`, so the posture gains
//! are kept small against the task's. The posture term holds the seventh
//! degree of freedom, the elbow's self-motion, that the task leaves free.
//!
//! The joint rates are estimated from the encoders ([`RateEstimate`]).

use super::pose_trajectory::PoseReference;
use super::{ControlError, RateEstimate, TickReport};
use crate::drivers::{AbsoluteEncoder, TorqueDrive};
use embedded_hal::pwm::SetDutyCycle;
use embedded_hal::spi::SpiDevice;
use rodyn::algorithm::dense::{cholesky_in_place, cholesky_solve};
use rodyn::algorithm::frame_chain::frame_kinematics_from_q;
use rodyn::algorithm::frames::ReferenceFrame;
use rodyn::algorithm::jacobian::mul_rates;
use rodyn::algorithm::rnea::rnea;
use rodyn::spatial::log3;
use rodyn::spatial::{Motion, Spatial, Vec3};
use rodyn::{Data, Frame, Model};

/// The task-space impedance, the posture term and the rate filter.
#[derive(Clone, Copy, Debug)]
pub struct TaskGains {
    /// Translational stiffness `K` (N/m), the same along every world axis.
    pub position_stiffness: f32,
    /// Translational damping `D` (N s/m).
    pub position_damping: f32,
    /// Rotational stiffness `K` (N m/rad).
    pub orientation_stiffness: f32,
    /// Rotational damping `D` (N m s/rad).
    pub orientation_damping: f32,
    /// Posture stiffness `K_n` of every joint (N m/rad), null space only.
    pub posture_stiffness: f32,
    /// Posture damping `D_n` of every joint (N m s/rad), null space only.
    pub posture_damping: f32,
    /// Damping `λ` of the pseudo-inverse (the units of `J`: m and 1, per
    /// radian of joint motion); keeps the 6×6 solve bounded near singular
    /// configurations.
    pub pseudo_inverse_damping: f32,
    /// Weight of the previous rate estimate, `exp(-dt / T_filter)`.
    pub rate_filter: f32,
}

impl TaskGains {
    /// The gains `task_space` drives the Panda's flange with, chosen by
    /// hand. The stiffnesses keep the impedance's natural frequencies
    /// `√(K / Λ)` (`Λ` the arm's inertia seen at the flange, smallest for
    /// turning the wrist) far below the 2 ms rate filter's corner and the
    /// 1 kHz tick; the dampings damp the tracking error without amplifying
    /// the rate estimate's quantisation noise; the posture gains are small
    /// against what the task's stiffness asks of the joints, so that the
    /// static projector's coupling into the task stays small.
    pub const PANDA_FLANGE: Self = Self {
        position_stiffness: 2_000.0,
        position_damping: 60.0,
        orientation_stiffness: 100.0,
        orientation_damping: 3.0,
        posture_stiffness: 5.0,
        posture_damping: 1.0,
        pseudo_inverse_damping: 1.0e-3,
        // A 2 ms filter time constant: exp(-1 ms / 2 ms).
        rate_filter: 0.606_530_66,
    };
}

/// A task-space impedance controller for a frame on a fixed-base chain of
/// `N` revolute joints, reading encoders and commanding torque drives.
#[derive(Debug)]
pub struct TaskSpaceImpedance<'m, SPI, PWM, const N: usize> {
    model: &'m Model<f32, N, N, N>,
    frame: Frame<f32>,
    data: Data<f32, N, N>,
    /// The frame's Jacobian (world axes, frame origin).
    j: [Motion<f32>; N],
    encoders: [AbsoluteEncoder<SPI>; N],
    drives: [TorqueDrive<PWM>; N],
    gains: TaskGains,
    /// The posture `q_n` the null-space term pulls toward (rad).
    posture: [f32; N],
    rate: RateEstimate<N>,
}

impl<'m, SPI: SpiDevice, PWM: SetDutyCycle, const N: usize> TaskSpaceImpedance<'m, SPI, PWM, N> {
    /// A controller of `frame` ticking every `dt` seconds, holding the
    /// redundant joints near `posture` (rad).
    pub fn new(
        model: &'m Model<f32, N, N, N>,
        frame: Frame<f32>,
        encoders: [AbsoluteEncoder<SPI>; N],
        drives: [TorqueDrive<PWM>; N],
        gains: TaskGains,
        posture: [f32; N],
        dt: f32,
    ) -> Self {
        Self {
            model,
            frame,
            data: Data::new(),
            j: [Motion::new(Vec3::ZERO, Vec3::ZERO); N],
            encoders,
            drives,
            gains,
            posture,
            rate: RateEstimate::new(gains.rate_filter, dt),
        }
    }

    /// One control tick: read the encoders, compute the torques that pull
    /// the frame toward `reference`, command the drives.
    ///
    /// # Errors
    /// A sensor, drive or dynamics failure, or a pseudo-inverse that is not
    /// finite; the drives keep their last command.
    pub fn tick(&mut self, reference: &PoseReference) -> Result<TickReport<N>, ControlError> {
        let mut q = [0.0; N];
        for (k, encoder) in self.encoders.iter_mut().enumerate() {
            q[k] = encoder
                .read_angle()
                .map_err(|e| ControlError::Encoder(k, e))?;
        }
        let v = *self.rate.update(&q);
        let g = self.gains;

        // The frame's pose, Jacobian, velocity `J q̇` and `J̇ q̇`, along the
        // joints that move it.
        let motion = frame_kinematics_from_q(
            self.model,
            &q,
            &v,
            &self.frame,
            ReferenceFrame::LocalWorldAligned,
            &mut self.j,
        )
        .map_err(ControlError::Dynamics)?;
        let (o_m_f, twist, dj_v) = (motion.placement, motion.velocity, motion.dj_v);

        // The task wrench (N m, N), angular first as the Jacobian's rows.
        let rate_error = reference.velocity - twist;
        let torque = log3(&reference.pose.rot.mul_mat_tr(&o_m_f.rot)) * g.orientation_stiffness
            + rate_error.ang * g.orientation_damping;
        let force = (reference.pose.trans - o_m_f.trans) * g.position_stiffness
            + rate_error.lin * g.position_damping;
        let wrench = components(&Motion::new(torque, force));

        // J Jᵀ + λ² I, factored once for both solves.
        let mut gram = [[0.0f32; 6]; 6];
        for column in &self.j {
            let c = components(column);
            for r in 0..6 {
                for s in 0..=r {
                    gram[r][s] += c[r] * c[s];
                }
            }
        }
        for (r, row) in gram.iter_mut().enumerate() {
            row[r] += g.pseudo_inverse_damping * g.pseudo_inverse_damping;
        }
        if cholesky_in_place(&mut gram, 6, 0.0).is_err() {
            return Err(ControlError::PseudoInverse);
        }

        // The joint accelerations of least norm that give the reference's
        // task acceleration: J⁺ (ẍ_d − J̇ q̇).
        let mut y = components(&(reference.acceleration - dj_v));
        cholesky_solve(&gram, 6, &mut y).map_err(ControlError::Dynamics)?;
        let a_feedforward: [f32; N] = core::array::from_fn(|k| dot6(&components(&self.j[k]), &y));

        // The posture torque without its component along the task: τ₀ − Jᵀ (J Jᵀ + λ² I)⁻¹ J τ₀.
        let tau_posture: [f32; N] = core::array::from_fn(|k| {
            g.posture_stiffness * (self.posture[k] - q[k]) - g.posture_damping * v[k]
        });
        let j_tau =
            mul_rates::<f32, N, Spatial>(&self.j, &tau_posture).map_err(ControlError::Dynamics)?;
        let mut z = components(&j_tau);
        cholesky_solve(&gram, 6, &mut z).map_err(ControlError::Dynamics)?;

        let tau_dynamics = *rnea(self.model, &mut self.data, &q, &v, &a_feedforward, None)
            .map_err(ControlError::Dynamics)?;
        let mut commanded = [0.0; N];
        for (k, drive) in self.drives.iter_mut().enumerate() {
            let c = components(&self.j[k]);
            let tau = tau_dynamics[k] + dot6(&c, &wrench) + tau_posture[k] - dot6(&c, &z);
            commanded[k] = drive
                .set_torque(tau)
                .map_err(|e| ControlError::Drive(k, e))?;
        }
        Ok(TickReport { q, tau: commanded })
    }
}

/// A motion's six components, angular first.
#[inline]
fn components(m: &Motion<f32>) -> [f32; 6] {
    [m.ang.x, m.ang.y, m.ang.z, m.lin.x, m.lin.y, m.lin.z]
}

#[inline]
fn dot6(a: &[f32; 6], b: &[f32; 6]) -> f32 {
    dot(a, b)
}

fn dot(a: &[f32], b: &[f32]) -> f32 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}
