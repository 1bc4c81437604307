//! Springs conserve energy: the seed's pendulum with its return spring and a
//! 3-D double pendulum with a hardening spring over a via point, integrated
//! with classical RK4. The drift of kinetic + gravitational + spring energy
//! must be at the integrator's accuracy and shrink like dt⁴.

// Row and column indices mirror the matrix equations being checked.
#![allow(clippy::needless_range_loop)]

use rodyn::algorithm::energy::{kinetic_energy, potential_energy};
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::algorithm::kinematics::forward_kinematics_velocity;
use rodyn::drive::{
    forward_dynamics_with_drives, DriveForces, LinearSpring, NonlinearSpring, Path, PointGeometry,
};
use rodyn::prelude::*;
use rodyn::Endpoint;

/// Integrates `(q, v)` with RK4 for `steps` steps of `dt` and returns the
/// largest deviation of `energy` from its initial value.
fn max_energy_drift<const N: usize>(
    q0: [f64; N],
    dt: f64,
    steps: usize,
    mut acceleration: impl FnMut(&[f64; N], &[f64; N]) -> [f64; N],
    mut energy: impl FnMut(&[f64; N], &[f64; N]) -> f64,
) -> (f64, f64) {
    let (mut q, mut v) = (q0, [0.0; N]);
    let e0 = energy(&q, &v);
    let mut drift = 0.0f64;
    let add = |x: &[f64; N], h: f64, d: &[f64; N]| -> [f64; N] {
        core::array::from_fn(|k| x[k] + h * d[k])
    };
    for _ in 0..steps {
        let (k1q, k1v) = (v, acceleration(&q, &v));
        let (q2, v2) = (add(&q, 0.5 * dt, &k1q), add(&v, 0.5 * dt, &k1v));
        let (k2q, k2v) = (v2, acceleration(&q2, &v2));
        let (q3, v3) = (add(&q, 0.5 * dt, &k2q), add(&v, 0.5 * dt, &k2v));
        let (k3q, k3v) = (v3, acceleration(&q3, &v3));
        let (q4, v4) = (add(&q, dt, &k3q), add(&v, dt, &k3v));
        let (k4q, k4v) = (v4, acceleration(&q4, &v4));
        q = core::array::from_fn(|k| {
            q[k] + dt / 6.0 * (k1q[k] + 2.0 * k2q[k] + 2.0 * k3q[k] + k4q[k])
        });
        v = core::array::from_fn(|k| {
            v[k] + dt / 6.0 * (k1v[k] + 2.0 * k2v[k] + 2.0 * k3v[k] + k4v[k])
        });
        drift = drift.max((energy(&q, &v) - e0).abs());
    }
    (drift, e0)
}

/// Kinetic + gravitational + spring energy (J).
fn total_energy<const NB: usize, const NV: usize, G: PointGeometry, const K: usize>(
    model: &Model<f64, NB, NV, NV, G>,
    path: &Path<f64, G, K>,
    spring_energy: impl Fn(f64) -> f64,
    q: &[f64; NV],
    v: &[f64; NV],
) -> f64 {
    let mut data = Data::new();
    let kinetic = kinetic_energy(model, &mut data, q, v).unwrap();
    let gravity = potential_energy(model, &mut data, q).unwrap();
    forward_kinematics_velocity(model, &mut data, q, v).unwrap();
    kinetic + gravity + spring_energy(path.kinematics(&data).unwrap().length)
}

