//! Frames: placements (position and orientation) fixed on bodies, such as a
//! tool flange, a foot sole or a sensor, as Pinocchio's `Frame` (its parent
//! joint and `placement`).
//!
//! An [`Endpoint`](crate::Endpoint) is a point; a [`Frame`] also keeps the
//! orientation, so a tool's axes survive the merge of fixed joints.

use crate::space::{RigidTransform, Space};
use crate::spatial::Spatial;
use crate::Scalar;

/// A frame fixed on body `body`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame<S: Scalar, G: Space = Spatial> {
    /// The body the frame is fixed to.
    pub body: usize,
    /// Body frame from the frame (`ⁱMf`): the frame's origin and axes in the
    /// body's frame.
    pub placement: G::Transform<S>,
}

impl<S: Scalar, G: Space> Frame<S, G> {
    /// A frame on `body` at `placement` (`ⁱMf`, body frame from frame).
    #[must_use]
    pub const fn new(body: usize, placement: G::Transform<S>) -> Self {
        Self { body, placement }
    }

    /// The frame in scalar type `T` (an f64 frame for an f32 firmware).
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> Frame<T, G> {
        Frame::new(self.body, G::cast_transform(&self.placement))
    }

    /// World frame from the frame (`ᵒMf = ᵒMᵢ ⁱMf`), from the body poses
    /// `o_m_i` that
    /// [`forward_kinematics`](crate::algorithm::kinematics::forward_kinematics)
    /// leaves in [`Data::o_m_i`](crate::Data::o_m_i).
    /// `None` when `body` is not below `o_m_i.len()`.
    #[must_use]
    pub(crate) fn world_placement(&self, o_m_i: &[G::Transform<S>]) -> Option<G::Transform<S>> {
        o_m_i
            .get(self.body)
            .map(|o_m_b| o_m_b.compose(&self.placement))
    }
}
