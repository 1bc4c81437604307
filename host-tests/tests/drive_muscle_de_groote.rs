//! The De Groote et al. (2016) muscle: its published curves at their
//! defining points, its activation dynamics, and its derivatives (with
//! respect to activation and to path length and velocity, and the
//! activation rate's partials) against central differences and dual
//! numbers.

use rodyn::drive::muscle_de_groote::{tendon_force_length, tendon_length_from_force};
use rodyn::drive::{DeGrooteMuscle, DeGrooteParameters, Path};
use rodyn::spatial::{Spatial, Vec3};
use rodyn::{Dual, Endpoint};

const P: DeGrooteParameters<f64> = DeGrooteParameters::<f64>::de_groote_2016(1000.0, 0.1, 0.2, 0.0);

fn muscle(params: DeGrooteParameters<f64>) -> DeGrooteMuscle<f64, Spatial, 2> {
    let path = Path::new([
        Endpoint::in_world(Vec3::ZERO),
        Endpoint::in_world(Vec3::new(0.3, 0.0, 0.0)),
    ]);
    DeGrooteMuscle::new(path, params, 0)
}

/// The paper's curves at the points they were fitted to pass through. Its
/// three-digit constants put them within a few thousandths of those
/// points (OpenSim Moco refits the constants to pass exactly; rodyn keeps
/// the published ones).
#[test]
fn curves_pass_near_their_defining_points() {
    // Active force-length: 1 at the optimal length (0.99933 with the
    // published constants; the peak, 1.0005, lies at l̃ = 1.014), small at
    // 0.4 and 1.8 optimal lengths.
    let (f_l, slope) = P.active_force_length(1.0);
    assert!((f_l - 1.0).abs() < 1e-3, "f_L(1) = {f_l}");
    assert!(
        slope > 0.0 && P.active_force_length(1.02).1 < 0.0,
        "peak not near 1.014"
    );
    assert!(P.active_force_length(1.014).0 < 1.001);
    assert!(P.active_force_length(0.4).0 < 0.05);
    assert!(P.active_force_length(1.8).0 < 0.05);
    // Passive force-length: 0 at l̃ = 1, 1 at the strain ε₀ᴹ = 0.6, and
    // never below −1/(e⁴ − 1) when short.
    assert_eq!(P.passive_force_length(1.0).0, 0.0);
    approx::assert_relative_eq!(P.passive_force_length(1.6).0, 1.0, max_relative = 1e-14);
    let floor = -1.0 / (4.0f64.exp() - 1.0);
    assert!(P.passive_force_length(0.3).0 > floor);
    // Force-velocity: 1 isometric (1.0023 published), about 0 at maximum
    // shortening (0.0121), 1.789 at maximum lengthening.
    assert!((P.force_velocity(0.0).0 - 1.0).abs() < 3e-3);
    assert!(P.force_velocity(-1.0).0.abs() < 0.015);
    approx::assert_relative_eq!(P.force_velocity(1.0).0, 1.78891, max_relative = 1e-5);
    // Its inverse (a sinh) recovers the velocity.
    for v in [-0.9, -0.3, 0.0, 0.4, 0.95] {
        let f = P.force_velocity(v).0;
        approx::assert_relative_eq!(P.velocity_from_force_multiplier(f), v, epsilon = 1e-12);
    }
    // Tendon: one normalised force at 4.74 % strain, slightly negative at
    // the slack length; the inverse recovers the length.
    let strain_at_one = tendon_length_from_force(1.0) - 1.0;
    approx::assert_relative_eq!(strain_at_one, 0.0474, epsilon = 1e-4);
    let (at_slack, _) = tendon_force_length(1.0);
    assert!((-0.012..0.0).contains(&at_slack), "f_T(1) = {at_slack}");
    approx::assert_relative_eq!(
        tendon_force_length(tendon_length_from_force(0.7)).0,
        0.7,
        max_relative = 1e-13
    );
}

/// Every curve's slope against central differences.
#[test]
fn curve_slopes_match_central_differences() {
    let h = 1e-6;
    let check = |f: &dyn Fn(f64) -> (f64, f64), x: f64| {
        let difference = (f(x + h).0 - f(x - h).0) / (2.0 * h);
        approx::assert_relative_eq!(f(x).1, difference, max_relative = 1e-7, epsilon = 1e-9);
    };
    for x in [0.5, 0.8, 1.0, 1.2, 1.5] {
        check(&|l| P.active_force_length(l), x);
        check(&|l| P.passive_force_length(l), x);
    }
    for v in [-0.9, -0.2, 0.0, 0.3, 0.9] {
        check(&|v| P.force_velocity(v), v);
    }
    for l in [0.99, 1.0, 1.03, 1.05] {
        check(&|l| tendon_force_length(l), l);
    }
}

#[test]
fn isometric_tension_at_optimal_length_is_activation_times_the_curves() {
    let m = muscle(P);
    // Path 0.3 m = tendon slack 0.2 m + optimal fibre 0.1 m.
    let s = m.state(0.3, 0.0, 0.7).unwrap();
    approx::assert_relative_eq!(s.fiber_length, 0.1, max_relative = 1e-14);
    let expected = 1000.0 * (0.7 * P.active_force_length(1.0).0 * P.force_velocity(0.0).0);
    approx::assert_relative_eq!(s.tension, expected, max_relative = 1e-14);
    approx::assert_relative_eq!(
        s.tension_per_activation,
        expected / 0.7,
        max_relative = 1e-14
    );
}

