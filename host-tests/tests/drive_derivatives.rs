//! The drives' analytic state derivatives against forward-mode dual numbers
//! (1e-10) and central differences (1e-6): a path's length gradient and
//! Hessian on a random floating-base tree, the Thelen muscle's tension
//! partials in every regime, and forward dynamics with springs, a damper
//! and muscles differentiated as a whole.
//!
//! Columns of `∂/∂q` are derivatives along `q ⊕ ε e_c` (tangent space).

use rodyn::algorithm::derivatives::DerivativeData;
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::algorithm::jacobian::joint_jacobians_time_variation;
use rodyn::algorithm::jacobian::JacobianData;
use rodyn::drive::{
    aba_derivatives_with_drives, forward_dynamics_with_drives, DriveDerivativeState,
    DriveDerivatives, DriveForces, LinearDamper, LinearSpring, NonlinearSpring, Path, ThelenMuscle,
    ThelenParameters,
};
use rodyn::prelude::*;
use rodyn::Endpoint;
use rodyn_host_tests::random::{random_configuration, random_floating_tree, Rng};

const NB: usize = 6;
const NQ: usize = NB + 5;
const NV: usize = NB + 4;

fn close(what: &str, x: f64, y: f64, tol: f64, scale: f64) {
    assert!(
        (x - y).abs() <= tol * scale.max(1.0),
        "{what}: {x:e} vs {y:e} (tolerance {tol:e} x {scale})"
    );
}

/// A path over the root (body 0), a deeper body and the world, and a
/// second one between two branches.
fn paths<S: Scalar>() -> (Path<S, Spatial, 4>, Path<S, Spatial, 2>) {
    let p = |x: f64, y: f64, z: f64| Vec3::new(S::from_f64(x), S::from_f64(y), S::from_f64(z));
    (
        Path::new([
            Endpoint::in_world(p(0.3, -0.2, 0.5)),
            Endpoint::on_body(0, p(0.1, 0.05, -0.02)),
            Endpoint::on_body(NB - 1, p(-0.05, 0.1, 0.08)),
            Endpoint::on_body(NB - 2, p(0.02, -0.07, 0.1)),
        ]),
        Path::new([
            Endpoint::on_body(2, p(0.04, 0.03, 0.0)),
            Endpoint::on_body(NB - 1, p(0.0, -0.06, 0.05)),
        ]),
    )
}

/// Fibres of `optimal` m on tendons of `slack` m.
fn muscle_params<S: Scalar>(optimal: f64, slack: f64) -> ThelenParameters<S> {
    let c = S::from_f64;
    ThelenParameters::thelen_2003_in(c(300.0), c(optimal), c(slack), c(0.2))
}

/// Two springs, a damper and two muscles on inputs 0 and 1, in scalar S;
/// the muscles' fibres and tendons sized to the paths' `lengths` (m), the
/// fibres at 0.9 of their optimal length.
#[allow(clippy::type_complexity)]
fn elements<S: Scalar>(
    lengths: (f64, f64),
) -> (
    LinearSpring<S, Spatial, 4>,
    NonlinearSpring<S, Spatial, 2>,
    LinearDamper<S, Spatial, 2>,
    ThelenMuscle<S, Spatial, 4>,
    ThelenMuscle<S, Spatial, 2>,
) {
    let c = S::from_f64;
    let (long, short) = paths::<S>();
    (
        LinearSpring::new(long, c(40.0), c(0.3)),
        NonlinearSpring::new(short, c(25.0), c(300.0), c(0.1)),
        LinearDamper::new(short, c(3.0)),
        ThelenMuscle::new(
            long,
            muscle_params(0.8 * lengths.0 / 0.9, 0.2 * lengths.0),
            0,
        ),
        ThelenMuscle::new(
            short,
            muscle_params(0.8 * lengths.1 / 0.9, 0.2 * lengths.1),
            1,
        ),
    )
}

