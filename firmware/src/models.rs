//! The example models as `const` values in f32.
//!
//! Written by hand until the model compiler (`crates/rodyn-model`) can
//! generate them from `models/` in `build.rs`. The host tests include this
//! file too (`#[path]`) and cast the models to f64, so the std build and the
//! firmware compute with exactly the same parameters.
//!
//! Units: metres, kilograms, kg m², radians. Gravity is 9.81 m/s² along -z
//! for the arm and the quadruped, along -y for the pendulum (it swings in
//! the x-y plane about z).

use rodyn::drive::{LinearSpring, Path};
use rodyn::planar::{Planar, PlanarInertia, PlanarJoint, PlanarMotion, PlanarTransform, Vec2};
use rodyn::prelude::*;
use rodyn::Endpoint;

/// Gravitational acceleration (m/s²).
const G: f32 = 9.81;

/// Pendulum link length (m).
pub const PENDULUM_LENGTH: f32 = 0.5;
/// Pendulum mass (kg), a uniform thin rod.
pub const PENDULUM_MASS: f32 = 1.0;
/// The rod's moment of inertia about its centre, `m l² / 12` (kg m²).
const PENDULUM_ROD_INERTIA: f32 = PENDULUM_MASS * PENDULUM_LENGTH * PENDULUM_LENGTH / 12.0;

/// The seed pendulum: one revolute joint about z at the origin, a uniform
/// rod of 0.5 m hanging along the body's -y axis (q = 0 hangs straight down).
pub const PENDULUM: Model<f32, 1, 1, 1> = Model::new(
    [None],
    [Joint::revolute(Axis::Z)],
    [Transform::IDENTITY],
    [Inertia::new(
        PENDULUM_MASS,
        Vec3::new(0.0, -PENDULUM_LENGTH / 2.0, 0.0),
        // A thin rod along y: no inertia about its own axis beyond a 1 cm radius.
        Sym3::diagonal(PENDULUM_ROD_INERTIA, 5.0e-5, PENDULUM_ROD_INERTIA),
    )],
    Motion::new(Vec3::ZERO, Vec3::new(0.0, -G, 0.0)),
);

/// The seed pendulum's return spring: from the rod's tip to an anchor 0.4 m
/// beside the pivot; 40 N/m, rest length 0.3 m.
pub const PENDULUM_SPRING: LinearSpring<f32, Spatial, 2> = LinearSpring::new(
    Path::new([
        Endpoint::on_body(0, Vec3::new(0.0, -PENDULUM_LENGTH, 0.0)),
        Endpoint::in_world(Vec3::new(0.4, 0.0, 0.0)),
    ]),
    40.0,
    0.3,
);

/// The same pendulum as a planar model: 3-component spatial algebra.
pub const PENDULUM_PLANAR: Model<f32, 1, 1, 1, Planar> = Model::new_planar(
    [None],
    [PlanarJoint::Revolute],
    [PlanarTransform::from_translation(Vec2::new(0.0, 0.0))],
    [PlanarInertia::new(
        PENDULUM_MASS,
        Vec2::new(0.0, -PENDULUM_LENGTH / 2.0),
        PENDULUM_ROD_INERTIA,
    )],
    PlanarMotion::new(0.0, Vec2::new(0.0, -G)),
);

/// Rotation about x by -90° (the modified-DH twist `α = -π/2`).
const RX_MINUS_90: Mat3<f32> =
    Mat3::from_rows([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]]);
/// Rotation about x by +90° (`α = +π/2`).
const RX_PLUS_90: Mat3<f32> = Mat3::from_rows([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]);

/// A link's inertia: mass, centre of mass, principal moments (kg m²).
const fn link(mass: f32, com: [f32; 3], moments: [f32; 3]) -> Inertia<f32> {
    Inertia::new(
        mass,
        Vec3::from_array(com),
        Sym3::diagonal(moments[0], moments[1], moments[2]),
    )
}

/// A Panda-like 7-DoF arm.
///
/// Kinematics from Franka Emika's published modified-DH table
/// (`d₁ = 0.333`, `d₃ = 0.316`, `a₄ = 0.0825`, `a₅ = -0.0825`, `d₅ = 0.384`,
/// `a₇ = 0.088`; twists ±90°): each placement is `Rot_x(α) Trans_x(a)
/// Trans_z(d)`. Masses and centres of mass are rounded from the identified
/// parameters published by Gaz et al. (2019); the rotational inertias keep
/// only plausible principal moments. Without hand or payload.
pub const PANDA: Model<f32, 7, 7, 7> = Model::new(
    [None, Some(0), Some(1), Some(2), Some(3), Some(4), Some(5)],
    [Joint::revolute(Axis::Z); 7],
    [
        Transform::from_translation(Vec3::new(0.0, 0.0, 0.333)),
        Transform::from_rotation(RX_MINUS_90),
        Transform::new(RX_PLUS_90, Vec3::new(0.0, -0.316, 0.0)),
        Transform::new(RX_PLUS_90, Vec3::new(0.0825, 0.0, 0.0)),
        Transform::new(RX_MINUS_90, Vec3::new(-0.0825, 0.384, 0.0)),
        Transform::from_rotation(RX_PLUS_90),
        Transform::new(RX_PLUS_90, Vec3::new(0.088, 0.0, 0.0)),
    ],
    [
        link(4.971, [0.0039, 0.0021, -0.0476], [0.0300, 0.0300, 0.0091]),
        link(0.647, [-0.0031, -0.0287, 0.0035], [0.0080, 0.0281, 0.0260]),
        link(3.229, [0.0275, 0.0393, -0.0665], [0.0372, 0.0362, 0.0108]),
        link(3.588, [-0.0532, 0.1044, 0.0275], [0.0259, 0.0196, 0.0283]),
        link(1.226, [-0.0120, 0.0411, -0.0384], [0.0355, 0.0295, 0.0086]),
        link(1.667, [0.0601, -0.0141, -0.0105], [0.0020, 0.0044, 0.0054]),
        link(0.736, [0.0105, -0.0043, 0.0616], [0.0125, 0.0100, 0.0048]),
    ],
    Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -G)),
);

