//! Joints: how a body moves relative to its parent.
//!
//! Every algorithm talks to a joint only through [`JointModel`], so a new joint
//! type never edits an algorithm. The built-in 3-D joints are the closed set
//! [`Joint`]; a user-defined joint enters through [`Joint::Custom`]. Planar
//! models use [`PlanarJoint`](crate::planar::PlanarJoint).
//!
//! Conventions (Pinocchio's, so reference data compares directly): a joint's
//! transform `jMi(q)` maps the moving frame i into the joint's parent-side
//! frame; its motion subspace `S` is expressed in frame i; joint velocities
//! are body-fixed. Angles in radians, lengths in metres.
//!
//! | joint                 | nq | nv | q                         | v                  |
//! |-----------------------|----|----|---------------------------|--------------------|
//! | [`Revolute`]          | 1  | 1  | angle                     | angular rate       |
//! | [`Prismatic`]         | 1  | 1  | displacement              | rate               |
//! | [`Joint::Fixed`]      | 0  | 0  |                           |                    |
//! | [`FreeFlyer`]         | 7  | 6  | `[x y z qx qy qz qw]`     | `[vx vy vz ωx ωy ωz]` in the body frame |

mod axis;
mod continuous;
mod custom;
mod free_flyer;
mod planar;
mod prismatic;
mod revolute;
mod spatial_geometry;

pub use axis::Axis;
pub use continuous::{angle_from_cos_sin, cos_sin_from_angle};
pub use custom::{CustomJoint, JointBehaviour};
pub use free_flyer::FreeFlyer;
pub use prismatic::Prismatic;
pub use revolute::Revolute;

use crate::spatial::{ArticulatedInertia6, Force, Motion, Spatial, Transform};
use crate::tuning::FREE_FLYER_SHORTCUT;
use crate::Scalar;

/// Largest number of velocity coordinates of one joint.
pub const MAX_JOINT_NV: usize = 6;

/// What is wrong with a joint's configuration (defined with the other
/// errors, so that the error module does not depend on the joints).
pub use crate::error::ConfigurationError;

/// The interface of a joint, defined with the geometry traits (which name
/// it) so that the algebra does not depend on the joints.
pub use crate::space::joint_model::{rate_from_integrate, JointModel, MAX_RATE_NQ};

/// `x[0]`, or zero when `x` is empty: a one-coordinate joint's entry
/// without a panic path. The algorithms hand each joint its `nq` (or `nv`)
/// entries, which [`Topology::new`](crate::topology::Topology::new) checks
/// fit the state vectors, so the zero is never read for a valid model.
#[inline(always)]
pub(crate) fn first<S: Scalar>(x: &[S]) -> S {
    x.first().copied().unwrap_or(S::ZERO)
}

/// Writes `value` to `x[0]`, when `x` has an entry (see [`first`]).
#[inline(always)]
pub(crate) fn set_first<S: Scalar>(x: &mut [S], value: S) {
    if let Some(x) = x.first_mut() {
        *x = value;
    }
}

/// The built-in joints of 3-D models.
#[derive(Clone, Copy, Debug)]
pub enum Joint<S: 'static> {
    /// One rotational degree of freedom about an axis.
    Revolute(Revolute<S>),
    /// One translational degree of freedom along an axis.
    Prismatic(Prismatic<S>),
    /// No degree of freedom: a rigid attachment.
    Fixed,
    /// A free-floating base: position and unit quaternion.
    FreeFlyer(FreeFlyer),
    /// A user-defined joint.
    Custom(CustomJoint<S>),
}

