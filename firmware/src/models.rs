//! The example models: the shipped model files of `models/`, compiled by
//! `rodyn-scenarios`' build script into `const` values, plus what the
//! examples add to them. Nothing here is written by hand twice: the host
//! tests use the same generated modules.
//!
//! Units: metres, kilograms, kg m², radians. Gravity is 9.81 m/s² along -z
//! for the arm and the quadruped, along -y for the pendulum (it swings in
//! the x-y plane about z).

use rodyn::algorithm::crba::CrbaPlan;
use rodyn::planar::{Planar, PlanarInertia, PlanarJoint, PlanarMotion, PlanarTransform, Vec2};
use rodyn::{Frame, Model};

pub use rodyn_scenarios::{aibo, muscle_robot, panda, pendulum, quadruped};

/// Where each of the simulated Panda's encoders has its zero on its disc
/// (counts of 2¹⁸): an arbitrary mounting, the same in every example.
pub const PANDA_ENCODER_OFFSETS: [u32; panda::NV] =
    [1_000, 70_000, 3_000, 200_000, 5_000, 131_072, 12_345];

/// The Panda's joint torque limits (N m), from its datasheet: the full
/// scale of the simulated drives.
pub const PANDA_TORQUE_LIMITS: [f32; panda::NV] = [87.0, 87.0, 87.0, 87.0, 12.0, 12.0, 12.0];

/// The Panda's "ready" pose (rad), away from joint limits and singularities.
pub const PANDA_READY: [f32; panda::NV] = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];

/// The Panda's flange (`panda_link8` of its URDF, merged into the last
/// link by the model compiler, which keeps it as a frame): 0.107 m along
/// the last link's z axis, with its axes, where a tool is mounted.
pub const PANDA_FLANGE: Frame<f32> = panda::FRAMES_F32[panda::frame::PANDA_LINK8];

/// The pendulum of `model` (`models/pendulum.toml` in one precision) as a
/// planar model, in a `const` of type `Model<$s, 1, 1, 1, Planar>`.
macro_rules! planar_pendulum {
    ($model:expr) => {{
        let link = $model.inertia(pendulum::body::LINK);
        let gravity = $model.gravity().lin;
        Model::new_planar(
            [None],
            [PlanarJoint::Revolute],
            [PlanarTransform::from_translation(Vec2::new(0.0, 0.0))],
            [PlanarInertia::new(
                link.mass,
                Vec2::new(link.com.x, link.com.y),
                link.rot_inertia.zz,
            )],
            PlanarMotion::new(0.0, Vec2::new(gravity.x, gravity.y)),
        )
    }};
}

/// The pendulum of `models/pendulum.toml` as a planar model: the same link
/// (it turns about z and its centre of mass lies in the x-y plane) with the
/// 3-component planar algebra, to measure what planarity saves.
pub const PENDULUM_PLANAR: Model<f32, 1, 1, 1, Planar> = planar_pendulum!(pendulum::MODEL_F32);

/// CRBA's plan for [`PENDULUM_PLANAR`] (a plane has no frames to turn).
pub const PENDULUM_PLANAR_CRBA_PLAN: CrbaPlan<f32, 1, Planar> =
    CrbaPlan::unturned(&PENDULUM_PLANAR);

/// [`PENDULUM_PLANAR`] in f64, for the f64 cost probe.
pub const PENDULUM_PLANAR_F64: Model<f64, 1, 1, 1, Planar> = planar_pendulum!(pendulum::MODEL_F64);

/// CRBA's plan for [`PENDULUM_PLANAR_F64`].
pub const PENDULUM_PLANAR_F64_CRBA_PLAN: CrbaPlan<f64, 1, Planar> =
    CrbaPlan::unturned(&PENDULUM_PLANAR_F64);
