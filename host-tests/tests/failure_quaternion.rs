//! Failure map 4: quaternion drift. Integrating `q̇ = ½ q ⊗ ω` in the
//! embedding space lets the norm drift; without renormalisation rodyn
//! rejects the configuration once the norm is off by more than 10³ ε, with
//! renormalisation (or the exponential map) the norm stays at rounding level.

use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::error::Error;
use rodyn::joint::ConfigurationError;
use rodyn::prelude::*;
use rodyn::sim::{
    ConfigurationUpdate, ExplicitEuler, Integrator, NoLoads, Rk4, SemiImplicitEuler, State,
};

fn tumbling_box<S: Scalar>() -> Model<S, 1, 7, 6> {
    let f = S::from_f64;
    Model::new(
        [None],
        [Joint::free_flyer()],
        [Transform::IDENTITY],
        [Inertia::new(
            f(2.0),
            Vec3::ZERO,
            Sym3::diagonal(
                f(2.0 / 12.0 * 0.05),
                f(2.0 / 12.0 * 0.1),
                f(2.0 / 12.0 * 0.13),
            ),
        )],
        Motion::new(Vec3::ZERO, Vec3::ZERO),
    )
}

/// Steps until the first error (or `steps`), and the largest norm error seen.
fn run<S: Scalar, I: Integrator>(mut integrator: I, steps: usize) -> (usize, f64, Option<Error>) {
    let model = tumbling_box::<S>();
    let mut data = Data::new();
    let z = S::ZERO;
    let mut state = State::new(
        [z, z, z, z, z, z, S::ONE],
        [
            z,
            z,
            z,
            S::from_f64(0.5),
            S::from_f64(3.0),
            S::from_f64(0.2),
        ],
    );
    let mut worst = 0.0f64;
    for n in 0..steps {
        if let Err(e) = integrator.step(
            Aba,
            &model,
            &mut data,
            &mut state,
            S::from_f64(1e-3),
            &mut NoLoads,
        ) {
            return (n, worst, Some(e));
        }
        let norm: f64 = state.q[3..]
            .iter()
            .map(|x| x.to_f64().powi(2))
            .sum::<f64>()
            .sqrt();
        worst = worst.max((norm - 1.0).abs());
    }
    (steps, worst, None)
}

#[test]
fn renormalised_and_exponential_updates_stay_on_the_manifold() {
    let (n, worst, e) = run::<f64, _>(Rk4::default(), 10_000);
    assert!(e.is_none() && n == 10_000 && worst < 1e-15, "{worst} {e:?}");
    let (_, worst, e) = run::<f32, _>(
        Rk4 {
            update: ConfigurationUpdate::Embedded { renormalize: true },
        },
        10_000,
    );
    assert!(e.is_none() && worst < 1e-6, "{worst}");
    let (_, worst, e) = run::<f32, _>(
        SemiImplicitEuler {
            update: ConfigurationUpdate::ExponentialMap,
        },
        10_000,
    );
    assert!(e.is_none() && worst < 1e-6, "{worst}");
}

#[test]
fn without_renormalisation_the_drift_is_reported() {
    let no = ConfigurationUpdate::Embedded { renormalize: false };
    // f32: the norm grows by (|ω| dt / 2)² / 2 ≈ 1.2e-6 per step; rodyn's
    // tolerance 10³ ε = 1.2e-4 is crossed after about 100 steps.
    let (n, worst, e) = run::<f32, _>(ExplicitEuler { update: no }, 10_000);
    assert!((80..130).contains(&n), "rejected after {n} steps");
    assert!(worst > 1e-4 && worst < 1.3e-4, "{worst}");
    assert!(
        matches!(
            e,
            Some(Error::InvalidConfiguration {
                joint: 0,
                reason: ConfigurationError::QuaternionNotUnit { .. }
            })
        ),
        "{e:?}"
    );
    // f64: the tolerance is 2.2e-13, crossed on the first step.
    let (n, _, e) = run::<f64, _>(ExplicitEuler { update: no }, 10);
    assert_eq!(n, 1);
    assert!(matches!(e, Some(Error::InvalidConfiguration { .. })));
}
