//! Moving a configuration on its manifold: `q ⊕ v dt`.
//!
//! Most coordinates are plain numbers (`q̇ = v`), but a free-floating base
//! stores its orientation as a unit quaternion (4 numbers for 3 degrees of
//! freedom) and its velocity in its own frame. Two ways to advance it:
//!
//! * [`ConfigurationUpdate::ExponentialMap`]: `q ⊕ v dt` through
//!   [`Model::integrate`], the exponential map of each joint's group. Exact
//!   for a constant body velocity and always on the manifold, but combining
//!   several stage velocities into one displacement (as RK4 does) ignores
//!   that rotations do not commute, which costs orders of accuracy for a
//!   spinning base (RK4 drops to second order in the base's rotation).
//! * [`ConfigurationUpdate::Embedded`]: treat `q` as a vector of `R^NQ` with
//!   the kinematic equation `q̇ = Q(q) v` ([`ConfigurationRate`]; for a
//!   quaternion `q̇ = ½ q ⊗ (ω, 0)`) and integrate it like any ODE. This keeps
//!   each integrator's full order, but the quaternion's norm is only
//!   preserved by the exact solution: every numerical step lets it drift.
//!   With `renormalize: true` the dynamics are evaluated at, and each step
//!   ends on, the projected configuration ([`Model::normalize`]). With
//!   `renormalize: false` nothing is projected, and once the norm is off by
//!   more than rodyn's tolerance (10³ ε) the dynamics reject the
//!   configuration with [`Error::InvalidConfiguration`](crate::Error::InvalidConfiguration):
//!   the drift is reported, not integrated into garbage.

use crate::joint::{Joint, JointModel};
use crate::model::Model;
use crate::planar::{Planar, PlanarJoint};
use crate::space::Space;
use crate::spatial::{Mat3, Spatial, Vec3};
use crate::Scalar;

/// How an integrator moves the configuration.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ConfigurationUpdate {
    /// `q ⊕ v dt` by each joint's exponential map ([`Model::integrate`]).
    ExponentialMap,
    /// `q + Q(q) v dt` in the embedding space, optionally renormalised.
    Embedded {
        /// Project onto the manifold before each dynamics evaluation and at
        /// the end of each step.
        renormalize: bool,
    },
}

/// The kinematic equation `q̇ = Q(q) v` of a geometry's joints.
pub trait ConfigurationRate: Space {
    /// Writes `q̇` of one joint (`q` has the joint's nq entries, `v` its nv,
    /// `q_dot` nq).
    fn joint_configuration_rate<S: Scalar>(
        joint: &Self::Joint<S>,
        q: &[S],
        v: &[S],
        q_dot: &mut [S],
    );
}

/// `q̇ = Q(q) v` for a whole model (NQ entries).
#[must_use]
pub fn configuration_rate<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: ConfigurationRate,
>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
) -> [S; NQ] {
    let t = model.topology();
    let mut q_dot = [S::ZERO; NQ];
    for i in 0..NB {
        let (iq, nq, iv, nv) = (t.idx_q[i], t.nq[i], t.idx_v[i], t.nv[i]);
        G::joint_configuration_rate(
            model.joint(i),
            &q[iq..iq + nq],
            &v[iv..iv + nv],
            &mut q_dot[iq..iq + nq],
        );
    }
    q_dot
}

/// `q + q_dot dt`, coordinate by coordinate (no projection).
#[must_use]
pub fn add_scaled<S: Scalar, const N: usize>(q: &[S; N], q_dot: &[S; N], dt: S) -> [S; N] {
    core::array::from_fn(|k| q[k] + q_dot[k] * dt)
}

