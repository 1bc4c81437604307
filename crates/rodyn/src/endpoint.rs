//! Endpoints: named points on bodies (or in the world) where forces,
//! contacts and muscle paths attach.

use crate::space::{RigidTransform, Space};
use crate::spatial::Spatial;
use crate::Scalar;

/// A point fixed on a body, or fixed in the world when `body` is `None`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Endpoint<S: Scalar, G: Space = Spatial> {
    /// The body the point is fixed to (`None`: the world).
    pub body: Option<usize>,
    /// The point in that body's frame (world frame when `body` is `None`), m.
    pub position: G::Point<S>,
}

impl<S: Scalar, G: Space> Endpoint<S, G> {
    /// A point fixed on `body` at `position` (body frame).
    #[must_use]
    pub const fn on_body(body: usize, position: G::Point<S>) -> Self {
        Self {
            body: Some(body),
            position,
        }
    }
    /// A point fixed in the world at `position`.
    #[must_use]
    pub const fn in_world(position: G::Point<S>) -> Self {
        Self {
            body: None,
            position,
        }
    }
    /// The point in the world frame, from body poses `o_m_i` (as
    /// [`forward_kinematics`](crate::algorithm::kinematics::forward_kinematics)
    /// leaves them in [`Data::o_m_i`](crate::Data::o_m_i)).
    #[must_use]
    pub fn world_position(&self, o_m_i: &[G::Transform<S>]) -> G::Point<S> {
        match self.body {
            Some(b) => o_m_i[b].act_point(&self.position),
            None => self.position,
        }
    }
}
