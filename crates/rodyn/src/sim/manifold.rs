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

use crate::error::{Quantity, Result};
use crate::joint::{Joint, JointModel};
use crate::model::{check_finite, check_result, Model};
use crate::planar::{Planar, PlanarJoint};
use crate::space::Space;
use crate::spatial::Spatial;
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
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first non-finite entry of `q` or `v`;
/// [`Error::NonFiniteResult`](crate::Error::NonFiniteResult) (`Quantity::Configuration`, the entry) when
/// finite inputs overflow. One finiteness test of `q̇` when all is well.
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
) -> Result<[S; NQ]> {
    let q_dot = configuration_rate_unchecked(model, q, v);
    if check_result(&q_dot, Quantity::Configuration).is_err() {
        check_finite(q, Quantity::Configuration)?;
        check_finite(v, Quantity::Velocity)?;
        check_result(&q_dot, Quantity::Configuration)?;
    }
    Ok(q_dot)
}

/// [`configuration_rate`] without its checks, for the integrators (which
/// check the state they step to).
pub(crate) fn configuration_rate_unchecked<
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
        let ((iq, nq), (iv, nv)) = (model.configuration_range(i), t.velocity_range(i));
        // A valid topology keeps the ranges in `q` and `v`
        // (`Topology::try_new`); one that does not fit leaves those rates zero.
        let (Some(q_i), Some(v_i), Some(q_dot_i)) = (
            q.get(iq..iq + nq),
            v.get(iv..iv + nv),
            q_dot.get_mut(iq..iq + nq),
        ) else {
            continue;
        };
        G::joint_configuration_rate(model.joint(i), q_i, v_i, q_dot_i);
    }
    q_dot
}

/// `q + q_dot dt`, coordinate by coordinate (no projection).
#[must_use]
pub(crate) fn add_scaled<S: Scalar, const N: usize>(q: &[S; N], q_dot: &[S; N], dt: S) -> [S; N] {
    core::array::from_fn(|k| q[k] + q_dot[k] * dt)
}

// The rates themselves live beside `integrate` in each joint
// ([`JointModel::configuration_rate`]); a geometry only forwards to them.
impl ConfigurationRate for Spatial {
    #[inline]
    fn joint_configuration_rate<S: Scalar>(joint: &Joint<S>, q: &[S], v: &[S], q_dot: &mut [S]) {
        joint.configuration_rate(q, v, q_dot);
    }
}

impl ConfigurationRate for Planar {
    #[inline]
    fn joint_configuration_rate<S: Scalar>(
        joint: &PlanarJoint<S>,
        q: &[S],
        v: &[S],
        q_dot: &mut [S],
    ) {
        joint.configuration_rate(q, v, q_dot);
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
        ConfigurationUpdate::ExponentialMap => model.integrate_unvalidated(q, v, dt),
        ConfigurationUpdate::Embedded { renormalize } => {
            let mut out = add_scaled(q, &configuration_rate_unchecked(model, q, v), dt);
            if renormalize {
                model.normalize_unvalidated(&mut out);
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
        model.normalize_unvalidated(&mut out);
    }
    out
}
