//! The contacts: what a [`Contact`] holds, its constrained rows, and the
//! right-hand side of its rows (Baumgarte's term less the drift).

use super::ConstraintSettings;
use crate::algorithm::frames::ReferenceFrame;
use crate::data::Data;
use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::space::RigidTransform;
use crate::spatial::{log6, Motion, Spatial, Transform, Vec3};
use crate::Scalar;

/// A contact the environment holds: a point (three constrained rows) or a
/// whole frame (six).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Contact<S: Scalar> {
    /// The origin of `frame` kept at `anchor` (world frame, m). Its force
    /// `λ` (N) is in world axes at the point: Pinocchio's `CONTACT_3D` in
    /// `LOCAL_WORLD_ALIGNED`. A foot that may roll about its sole.
    Point {
        /// The contact point, as a frame on its body (only its origin counts).
        frame: Frame<S, Spatial>,
        /// Where the point should be, world frame (m): the Baumgarte
        /// term's reference. Set it where the contact was made.
        anchor: Vec3<S>,
    },
    /// `frame` kept at the placement `anchor` (world frame): position and
    /// orientation. Its wrench `λ` is in the frame's own axes about its
    /// origin, force (N) then moment (N m): Pinocchio's `CONTACT_6D` in
    /// `LOCAL`. A flat foot on the ground, a hand on a handle.
    Frame {
        /// The held frame.
        frame: Frame<S, Spatial>,
        /// Where the frame should be, world frame: the Baumgarte term's
        /// reference (its error is `e = −log6(ᶜX_anchor)`, the twist from
        /// the anchor to the frame, in the frame's axes).
        anchor: Transform<S>,
    },
}

impl<S: Scalar> Contact<S> {
    /// A point contact (see [`Contact::Point`]).
    #[must_use]
    pub const fn point(frame: Frame<S, Spatial>, anchor: Vec3<S>) -> Self {
        Self::Point { frame, anchor }
    }

    /// A frame contact (see [`Contact::Frame`]).
    #[must_use]
    pub const fn frame(frame: Frame<S, Spatial>, anchor: Transform<S>) -> Self {
        Self::Frame { frame, anchor }
    }

    /// The contact in scalar type `T`.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> Contact<T> {
        match self {
            Self::Point { frame, anchor } => Contact::point(frame.cast(), anchor.cast()),
            Self::Frame { frame, anchor } => Contact::frame(frame.cast(), anchor.cast()),
        }
    }

    /// Constrained rows: 3 for a point, 6 for a frame.
    #[must_use]
    pub const fn rows(&self) -> usize {
        match self {
            Self::Point { .. } => 3,
            Self::Frame { .. } => 6,
        }
    }

    /// The held frame.
    #[must_use]
    pub const fn held_frame(&self) -> &Frame<S, Spatial> {
        match self {
            Self::Point { frame, .. } | Self::Frame { frame, .. } => frame,
        }
    }

    pub(super) fn anchor_is_finite(&self) -> bool {
        match self {
            Self::Point { anchor, .. } => anchor.is_finite(),
            Self::Frame { anchor, .. } => anchor.is_finite(),
        }
    }

    /// The reference frame of the rows and of `λ`.
    pub(super) const fn reference(&self) -> ReferenceFrame {
        match self {
            Self::Point { .. } => ReferenceFrame::LocalWorldAligned,
            Self::Frame { .. } => ReferenceFrame::Local,
        }
    }
}

/// The rows of all `contacts`: the sum of [`Contact::rows`].
#[must_use]
pub fn constrained_rows<S: Scalar>(contacts: &[Contact<S>]) -> usize {
    contacts.iter().map(Contact::rows).sum()
}

/// `−K_p e − K_d v_c − a_drift` of one contact, in its rows' order
/// (linear before angular): `e` the contact's error against its anchor,
/// `v_c` its velocity and `a_drift` its acceleration at `q̈ = 0`, all in the
/// contact's reference frame. Reads `data` after
/// `forward_kinematics_acceleration` at `q̈ = 0`.
pub(crate) fn baumgarte_less_drift<S: Scalar, const NB: usize, const NV: usize>(
    data: &Data<S, NB, NV, Spatial>,
    contact: &Contact<S>,
    settings: &ConstraintSettings<S>,
    out: &mut [S],
) -> Result<()> {
    let frame = contact.held_frame();
    let body = frame.body;
    let (Some(o_m_b), Some(v_b), Some(a_b)) =
        (data.o_m_i.get(body), data.v.get(body), data.a.get(body))
    else {
        return Err(Error::FrameBodyOutOfRange { body });
    };
    // The frame's pose once, then its velocity and acceleration in its own
    // axes at its origin (what `frames` computes, without forming the pose
    // three times).
    let placement = o_m_b.compose(&frame.placement);
    let v = frame.placement.act_inv_motion(v_b);
    let a = frame.placement.act_inv_motion(a_b);
    let (error, velocity, drift) = match contact {
        // World axes at the point; the classical acceleration a + ω × v.
        Contact::Point { anchor, .. } => {
            let to_world = |x: Vec3<S>| placement.rot.mul_vec(&x);
            let error = Motion::new(Vec3::ZERO, placement.trans - *anchor);
            let velocity = Motion::new(Vec3::ZERO, to_world(v.lin));
            let drift = Motion::new(Vec3::ZERO, to_world(a.lin + v.ang.cross(&v.lin)));
            (error, velocity, drift)
        }
        // Pinocchio's corrector: e = −log6(ᶜX_anchor), in the frame's axes;
        // the frame's spatial (not classical) acceleration, as its rows are
        // the frame's local Jacobian.
        Contact::Frame { anchor, .. } => {
            let error = -log6(&placement.inverse().compose(anchor));
            (error, v, a)
        }
    };
    let target =
        |e: Vec3<S>, v: Vec3<S>, a: Vec3<S>| (-(e * settings.kp) - v * settings.kd - a).to_array();
    let lin = target(error.lin, velocity.lin, drift.lin);
    out[..3].copy_from_slice(&lin);
    if out.len() == 6 {
        let ang = target(error.ang, velocity.ang, drift.ang);
        out[3..].copy_from_slice(&ang);
    }
    Ok(())
}
