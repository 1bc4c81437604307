//! Failure map 3: a vanishing link. A two-link pendulum whose tip link has
//! mass m (and a proportional inertia). ABA's pivot D of the tip joint stays
//! proportional to the tip's own inertia, so ABA keeps its accuracy until m
//! underflows. CRBA's factorisation tests each pivot against its own
//! diagonal entry of the mass matrix, the tip's against the tip's own
//! inertia, so it too keeps its accuracy until the tip's inertia
//! underflows. A truly massless tip is reported by both.

use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::prelude::*;

fn pendulum<S: Scalar>(tip_mass: f64) -> Model<S, 2, 2, 2> {
    let rod = |m: f64| {
        let across = S::from_f64(m * 0.25 / 12.0);
        Inertia::new(
            S::from_f64(m),
            Vec3::new(S::ZERO, S::ZERO, S::from_f64(-0.25)),
            Sym3::diagonal(across, across, across * S::from_f64(0.01)),
        )
    };
    Model::new(
        [None, Some(0)],
        [Joint::revolute(Axis::Y), Joint::revolute(Axis::Y)],
        [
            Transform::IDENTITY,
            Transform::from_translation(Vec3::new(S::ZERO, S::ZERO, S::from_f64(-0.5))),
        ],
        [rod(1.0), rod(tip_mass)],
        Motion::new(Vec3::ZERO, Vec3::new(S::ZERO, S::ZERO, S::from_f64(-9.81))),
    )
}

fn relative_error<F: ForwardDynamics, S: Scalar>(tip_mass: f64) -> Result<f64, Error> {
    let (q, v) = ([0.4, -0.9], [0.3, 1.1]);
    let reference = *Aba::forward_dynamics(
        &pendulum::<f64>(tip_mass.max(1e-30)),
        &mut Data::new(),
        &q,
        &v,
        &[0.0; 2],
        None,
    )?;
    let a = *F::forward_dynamics(
        &pendulum::<S>(tip_mass),
        &mut Data::new(),
        &q.map(S::from_f64),
        &v.map(S::from_f64),
        &[S::ZERO; 2],
        None,
    )?;
    assert!(a.iter().all(|x| x.is_finite()));
    let scale = reference.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    Ok(a.iter()
        .zip(&reference)
        .fold(0.0f64, |m, (a, b)| m.max((a.to_f64() - b).abs()))
        / scale)
}

#[test]
fn crba_keeps_its_accuracy_until_the_tip_is_massless() {
    // A light *leaf* link costs CRBA no accuracy (the 2x2 LTDL solve is
    // well scaled), and each pivot is tested against its own diagonal
    // entry, the tip's pivot against the tip's own inertia: as ABA, CRBA
    // answers until the tip's inertia underflows.
    for m in [1e-2, 1e-6, 1e-14, 1e-30] {
        let e = relative_error::<Crba, f32>(m).unwrap();
        eprintln!("CRBA f32 at {m} kg: {e:e}");
        assert!(e < 1e-5, "CRBA f32 at {m} kg: {e}");
    }
    for m in [1e-12, 1e-14, 1e-100] {
        let e = relative_error::<Crba, f64>(m).unwrap();
        eprintln!("CRBA f64 at {m} kg: {e:e}");
        assert!(e < 1e-14, "CRBA f64 at {m} kg: {e}");
    }
    // f32 underflow, and an exactly massless tip: a zero pivot, named.
    for m in [1e-45, 0.0] {
        assert!(matches!(
            relative_error::<Crba, f32>(m),
            Err(Error::MassMatrixNotPositiveDefinite { dof: 1, .. })
        ));
    }
    assert!(matches!(
        relative_error::<Crba, f64>(0.0),
        Err(Error::MassMatrixNotPositiveDefinite { dof: 1, .. })
    ));
}

#[test]
fn aba_keeps_its_accuracy_until_the_tip_is_massless() {
    for m in [1e-3, 1e-10, 1e-30] {
        let e = relative_error::<Aba, f32>(m).unwrap();
        assert!(e < 1e-5, "ABA f32 at tip mass {m}: {e}");
    }
    // f32 underflow (1e-40 kg is subnormal, its inertia rounds to zero) and
    // an exactly massless tip: D = 0, reported with the joint's index.
    assert!(matches!(
        relative_error::<Aba, f32>(1e-40),
        Err(Error::SingularArticulatedInertia { .. })
    ));
    assert!(matches!(
        Aba::forward_dynamics(
            &pendulum::<f64>(0.0),
            &mut Data::new(),
            &[0.4, -0.9],
            &[0.3, 1.1],
            &[0.0; 2],
            None
        ),
        Err(Error::SingularArticulatedInertia { joint: 1, .. })
    ));
    assert!(matches!(
        Crba::forward_dynamics(
            &pendulum::<f64>(0.0),
            &mut Data::new(),
            &[0.4, -0.9],
            &[0.3, 1.1],
            &[0.0; 2],
            None
        ),
        Err(Error::MassMatrixNotPositiveDefinite { dof: 1, .. })
    ));
}
