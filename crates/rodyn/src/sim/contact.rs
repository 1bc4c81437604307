//! Compliant point contact with flat ground, for the feet of legged robots.
//!
//! The ground is the plane `z = 0` of the world frame, its normal `+z`
//! (gravity should point along `-z`). A contact point (an
//! [`Endpoint`] on a body) that sinks below it by the
//! penetration `δ = -z > 0` feels
//!
//! * a **normal force** from a spring-damper ([`NormalLaw`]): linear,
//!   `λ = k δ + c δ̇`, or Hunt-Crossley, `λ = k δ (1 + d δ̇)`, whose damping
//!   vanishes with the penetration so that the force is continuous at
//!   touch-down;
//! * **no pull**: `λ` is clamped at zero. The ground can push a foot but not
//!   hold it; a fast-rising foot whose damping term would make `λ`
//!   negative simply leaves. This is physics, not a numerical patch: the
//!   clamp is where the contact force stops being smooth, which is why
//!   high-order integrators lose their order through contact;
//! * a **regularised Coulomb friction** force opposing the tangential slip
//!   velocity `s`: `f_t = -μ λ tanh(|s| / s₀) s / |s|`. Below the slip
//!   scale `s₀` it behaves like a viscous damper of coefficient `μ λ / s₀`,
//!   so a "standing" foot creeps slowly instead of sticking; above it the
//!   force is Coulomb's `μ λ`. A smaller `s₀` is stiffer (smaller steps).
//!
//! The force acts at the contact point and is handed to the dynamics as a
//! spatial force on the point's body, in that body's frame.
//!
//! Units: N/m, N s/m, s/m, m/s, N.

use crate::algorithm::kinematics::forward_kinematics_velocity;
use crate::data::Data;
use crate::endpoint::Endpoint;
use crate::error::{Error, Quantity, Result};
use crate::model::Model;
use crate::spatial::{Force, Spatial, Vec3};
use crate::Scalar;

/// The normal force law of a penetrating point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NormalLaw<S> {
    /// `λ = k δ + c δ̇`: stiffness `k` (N/m), damping `c` (N s/m).
    LinearSpringDamper {
        /// Stiffness k (N/m).
        stiffness: S,
        /// Damping c (N s/m).
        damping: S,
    },
    /// `λ = k δ (1 + d δ̇)`: stiffness `k` (N/m), Hunt-Crossley damping `d` (s/m).
    HuntCrossley {
        /// Stiffness k (N/m).
        stiffness: S,
        /// Damping d (s/m); `d ≈ 1.5 (1 - e) / v_impact` for a restitution e.
        damping: S,
    },
}

/// Ground contact parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GroundContact<S> {
    /// The normal force law.
    pub normal: NormalLaw<S>,
    /// Coulomb friction coefficient μ.
    pub friction: S,
    /// Slip velocity scale s₀ of the regularisation (m/s).
    pub slip_scale: S,
}

/// What one contact point is doing, for logs and plots.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactReport<S> {
    /// The point in the world frame (m).
    pub position: Vec3<S>,
    /// Penetration δ (m), zero when above ground.
    pub penetration: S,
    /// The force the ground applies, world frame (N).
    pub force: Vec3<S>,
}

impl<S: Scalar> GroundContact<S> {
    /// Checks the parameters: finite; stiffness, damping and friction not
    /// negative; a positive slip scale.
    ///
    /// # Errors
    /// [`Error::NonFinite`] with [`Quantity::Contact`] naming the first bad
    /// parameter (index 0: stiffness, 1: damping, 2: friction, 3: slip
    /// scale).
    pub fn validate(&self) -> Result<()> {
        let (stiffness, damping) = match self.normal {
            NormalLaw::LinearSpringDamper { stiffness, damping }
            | NormalLaw::HuntCrossley { stiffness, damping } => (stiffness, damping),
        };
        let parameters = [stiffness, damping, self.friction, self.slip_scale];
        let valid = |k: usize, x: S| {
            let lowest = if k == 3 { f64::MIN_POSITIVE } else { 0.0 };
            x.is_finite() && x.to_f64() >= lowest
        };
        match parameters
            .iter()
            .enumerate()
            .position(|(k, &x)| !valid(k, x))
        {
            Some(index) => Err(Error::NonFinite {
                quantity: Quantity::Contact,
                index,
            }),
            None => Ok(()),
        }
    }

