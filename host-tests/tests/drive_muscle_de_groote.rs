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
    let (f_l, slope) = P.active_force_length(1.0).unwrap();
    assert!((f_l - 1.0).abs() < 1e-3, "f_L(1) = {f_l}");
    assert!(
        slope > 0.0 && P.active_force_length(1.02).unwrap().1 < 0.0,
        "peak not near 1.014"
    );
    assert!(P.active_force_length(1.014).unwrap().0 < 1.001);
    assert!(P.active_force_length(0.4).unwrap().0 < 0.05);
    assert!(P.active_force_length(1.8).unwrap().0 < 0.05);
    // Passive force-length: 0 at l̃ = 1, 1 at the strain ε₀ᴹ = 0.6, and
    // never below −1/(e⁴ − 1) when short.
    assert_eq!(P.passive_force_length(1.0).unwrap().0, 0.0);
    approx::assert_relative_eq!(
        P.passive_force_length(1.6).unwrap().0,
        1.0,
        max_relative = 1e-14
    );
    let floor = -1.0 / (4.0f64.exp() - 1.0);
    assert!(P.passive_force_length(0.3).unwrap().0 > floor);
    // Force-velocity: 1 isometric (1.0023 published), about 0 at maximum
    // shortening (0.0121), 1.789 at maximum lengthening.
    assert!((P.force_velocity(0.0).unwrap().0 - 1.0).abs() < 3e-3);
    assert!(P.force_velocity(-1.0).unwrap().0.abs() < 0.015);
    approx::assert_relative_eq!(
        P.force_velocity(1.0).unwrap().0,
        1.78891,
        max_relative = 1e-5
    );
    // Its inverse (a sinh) recovers the velocity.
    for v in [-0.9, -0.3, 0.0, 0.4, 0.95] {
        let f = P.force_velocity(v).unwrap().0;
        approx::assert_relative_eq!(
            P.velocity_from_force_multiplier(f).unwrap(),
            v,
            epsilon = 1e-12
        );
    }
    // Tendon: one normalised force at 4.74 % strain, slightly negative at
    // the slack length; the inverse recovers the length.
    let strain_at_one = tendon_length_from_force(1.0).unwrap() - 1.0;
    approx::assert_relative_eq!(strain_at_one, 0.0474, epsilon = 1e-4);
    let (at_slack, _) = tendon_force_length(1.0).unwrap();
    assert!((-0.012..0.0).contains(&at_slack), "f_T(1) = {at_slack}");
    approx::assert_relative_eq!(
        tendon_force_length(tendon_length_from_force(0.7).unwrap())
            .unwrap()
            .0,
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
        check(&|l| P.active_force_length(l).unwrap(), x);
        check(&|l| P.passive_force_length(l).unwrap(), x);
    }
    for v in [-0.9, -0.2, 0.0, 0.3, 0.9] {
        check(&|v| P.force_velocity(v).unwrap(), v);
    }
    for l in [0.99, 1.0, 1.03, 1.05] {
        check(&|l| tendon_force_length(l).unwrap(), l);
    }
}

#[test]
fn isometric_tension_at_optimal_length_is_activation_times_the_curves() {
    let m = muscle(P);
    // Path 0.3 m = tendon slack 0.2 m + optimal fibre 0.1 m.
    let s = m.state(0.3, 0.0, 0.7).unwrap();
    approx::assert_relative_eq!(s.fiber_length, 0.1, max_relative = 1e-14);
    let expected =
        1000.0 * (0.7 * P.active_force_length(1.0).unwrap().0 * P.force_velocity(0.0).unwrap().0);
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
        let (rate, d_du, d_da) = P.activation_rate_partials(u, a).unwrap();
        assert_eq!(rate, P.activation_rate(u, a).unwrap());
        let by_u = (P.activation_rate(u + h, a).unwrap() - P.activation_rate(u - h, a).unwrap())
            / (2.0 * h);
        let by_a = (P.activation_rate(u, a + h).unwrap() - P.activation_rate(u, a - h).unwrap())
            / (2.0 * h);
        approx::assert_relative_eq!(d_du, by_u, max_relative = 1e-7);
        approx::assert_relative_eq!(d_da, by_a, max_relative = 1e-7);
        let dual_u = pd
            .activation_rate(Dual::variable(u), Dual::constant(a))
            .unwrap()
            .du;
        let dual_a = pd
            .activation_rate(Dual::constant(u), Dual::variable(a))
            .unwrap()
            .du;
        approx::assert_relative_eq!(d_du, dual_u, max_relative = 1e-13);
        approx::assert_relative_eq!(d_da, dual_a, max_relative = 1e-13);
    }
    assert_eq!(P.activation_rate(0.4, 0.4).unwrap(), 0.0);
    // A sharp blend gives the activation time constant τ_act (½ + 1.5a)
    // while rising and τ_deact / (½ + 1.5a) while falling.
    let sharp = DeGrooteParameters {
        activation_smoothing: 1e3,
        ..P
    };
    approx::assert_relative_eq!(
        sharp.activation_rate(1.0, 0.0).unwrap(),
        1.0 / 0.0075,
        max_relative = 1e-12
    );
    approx::assert_relative_eq!(
        sharp.activation_rate(0.0, 1.0).unwrap(),
        -2.0 / 0.06,
        max_relative = 1e-12
    );
    // The paper's gentle blend (b = 0.1): within 5 % of the mean of the
    // two rates.
    let rising = P.activation_rate(1.0, 0.0).unwrap();
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