impl ConfigurationRate for Spatial {
    fn joint_configuration_rate<S: Scalar>(joint: &Joint<S>, q: &[S], v: &[S], q_dot: &mut [S]) {
        match joint {
            Joint::Revolute(_) | Joint::Prismatic(_) => q_dot[0] = v[0],
            Joint::Fixed => {}
            Joint::FreeFlyer(_) => {
                // Position: the body-frame linear velocity rotated into the
                // parent. The rotation is built from the normalised
                // quaternion so that an unnormalised one does not scale it.
                let (x, y, z, w) = (q[3], q[4], q[5], q[6]);
                let n2 = x * x + y * y + z * z + w * w;
                let inv = if n2 > S::ZERO {
                    S::ONE / n2.sqrt()
                } else {
                    S::ONE
                };
                let rot = Mat3::from_quaternion(x * inv, y * inv, z * inv, w * inv);
                let p_dot = rot.mul_vec(&Vec3::new(v[0], v[1], v[2]));
                q_dot[..3].copy_from_slice(&p_dot.to_array());
                // Orientation: q̇ = ½ q ⊗ (ω, 0), linear in q, so its exact
                // flow keeps |q| constant whatever |q| is.
                let half = S::from_f64(0.5);
                let (wx, wy, wz) = (v[3] * half, v[4] * half, v[5] * half);
                q_dot[3] = w * wx + y * wz - z * wy;
                q_dot[4] = w * wy + z * wx - x * wz;
                q_dot[5] = w * wz + x * wy - y * wx;
                q_dot[6] = -(x * wx + y * wy + z * wz);
            }
            Joint::Custom(c) => custom_rate(joint, c.nq, c.nv, q, v, q_dot),
        }
    }
}

/// A custom joint with `nq == nv` is taken as `q̇ = v`; otherwise its rate is
/// the central difference of its own `integrate` over a step of ε^⅓ (an
/// error of about ε^⅔ relative: 4e-11 in f64, 2e-5 in f32).
fn custom_rate<S: Scalar, J: JointModel<S, Spatial>>(
    joint: &J,
    nq: usize,
    nv: usize,
    q: &[S],
    v: &[S],
    q_dot: &mut [S],
) {
    if nq == nv {
        q_dot[..nq].copy_from_slice(&v[..nv]);
        return;
    }
    const MAX_NQ: usize = 8;
    let n = nq.min(MAX_NQ);
    let h = (S::from_f64(S::EPSILON).ln() * S::from_f64(1.0 / 3.0)).exp();
    let (mut ahead, mut behind) = ([S::ZERO; MAX_NQ], [S::ZERO; MAX_NQ]);
    joint.integrate(q, v, h, &mut ahead[..n]);
    joint.integrate(q, v, -h, &mut behind[..n]);
    let inv = S::ONE / (h + h);
    for k in 0..n {
        q_dot[k] = (ahead[k] - behind[k]) * inv;
    }
}

impl ConfigurationRate for Planar {
    fn joint_configuration_rate<S: Scalar>(
        joint: &PlanarJoint<S>,
        q: &[S],
        v: &[S],
        q_dot: &mut [S],
    ) {
        match joint {
            PlanarJoint::Revolute | PlanarJoint::Prismatic(_) => q_dot[0] = v[0],
            PlanarJoint::Fixed => {}
            PlanarJoint::Floating => {
                // [x y θ] with [vx vy ω] in the body frame.
                let (s, c) = q[2].sin_cos();
                q_dot[0] = c * v[0] - s * v[1];
                q_dot[1] = s * v[0] + c * v[1];
                q_dot[2] = v[2];
            }
        }
    }
}

/// `q` displaced by `dt` along `v` (for [`ConfigurationUpdate::ExponentialMap`])
/// or along `q_dot` (for [`ConfigurationUpdate::Embedded`]), renormalised when
/// asked to.
#[must_use]
pub(crate) fn displace<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: ConfigurationRate,
>(
    model: &Model<S, NB, NQ, NV, G>,
    update: ConfigurationUpdate,
    q: &[S; NQ],
    v: &[S; NV],
    dt: S,
) -> [S; NQ] {
    match update {
        ConfigurationUpdate::ExponentialMap => model.integrate(q, v, dt),
        ConfigurationUpdate::Embedded { renormalize } => {
            let mut out = add_scaled(q, &configuration_rate(model, q, v), dt);
            if renormalize {
                model.normalize(&mut out);
            }
            out
        }
    }
}

/// The configuration the dynamics should see: projected when the update
/// renormalises, as is otherwise (so that rodyn's check reports drift).
#[inline]
#[must_use]
pub(crate) fn for_dynamics<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    update: ConfigurationUpdate,
    q: &[S; NQ],
) -> [S; NQ] {
    let mut out = *q;
    if let ConfigurationUpdate::Embedded { renormalize: true } = update {
        model.normalize(&mut out);
    }
    out
}
