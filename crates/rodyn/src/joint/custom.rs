//! The extension point: a joint type defined outside rodyn.
//!
//! Implement [`JointBehaviour`] for a type, keep a `static` of it, and put a
//! [`CustomJoint`] into the model through [`Joint::Custom`](super::Joint::Custom).
//! The algorithms call it through the same [`JointModel`](super::JointModel)
//! interface as the built-in joints.

use super::ConfigurationError;
use crate::spatial::{Force, Motion, Transform};
use crate::Scalar;
use core::fmt;

/// The behaviour of a user-defined 3-D joint (see [`JointModel`](super::JointModel)
/// for the meaning of each method; sizes are the [`CustomJoint`]'s nq and nv).
pub trait JointBehaviour<S: Scalar>: Sync {
    /// `jMi(q)`.
    fn transform(&self, q: &[S]) -> Transform<S>;
    /// `S qd`.
    fn motion(&self, qd: &[S]) -> Motion<S>;
    /// Column `k` of `S`.
    fn subspace_column(&self, k: usize) -> Motion<S>;
    /// `Sᵀ f` into `out[..nv]`.
    fn project_force(&self, f: &Force<S>, out: &mut [S]);
    /// The neutral configuration.
    fn neutral(&self, q: &mut [S]);
    /// `out = q ⊕ v dt`.
    fn integrate(&self, q: &[S], v: &[S], dt: S, out: &mut [S]);
    /// Validity of `q`; the default accepts every finite `q`.
    fn check_configuration(&self, q: &[S]) -> Result<(), ConfigurationError> {
        if q.iter().all(|x| x.is_finite()) {
            Ok(())
        } else {
            Err(ConfigurationError::NonFinite)
        }
    }
    /// Projection onto the configuration manifold; the default does nothing.
    fn normalize(&self, _q: &mut [S]) {}
}

/// A user-defined joint with its sizes.
#[derive(Clone, Copy)]
pub struct CustomJoint<S: 'static> {
    /// Number of configuration coordinates.
    pub nq: usize,
    /// Number of velocity coordinates (at most [`MAX_JOINT_NV`](super::MAX_JOINT_NV)).
    pub nv: usize,
    /// What the joint does.
    pub behaviour: &'static dyn JointBehaviour<S>,
}

impl<S> CustomJoint<S> {
    /// A custom joint's own [`JointBehaviour::check_configuration`] decides
    /// what is valid, so it is always asked.
    pub const CONSTRAINS_CONFIGURATION: bool = true;
}

impl<S: Scalar> CustomJoint<S> {
    /// Its behaviour's transform of `q[..nq]`: the algorithms pass the
    /// state from the joint's first coordinate on, and a behaviour is
    /// promised exactly its own entries. Out of line, so that the
    /// built-in joints' dispatch stays small enough to inline.
    #[inline(never)]
    pub(crate) fn transform(&self, q: &[S]) -> Transform<S> {
        self.behaviour.transform(q.get(..self.nq).unwrap_or(q))
    }
    /// Its behaviour's `S qd` of `qd[..nv]` (as [`Self::transform`]).
    #[inline(never)]
    pub(crate) fn motion(&self, qd: &[S]) -> Motion<S> {
        self.behaviour.motion(qd.get(..self.nv).unwrap_or(qd))
    }
}

impl<S> fmt::Debug for CustomJoint<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("CustomJoint")
            .field("nq", &self.nq)
            .field("nv", &self.nv)
            .finish_non_exhaustive()
    }
}
