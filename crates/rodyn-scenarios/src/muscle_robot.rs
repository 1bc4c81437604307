//! The first seed's two-link robot driven by four muscles (its figure 3),
//! from [`two_link_muscles`](crate::two_link_muscles)
//! (`models/two_link_muscles.toml`): forward dynamics with its muscles and
//! the sensitivity of the joint accelerations to the activations.
//!
//! Two uniform rods of 0.4 m (2 kg and 1 kg) hang from a revolute shoulder
//! at the world origin and are joined by a revolute elbow; gravity is `-y`;
//! at `q = 0` both links point straight down and positive angles swing the
//! arm forward (`+x`). Four Thelen (2003) muscles with rigid tendons, each a
//! path origin → via point → insertion, move it:
//!
//! | input | muscle | crosses            | action               |
//! |-------|--------|--------------------|----------------------|
//! | 0     | m1     | shoulder           | flexes the shoulder  |
//! | 1     | m2     | shoulder           | extends the shoulder |
//! | 2     | m3     | elbow              | flexes the elbow     |
//! | 3     | m4     | shoulder and elbow | extends both         |
//!
//! The drive inputs `w` are the four activations. [`forward_dynamics`] and
//! [`sensitivity`] are what a firmware calls every tick.

use crate::two_link_muscles::{self as file, M1_F32, M1_F64, M2_F32, M2_F64, M3_F32, M3_F64};
use crate::two_link_muscles::{M4_F32, M4_F64};
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::drive::{forward_dynamics_with_drives, DriveForces, ThelenMuscle};
use rodyn::planar::Planar;
use rodyn::sensitivity::forward_dynamics_and_sensitivity;
use rodyn::{Data, Model, Result, Scalar};

pub use file::{NB, NU, NV};

/// The robot's multibody model.
pub type RobotModel<S> = Model<S, NB, NV, NV, Planar>;
/// Its workspace.
pub type RobotData<S> = Data<S, NB, NV, Planar>;
/// Its four muscles, in input order.
pub type RobotMuscles<S> = [ThelenMuscle<S, Planar, 3>; NU];
/// Its drive forces.
pub type RobotForces<S> = DriveForces<S, Planar, NB, NV>;

/// The model in `f32`, as the firmware uses it.
pub const MODEL_F32: RobotModel<f32> = file::MODEL_F32;
/// The model in `f64`.
pub const MODEL_F64: RobotModel<f64> = file::MODEL_F64;
/// The muscles in `f32`.
pub const MUSCLES_F32: RobotMuscles<f32> = [M1_F32, M2_F32, M3_F32, M4_F32];
/// The muscles in `f64`.
pub const MUSCLES_F64: RobotMuscles<f64> = [M1_F64, M2_F64, M3_F64, M4_F64];

/// The model in any scalar type (e.g. a dual number, for parameter
/// derivatives).
///
/// # Errors
/// None for this model (planar revolute joints always cast); the `Result`
/// is that of [`Model::cast`].
pub fn model<S: Scalar>() -> Result<RobotModel<S>> {
    MODEL_F64.cast()
}

/// The four muscles in any scalar type.
#[must_use]
pub fn muscles<S: Scalar>() -> RobotMuscles<S> {
    MUSCLES_F64.map(|m| m.cast())
}

/// Joint accelerations (rad/s²) at `(q, v)` under activations `a`, by ABA.
/// `forces` receives the muscle forces.
///
/// # Errors
/// Non-finite state or activations.
pub fn forward_dynamics<'d, S: Scalar>(
    model: &RobotModel<S>,
    muscles: &RobotMuscles<S>,
    data: &'d mut RobotData<S>,
    q: &[S; NV],
    v: &[S; NV],
    activation: &[S; NU],
    forces: &mut RobotForces<S>,
) -> Result<&'d [S; NV]> {
    forward_dynamics_with_drives::<Aba, _, _, _, NB, NV, NV>(
        model,
        data,
        q,
        v,
        &[S::ZERO; NV],
        muscles,
        activation,
        forces,
    )
}

/// Joint accelerations and the full sensitivity matrix `∂q̈/∂a` (2 × 4,
/// rad/s² per unit activation), one extra articulated-body pass per muscle.
///
/// # Errors
/// As [`forward_dynamics`].
#[allow(clippy::too_many_arguments)]
pub fn sensitivity<'d, S: Scalar>(
    model: &RobotModel<S>,
    muscles: &RobotMuscles<S>,
    data: &'d mut RobotData<S>,
    q: &[S; NV],
    v: &[S; NV],
    activation: &[S; NU],
    forces: &mut RobotForces<S>,
    d_ddq_d_activation: &mut [[S; NU]; NV],
) -> Result<&'d [S; NV]> {
    forward_dynamics_and_sensitivity(
        model,
        data,
        q,
        v,
        &[S::ZERO; NV],
        muscles,
        activation,
        forces,
        d_ddq_d_activation,
    )
}

/// Activation rates `ȧ` (1/s) of the four muscles for excitations `u`.
#[must_use]
pub fn activation_rates<S: Scalar>(
    muscles: &RobotMuscles<S>,
    excitation: &[S; NU],
    activation: &[S; NU],
) -> [S; NU] {
    core::array::from_fn(|k| muscles[k].activation_rate(excitation[k], activation[k]))
}