impl<S: Scalar> Joint<S> {
    /// A revolute joint about `axis`.
    #[must_use]
    pub const fn revolute(axis: Axis<S>) -> Self {
        Self::Revolute(Revolute { axis })
    }
    /// A prismatic joint along `axis`.
    #[must_use]
    pub const fn prismatic(axis: Axis<S>) -> Self {
        Self::Prismatic(Prismatic { axis })
    }
    /// A free-floating base.
    #[must_use]
    pub const fn free_flyer() -> Self {
        Self::FreeFlyer(FreeFlyer)
    }
    /// Number of configuration coordinates, usable in `const` context.
    #[must_use]
    pub const fn const_nq(&self) -> usize {
        match self {
            Self::Revolute(_) => Revolute::<S>::NQ,
            Self::Prismatic(_) => Prismatic::<S>::NQ,
            Self::Fixed => 0,
            Self::FreeFlyer(_) => FreeFlyer::NQ,
            Self::Custom(c) => c.nq,
        }
    }
    /// Number of velocity coordinates, usable in `const` context.
    #[must_use]
    pub const fn const_nv(&self) -> usize {
        match self {
            Self::Revolute(_) => Revolute::<S>::NV,
            Self::Prismatic(_) => Prismatic::<S>::NV,
            Self::Fixed => 0,
            Self::FreeFlyer(_) => FreeFlyer::NV,
            Self::Custom(c) => c.nv,
        }
    }
    /// Whether a finite `q` can still be invalid (a quaternion off unit
    /// length, a custom joint's own rule), usable in `const` context: each
    /// variant answers with its type's `CONSTRAINS_CONFIGURATION`, so a new
    /// joint type must state it here rather than be left out of a list.
    #[must_use]
    pub const fn const_constrains_configuration(&self) -> bool {
        match self {
            Self::Revolute(_) => Revolute::<S>::CONSTRAINS_CONFIGURATION,
            Self::Prismatic(_) => Prismatic::<S>::CONSTRAINS_CONFIGURATION,
            Self::Fixed => false,
            Self::FreeFlyer(_) => FreeFlyer::CONSTRAINS_CONFIGURATION,
            Self::Custom(_) => CustomJoint::<S>::CONSTRAINS_CONFIGURATION,
        }
    }
    /// Converts the scalar type; `None` for a custom joint, whose behaviour
    /// is tied to one scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> Option<Joint<T>> {
        Some(match self {
            Self::Revolute(r) => Joint::Revolute(Revolute {
                axis: r.axis.cast(),
            }),
            Self::Prismatic(p) => Joint::Prismatic(Prismatic {
                axis: p.axis.cast(),
            }),
            Self::Fixed => Joint::Fixed,
            Self::FreeFlyer(f) => Joint::FreeFlyer(*f),
            Self::Custom(_) => return None,
        })
    }
}