/// The Panda's joint torque limits (N m), from its datasheet.
pub const PANDA_TORQUE_LIMITS: [f32; 7] = [87.0, 87.0, 87.0, 87.0, 12.0, 12.0, 12.0];

/// The Panda's "ready" pose (rad), away from joint limits and singularities.
pub const PANDA_READY: [f32; 7] = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785];

/// Number of bodies of [`QUADRUPED`]: trunk plus three links per leg.
pub const QUADRUPED_NB: usize = 13;
/// Configuration size of [`QUADRUPED`]: `[x y z qx qy qz qw]` and 12 angles.
pub const QUADRUPED_NQ: usize = 19;
/// Velocity size of [`QUADRUPED`]: base twist (6) and 12 joint rates.
pub const QUADRUPED_NV: usize = 18;

/// Hip positions in the trunk frame (x forward, y left, z up), in the body
/// order front-left, front-right, hind-left, hind-right.
const HIPS: [[f32; 3]; 4] = [
    [0.09, 0.05, 0.0],
    [0.09, -0.05, 0.0],
    [-0.09, 0.05, 0.0],
    [-0.09, -0.05, 0.0],
];
/// Thigh and shank length (m).
const LEG_SEGMENT: f32 = 0.07;

const TRUNK: Inertia<f32> = link(1.0, [0.0, 0.0, 0.0], [0.0017, 0.0053, 0.0061]);
const HIP: Inertia<f32> = link(0.05, [0.0, 0.0, 0.0], [2.0e-5, 2.0e-5, 2.0e-5]);
const THIGH: Inertia<f32> = link(0.10, [0.0, 0.0, -0.035], [4.5e-5, 4.5e-5, 5.0e-6]);
const SHANK: Inertia<f32> = link(0.06, [0.0, 0.0, -0.035], [2.7e-5, 2.7e-5, 3.0e-6]);

/// A floating-base quadruped the size of a Sony Aibo (1.84 kg): a free-flyer
/// trunk and four legs of hip abduction (x), hip flexion (y) and knee (y).
pub const QUADRUPED: Model<f32, QUADRUPED_NB, QUADRUPED_NQ, QUADRUPED_NV> = Model::new(
    [
        None,
        Some(0),
        Some(1),
        Some(2),
        Some(0),
        Some(4),
        Some(5),
        Some(0),
        Some(7),
        Some(8),
        Some(0),
        Some(10),
        Some(11),
    ],
    [
        Joint::free_flyer(),
        Joint::revolute(Axis::X),
        Joint::revolute(Axis::Y),
        Joint::revolute(Axis::Y),
        Joint::revolute(Axis::X),
        Joint::revolute(Axis::Y),
        Joint::revolute(Axis::Y),
        Joint::revolute(Axis::X),
        Joint::revolute(Axis::Y),
        Joint::revolute(Axis::Y),
        Joint::revolute(Axis::X),
        Joint::revolute(Axis::Y),
        Joint::revolute(Axis::Y),
    ],
    [
        Transform::IDENTITY,
        Transform::from_translation(Vec3::from_array(HIPS[0])),
        Transform::IDENTITY,
        Transform::from_translation(Vec3::new(0.0, 0.0, -LEG_SEGMENT)),
        Transform::from_translation(Vec3::from_array(HIPS[1])),
        Transform::IDENTITY,
        Transform::from_translation(Vec3::new(0.0, 0.0, -LEG_SEGMENT)),
        Transform::from_translation(Vec3::from_array(HIPS[2])),
        Transform::IDENTITY,
        Transform::from_translation(Vec3::new(0.0, 0.0, -LEG_SEGMENT)),
        Transform::from_translation(Vec3::from_array(HIPS[3])),
        Transform::IDENTITY,
        Transform::from_translation(Vec3::new(0.0, 0.0, -LEG_SEGMENT)),
    ],
    [
        TRUNK, HIP, THIGH, SHANK, HIP, THIGH, SHANK, HIP, THIGH, SHANK, HIP, THIGH, SHANK,
    ],
    Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -G)),
);