    /// The force (world frame, N) on a point at world position `p` moving
    /// at world velocity `p_dot`.
    ///
    /// # Errors
    /// Those of [`validate`](Self::validate); [`Error::NonFinite`] with
    /// [`Quantity::ContactPoint`] naming a non-finite entry of `p` (index
    /// 0–2) or `p_dot` (3–5), so that a NaN height is not read as "no
    /// contact"; [`Error::NonFiniteResult`] with [`Quantity::Contact`] for
    /// a force that overflows.
    pub fn force_at(&self, p: &Vec3<S>, p_dot: &Vec3<S>) -> Result<Vec3<S>> {
        self.validate()?;
        let (p_arr, p_dot_arr) = (p.to_array(), p_dot.to_array());
        if let Some(index) = p_arr
            .iter()
            .chain(p_dot_arr.iter())
            .position(|x| !x.is_finite())
        {
            return Err(Error::NonFinite {
                quantity: Quantity::ContactPoint,
                index,
            });
        }
        let force = self.force_unvalidated(p, p_dot);
        if force.is_finite() {
            Ok(force)
        } else {
            Err(Error::NonFiniteResult {
                quantity: Quantity::Contact,
                index: 0,
            })
        }
    }

    /// [`force_at`](Self::force_at) without its checks, for
    /// [`add_forces`](Self::add_forces), which validates once per call and
    /// checks each force; non-finite for a non-finite input.
    fn force_unvalidated(&self, p: &Vec3<S>, p_dot: &Vec3<S>) -> Vec3<S> {
        let depth = -p.z;
        // Out of contact only when the depth says so: a NaN height gives a
        // NaN force, which `add_forces` reports, rather than "no contact".
        if depth
            .partial_cmp(&S::ZERO)
            .is_some_and(|o| o != core::cmp::Ordering::Greater)
        {
            return Vec3::ZERO;
        }
        let depth_rate = -p_dot.z;
        let normal = match self.normal {
            NormalLaw::LinearSpringDamper { stiffness, damping } => {
                stiffness * depth + damping * depth_rate
            }
            NormalLaw::HuntCrossley { stiffness, damping } => {
                stiffness * depth * (S::ONE + damping * depth_rate)
            }
        }
        .max(S::ZERO);
        let slip = Vec3::new(p_dot.x, p_dot.y, S::ZERO);
        let speed = slip.norm();
        // tanh(|s|/s₀)/|s|, continued by its limit 1/s₀ at standstill.
        let ratio = speed / self.slip_scale;
        let gain = if ratio > S::from_f64(1e-4) {
            ratio.tanh() / speed
        } else {
            S::ONE / self.slip_scale
        };
        let friction = slip * (-(self.friction * normal * gain));
        Vec3::new(friction.x, friction.y, normal)
    }

    /// Adds the ground forces on every point in `points` to `f_ext` (body
    /// frames), and writes what each point does to `reports` when given
    /// (as many entries as points are filled).
    ///
    /// Runs [`forward_kinematics_velocity`] on `data` (leaves `li_m_i`,
    /// `o_m_i`, `v`, `c` valid at `(q, v)`). Points fixed in the world are
    /// skipped.
    ///
    /// # Errors
    /// Those of [`forward_kinematics_velocity`] and [`GroundContact::validate`];
    /// [`Error::BodyOutOfRange`] for a point on a body the model does not
    /// have; [`Error::NonFinite`] with [`Quantity::Contact`] and the point's
    /// index for a non-finite point, [`Error::NonFiniteResult`] for a force
    /// that overflows. `f_ext` may hold the forces of the points before.
    #[allow(clippy::too_many_arguments)]
    pub fn add_forces<const NB: usize, const NQ: usize, const NV: usize>(
        &self,
        model: &Model<S, NB, NQ, NV, Spatial>,
        data: &mut Data<S, NB, NV, Spatial>,
        q: &[S; NQ],
        v: &[S; NV],
        points: &[Endpoint<S>],
        f_ext: &mut [Force<S>; NB],
        mut reports: Option<&mut [ContactReport<S>]>,
    ) -> Result<()> {
        self.validate()?;
        forward_kinematics_velocity(model, data, q, v)?;
        for (n, point) in points.iter().enumerate() {
            let Some(body) = point.body else { continue };
            if body >= NB {
                return Err(Error::BodyOutOfRange { body });
            }
            if !point.position.is_finite() {
                return Err(Error::NonFinite {
                    quantity: Quantity::Contact,
                    index: n,
                });
            }
            let pose = &data.o_m_i[body];
            let twist = &data.v[body];
            let p_local = point.position;
            let p_world = pose.rot.mul_vec(&p_local) + pose.trans;
            // Velocity of the material point: body twist at p, then rotated.
            let p_dot_local = twist.lin + twist.ang.cross(&p_local);
            let p_dot_world = pose.rot.mul_vec(&p_dot_local);
            let force_world = self.force_unvalidated(&p_world, &p_dot_world);
            if !force_world.is_finite() {
                return Err(Error::NonFiniteResult {
                    quantity: Quantity::Contact,
                    index: n,
                });
            }
            let force_local = pose.rot.tr_mul_vec(&force_world);
            f_ext[body] += Force::at_point(force_local, &p_local);
            if let Some(out) = reports.as_deref_mut().and_then(|r| r.get_mut(n)) {
                *out = ContactReport {
                    position: p_world,
                    penetration: (-p_world.z).max(S::ZERO),
                    force: force_world,
                };
            }
        }
        Ok(())
    }
}