/// `∂T/∂a`, `∂T/∂L`, `∂T/∂L̇` against central differences and dual numbers,
/// pennate and not, shortening and lengthening (no kink at zero velocity
/// to avoid).
#[test]
fn tension_partials_match_differences_and_dual_numbers() {
    for alpha0 in [0.0, 0.3] {
        let params = DeGrooteParameters::<f64>::de_groote_2016(800.0, 0.12, 0.18, alpha0);
        let m = muscle(params);
        let md: DeGrooteMuscle<Dual, Spatial, 2> = m.cast();
        for (l, ldot, a) in [
            (0.30, -0.4, 0.3),
            (0.31, 0.0, 0.6),
            (0.27, 0.3, 0.2),
            (0.33, 1.0, 0.9),
        ] {
            let s = m.state(l, ldot, a).unwrap();
            let tension = |l: f64, ldot: f64, a: f64| m.state(l, ldot, a).unwrap().tension;
            let h = 1e-7;
            let differences = [
                (tension(l, ldot, a + h) - tension(l, ldot, a - h)) / (2.0 * h),
                (tension(l + h, ldot, a) - tension(l - h, ldot, a)) / (2.0 * h),
                (tension(l, ldot + h, a) - tension(l, ldot - h, a)) / (2.0 * h),
            ];
            let dual = |seed: [f64; 3]| {
                let d = |x: f64, du: f64| Dual { re: x, du };
                md.state(d(l, seed[1]), d(ldot, seed[2]), d(a, seed[0]))
                    .unwrap()
                    .tension
                    .du
            };
            let duals = [
                dual([1.0, 0.0, 0.0]),
                dual([0.0, 1.0, 0.0]),
                dual([0.0, 0.0, 1.0]),
            ];
            let analytic = [
                s.tension_per_activation,
                s.tension_per_length,
                s.tension_per_velocity,
            ];
            for k in 0..3 {
                approx::assert_relative_eq!(
                    analytic[k],
                    duals[k],
                    max_relative = 1e-12,
                    epsilon = 1e-9
                );
                approx::assert_relative_eq!(
                    analytic[k],
                    differences[k],
                    max_relative = 1e-6,
                    epsilon = 1e-4
                );
            }
        }
    }
}

/// The activation rate's partials against dual numbers and differences,
/// including across `u = a`, where Thelen's dynamics switch; the rates at
/// equilibrium and, with a sharp blend, the two time constants.
#[test]
fn activation_dynamics_are_smooth_and_blend_the_time_constants() {
    let h = 1e-7;
    let pd: DeGrooteParameters<Dual> = P.cast();
    for (u, a) in [
        (0.9, 0.1),
        (0.5, 0.5),
        (0.5 + 1e-9, 0.5),
        (0.1, 0.8),
        (0.0, 0.0),
    ] {
        let (rate, d_du, d_da) = P.activation_rate_partials(u, a);
        assert_eq!(rate, P.activation_rate(u, a));
        let by_u = (P.activation_rate(u + h, a) - P.activation_rate(u - h, a)) / (2.0 * h);
        let by_a = (P.activation_rate(u, a + h) - P.activation_rate(u, a - h)) / (2.0 * h);
        approx::assert_relative_eq!(d_du, by_u, max_relative = 1e-7);
        approx::assert_relative_eq!(d_da, by_a, max_relative = 1e-7);
        let dual_u = pd.activation_rate(Dual::variable(u), Dual::constant(a)).du;
        let dual_a = pd.activation_rate(Dual::constant(u), Dual::variable(a)).du;
        approx::assert_relative_eq!(d_du, dual_u, max_relative = 1e-13);
        approx::assert_relative_eq!(d_da, dual_a, max_relative = 1e-13);
    }
    assert_eq!(P.activation_rate(0.4, 0.4), 0.0);
    // A sharp blend gives the activation time constant τ_act (½ + 1.5a)
    // while rising and τ_deact / (½ + 1.5a) while falling.
    let sharp = DeGrooteParameters {
        activation_smoothing: 1e3,
        ..P
    };
    approx::assert_relative_eq!(
        sharp.activation_rate(1.0, 0.0),
        1.0 / 0.0075,
        max_relative = 1e-12
    );
    approx::assert_relative_eq!(
        sharp.activation_rate(0.0, 1.0),
        -2.0 / 0.06,
        max_relative = 1e-12
    );
    // The paper's gentle blend (b = 0.1): within 5 % of the mean of the
    // two rates.
    let rising = P.activation_rate(1.0, 0.0);
    let mean = 0.5 * (1.0 / 0.0075 + 0.5 / 0.06);
    assert!((rising / mean - 1.0).abs() < 0.1, "{rising} against {mean}");
}

#[test]
fn bad_inputs_and_parameters_are_named() {
    let m = muscle(P);
    assert!(m.state(f64::NAN, 0.0, 0.5).is_err());
    assert!(m.state(0.3, f64::INFINITY, 0.5).is_err());
    assert!(m.state(0.3, 0.0, f64::NAN).is_err());
    // A fibre beyond two optimal lengths.
    assert!(m.state(0.45, 0.0, 0.5).is_err());
    assert!(P.validate().is_ok());
    let bad = DeGrooteParameters {
        deactivation_time_constant: 0.0,
        ..P
    };
    assert_eq!(
        bad.validate(),
        Err(rodyn::Error::InvalidDrive {
            problem: rodyn::error::DriveProblem::MuscleParameter { index: 6 }
        })
    );
}