mod on_a_floating_tree {
    //! `dq̈/d(q, v)` of forward dynamics with two pennate De Groote muscles
    //! on a random floating-base tree (`aba_derivatives_with_drives`)
    //! against dual numbers (1e-10) and central differences (1e-6). Columns
    //! of `∂/∂q` are derivatives along `q ⊕ ε e_c` (tangent space).

    use rodyn::algorithm::derivatives::DerivativeData;
    use rodyn::algorithm::forward_dynamics::Aba;
    use rodyn::algorithm::jacobian::JacobianData;
    use rodyn::drive::{
        aba_derivatives_with_drives, forward_dynamics_with_drives, DeGrooteMuscle,
        DeGrooteParameters, DriveDerivatives, DriveForces, Path,
    };
    use rodyn::prelude::*;
    use rodyn::Endpoint;
    use rodyn_host_tests::random::{random_configuration, random_floating_tree, Rng};

    const NB: usize = 6;
    const NQ: usize = NB + 5;
    const NV: usize = NB + 4;

    type Muscles<S> = (DeGrooteMuscle<S, Spatial, 3>, DeGrooteMuscle<S, Spatial, 2>);

    /// Two muscles on inputs 0 and 1, over a via point and between two
    /// branches, sized so that their fibres sit at 0.9 of their optimal
    /// length at the path lengths `lengths` (m).
    fn muscles<S: Scalar>(lengths: (f64, f64)) -> Muscles<S> {
        let c = S::from_f64;
        let p = |x: f64, y: f64, z: f64| Vec3::new(c(x), c(y), c(z));
        let params = |length: f64| {
            DeGrooteParameters::de_groote_2016_in(
                c(300.0),
                c(0.8 * length / 0.9),
                c(0.2 * length),
                c(0.2),
            )
        };
        (
            DeGrooteMuscle::new(
                Path::new([
                    Endpoint::in_world(p(0.3, -0.2, 0.5)),
                    Endpoint::on_body(0, p(0.1, 0.05, -0.02)),
                    Endpoint::on_body(NB - 1, p(-0.05, 0.1, 0.08)),
                ]),
                params(lengths.0),
                0,
            ),
            DeGrooteMuscle::new(
                Path::new([
                    Endpoint::on_body(2, p(0.04, 0.03, 0.0)),
                    Endpoint::on_body(NB - 1, p(0.0, -0.06, 0.05)),
                ]),
                params(lengths.1),
                1,
            ),
        )
    }

    #[allow(clippy::too_many_arguments)]
    fn forward<S: Scalar>(
        model: &Model<S, NB, NQ, NV>,
        lengths: (f64, f64),
        q: &[S; NQ],
        v: &[S; NV],
        w: &[S; 2],
        dq: &[S; NV],
    ) -> [S; NV] {
        let mut data = Box::new(Data::<S, NB, NV>::new());
        let mut forces = DriveForces::new();
        let q = model.integrate(q, dq, S::ONE).unwrap();
        *forward_dynamics_with_drives::<Aba, _, _, _, NB, NQ, NV>(
            model,
            &mut data,
            &q,
            v,
            &[S::ZERO; NV],
            &muscles::<S>(lengths),
            w,
            &mut forces,
        )
        .unwrap()
    }

