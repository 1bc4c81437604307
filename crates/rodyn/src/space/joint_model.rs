//! The interface every joint offers the algorithms, [`JointModel`]
//! (public as `rodyn::joint::JointModel`). It is defined beside the
//! geometry traits because a [`Geometry`] names its joints' type by it;
//! the joints themselves ([`crate::joint`]) stand a layer above and
//! implement it.

use super::Geometry;
use crate::error::ConfigurationError;
use crate::Scalar;
use core::fmt::Debug;

/// The behaviour of one joint type in a geometry `G`.
///
/// Sizes: `q` has [`nq`](Self::nq) entries, `v`, `qd`, `out` have
/// [`nv`](Self::nv). The methods that read `q` or `qd` (the transforms,
/// [`angle`](Self::angle), the motions) read them from the front and must
/// accept longer slices: the algorithms pass a joint the state vector from
/// its first coordinate on. Vectors are in the joint's moving frame.
pub trait JointModel<S: Scalar, G: Geometry>: Copy + Debug {
    /// Number of configuration coordinates.
    fn nq(&self) -> usize;
    /// Number of velocity coordinates (degrees of freedom).
    fn nv(&self) -> usize;
    /// The joint transform `jMi(q)` (the book's `X_J`, as a transform).
    fn transform(&self, q: &[S]) -> G::Transform<S>;
    /// `placement · jMi(q)`: the moving frame in the parent body's frame,
    /// given the joint's placement. A joint whose transform is sparse
    /// overrides it to skip the full composition.
    #[inline]
    fn placed_transform(&self, placement: &G::Transform<S>, q: &[S]) -> G::Transform<S> {
        use crate::space::RigidTransform;
        placement.compose(&self.transform(q))
    }
    /// The angle whose sine and cosine
    /// [`placed_transform_from_sin_cos`](Self::placed_transform_from_sin_cos)
    /// takes (a revolute joint's `q[0]`), or `None`. An algorithm that
    /// forms many joints' transforms forms these together
    /// ([`Scalar::sin_cos_array`]).
    #[inline]
    fn angle(&self, _q: &[S]) -> Option<S> {
        None
    }
    /// [`placed_transform`](Self::placed_transform) given `sin_cos`, the
    /// sine and cosine of [`angle`](Self::angle); a joint without an angle
    /// ignores it.
    #[inline]
    fn placed_transform_from_sin_cos(
        &self,
        placement: &G::Transform<S>,
        q: &[S],
        _sin_cos: (S, S),
    ) -> G::Transform<S> {
        self.placed_transform(placement, q)
    }
    /// The joint velocity `S qd`.
    fn motion(&self, qd: &[S]) -> G::Motion<S>;
    /// `m + S qd`. Coordinate-axis joints override it to touch one component.
    #[inline]
    fn add_motion(&self, m: &G::Motion<S>, qd: &[S]) -> G::Motion<S> {
        *m + self.motion(qd)
    }
    /// `v × (S qd)`, the velocity-product acceleration of a joint moving at
    /// `qd` in a body moving at `v`. Coordinate-axis joints override it.
    #[inline]
    fn cross_motion(&self, v: &G::Motion<S>, qd: &[S]) -> G::Motion<S> {
        use crate::space::MotionVector;
        v.cross_motion(&self.motion(qd))
    }
    /// `(vᵢ, vᵢ × (S qd))` with `vᵢ = m + S qd`: a body's velocity from
    /// its parent's `m` (in the body's frame) and its joint's
    /// velocity-product acceleration, as [`add_motion`](Self::add_motion)
    /// then [`cross_motion`](Self::cross_motion). A joint may override it
    /// to branch on its kind once.
    #[inline(always)]
    fn velocity_and_bias(&self, m: &G::Motion<S>, qd: &[S]) -> (G::Motion<S>, G::Motion<S>) {
        let v = self.add_motion(m, qd);
        (v, self.cross_motion(&v, qd))
    }
    /// Column `k` of the motion subspace `S`.
    fn subspace_column(&self, k: usize) -> G::Motion<S>;
    /// `Some(k)` for a revolute joint about coordinate axis k (`S = eₖ`,
    /// angular): a hint that lets ABA skip the entries its projection
    /// zeroes. The default, `None`, never skips.
    #[inline]
    fn revolute_axis_index(&self) -> Option<usize> {
        None
    }
    /// The generalised force `Sᵀ f`, written to `out[..nv]`.
    fn project_force(&self, f: &G::Force<S>, out: &mut [S]);
    /// The columns of `U = I^A S`, written to `u[..nv]`.
    fn articulated_columns(&self, ia: &G::Articulated<S>, u: &mut [G::Force<S>]) {
        use crate::space::ArticulatedInertia;
        for (k, uk) in u.iter_mut().enumerate().take(self.nv()) {
            *uk = ia.mul_motion(&self.subspace_column(k));
        }
    }
    /// The neutral configuration (zero angles, identity quaternion).
    fn neutral(&self, q: &mut [S]);
    /// `out = q ⊕ v dt`: the configuration reached moving at `v` for `dt`.
    fn integrate(&self, q: &[S], v: &[S], dt: S, out: &mut [S]);
    /// The configuration rate `q̇ = Q(q) v`, written to `q_dot[..nq]`: the
    /// derivative of [`integrate`](Self::integrate) with respect to `dt` at
    /// zero. The default is `q̇ = v` when nq = nv and otherwise
    /// [`rate_from_integrate`], a central difference of `integrate`.
    fn configuration_rate(&self, q: &[S], v: &[S], q_dot: &mut [S]) {
        if self.nq() == self.nv() {
            for (d, v) in q_dot.iter_mut().zip(v).take(self.nq()) {
                *d = *v;
            }
        } else {
            rate_from_integrate(self, q, v, q_dot);
        }
    }
    /// Checks that `q` is a valid configuration (finite, unit quaternion).
    fn check_configuration(&self, q: &[S]) -> Result<(), ConfigurationError>;
    /// `false` when every finite `q` is a valid configuration, so that
    /// [`check_configuration`](Self::check_configuration) need not be asked
    /// once `q` is known to be finite. The default, `true`, always asks.
    #[inline]
    fn constrains_configuration(&self) -> bool {
        true
    }
    /// [`check_configuration`](Self::check_configuration) of a `q` already
    /// known to be finite: only the further conditions need asking. The
    /// default asks them all.
    #[inline]
    fn check_finite_configuration(&self, q: &[S]) -> Result<(), ConfigurationError> {
        self.check_configuration(q)
    }
    /// Projects `q` back onto the configuration manifold (renormalises quaternions).
    fn normalize(&self, q: &mut [S]);
}

