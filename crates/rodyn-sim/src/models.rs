//! The models the scenarios and experiments run, built in Rust for any scalar.

use rodyn::joint::{Axis, Joint};
use rodyn::spatial::{Inertia, Mat3, Motion, Sym3, Transform, Vec3};
use rodyn::{Model, Scalar};

/// Gravity along -z (m/s²).
pub const GRAVITY: f64 = 9.81;

fn gravity_z<S: Scalar>() -> Motion<S> {
    Motion::new(
        Vec3::ZERO,
        Vec3::new(S::ZERO, S::ZERO, S::from_f64(-GRAVITY)),
    )
}

fn v3<S: Scalar>(x: f64, y: f64, z: f64) -> Vec3<S> {
    Vec3::new(S::from_f64(x), S::from_f64(y), S::from_f64(z))
}

/// A 7-DoF arm with the Franka Emika Panda's kinematics and inertias, as
/// published in its URDF (`models/urdf/panda.urdf`: joint origins, link
/// masses, centres of mass and inertia tensors of links 1-7; the hand is
/// left off). Base fixed, gravity along -z, no joint friction or limits.
#[must_use]
pub fn arm7<S: Scalar>() -> Model<S, 7, 7, 7> {
    let f = S::from_f64;
    let half_pi = core::f64::consts::FRAC_PI_2;
    let about_x = |angle: f64| Mat3::from_axis_index(0, f(angle.sin()), f(angle.cos()));
    // Joint origins: xyz and roll (rpy has only a roll in the Panda).
    let origins: [([f64; 3], f64); 7] = [
        ([0.0, 0.0, 0.333], 0.0),
        ([0.0, 0.0, 0.0], -half_pi),
        ([0.0, -0.316, 0.0], half_pi),
        ([0.0825, 0.0, 0.0], half_pi),
        ([-0.0825, 0.384, 0.0], -half_pi),
        ([0.0, 0.0, 0.0], half_pi),
        ([0.088, 0.0, 0.0], half_pi),
    ];
    // mass, com, [ixx ixy ixz iyy iyz izz].
    let links: [(f64, [f64; 3], [f64; 6]); 7] = [
        (
            4.970684,
            [0.003875, 0.002081, -0.04762],
            [0.70337, -0.000139, 0.006772, 0.70661, 0.019169, 0.009117],
        ),
        (
            0.646926,
            [-0.003141, -0.02872, 0.003495],
            [0.007962, -0.003925, 0.010254, 0.02811, 0.000704, 0.025995],
        ),
        (
            3.228604,
            [0.027518, 0.039252, -0.066502],
            [0.037242, -0.004761, -0.011396, 0.036155, -0.012805, 0.01083],
        ),
        (
            3.587895,
            [-0.05317, 0.104419, 0.027454],
            [0.025853, 0.007796, -0.001332, 0.019552, 0.008641, 0.028323],
        ),
        (
            1.225946,
            [-0.011953, 0.041065, -0.038437],
            [0.035549, -0.002117, -0.004037, 0.029474, 0.000229, 0.008627],
        ),
        (
            1.666555,
            [0.060149, -0.014117, -0.010517],
            [0.001964, 0.000109, -0.001158, 0.004354, 0.000341, 0.005433],
        ),
        (
            0.735522,
            [0.010517, -0.004252, 0.061597],
            [
                0.012516, -0.000428, -0.001196, 0.010027, -0.000741, 0.004815,
            ],
        ),
    ];
    let placements =
        origins.map(|(xyz, roll)| Transform::new(about_x(roll), v3(xyz[0], xyz[1], xyz[2])));
    let inertias = links.map(|(m, c, i)| {
        Inertia::new(
            f(m),
            v3(c[0], c[1], c[2]),
            Sym3::new(f(i[0]), f(i[1]), f(i[2]), f(i[3]), f(i[4]), f(i[5])),
        )
    });
    Model::new(
        [None, Some(0), Some(1), Some(2), Some(3), Some(4), Some(5)],
        [Joint::revolute(Axis::Z); 7],
        placements,
        inertias,
        gravity_z(),
    )
}