    #[test]
    fn forward_dynamics_derivatives_match_dual_numbers_and_differences() {
        let mut rng = Rng::new(2016);
        let model = random_floating_tree::<NB, NQ, NV>(&mut rng);
        let dual_model = model.cast::<Dual>().unwrap();
        let mut data = Box::new(Data::<f64, NB, NV>::new());
        let mut deriv = Box::new(DerivativeData::<f64, NB, NV>::new());
        let mut jac = Box::new(JacobianData::<f64, NV>::new());
        let mut drive = Box::new(DriveDerivatives::<f64, NV>::new());
        for _ in 0..4 {
            let q = random_configuration(&model, &mut rng);
            let v: [f64; NV] = rng.vector(2.0);
            let w = [rng.uniform(0.0, 1.0), rng.uniform(0.0, 1.0)];
            rodyn::algorithm::kinematics::forward_kinematics_velocity(&model, &mut data, &q, &v)
                .unwrap();
            let sized = muscles::<f64>((1.0, 1.0));
            let lengths = (
                sized.0.path.kinematics(&data).unwrap().length,
                sized.1.path.kinematics(&data).unwrap().length,
            );
            aba_derivatives_with_drives(
                &model,
                &mut data,
                &mut deriv,
                &mut jac,
                &mut drive,
                &q,
                &v,
                &[0.0; NV],
                &muscles::<f64>(lengths),
                &w,
            )
            .unwrap();
            let largest = drive.tau.iter().fold(0.0f64, |m, t| m.max(t.abs()));
            assert!(
                (1e-2..1e5).contains(&largest),
                "drive forces {:?}",
                drive.tau
            );
            let scale =
                |m: &[[f64; NV]; NV]| m.iter().flatten().fold(1.0f64, |s, x| s.max(x.abs()));
            let (scale_q, scale_v) = (scale(&deriv.ddq_dq), scale(&deriv.ddq_dv));
            let (qd, vd, wd) = (
                q.map(Dual::constant),
                v.map(Dual::constant),
                w.map(Dual::constant),
            );
            for c in 0..NV {
                let mut dq = [Dual::constant(0.0); NV];
                dq[c] = Dual::variable(0.0);
                let along_q = forward(&dual_model, lengths, &qd, &vd, &wd, &dq);
                let mut vc = vd;
                vc[c] = Dual::variable(v[c]);
                let along_v = forward(
                    &dual_model,
                    lengths,
                    &qd,
                    &vc,
                    &wd,
                    &[Dual::constant(0.0); NV],
                );
                let h = 1e-6;
                let mut step = [0.0; NV];
                step[c] = h;
                let plus = forward(&model, lengths, &q, &v, &w, &step);
                step[c] = -h;
                let minus = forward(&model, lengths, &q, &v, &w, &step);
                for r in 0..NV {
                    let (dq_dq, dq_dv) = (deriv.ddq_dq[r][c], deriv.ddq_dv[r][c]);
                    assert!(
                        (dq_dq - along_q[r].du).abs() <= 1e-10 * scale_q,
                        "dq̈{r}/dq{c}: {dq_dq} vs dual {}",
                        along_q[r].du
                    );
                    assert!(
                        (dq_dv - along_v[r].du).abs() <= 1e-10 * scale_v,
                        "dq̈{r}/dv{c}: {dq_dv} vs dual {}",
                        along_v[r].du
                    );
                    let fd = (plus[r] - minus[r]) / (2.0 * h);
                    assert!(
                        (dq_dq - fd).abs() <= 1e-6 * scale_q,
                        "dq̈{r}/dq{c}: {dq_dq} vs differences {fd}"
                    );
                }
            }
        }
    }
}

/// The curves' checked forms name what is wrong: the argument that is not
/// finite, the parameter that is out of range, a curve that overflows,
/// and a tendon force the curve never reaches.
#[test]
fn curves_name_their_bad_inputs() {
    use rodyn::error::{DriveProblem, Error, Quantity};
    let argument = |index| Error::NonFinite {
        quantity: Quantity::MuscleCurve,
        index,
    };
    assert_eq!(P.active_force_length(f64::NAN), Err(argument(0)));
    assert_eq!(P.force_velocity(f64::INFINITY), Err(argument(0)));
    assert_eq!(P.activation_rate(0.5, f64::NAN), Err(argument(1)));
    assert_eq!(tendon_force_length(f64::NAN), Err(argument(0)));
    // exp(kᴾᴱ (l̃ − 1)/ε₀ᴹ) overflows f64 near l̃ = 107.
    assert_eq!(
        P.passive_force_length(200.0),
        Err(Error::NonFiniteResult {
            quantity: Quantity::MuscleCurve,
            index: 0
        })
    );
    // f_T = −c₃ is the curve's asymptote: no tendon length gives it.
    assert_eq!(
        tendon_length_from_force(-1.0),
        Err(Error::OutOfRange {
            quantity: Quantity::MuscleCurve,
            index: 0
        })
    );
    // A zero passive strain (field 9) divides by zero: the parameter is
    // named, not the curve.
    let mut bad = P;
    bad.passive_strain_at_one = 0.0;
    assert_eq!(
        bad.passive_force_length(1.2),
        Err(Error::InvalidDrive {
            problem: DriveProblem::MuscleParameter { index: 9 }
        })
    );
}
