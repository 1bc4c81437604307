//! One change of a model's physical parameters, checked as the model's
//! validated setters check it.

use crate::drive::JointMotor;
use crate::error::{Error, Quantity, Result};
use crate::frame::Frame;
use crate::model::Model;
use crate::space::{BodyInertia, Space};
use crate::spatial::Spatial;
use crate::Scalar;

/// One change of a model's parameters, in the units and frames of the
/// model's setters. A [`ModelUpdate`](super::ModelUpdate) applies a batch of
/// them as one.
#[derive(Clone, Copy, Debug)]
pub enum ParameterChange<S: Scalar, G: Space = Spatial> {
    /// Replaces body `body`'s inertia (mass in kg, centre of mass in m and
    /// rotational inertia about it in kg m², in the body's frame), as
    /// [`Model::set_inertia`].
    Inertia {
        /// The body.
        body: usize,
        /// Its new inertia, in its own frame.
        inertia: G::Inertia<S>,
    },
    /// A payload held rigidly at `frame` (a gripper's tool frame, a
    /// flange): its inertia, expressed in the frame, is moved into the
    /// frame's body (`ⁱMf`, [`Frame::placement`]) and added to that body's
    /// inertia (masses add, centres of mass average, rotational inertias
    /// add with Steiner's terms). A payload released later is removed by an
    /// [`Inertia`](Self::Inertia) change back to the body's own inertia.
    Payload {
        /// Where the payload is held.
        frame: Frame<S, G>,
        /// The payload's inertia in the frame's axes about its origin
        /// (its centre of mass in the frame, m).
        inertia: G::Inertia<S>,
    },
    /// Replaces joint `body`'s placement in its parent (`ˡⁱMᵢ` at `q = 0`),
    /// as [`Model::set_placement`].
    Placement {
        /// The body whose joint moves.
        body: usize,
        /// The joint frame in the parent's frame.
        placement: G::Transform<S>,
    },
    /// Replaces velocity coordinate `dof`'s armature (kg m² or kg), as
    /// [`Model::set_armature`].
    Armature {
        /// The velocity coordinate.
        dof: usize,
        /// Its armature.
        armature: S,
    },
    /// A motor's new constants: its reflected rotor inertia `N² J_r`
    /// ([`JointMotor::reflected_inertia`]) becomes the armature of the
    /// coordinate it drives. The motor's torque constant stays with the
    /// motor (a drive element, outside the model).
    Motor(JointMotor<S>),
    /// Replaces gravity (world frame, linear part in m/s²), as
    /// [`Model::set_gravity`].
    Gravity(G::Motion<S>),
}

impl<S: Scalar, G: Space> ParameterChange<S, G> {
    /// Checks the change and writes it into `model`; on an error `model`
    /// is unchanged.
    ///
    /// # Errors
    /// Those of the setter the change stands for. A payload:
    /// [`Error::FrameBodyOutOfRange`] for a frame on a body the model does
    /// not have, [`Error::InvalidPose`] ([`Quantity::FramePlacement`], the
    /// frame's body) for a frame placement that is not a rigid motion,
    /// [`Error::InvalidModel`] naming the frame's body for a payload
    /// inertia that is not physical or a sum that overflows. A motor:
    /// [`Error::NonFinite`] ([`Quantity::Drive`], the motor's parameter) and
    /// those of [`Model::set_armature`].
    pub fn apply_to<const NB: usize, const NQ: usize, const NV: usize>(
        &self,
        model: &mut Model<S, NB, NQ, NV, G>,
    ) -> Result<()> {
        match self {
            Self::Inertia { body, inertia } => model.set_inertia(*body, *inertia),
            Self::Payload { frame, inertia } => {
                let body = frame.body;
                if body >= NB {
                    return Err(Error::FrameBodyOutOfRange { body });
                }
                G::validate_transform(&frame.placement).map_err(|problem| Error::InvalidPose {
                    quantity: Quantity::FramePlacement,
                    index: body,
                    problem,
                })?;
                G::validate_inertia(inertia)
                    .map_err(|problem| Error::InvalidModel { body, problem })?;
                // ⁱI = ⁱI + ⁱMf · ᶠI_payload; the sum is checked by the setter.
                let in_body = inertia.act(&frame.placement);
                model.set_inertia(body, model.inertia(body).combine(&in_body))
            }
            Self::Placement { body, placement } => model.set_placement(*body, *placement),
            Self::Armature { dof, armature } => model.set_armature(*dof, *armature),
            Self::Motor(motor) => model.set_armature(motor.dof, motor.reflected_inertia()?),
            Self::Gravity(gravity) => model.set_gravity(*gravity),
        }
    }
}