#[test]
fn path_gradient_and_hessian_match_dual_numbers() {
    let mut rng = Rng::new(41);
    let model = random_floating_tree::<NB, NQ, NV>(&mut rng);
    let dual_model = model.cast::<Dual>().unwrap();
    let (path, _) = paths::<f64>();
    let (dual_path, _) = paths::<Dual>();
    let mut data = Box::new(Data::<f64, NB, NV>::new());
    let mut jac = Box::new(JacobianData::<f64, NV>::new());
    let mut dual_data = Box::new(Data::<Dual, NB, NV>::new());
    let mut dual_jac = Box::new(JacobianData::<Dual, NV>::new());
    for _ in 0..5 {
        let q = random_configuration(&model, &mut rng);
        let v: [f64; NV] = rng.vector(2.0);
        joint_jacobians_time_variation(&model, &mut data, &mut jac, &q, &v).unwrap();
        let state = DriveDerivativeState {
            data: &data,
            columns: &jac.j,
            topology: model.topology(),
            v: &v,
        };
        let d = path.length_derivatives(&state).unwrap();
        let kin = path.kinematics(&data).unwrap();
        close("length", d.length, kin.length, 1e-14, 1.0);
        close(
            "lengthening velocity",
            d.lengthening_velocity,
            kin.lengthening_velocity,
            1e-12,
            1.0,
        );
        let gscale = d.gradient.iter().fold(0.0f64, |m, g| m.max(g.abs()));
        let hscale = d
            .hessian
            .iter()
            .flatten()
            .fold(0.0f64, |m, h| m.max(h.abs()));
        for c in 0..NV {
            // Move q along e_c with dual numbers; the gradient and the length
            // carry their derivatives along.
            let qd = q.map(Dual::constant);
            let mut dq = [Dual::constant(0.0); NV];
            dq[c] = Dual::variable(0.0);
            let qd = dual_model.integrate(&qd, &dq, Dual::constant(1.0)).unwrap();
            let vd = v.map(Dual::constant);
            joint_jacobians_time_variation(&dual_model, &mut dual_data, &mut dual_jac, &qd, &vd)
                .unwrap();
            let dual_state = DriveDerivativeState {
                data: &dual_data,
                columns: &dual_jac.j,
                topology: dual_model.topology(),
                v: &vd,
            };
            let dd = dual_path.length_derivatives(&dual_state).unwrap();
            close(
                &format!("∂L/∂q{c}"),
                d.gradient[c],
                dd.length.du,
                1e-10,
                gscale,
            );
            for r in 0..NV {
                close(
                    &format!("∂²L/∂q{r}∂q{c}"),
                    d.hessian[r][c],
                    dd.gradient[r].du,
                    1e-10,
                    hscale,
                );
            }
        }
        // Symmetric but for the free-flyer's block (coordinates 0-5), whose
        // body-frame increments do not commute.
        for r in 0..NV {
            for c in 0..NV {
                if r >= 6 || c >= 6 {
                    close(
                        "Hessian symmetry",
                        d.hessian[r][c],
                        d.hessian[c][r],
                        1e-12,
                        hscale,
                    );
                }
            }
        }
    }
}

#[test]
fn muscle_tension_partials_match_dual_numbers() {
    let muscle = ThelenMuscle::new(paths::<f64>().1, muscle_params(0.08, 0.05), 0);
    let dual = ThelenMuscle::new(paths::<Dual>().1, muscle_params(0.08, 0.05), 0);
    // Slack (minimum fibre), short and long fibres (passive force on),
    // shortening and lengthening, activations inside and at the bounds.
    for length in [0.04, 0.11, 0.13, 0.16, 0.2] {
        for velocity in [-0.6, -0.1, 0.0, 0.05, 0.4] {
            for activation in [0.0, 0.3, 1.0] {
                let (t, t_l, t_v) = muscle
                    .tension_partials(length, velocity, activation)
                    .unwrap();
                let a = Dual::constant(activation);
                let tension = |l: Dual, v: Dual| dual.state(l, v, a).unwrap().tension;
                let along_l = tension(Dual::variable(length), Dual::constant(velocity));
                let along_v = tension(Dual::constant(length), Dual::variable(velocity));
                let what = format!("L {length}, L̇ {velocity}, a {activation}");
                close(&format!("{what}: T"), t, along_l.re, 1e-12, t.abs());
                close(&format!("{what}: ∂T/∂L"), t_l, along_l.du, 1e-10, t_l.abs());
                close(&format!("{what}: ∂T/∂L̇"), t_v, along_v.du, 1e-10, t_v.abs());
            }
        }
    }
}

/// `q̈ = FD(q, v, τ + Q(q, v, w))` with all five elements, at `(q ⊕ dq, v + dv)`.
#[allow(clippy::too_many_arguments)]
fn forward<S: Scalar>(
    model: &Model<S, NB, NQ, NV>,
    lengths: (f64, f64),
    q: &[S; NQ],
    v: &[S; NV],
    tau: &[S; NV],
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
        tau,
        &elements::<S>(lengths),
        w,
        &mut forces,
    )
    .unwrap()
}

