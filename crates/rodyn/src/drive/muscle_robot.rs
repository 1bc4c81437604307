//! The first seed's two-link robot driven by four muscles (its figure 3),
//! as a ready-made planar model for examples, tests and firmware benchmarks.
//!
//! Two links of length [`LINK_LENGTH`] hang from a revolute shoulder at the
//! world origin and are joined by a revolute elbow; gravity is `-y`; at
//! `q = 0` both links point straight down and positive angles swing the arm
//! forward (`+x`). Four Thelen muscles with rigid tendons, each a path of
//! three points (origin, via point, insertion), move it:
//!
//! | input | muscle | crosses           | action                 |
//! |-------|--------|-------------------|------------------------|
//! | 0     | m1     | shoulder          | flexes the shoulder    |
//! | 1     | m2     | shoulder          | extends the shoulder   |
//! | 2     | m3     | elbow             | flexes the elbow       |
//! | 3     | m4     | shoulder and elbow| extends both           |
//!
//! The drive inputs `w` are the four activations. The functions here are
//! what a firmware calls every tick: [`forward_dynamics`] and
//! [`sensitivity`].

use crate::algorithm::forward_dynamics::Aba;
use crate::drive::{
    forward_dynamics_with_drives, DriveForces, Path, ThelenMuscle, ThelenParameters,
};
use crate::endpoint::Endpoint;
use crate::error::Result;
use crate::planar::{Planar, PlanarInertia, PlanarJoint, PlanarMotion, PlanarTransform, Vec2};
use crate::sensitivity::forward_dynamics_and_sensitivity;
use crate::{Data, Model, Scalar};

/// Bodies.
pub const NB: usize = 2;
/// Joint coordinates (shoulder, elbow).
pub const NV: usize = 2;
/// Muscles, hence drive inputs.
pub const NU: usize = 4;
/// Length of each link (m).
pub const LINK_LENGTH: f64 = 0.4;

/// The robot's multibody model.
pub type RobotModel<S> = Model<S, NB, NV, NV, Planar>;
/// Its workspace.
pub type RobotData<S> = Data<S, NB, NV, Planar>;
/// Its four muscles.
pub type RobotMuscles<S> = [ThelenMuscle<S, Planar, 3>; NU];
/// Its drive forces.
pub type RobotForces<S> = DriveForces<S, Planar, NB, NV>;

/// The multibody model: upper link 2 kg, lower link 1 kg, uniform rods.
#[must_use]
pub fn model<S: Scalar>() -> RobotModel<S> {
    let c = S::from_f64;
    let l = LINK_LENGTH;
    let rod = |m: f64| PlanarInertia::new(c(m), Vec2::new(c(0.5 * l), c(0.0)), c(m * l * l / 12.0));
    // The shoulder frame is turned by -90° so that the links' x axes point
    // down at q = 0.
    Model::new_planar(
        [None, Some(0)],
        [PlanarJoint::Revolute, PlanarJoint::Revolute],
        [
            PlanarTransform::from_cos_sin(c(0.0), c(-1.0), Vec2::ZERO),
            PlanarTransform::from_translation(Vec2::new(c(l), c(0.0))),
        ],
        [rod(2.0), rod(1.0)],
        PlanarMotion::new(c(0.0), Vec2::new(c(0.0), c(-9.81))),
    )
}

/// The four muscles (see the module table). Points are in the body frames
/// (x along the link, y toward the front at `q = 0`) or the world frame.
#[must_use]
pub fn muscles<S: Scalar>() -> RobotMuscles<S> {
    let c = S::from_f64;
    let world = |x: f64, y: f64| Endpoint::<S, Planar>::in_world(Vec2::new(c(x), c(y)));
    let upper = |x: f64, y: f64| Endpoint::<S, Planar>::on_body(0, Vec2::new(c(x), c(y)));
    let lower = |x: f64, y: f64| Endpoint::<S, Planar>::on_body(1, Vec2::new(c(x), c(y)));
    // (max isometric force N, optimal fibre length m, tendon slack length m)
    let muscle = |path, (f0, l0, lts): (f64, f64, f64), input| {
        ThelenMuscle::new(
            path,
            ThelenParameters::thelen_2003_in(c(f0), c(l0), c(lts), c(0.0)),
            input,
        )
    };
    [
        muscle(
            Path::new([world(0.10, 0.0), upper(0.05, 0.04), upper(0.20, 0.03)]),
            MUSCLE_PARAMETERS[0],
            0,
        ),
        muscle(
            Path::new([world(-0.10, 0.0), upper(0.05, -0.04), upper(0.20, -0.03)]),
            MUSCLE_PARAMETERS[1],
            1,
        ),
        muscle(
            Path::new([upper(0.10, 0.03), upper(0.35, 0.04), lower(0.10, 0.03)]),
            MUSCLE_PARAMETERS[2],
            2,
        ),
        muscle(
            Path::new([world(-0.08, 0.02), upper(0.35, -0.04), lower(0.10, -0.03)]),
            MUSCLE_PARAMETERS[3],
            3,
        ),
    ]
}

/// `(F₀ᴹ N, l₀ᴹ m, lₛᵀ m)` of m1 … m4, chosen so that every fibre is near
/// its optimal length with the arm hanging (`q = 0`): the path lengths there
/// are 0.228, 0.228, 0.400 and 0.522 m.
pub const MUSCLE_PARAMETERS: [(f64, f64, f64); NU] = [
    (400.0, 0.12, 0.11),
    (400.0, 0.12, 0.11),
    (300.0, 0.12, 0.27),
    (300.0, 0.12, 0.41),
];

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

/// Joint accelerations and the full sensitivity matrix `∂q̈/∂a` (2 × 4).
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
