//! The Thelen (2003) muscle: its published curves at their defining points,
//! its activation dynamics, the activation derivative, and the guards of its
//! singular regions.

// Row and column indices mirror the matrix equations being checked.
#![allow(clippy::needless_range_loop)]

use rodyn::drive::{Path, ThelenMuscle, ThelenParameters};
use rodyn::spatial::{Spatial, Vec3};
use rodyn::Endpoint;

const P: ThelenParameters<f64> = ThelenParameters::<f64>::thelen_2003(1000.0, 0.1, 0.2, 0.0);

fn muscle(params: ThelenParameters<f64>) -> ThelenMuscle<f64, Spatial, 2> {
    let path = Path::new([
        Endpoint::in_world(Vec3::ZERO),
        Endpoint::in_world(Vec3::new(0.3, 0.0, 0.0)),
    ]);
    ThelenMuscle::new(path, params, 0)
}

#[test]
fn curves_pass_through_their_defining_points() {
    // f_L = 1 at optimal length and e⁻¹ at l̃ = 1 ± √γ.
    assert_eq!(P.active_force_length(1.0).unwrap(), 1.0);
    let e_inv = (-1.0f64).exp();
    approx::assert_relative_eq!(
        P.active_force_length(1.0 + 0.45f64.sqrt()).unwrap(),
        e_inv,
        max_relative = 1e-14
    );
    approx::assert_relative_eq!(
        P.active_force_length(1.0 - 0.45f64.sqrt()).unwrap(),
        e_inv,
        max_relative = 1e-14
    );
    // f_PE = 0 at and below optimal length, 1 at strain ε₀ᴹ = 0.6.
    assert_eq!(P.passive_force_length(1.0).unwrap(), 0.0);
    assert_eq!(P.passive_force_length(0.7).unwrap(), 0.0);
    approx::assert_relative_eq!(
        P.passive_force_length(1.6).unwrap(),
        1.0,
        max_relative = 1e-14
    );
    // f_V: 1 isometric, 0 at maximum shortening, toward F̃_len = 1.4 lengthening.
    assert_eq!(P.force_velocity(0.0).unwrap().0, 1.0);
    assert_eq!(P.force_velocity(-1.0).unwrap().0, 0.0);
    assert_eq!(P.force_velocity(-3.0).unwrap(), (0.0, 0.0));
    approx::assert_relative_eq!(P.force_velocity(1e6).unwrap().0, 1.4, max_relative = 1e-5);
    // Hill's hyperbola at half the maximum shortening speed: (1 - ½)/(1 + ½/A_f) = 0.5/3.
    approx::assert_relative_eq!(
        P.force_velocity(-0.5).unwrap().0,
        0.5 / 3.0,
        max_relative = 1e-14
    );
}

#[test]
fn force_velocity_slope_matches_central_differences_on_both_branches() {
    let h = 1e-6;
    for v in [-0.9, -0.5, -0.1, 0.1, 0.5, 3.0] {
        let fd =
            (P.force_velocity(v + h).unwrap().0 - P.force_velocity(v - h).unwrap().0) / (2.0 * h);
        approx::assert_relative_eq!(P.force_velocity(v).unwrap().1, fd, max_relative = 1e-7);
    }
    // Thelen's curve has a kink at ṽ = 0: slope 1 + 1/A_f = 5 below, 2 + 2/A_f = 10 above.
    approx::assert_relative_eq!(
        P.force_velocity(-1e-12).unwrap().1,
        5.0,
        max_relative = 1e-9
    );
    approx::assert_relative_eq!(
        P.force_velocity(1e-12).unwrap().1,
        10.0,
        max_relative = 1e-9
    );
}

#[test]
fn isometric_tension_at_optimal_length_is_activation_times_max_force() {
    let m = muscle(P);
    // Path 0.3 m = tendon slack 0.2 m + optimal fibre 0.1 m.
    let s = m.state(0.3, 0.0, 0.7).unwrap();
    approx::assert_relative_eq!(s.fiber_length, 0.1, max_relative = 1e-14);
    approx::assert_relative_eq!(s.tension, 700.0, max_relative = 1e-14);
    approx::assert_relative_eq!(s.tension_per_activation, 1000.0, max_relative = 1e-14);
}