#[test]
fn forward_dynamics_with_drives_match_dual_numbers_and_differences() {
    let mut rng = Rng::new(77);
    let model = random_floating_tree::<NB, NQ, NV>(&mut rng);
    let dual_model = model.cast::<Dual>().unwrap();
    let mut data = Box::new(Data::<f64, NB, NV>::new());
    let mut deriv = Box::new(DerivativeData::<f64, NB, NV>::new());
    let mut jac = Box::new(JacobianData::<f64, NV>::new());
    let mut drive = Box::new(DriveDerivatives::<f64, NV>::new());
    for _ in 0..4 {
        let q = random_configuration(&model, &mut rng);
        let v: [f64; NV] = rng.vector(2.0);
        let tau: [f64; NV] = rng.vector(3.0);
        let w = [rng.uniform(0.0, 1.0), rng.uniform(0.0, 1.0)];
        let lengths = {
            let (long, short) = paths::<f64>();
            rodyn::algorithm::kinematics::forward_kinematics_velocity(&model, &mut data, &q, &v)
                .unwrap();
            (
                long.kinematics(&data).unwrap().length,
                short.kinematics(&data).unwrap().length,
            )
        };
        let elements = elements::<f64>(lengths);
        aba_derivatives_with_drives(
            &model, &mut data, &mut deriv, &mut jac, &mut drive, &q, &v, &tau, &elements, &w,
        )
        .unwrap();
        // The drives matter but do not swamp the dynamics.
        let q_scale = drive.tau.iter().fold(0.0f64, |m, t| m.max(t.abs()));
        println!("largest generalised drive force {q_scale:.3e}");
        assert!(
            (1e-2..1e5).contains(&q_scale),
            "drive forces {:?}",
            drive.tau
        );
        let ddq = forward(&model, lengths, &q, &v, &tau, &w, &[0.0; NV]);
        for (x, y) in data.ddq.iter().zip(&ddq) {
            close("q̈", *x, *y, 1e-12, y.abs());
        }
        let scale_q = deriv
            .ddq_dq
            .iter()
            .flatten()
            .fold(0.0f64, |m, x| m.max(x.abs()));
        let scale_v = deriv
            .ddq_dv
            .iter()
            .flatten()
            .fold(0.0f64, |m, x| m.max(x.abs()));
        let (qd, vd, taud, wd) = (
            q.map(Dual::constant),
            v.map(Dual::constant),
            tau.map(Dual::constant),
            w.map(Dual::constant),
        );
        for c in 0..NV {
            let mut dq = [Dual::constant(0.0); NV];
            dq[c] = Dual::variable(0.0);
            let along_q = forward(&dual_model, lengths, &qd, &vd, &taud, &wd, &dq);
            let mut vc = vd;
            vc[c] = Dual::variable(v[c]);
            let along_v = forward(
                &dual_model,
                lengths,
                &qd,
                &vc,
                &taud,
                &wd,
                &[Dual::constant(0.0); NV],
            );
            let h = 1e-6;
            let mut step = [0.0; NV];
            step[c] = h;
            let plus = forward(&model, lengths, &q, &v, &tau, &w, &step);
            step[c] = -h;
            let minus = forward(&model, lengths, &q, &v, &tau, &w, &step);
            for r in 0..NV {
                close(
                    &format!("dq̈{r}/dq{c} vs dual"),
                    deriv.ddq_dq[r][c],
                    along_q[r].du,
                    1e-10,
                    scale_q,
                );
                close(
                    &format!("dq̈{r}/dv{c} vs dual"),
                    deriv.ddq_dv[r][c],
                    along_v[r].du,
                    1e-10,
                    scale_v,
                );
                let fd = (plus[r] - minus[r]) / (2.0 * h);
                close(
                    &format!("dq̈{r}/dq{c} vs differences"),
                    deriv.ddq_dq[r][c],
                    fd,
                    1e-6,
                    scale_q,
                );
            }
        }
    }
}

/// An element that does not implement state derivatives is reported, not
/// silently treated as constant.
#[test]
fn elements_without_derivatives_are_reported() {
    struct Opaque;
    impl rodyn::drive::ForceElement<f64, Spatial, NB, NV> for Opaque {
        fn add_forces(
            &self,
            _: &rodyn::drive::DriveState<'_, f64, Spatial, NB, NV>,
            _: &[f64],
            _: &mut DriveForces<f64, Spatial, NB, NV>,
        ) -> rodyn::Result<()> {
            Ok(())
        }
    }
    let mut rng = Rng::new(5);
    let model = random_floating_tree::<NB, NQ, NV>(&mut rng);
    let q = random_configuration(&model, &mut rng);
    let mut data = Box::new(Data::<f64, NB, NV>::new());
    let mut deriv = Box::new(DerivativeData::<f64, NB, NV>::new());
    let mut jac = Box::new(JacobianData::<f64, NV>::new());
    let mut drive = Box::new(DriveDerivatives::<f64, NV>::new());
    let err = aba_derivatives_with_drives(
        &model,
        &mut data,
        &mut deriv,
        &mut jac,
        &mut drive,
        &q,
        &[0.0; NV],
        &[0.0; NV],
        &Opaque,
        &[],
    );
    assert!(
        matches!(
            err,
            Err(Error::InvalidDrive {
                problem: rodyn::error::DriveProblem::NotDifferentiable
            })
        ),
        "{err:?}"
    );
}