impl<S: Scalar> JointModel<S, Spatial> for Joint<S> {
    #[inline]
    fn nq(&self) -> usize {
        self.const_nq()
    }
    #[inline]
    fn nv(&self) -> usize {
        self.const_nv()
    }
    #[inline]
    fn transform(&self, q: &[S]) -> Transform<S> {
        match self {
            Self::Revolute(j) => j.transform(first(q)),
            Self::Prismatic(j) => j.transform(first(q)),
            Self::Fixed => Transform::from_translation(crate::spatial::Vec3::ZERO),
            // A slice of another length is a caller's bug (see `first`).
            Self::FreeFlyer(j) => q
                .first_chunk()
                .map_or(Transform::IDENTITY, |q| j.transform(q)),
            Self::Custom(c) => c.transform(q),
        }
    }
    #[cfg_attr(rodyn_tuning = "out_of_order", inline(always))]
    #[cfg_attr(rodyn_tuning = "in_order", inline)]
    fn placed_transform(&self, placement: &Transform<S>, q: &[S]) -> Transform<S> {
        use crate::space::RigidTransform;
        match self {
            Self::Revolute(j) => j.placed_transform(placement, first(q)),
            // A floating base usually sits at the world's origin without a
            // turn: its pose is then the joint's own, and composing with
            // the identity would be a full 3x3 product (a choice of the
            // tuning profile).
            Self::FreeFlyer(j) if FREE_FLYER_SHORTCUT && placement.rot.is_identity() => {
                // Its own transform directly: through `transform`'s match
                // on the kind, it stayed out of line.
                let x = q
                    .first_chunk()
                    .map_or(Transform::IDENTITY, |q| j.transform(q));
                Transform::new(x.rot, x.trans + placement.trans)
            }
            _ => placement.compose(&self.transform(q)),
        }
    }
    #[inline(always)]
    fn angle(&self, q: &[S]) -> Option<S> {
        matches!(self, Self::Revolute(_)).then(|| first(q))
    }
    #[inline(always)]
    fn placed_transform_from_sin_cos(
        &self,
        placement: &Transform<S>,
        q: &[S],
        (sin, cos): (S, S),
    ) -> Transform<S> {
        match self {
            Self::Revolute(j) => j.placed_transform_from_sin_cos(placement, sin, cos),
            _ => self.placed_transform(placement, q),
        }
    }
    #[inline(always)]
    fn motion(&self, qd: &[S]) -> Motion<S> {
        match self {
            Self::Revolute(j) => j.motion(first(qd)),
            Self::Prismatic(j) => j.motion(first(qd)),
            Self::Fixed => crate::space::VectorOps::ZERO,
            Self::FreeFlyer(j) => qd
                .first_chunk()
                .map_or(crate::space::VectorOps::ZERO, |qd| j.motion(qd)),
            Self::Custom(c) => c.motion(qd),
        }
    }
    #[inline]
    fn revolute_axis_index(&self) -> Option<usize> {
        match self {
            Self::Revolute(j) => j.axis.index(),
            _ => None,
        }
    }
    #[inline(always)]
    fn add_motion(&self, m: &Motion<S>, qd: &[S]) -> Motion<S> {
        match self {
            Self::Revolute(j) => j.add_motion(m, first(qd)),
            Self::Prismatic(j) => j.add_motion(m, first(qd)),
            Self::Fixed => *m,
            _ => *m + self.motion(qd),
        }
    }
    #[inline(always)]
    fn cross_motion(&self, v: &Motion<S>, qd: &[S]) -> Motion<S> {
        use crate::space::MotionVector;
        match self {
            Self::Revolute(j) => j.cross_motion(v, first(qd)),
            Self::Prismatic(j) => j.cross_motion(v, first(qd)),
            Self::Fixed => crate::space::VectorOps::ZERO,
            _ => v.cross_motion(&self.motion(qd)),
        }
    }
    #[inline]
    fn subspace_column(&self, k: usize) -> Motion<S> {
        match self {
            Self::Revolute(j) => j.motion(S::ONE),
            Self::Prismatic(j) => j.motion(S::ONE),
            Self::Fixed => crate::space::VectorOps::ZERO,
            Self::FreeFlyer(j) => j.subspace_column(k),
            Self::Custom(c) => c.behaviour.subspace_column(k),
        }
    }
    #[inline(always)]
    fn project_force(&self, f: &Force<S>, out: &mut [S]) {
        match self {
            Self::Revolute(j) => set_first(out, j.project_force(f)),
            Self::Prismatic(j) => set_first(out, j.project_force(f)),
            Self::Fixed => {}
            Self::FreeFlyer(j) => {
                if let Some(out) = out.first_chunk_mut() {
                    j.project_force(f, out);
                }
            }
            Self::Custom(c) => c.behaviour.project_force(f, out),
        }
    }
    #[inline(always)]
    fn articulated_columns(&self, ia: &ArticulatedInertia6<S>, u: &mut [Force<S>]) {
        match self {
            Self::Revolute(j) => {
                if let Some(u) = u.first_mut() {
                    *u = j.articulated_column(ia);
                }
            }
            Self::Prismatic(j) => {
                if let Some(u) = u.first_mut() {
                    *u = j.articulated_column(ia);
                }
            }
            Self::Fixed => {}
            Self::FreeFlyer(j) => {
                if let Some(u) = u.first_chunk_mut() {
                    j.articulated_columns(ia, u);
                }
            }
            Self::Custom(c) => {
                use crate::space::ArticulatedInertia;
                for (k, uk) in u.iter_mut().enumerate().take(c.nv) {
                    *uk = ia.mul_motion(&c.behaviour.subspace_column(k));
                }
            }
        }
    }
    fn neutral(&self, q: &mut [S]) {
        match self {
            Self::Revolute(_) | Self::Prismatic(_) => set_first(q, S::ZERO),
            Self::Fixed => {}
            Self::FreeFlyer(j) => {
                if let Some(q) = q.first_chunk_mut() {
                    j.neutral(q);
                }
            }
            Self::Custom(c) => c.behaviour.neutral(q),
        }
    }
    fn integrate(&self, q: &[S], v: &[S], dt: S, out: &mut [S]) {
        match self {
            Self::Revolute(_) | Self::Prismatic(_) => set_first(out, first(q) + first(v) * dt),
            Self::Fixed => {}
            Self::FreeFlyer(j) => {
                if let (Some(q), Some(v), Some(out)) =
                    (q.first_chunk(), v.first_chunk(), out.first_chunk_mut())
                {
                    j.integrate(q, v, dt, out);
                }
            }
            Self::Custom(c) => c.behaviour.integrate(q, v, dt, out),
        }
    }
    fn configuration_rate(&self, q: &[S], v: &[S], q_dot: &mut [S]) {
        match self {
            Self::Revolute(_) | Self::Prismatic(_) => set_first(q_dot, first(v)),
            Self::Fixed => {}
            Self::FreeFlyer(j) => {
                if let (Some(q), Some(v), Some(q_dot)) =
                    (q.first_chunk(), v.first_chunk(), q_dot.first_chunk_mut())
                {
                    j.configuration_rate(q, v, q_dot);
                }
            }
            Self::Custom(c) if c.nq == c.nv => {
                for (d, v) in q_dot.iter_mut().zip(v).take(c.nq) {
                    *d = *v;
                }
            }
            Self::Custom(_) => rate_from_integrate(self, q, v, q_dot),
        }
    }
    #[inline]
    fn constrains_configuration(&self) -> bool {
        self.const_constrains_configuration()
    }
    fn check_configuration(&self, q: &[S]) -> Result<(), ConfigurationError> {
        match self {
            Self::FreeFlyer(j) => q
                .first_chunk()
                .map_or(Err(ConfigurationError::NonFinite), |q| {
                    j.check_configuration(q)
                }),
            Self::Custom(c) => c.behaviour.check_configuration(q),
            _ => {
                if q.iter().take(self.nq()).all(|x| x.is_finite()) {
                    Ok(())
                } else {
                    Err(ConfigurationError::NonFinite)
                }
            }
        }
    }
    fn check_finite_configuration(&self, q: &[S]) -> Result<(), ConfigurationError> {
        match self {
            Self::FreeFlyer(j) => q
                .first_chunk()
                .map_or(Err(ConfigurationError::NonFinite), |q| j.check_unit(q)),
            Self::Custom(c) => c.behaviour.check_configuration(q),
            _ => Ok(()),
        }
    }
    fn normalize(&self, q: &mut [S]) {
        match self {
            Self::FreeFlyer(j) => {
                if let Some(q) = q.first_chunk_mut() {
                    j.normalize(q);
                }
            }
            Self::Custom(c) => c.behaviour.normalize(q),
            _ => {}
        }
    }
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::{Axis, FreeFlyer, Joint, JointModel};
    use crate::spatial::Spatial;

    /// For a finite `q`, the check without the finiteness test answers as
    /// the whole check: unit, non-unit and zero quaternions, short slices.
    #[test]
    fn finite_check_is_the_whole_check_on_finite_q() {
        let joints: [Joint<f64>; 3] = [
            Joint::FreeFlyer(FreeFlyer),
            Joint::revolute(Axis::X),
            Joint::Fixed,
        ];
        let half = 0.5_f64.sqrt();
        let qs: [&[f64]; 6] = [
            &[0.1, -2.0, 3.0, 0.0, 0.0, 0.0, 1.0],
            &[0.0, 0.0, 0.0, half, 0.0, -half, 0.0],
            &[1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 1.01],
            &[1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 0.0],
            &[0.3],
            &[],
        ];
        for joint in &joints {
            for q in qs {
                assert_eq!(
                    JointModel::<f64, Spatial>::check_finite_configuration(joint, q),
                    JointModel::<f64, Spatial>::check_configuration(joint, q),
                    "{joint:?} at {q:?}"
                );
            }
        }
    }
}
