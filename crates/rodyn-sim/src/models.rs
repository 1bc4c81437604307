//! The models the scenarios and experiments run, built in Rust for any scalar.

use rodyn::joint::{Axis, Joint};
use rodyn::spatial::{Inertia, Motion, Sym3, Transform, Vec3};
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

/// The 7-DoF Franka Emika Panda of `models/panda.toml` (its URDF, hand
/// merged into the last link), as `rodyn-scenarios` compiles it, in any
/// scalar. Base fixed, gravity along -z, no joint friction or limits.
#[must_use]
pub fn arm7<S: Scalar>() -> Model<S, 7, 7, 7> {
    rodyn_scenarios::panda::MODEL_F64
        .cast()
        .expect("the Panda has no custom joint, so every scalar conversion succeeds")
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
