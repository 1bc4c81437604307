//! Failure map 2: the largest stable step against spring stiffness. A 1 kg
//! slider on a spring k has ω = √k; the explicit schemes are bounded only
//! below a step proportional to 1/ω, the linearly implicit Euler at any step.

use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::prelude::*;
use rodyn::sim::{ImplicitEuler, Integrator, Rk4, SemiImplicitEuler, State};

fn slider() -> Model<f64, 1, 1, 1> {
    Model::new(
        [None],
        [Joint::prismatic(Axis::Z)],
        [Transform::IDENTITY],
        [Inertia::point_mass(1.0, Vec3::ZERO)],
        Motion::new(Vec3::ZERO, Vec3::ZERO),
    )
}

/// Runs 2000 steps; `Ok(max amplitude / initial)` or the step's error.
fn amplitude_growth<I: Integrator>(mut integrator: I, k: f64, dt: f64) -> Result<f64, Error> {
    let model = slider();
    let mut data = Data::new();
    let mut state = State::new([0.01], [0.0]);
    let mut spring = |_: &Model<f64, 1, 1, 1>,
                      _: &mut Data<f64, 1, 1>,
                      _: f64,
                      q: &[f64; 1],
                      _: &[f64; 1],
                      tau: &mut [f64; 1],
                      _: &mut [Force<f64>; 1]| {
        tau[0] -= k * q[0];
        Ok(())
    };
    let mut worst = 1.0f64;
    for _ in 0..2000 {
        integrator.step(Aba, &model, &mut data, &mut state, dt, &mut spring)?;
        assert!(
            state.q[0].is_finite() && state.v[0].is_finite(),
            "Ok steps leave a finite state"
        );
        worst = worst.max((state.q[0].powi(2) + state.v[0].powi(2) / k).sqrt() / 0.01);
    }
    Ok(worst)
}

#[test]
fn boundaries_scale_with_one_over_omega() {
    for k in [1.0e2, 1.0e4, 1.0e6] {
        let omega = f64::sqrt(k);
        // Symplectic Euler: bounded (if stretched) below ω dt = 2, unbounded above.
        assert!(amplitude_growth(SemiImplicitEuler::default(), k, 1.9 / omega).unwrap() < 10.0);
        assert!(
            !matches!(amplitude_growth(SemiImplicitEuler::default(), k, 2.1 / omega), Ok(g) if g < 1e3)
        );
        // RK4: stable below ω dt ≈ 2.785, unbounded above.
        assert!(amplitude_growth(Rk4::default(), k, 2.7 / omega).unwrap() < 2.0);
        assert!(!matches!(amplitude_growth(Rk4::default(), k, 2.9 / omega), Ok(g) if g < 1e3));
        // Implicit Euler: bounded even at ω dt = 1000.
        assert!(
            amplitude_growth(ImplicitEuler::default(), k, 1000.0 / omega).unwrap() <= 1.0 + 1e-9
        );
    }
}

#[test]
fn past_the_boundary_rodyn_reports_instead_of_returning_nan() {
    // RK4 at ω dt = 10 grows by ~10³ per step: after some steps the state
    // would overflow; the step that would produce it returns an error and
    // the last finite state is kept.
    let (k, dt) = (1.0e6, 1.0e-2);
    let model = slider();
    let mut data = Data::new();
    let mut state = State::new([0.01], [0.0]);
    let mut spring = |_: &Model<f64, 1, 1, 1>,
                      _: &mut Data<f64, 1, 1>,
                      _: f64,
                      q: &[f64; 1],
                      _: &[f64; 1],
                      tau: &mut [f64; 1],
                      _: &mut [Force<f64>; 1]| {
        tau[0] -= k * q[0];
        Ok(())
    };
    let mut error = None;
    for _ in 0..1000 {
        if let Err(e) = Rk4::default().step(Aba, &model, &mut data, &mut state, dt, &mut spring) {
            error = Some(e);
            break;
        }
    }
    assert!(matches!(error, Some(Error::NonFinite { .. })), "{error:?}");
    assert!(state.q[0].is_finite() && state.v[0].is_finite());
}