#[test]
fn tension_derivative_by_activation_matches_central_differences() {
    let m = muscle(ThelenParameters::<f64>::thelen_2003(800.0, 0.12, 0.18, 0.3));
    let h = 1e-7;
    for (l, ldot, a) in [
        (0.30, -0.4, 0.3),
        (0.31, -0.6, 0.6),
        (0.27, 0.3, 0.2),
        (0.33, 2.0, 0.9),
    ] {
        let s = m.state(l, ldot, a).unwrap();
        let fd = (m.state(l, ldot, a + h).unwrap().tension
            - m.state(l, ldot, a - h).unwrap().tension)
            / (2.0 * h);
        approx::assert_relative_eq!(s.tension_per_activation, fd, max_relative = 1e-6);
        // Not affine in a: the velocity normalisation depends on it while
        // the fibre moves, so the slope changes with a.
        let half = m.state(l, ldot, 0.5 * a).unwrap().tension_per_activation;
        assert!(
            (s.tension_per_activation - half).abs() > 1e-3 * s.tension_per_activation.abs(),
            "{s:?}"
        );
    }
}

#[test]
fn pennation_follows_the_constant_thickness_geometry() {
    let alpha0 = 0.4f64;
    let m = muscle(ThelenParameters::<f64>::thelen_2003(
        1000.0, 0.1, 0.2, alpha0,
    ));
    // At optimal fibre length the fibre's projection is l₀ cos α₀.
    let s = m.state(0.2 + 0.1 * alpha0.cos(), 0.5, 0.5).unwrap();
    approx::assert_relative_eq!(s.fiber_length, 0.1, max_relative = 1e-14);
    approx::assert_relative_eq!(s.cos_pennation, alpha0.cos(), max_relative = 1e-14);
    approx::assert_relative_eq!(s.fiber_velocity, 0.5 * alpha0.cos(), max_relative = 1e-14);
}

#[test]
fn singular_regions_are_guarded() {
    // Path shorter than the tendon: the fibre stays at its minimum length
    // with zero velocity and a finite, non-negative tension.
    let m = muscle(P);
    for l in [0.2, 0.15, 0.0, -1.0] {
        let s = m.state(l, -5.0, 1.0).unwrap();
        assert!(s.tension.is_finite() && s.tension >= 0.0, "{s:?}");
        approx::assert_relative_eq!(s.fiber_length, 0.001, max_relative = 1e-12);
        assert_eq!(s.fiber_velocity, 0.0);
    }
    // Pennation near 90°: cos α never drops below 0.1.
    let pennate = muscle(ThelenParameters::<f64>::thelen_2003(1000.0, 0.1, 0.2, 1.2));
    let s = pennate.state(0.2, -0.3, 1.0).unwrap();
    assert!(s.cos_pennation >= 0.1 - 1e-15, "{s:?}");
    assert!(s.tension.is_finite());
    // Shortening faster than the maximum contraction velocity: no active
    // force, only the passive one (zero here), never a negative tension.
    let s = m.state(0.3, -50.0, 1.0).unwrap();
    assert_eq!(s.force_velocity, 0.0);
    assert_eq!(s.tension, 0.0);
}

#[test]
fn activation_dynamics_follow_thelens_time_constants() {
    // Rising from a = 0 with u = 1: τ = τ_act (0.5 + 1.5·0) = 7.5 ms.
    approx::assert_relative_eq!(
        P.activation_rate(1.0, 0.0).unwrap(),
        1.0 / 0.0075,
        max_relative = 1e-14
    );
    // Falling from a = 1 with u = 0: τ = τ_deact / (0.5 + 1.5) = 25 ms.
    approx::assert_relative_eq!(
        P.activation_rate(0.0, 1.0).unwrap(),
        -1.0 / 0.025,
        max_relative = 1e-14
    );
    // At equilibrium nothing moves; excitation is clamped to [0, 1].
    assert_eq!(P.activation_rate(0.4, 0.4).unwrap(), 0.0);
    assert_eq!(P.activation_rate(3.0, 1.0).unwrap(), 0.0);
}
