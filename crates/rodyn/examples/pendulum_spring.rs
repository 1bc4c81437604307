//! The first seed's pendulum with a return spring (its figure 1): a
//! revolute joint on a fixed base, a rigid link with an endpoint at its end,
//! and a spring from that endpoint to a second endpoint shifted by a fixed
//! translation from the base. Prints a short trajectory and the energy.
//!
//! Run: `cargo run -p rodyn --example pendulum_spring`

use rodyn::algorithm::energy::{kinetic_energy, potential_energy};
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::drive::{forward_dynamics_with_drives, DriveForces, LinearSpring, Path};
use rodyn::prelude::*;
use rodyn::Endpoint;

/// Length of the link (m); it hangs along -y at q = 0.
const LINK: f64 = 0.5;

/// The pendulum: 1 kg at the end of the link, gravity -y.
const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
    [None],
    [Joint::revolute(Axis::Z)],
    [Transform::IDENTITY],
    [Inertia::new(
        1.0,
        Vec3::new(0.0, -LINK, 0.0),
        Sym3::diagonal(0.02, 0.001, 0.02),
    )],
    Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
);

/// The return spring: from the link's endpoint to an anchor 0.4 m beside
/// the base; 80 N/m, rest length 0.3 m.
const SPRING: LinearSpring<f64, Spatial, 2> = LinearSpring::new(
    Path::new([
        Endpoint::on_body(0, Vec3::new(0.0, -LINK, 0.0)),
        Endpoint::in_world(Vec3::new(0.4, 0.0, 0.0)),
    ]),
    80.0,
    0.3,
);

fn main() -> Result<(), rodyn::Error> {
    let mut data = Data::new();
    let mut forces = DriveForces::new();
    let energy =
        |data: &mut Data<f64, 1, 1>, q: &[f64; 1], v: &[f64; 1]| -> Result<f64, rodyn::Error> {
            let kinetic = kinetic_energy(&PENDULUM, data, q, v)?;
            let gravity = potential_energy(&PENDULUM, data, q)?;
            let length = SPRING.path.kinematics(data)?.length;
            Ok(kinetic + gravity + SPRING.potential_energy(length)?)
        };
    let (mut q, mut v) = ([1.2], [0.0]);
    let dt = 1e-3;
    rodyn_cli::outln!(
        "{:>5} {:>9} {:>9} {:>9} {:>10} {:>12}",
        "t s",
        "q rad",
        "v rad/s",
        "L m",
        "tension N",
        "energy J"
    );
    for step in 0..=2000 {
        if step % 100 == 0 {
            let e = energy(&mut data, &q, &v)?;
            let kin = SPRING.path.kinematics(&data)?;
            rodyn_cli::outln!(
                "{:5.2} {:9.5} {:9.5} {:9.5} {:10.4} {:12.9}",
                step as f64 * dt,
                q[0],
                v[0],
                kin.length,
                SPRING.tension(kin.length)?,
                e
            );
        }
        // Classical RK4 on (q, v).
        let mut accel = |q: f64, v: f64| -> Result<f64, rodyn::Error> {
            Ok(forward_dynamics_with_drives::<Aba, _, _, _, 1, 1, 1>(
                &PENDULUM,
                &mut data,
                &[q],
                &[v],
                &[0.0],
                &SPRING,
                &[],
                &mut forces,
            )?[0])
        };
        let (q0, v0) = (q[0], v[0]);
        let k1 = (v0, accel(q0, v0)?);
        let k2 = (
            v0 + 0.5 * dt * k1.1,
            accel(q0 + 0.5 * dt * k1.0, v0 + 0.5 * dt * k1.1)?,
        );
        let k3 = (
            v0 + 0.5 * dt * k2.1,
            accel(q0 + 0.5 * dt * k2.0, v0 + 0.5 * dt * k2.1)?,
        );
        let k4 = (v0 + dt * k3.1, accel(q0 + dt * k3.0, v0 + dt * k3.1)?);
        q[0] += dt / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
        v[0] += dt / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
    }
    Ok(())
}