/// Largest nq [`rate_from_integrate`] differentiates.
pub const MAX_RATE_NQ: usize = 8;

/// `q̇ = Q(q) v` of any joint as the central difference of its
/// [`integrate`](JointModel::integrate) over a step of ε^⅓ (an error of
/// about ε^⅔ relative: 4e-11 in f64, 2e-5 in f32), for joints with
/// nq ≠ nv that do not state their rate. Writes `q_dot[..nq]`, nq at most
/// [`MAX_RATE_NQ`] (entries beyond it are left untouched).
pub fn rate_from_integrate<S: Scalar, G: Geometry, J: JointModel<S, G>>(
    joint: &J,
    q: &[S],
    v: &[S],
    q_dot: &mut [S],
) {
    let n = joint.nq().min(MAX_RATE_NQ);
    let h = (S::from_f64(S::EPSILON).ln() * S::from_f64(1.0 / 3.0)).exp();
    let (mut ahead, mut behind) = ([S::ZERO; MAX_RATE_NQ], [S::ZERO; MAX_RATE_NQ]);
    joint.integrate(q, v, h, &mut ahead[..n]);
    joint.integrate(q, v, -h, &mut behind[..n]);
    let inv = S::ONE / (h + h);
    for ((d, a), b) in q_dot.iter_mut().zip(&ahead[..n]).zip(&behind[..n]) {
        *d = (*a - *b) * inv;
    }
}
