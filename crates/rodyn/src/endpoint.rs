//! Endpoints: named points on bodies (or in the world) where forces,
//! contacts and muscle paths attach.

use crate::error::{Error, Quantity, Result};
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
    ///
    /// # Errors
    /// [`Error::BodyOutOfRange`] when `o_m_i` has no pose for the body;
    /// [`Error::NonFinite`] naming the point (`Quantity::PathPoint`, index
    /// 0) or the body's pose (`Quantity::WorldPose`, the body) when the
    /// position comes out non-finite; [`Error::NonFiniteResult`] when
    /// finite ones overflow.
    pub fn world_position(&self, o_m_i: &[G::Transform<S>]) -> Result<G::Point<S>> {
        let Some(b) = self.body else {
            if !G::point_is_finite(&self.position) {
                return Err(Error::NonFinite {
                    quantity: Quantity::PathPoint,
                    index: 0,
                });
            }
            return Ok(self.position);
        };
        let o_m_b = o_m_i.get(b).ok_or(Error::BodyOutOfRange { body: b })?;
        let p = o_m_b.act_point(&self.position);
        if G::point_is_finite(&p) {
            return Ok(p);
        }
        Err(if !G::point_is_finite(&self.position) {
            Error::NonFinite {
                quantity: Quantity::PathPoint,
                index: 0,
            }
        } else if !o_m_b.is_finite() {
            Error::NonFinite {
                quantity: Quantity::WorldPose,
                index: b,
            }
        } else {
            Error::NonFiniteResult {
                quantity: Quantity::PathPoint,
                index: 0,
            }
        })
    }
}