#[test]
fn pendulum_with_return_spring_conserves_energy() {
    // The seed's figure 1: revolute joint, 0.5 m link with 1 kg at its end,
    // endpoint at the end, spring to a world point 0.4 m beside the base.
    let model: Model<f64, 1, 1, 1> = Model::new(
        [None],
        [Joint::revolute(Axis::Z)],
        [Transform::IDENTITY],
        [Inertia::new(
            1.0,
            Vec3::new(0.0, -0.5, 0.0),
            Sym3::diagonal(0.02, 0.001, 0.02),
        )],
        Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
    );
    let spring = LinearSpring::new(
        Path::new([
            Endpoint::on_body(0, Vec3::new(0.0, -0.5, 0.0)),
            Endpoint::in_world(Vec3::new(0.4, 0.0, 0.0)),
        ]),
        80.0,
        0.3,
    );
    let run = |dt: f64| {
        let mut data = Data::new();
        let mut forces = DriveForces::new();
        max_energy_drift(
            [1.2],
            dt,
            (2.0 / dt) as usize,
            |q, v| {
                *forward_dynamics_with_drives::<Aba, _, _, _, 1, 1, 1>(
                    &model,
                    &mut data,
                    q,
                    v,
                    &[0.0],
                    &spring,
                    &[],
                    &mut forces,
                )
                .unwrap()
            },
            |q, v| {
                total_energy(
                    &model,
                    &spring.path,
                    |l| spring.potential_energy(l).unwrap(),
                    q,
                    v,
                )
            },
        )
    };
    let (coarse, e0) = run(2e-3);
    let (fine, _) = run(1e-3);
    println!("E0 = {e0:.6} J, max drift {coarse:.3e} J at dt = 2 ms, {fine:.3e} J at dt = 1 ms");
    assert!(
        e0.abs() > 1.0,
        "the test needs a non-trivial energy, got {e0}"
    );
    assert!(fine < 1e-9, "drift {fine} J at dt = 1 ms");
    // Fourth order: halving dt divides the drift by about 16.
    assert!(
        coarse / fine > 10.0,
        "drift ratio {} (coarse {coarse}, fine {fine})",
        coarse / fine
    );
}

#[test]
fn double_pendulum_with_hardening_spring_over_a_via_point_conserves_energy() {
    let link = |m: f64| {
        Inertia::new(
            m,
            Vec3::new(0.2, 0.0, 0.02),
            Sym3::diagonal(0.003, 0.01, 0.01),
        )
    };
    let model: Model<f64, 2, 2, 2> = Model::new(
        [None, Some(0)],
        [
            Joint::revolute(Axis::Z),
            Joint::revolute(Axis::Unit(Vec3::new(0.0, 0.6, 0.8))),
        ],
        [
            Transform::IDENTITY,
            Transform::from_translation(Vec3::new(0.4, 0.0, 0.0)),
        ],
        [link(1.0), link(0.6)],
        Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
    );
    let spring = NonlinearSpring::new(
        Path::new([
            Endpoint::in_world(Vec3::new(0.1, 0.3, 0.0)),
            Endpoint::on_body(0, Vec3::new(0.35, 0.05, 0.0)),
            Endpoint::on_body(1, Vec3::new(0.3, 0.0, 0.05)),
        ]),
        40.0,
        400.0,
        0.5,
    );
    let run = |dt: f64| {
        let mut data = Data::new();
        let mut forces = DriveForces::new();
        max_energy_drift(
            [0.7, -1.1],
            dt,
            (1.5 / dt) as usize,
            |q, v| {
                *forward_dynamics_with_drives::<Aba, _, _, _, 2, 2, 2>(
                    &model,
                    &mut data,
                    q,
                    v,
                    &[0.0; 2],
                    &spring,
                    &[],
                    &mut forces,
                )
                .unwrap()
            },
            |q, v| {
                total_energy(
                    &model,
                    &spring.path,
                    |l| spring.potential_energy(l).unwrap(),
                    q,
                    v,
                )
            },
        )
    };
    let (coarse, e0) = run(2e-3);
    let (fine, _) = run(1e-3);
    println!("E0 = {e0:.6} J, max drift {coarse:.3e} J at dt = 2 ms, {fine:.3e} J at dt = 1 ms");
    assert!(
        e0.abs() > 1.0,
        "the test needs a non-trivial energy, got {e0}"
    );
    assert!(fine < 1e-9, "drift {fine} J at dt = 1 ms");
    assert!(
        coarse / fine > 10.0,
        "drift ratio {} (coarse {coarse}, fine {fine})",
        coarse / fine
    );
}