/// The arm's release pose (rad): elbow bent, wrist turned; it then swings
/// freely under gravity.
pub const ARM7_RELEASE: [f64; 7] = [0.0, 0.6, 0.3, -1.8, 0.4, 1.6, 0.8];

/// A serial chain of `N` identical links swinging about alternating y and x
/// axes (a 3-D chain), each 1/N m long with mass 1/N kg, hanging along -z:
/// total length 1 m and mass 1 kg whatever N, so chains of different
/// lengths are comparable.
#[must_use]
pub fn chain<S: Scalar, const N: usize>() -> Model<S, N, N, N> {
    let l = 1.0 / N as f64;
    let m = 1.0 / N as f64;
    // A thin rod: inertia m l²/12 across, a little along it.
    let across = m * l * l / 12.0;
    let link = Inertia::new(
        S::from_f64(m),
        v3(0.0, 0.0, -l / 2.0),
        Sym3::diagonal(
            S::from_f64(across),
            S::from_f64(across),
            S::from_f64(across * 0.01),
        ),
    );
    let parents = core::array::from_fn(|i| i.checked_sub(1));
    let joints =
        core::array::from_fn(|i| Joint::revolute(if i % 2 == 0 { Axis::Y } else { Axis::X }));
    let placements = core::array::from_fn(|i| {
        Transform::from_translation(if i == 0 { Vec3::ZERO } else { v3(0.0, 0.0, -l) })
    });
    Model::new(parents, joints, placements, [link; N], gravity_z())
}

/// A point mass of 1 kg on a prismatic joint along z, without gravity: the
/// spring `-k z` and damper come from the loads.
#[must_use]
pub fn slider<S: Scalar>() -> Model<S, 1, 1, 1> {
    Model::new(
        [None],
        [Joint::prismatic(Axis::Z)],
        [Transform::IDENTITY],
        [Inertia::point_mass(S::ONE, Vec3::ZERO)],
        Motion::new(Vec3::ZERO, Vec3::ZERO),
    )
}

/// A free-floating box (0.3 x 0.2 x 0.1 m, 2 kg) without gravity: a
/// torque-free tumbling body for the quaternion experiments.
#[must_use]
pub fn tumbling_box<S: Scalar>() -> Model<S, 1, 7, 6> {
    let m = 2.0;
    let (a, b, c) = (0.3, 0.2, 0.1);
    Model::new(
        [None],
        [Joint::free_flyer()],
        [Transform::IDENTITY],
        [Inertia::new(
            S::from_f64(m),
            Vec3::ZERO,
            Sym3::diagonal(
                S::from_f64(m / 12.0 * (b * b + c * c)),
                S::from_f64(m / 12.0 * (a * a + c * c)),
                S::from_f64(m / 12.0 * (a * a + b * b)),
            ),
        )],
        Motion::new(Vec3::ZERO, Vec3::ZERO),
    )
}

/// A two-link pendulum whose second link has mass `tip_mass` (kg) and a
/// proportional rotational inertia: as it goes to zero, the second joint
/// moves a massless body (ABA's D → 0, the mass matrix turns singular).
#[must_use]
pub fn light_tip_pendulum<S: Scalar>(tip_mass: f64) -> Model<S, 2, 2, 2> {
    let rod = |m: f64| {
        let across = m * 0.5 * 0.5 / 12.0;
        Inertia::new(
            S::from_f64(m),
            v3(0.0, 0.0, -0.25),
            Sym3::diagonal(
                S::from_f64(across),
                S::from_f64(across),
                S::from_f64(across * 0.01),
            ),
        )
    };
    Model::new(
        [None, Some(0)],
        [Joint::revolute(Axis::Y), Joint::revolute(Axis::Y)],
        [
            Transform::IDENTITY,
            Transform::from_translation(v3(0.0, 0.0, -0.5)),
        ],
        [rod(1.0), rod(tip_mass)],
        gravity_z(),
    )
}
