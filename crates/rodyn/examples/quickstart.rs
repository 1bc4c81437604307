use rodyn::algorithm::crba::crba;
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::algorithm::rnea::rnea;
use rodyn::prelude::*;

// A double pendulum about z, links 1 m, 1 kg at the tips; checked at compile time.
const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
const MODEL: Model<f64, 2, 2, 2> = Model::new(
    [None, Some(0)],                                      // parents
    [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)], // joints
    [
        Transform::IDENTITY,
        Transform::from_translation(Vec3::new(1.0, 0.0, 0.0)),
    ],
    [LINK, LINK],                                        // inertias, body frames
    Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)), // gravity, world frame
);

fn main() -> Result<(), Error> {
    let mut data = Data::new(); // every intermediate; `const`, can be a `static`
    let (q, v, a) = ([0.1, -0.2], [0.5, 0.3], [1.0, -1.0]);
    let tau = *rnea(&MODEL, &mut data, &q, &v, &a, None)?; // inverse dynamics, N m
    let by_aba = *Aba::forward_dynamics(&MODEL, &mut data, &q, &v, &tau, None)?;
    let by_crba = *Crba::forward_dynamics(&MODEL, &mut data, &q, &v, &tau, None)?;
    println!(
        "tau = {tau:.6?} N m, mass matrix = {:.6?}",
        crba(&MODEL, &mut data, &q)?
    );
    println!("ABA recovers a = {by_aba:.12?}, CRBA {by_crba:.12?}");
    Ok(())
}
