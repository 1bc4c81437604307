//! Quick start: a `const` model, inverse dynamics, and both forward-dynamics
//! methods behind one interface.
//!
//! Run with `cargo run -p rodyn --example quickstart`.

use rodyn::algorithm::crba::crba;
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics, Method};
use rodyn::algorithm::rnea::{gravity_torques, rnea};
use rodyn::prelude::*;

/// A two-link arm: shoulder about z, elbow about z, 0.4 m and 0.3 m links.
const ARM: Model<f64, 2, 2, 2> = Model::new(
    [None, Some(0)],
    [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
    [
        Transform::IDENTITY,
        Transform::from_translation(Vec3::new(0.4, 0.0, 0.0)),
    ],
    [
        Inertia::new(
            2.0,
            Vec3::new(0.2, 0.0, 0.0),
            Sym3::diagonal(0.002, 0.03, 0.03),
        ),
        Inertia::new(
            1.2,
            Vec3::new(0.15, 0.0, 0.0),
            Sym3::diagonal(0.001, 0.01, 0.01),
        ),
    ],
    Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
);

fn main() -> Result<(), Error> {
    ARM.validate()?;
    let mut data = Data::new();
    let (q, v, a) = ([0.3, -0.5], [1.0, 0.5], [0.2, -0.1]);

    let tau = *rnea(&ARM, &mut data, &q, &v, &a, None)?;
    println!("RNEA torques for a = {a:?}: {tau:.6?} N m");
    println!(
        "gravity torques: {:.6?} N m",
        gravity_torques(&ARM, &mut data, &q)?
    );
    println!("mass matrix: {:.6?}", crba(&ARM, &mut data, &q)?);

    // Swap the method by changing one type ...
    let by_aba = *Aba::forward_dynamics(&ARM, &mut data, &q, &v, &tau, None)?;
    let by_crba = *Crba::forward_dynamics(&ARM, &mut data, &q, &v, &tau, None)?;
    // ... or one run-time value.
    let by_value = *Method::Crba.forward_dynamics(&ARM, &mut data, &q, &v, &tau, None)?;
    println!("ABA  recovers a = {by_aba:.12?}");
    println!("CRBA recovers a = {by_crba:.12?} (also {by_value:.12?})");
    Ok(())
}
