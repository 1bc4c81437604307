//! The analytic derivatives of inverse and forward dynamics against
//! forward-mode dual numbers (exact to rounding: 1e-10) and central
//! differences (1e-6), on random trees with a fixed and a floating base,
//! in random states with external forces; and a planar chain's derivatives
//! against its 3-D twin's (1e-12).
//!
//! A column c of `∂/∂q` is the derivative along `q ⊕ ε e_c`, taken with
//! [`Model::integrate`] (so a free-flyer's columns are body-frame
//! increments). Tolerances: `‖x − y‖∞ ≤ tol · max(1, ‖y‖∞)` per matrix.

use rodyn::algorithm::aba::aba;
use rodyn::algorithm::derivatives::{
    aba_derivatives, aba_derivatives_by_solves, rnea_derivatives, DerivativeData,
};
use rodyn::algorithm::rnea::rnea;
use rodyn::planar::Planar;
use rodyn::prelude::*;
use rodyn::topology::Topology;
use rodyn_host_tests::random::{
    gravity, random_configuration, random_floating_tree, random_planar_chain, random_tree, Rng,
};

fn assert_close<const N: usize>(what: &str, x: &[[f64; N]; N], y: &[[f64; N]; N], tol: f64) {
    let scale = y.iter().flatten().fold(1.0f64, |m, v| m.max(v.abs()));
    let err = x
        .iter()
        .flatten()
        .zip(y.iter().flatten())
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(
        err <= tol * scale,
        "{what}: error {err:e} exceeds {tol:e} x {scale}\n  got  {x:?}\n  want {y:?}"
    );
}

/// Which function of the state is differentiated.
#[derive(Clone, Copy, Debug)]
enum Dynamics {
    /// `τ = ID(q, v, u)`.
    Inverse,
    /// `q̈ = FD(q, v, u)`.
    Forward,
}

/// The model's inverse or forward dynamics at `(q ⊕ dq, v + dv, u + du)`.
#[allow(clippy::too_many_arguments)]
fn evaluate<S: Scalar, const NB: usize, const NQ: usize, const NV: usize>(
    dynamics: Dynamics,
    model: &Model<S, NB, NQ, NV>,
    q: &[S; NQ],
    v: &[S; NV],
    u: &[S; NV],
    f_ext: &[Force<S>; NB],
    (dq, dv, du): ([S; NV], [S; NV], [S; NV]),
) -> [S; NV] {
    let mut data = Box::new(Data::<S, NB, NV>::new());
    let q = model.integrate(q, &dq, S::ONE).unwrap();
    let v: [S; NV] = core::array::from_fn(|k| v[k] + dv[k]);
    let u: [S; NV] = core::array::from_fn(|k| u[k] + du[k]);
    match dynamics {
        Dynamics::Inverse => *rnea(model, &mut data, &q, &v, &u, Some(f_ext)).unwrap(),
        Dynamics::Forward => *aba(model, &mut data, &q, &v, &u, Some(f_ext)).unwrap(),
    }
}

/// A state `(q, v, u, f_ext)`, u being `a` or `τ`.
type Point<'a, const NB: usize, const NQ: usize, const NV: usize> = (
    &'a [f64; NQ],
    &'a [f64; NV],
    &'a [f64; NV],
    &'a [Force<f64>; NB],
);

/// `∂/∂q`, `∂/∂v`, `∂/∂u` column by column, with dual numbers.
fn dual_jacobians<const NB: usize, const NQ: usize, const NV: usize>(
    dynamics: Dynamics,
    model: &Model<f64, NB, NQ, NV>,
    (q, v, u, f_ext): Point<NB, NQ, NV>,
) -> [[[f64; NV]; NV]; 3] {
    let dual_model = model.cast::<Dual>().unwrap();
    let q = q.map(Dual::constant);
    let v = v.map(Dual::constant);
    let u = u.map(Dual::constant);
    let f_ext: [Force<Dual>; NB] =
        core::array::from_fn(|i| Force::new(f_ext[i].ang.cast(), f_ext[i].lin.cast()));
    let mut out = [[[0.0; NV]; NV]; 3];
    for (wrt, jacobian) in out.iter_mut().enumerate() {
        for c in 0..NV {
            let mut direction = [[Dual::constant(0.0); NV]; 3];
            direction[wrt][c] = Dual::variable(0.0);
            let y = evaluate(
                dynamics,
                &dual_model,
                &q,
                &v,
                &u,
                &f_ext,
                (direction[0], direction[1], direction[2]),
            );
            for r in 0..NV {
                jacobian[r][c] = y[r].du;
            }
        }
    }
    out
}

/// `∂/∂q`, `∂/∂v`, `∂/∂u` by central differences of step `h`.
fn central_differences<const NB: usize, const NQ: usize, const NV: usize>(
    dynamics: Dynamics,
    model: &Model<f64, NB, NQ, NV>,
    (q, v, u, f_ext): Point<NB, NQ, NV>,
    h: f64,
) -> [[[f64; NV]; NV]; 3] {
    let mut out = [[[0.0; NV]; NV]; 3];
    for (wrt, jacobian) in out.iter_mut().enumerate() {
        for c in 0..NV {
            let step = |sign: f64| {
                let mut direction = [[0.0; NV]; 3];
                direction[wrt][c] = sign * h;
                let (dq, dv, du) = (direction[0], direction[1], direction[2]);
                evaluate(dynamics, model, q, v, u, f_ext, (dq, dv, du))
            };
            let (plus, minus) = (step(1.0), step(-1.0));
            for r in 0..NV {
                jacobian[r][c] = (plus[r] - minus[r]) / (2.0 * h);
            }
        }
    }
    out
}

fn check_model<const NB: usize, const NQ: usize, const NV: usize>(
    what: &str,
    model: &Model<f64, NB, NQ, NV>,
    rng: &mut Rng,
) {
    model.validate().unwrap();
    let mut data = Box::new(Data::<f64, NB, NV>::new());
    let mut deriv = Box::new(DerivativeData::<f64, NB, NV>::new());
    for state in 0..3 {
        let q = random_configuration(model, rng);
        let v: [f64; NV] = rng.vector(2.0);
        let a: [f64; NV] = rng.vector(2.0);
        let tau: [f64; NV] = rng.vector(5.0);
        let f_ext: [Force<f64>; NB] = core::array::from_fn(|_| rng.force());

        // No entry of the matrices may be left from before the call (the
        // passes write only the entries the tree relates; the others are
        // cleared).
        let poison = |data: &mut Data<f64, NB, NV>, deriv: &mut DerivativeData<f64, NB, NV>| {
            data.mass_matrix = [[f64::NAN; NV]; NV];
            deriv.dtau_dq = [[f64::NAN; NV]; NV];
            deriv.dtau_dv = [[f64::NAN; NV]; NV];
        };
        poison(&mut data, &mut deriv);
        rnea_derivatives(model, &mut data, &mut deriv, &q, &v, &a, Some(&f_ext)).unwrap();
        let (m, tau_world) = (data.mass_matrix, data.tau);
        // Its RNEA, run in the world frame, against RNEA in body frames.
        let tau_body = *rnea(model, &mut data, &q, &v, &a, Some(&f_ext)).unwrap();
        let scale = tau_body.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        for (x, y) in tau_world.iter().zip(&tau_body) {
            assert!(
                (x - y).abs() <= 1e-12 * scale,
                "{what}: τ {tau_world:?} against {tau_body:?}"
            );
        }
        let point = (&q, &v, &a, &f_ext);
        let [dq, dv, da] = dual_jacobians(Dynamics::Inverse, model, point);
        let ctx = |x: &str| format!("{what} state {state}: RNEA {x}");
        assert_close(&ctx("dq vs dual"), &deriv.dtau_dq, &dq, 1e-10);
        assert_close(&ctx("dv vs dual"), &deriv.dtau_dv, &dv, 1e-10);
        assert_close(&ctx("da (M) vs dual"), &m, &da, 1e-10);
        let [dq, dv, _] = central_differences(Dynamics::Inverse, model, point, 1e-6);
        assert_close(&ctx("dq vs central differences"), &deriv.dtau_dq, &dq, 1e-6);
        assert_close(&ctx("dv vs central differences"), &deriv.dtau_dv, &dv, 1e-6);

        poison(&mut data, &mut deriv);
        aba_derivatives(model, &mut data, &mut deriv, &q, &v, &tau, Some(&f_ext)).unwrap();
        let point = (&q, &v, &tau, &f_ext);
        let [dq, dv, dtau] = dual_jacobians(Dynamics::Forward, model, point);
        let ctx = |x: &str| format!("{what} state {state}: ABA {x}");
        assert_close(&ctx("dq vs dual"), &deriv.ddq_dq, &dq, 1e-10);
        assert_close(&ctx("dv vs dual"), &deriv.ddq_dv, &dv, 1e-10);
        assert_close(&ctx("dtau (M⁻¹) vs dual"), &deriv.minv, &dtau, 1e-10);
        let [dq, dv, _] = central_differences(Dynamics::Forward, model, point, 1e-6);
        assert_close(&ctx("dq vs central differences"), &deriv.ddq_dq, &dq, 1e-6);
        assert_close(&ctx("dv vs central differences"), &deriv.ddq_dv, &dv, 1e-6);

        // The tuned path (q̈ from the derivative passes, rows solved in
        // registers) against the plain one (ABA, RNEA's derivatives, plain
        // multi-column solves).
        let (tuned, ddq) = (deriv.clone(), data.ddq);
        aba_derivatives_by_solves(model, &mut data, &mut deriv, &q, &v, &tau, Some(&f_ext))
            .unwrap();
        let scale = data.ddq.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        for (x, y) in ddq.iter().zip(&data.ddq) {
            assert!(
                (x - y).abs() <= 1e-12 * scale,
                "{what}: q̈ {ddq:?} against {:?}",
                data.ddq
            );
        }
        assert_close(&ctx("dq vs plain"), &tuned.ddq_dq, &deriv.ddq_dq, 1e-12);
        assert_close(&ctx("dv vs plain"), &tuned.ddq_dv, &deriv.ddq_dv, 1e-12);
        assert_close(&ctx("M⁻¹ vs plain"), &tuned.minv, &deriv.minv, 1e-12);
        assert_close(
            &ctx("RNEA dq vs plain"),
            &tuned.dtau_dq,
            &deriv.dtau_dq,
            1e-12,
        );
        assert_close(
            &ctx("RNEA dv vs plain"),
            &tuned.dtau_dv,
            &deriv.dtau_dv,
            1e-12,
        );
    }
}

#[test]
fn fixed_base_trees_agree_with_dual_numbers_and_differences() {
    let mut rng = Rng::new(20_261_125);
    for tree in 0..4 {
        let model = random_tree::<9>(&mut rng);
        check_model(&format!("tree {tree}"), &model, &mut rng);
    }
}

#[test]
fn floating_base_trees_agree_with_dual_numbers_and_differences() {
    let mut rng = Rng::new(7);
    for tree in 0..4 {
        let model = random_floating_tree::<8, 13, 12>(&mut rng);
        check_model(&format!("floating tree {tree}"), &model, &mut rng);
    }
}

/// Trees numbered depth first with entries between branches (zero in
/// `M`, `∂τ/∂q` and `∂τ/∂v`): three limbs of three on one body, fixed and
/// (as a free-flyer) floating.
#[test]
fn depth_first_limbs_agree_with_dual_numbers_and_differences() {
    let mut rng = Rng::new(12);
    let parents = |i: usize| match i {
        0 => None,
        1 | 4 | 7 => Some(0),
        _ => Some(i - 1),
    };
    let limbs = tree_with_parents::<10>(&mut rng, core::array::from_fn(parents));
    assert!(limbs.topology().depth_first);
    check_model("three limbs", &limbs, &mut rng);
    let floating = Model::<f64, 10, 16, 15>::from_parts(
        Topology::new(
            core::array::from_fn(parents),
            core::array::from_fn(|i| if i == 0 { 7 } else { 1 }),
            core::array::from_fn(|i| if i == 0 { 6 } else { 1 }),
            16,
        ),
        core::array::from_fn(|i| {
            if i == 0 {
                Joint::free_flyer()
            } else {
                rng.one_dof_joint()
            }
        }),
        core::array::from_fn(|_| rng.placement()),
        core::array::from_fn(|_| rng.inertia()),
        gravity(),
    );
    assert!(floating.topology().depth_first);
    check_model("three limbs on a free-flyer", &floating, &mut rng);
}

#[test]
fn planar_chain_matches_its_3d_twin() {
    const N: usize = 6;
    let mut rng = Rng::new(11);
    let (planar, spatial) = random_planar_chain::<N>(&mut rng);
    let mut dp = Box::new(Data::<f64, N, N, Planar>::new());
    let mut ds = Box::new(Data::<f64, N, N>::new());
    let mut vp = Box::new(DerivativeData::<f64, N, N, Planar>::new());
    let mut vs = Box::new(DerivativeData::<f64, N, N>::new());
    for _ in 0..3 {
        let q: [f64; N] = rng.vector(2.0);
        let v: [f64; N] = rng.vector(2.0);
        let a: [f64; N] = rng.vector(2.0);
        aba_derivatives(&planar, &mut dp, &mut vp, &q, &v, &a, None).unwrap();
        aba_derivatives(&spatial, &mut ds, &mut vs, &q, &v, &a, None).unwrap();
        assert_close("RNEA dq", &vp.dtau_dq, &vs.dtau_dq, 1e-12);
        assert_close("RNEA dv", &vp.dtau_dv, &vs.dtau_dv, 1e-12);
        assert_close("ABA dq", &vp.ddq_dq, &vs.ddq_dq, 1e-12);
        assert_close("ABA dv", &vp.ddq_dv, &vs.ddq_dv, 1e-12);
        assert_close("M⁻¹", &vp.minv, &vs.minv, 1e-12);
    }
}

/// With no velocity, `∂τ/∂v = 0`; and with no velocity and no
/// acceleration, `∂τ/∂q` is the gravity torques' Jacobian, symmetric for a
/// fixed base (the Hessian of the potential energy).
#[test]
fn at_rest_the_gravity_jacobian_is_symmetric() {
    let mut rng = Rng::new(3);
    let model = random_tree::<7>(&mut rng);
    let mut data = Box::new(Data::<f64, 7, 7>::new());
    let mut deriv = Box::new(DerivativeData::<f64, 7, 7>::new());
    let q: [f64; 7] = rng.vector(2.0);
    rnea_derivatives(
        &model, &mut data, &mut deriv, &q, &[0.0; 7], &[0.0; 7], None,
    )
    .unwrap();
    let transposed: [[f64; 7]; 7] =
        core::array::from_fn(|r| core::array::from_fn(|c| deriv.dtau_dq[c][r]));
    assert_close(
        "dτ/dq at rest vs its transpose",
        &deriv.dtau_dq,
        &transposed,
        1e-13,
    );
    assert_close("dτ/dv at rest", &deriv.dtau_dv, &[[0.0; 7]; 7], 1e-15);
}

/// Bad input is an error, never a panic or NaN.
#[test]
fn bad_input_is_reported() {
    let mut rng = Rng::new(5);
    let model = random_tree::<4>(&mut rng);
    let mut data = Box::new(Data::<f64, 4, 4>::new());
    let mut deriv = Box::new(DerivativeData::<f64, 4, 4>::new());
    let mut v = [0.0; 4];
    v[2] = f64::NAN;
    let err = rnea_derivatives(
        &model, &mut data, &mut deriv, &[0.0; 4], &v, &[0.0; 4], None,
    );
    assert!(
        matches!(err, Err(Error::NonFinite { index: 2, .. })),
        "{err:?}"
    );
    let err = aba_derivatives(
        &model,
        &mut data,
        &mut deriv,
        &[0.0; 4],
        &[1e200; 4],
        &[0.0; 4],
        None,
    );
    assert!(err.is_err(), "{err:?}");
    // A mass matrix that overflows (finite bias forces: no gravity, at
    // rest) is reported as such, not as a failed pivot.
    let heavy = Model::<f64, 1, 1, 1>::new(
        [None],
        [Joint::revolute(Axis::Z)],
        [Transform::IDENTITY],
        [Inertia::point_mass(1e307, Vec3::new(100.0, 0.0, 0.0))],
        Motion::new(Vec3::ZERO, Vec3::ZERO),
    );
    let (mut data, mut deriv) = (Box::new(Data::new()), Box::new(DerivativeData::new()));
    let err = aba_derivatives(&heavy, &mut data, &mut deriv, &[0.0], &[0.0], &[1.0], None);
    assert!(
        matches!(
            err,
            Err(Error::NonFiniteResult {
                quantity: rodyn::error::Quantity::MassMatrix,
                ..
            })
        ),
        "{err:?}"
    );
}

/// The closed form of `Ẏ` in space against its definition applied to a
/// basis (`ColumnVariation`, the plane's form), on random bodies, velocities
/// and directions, and sums of them (a composite).
#[test]
fn spatial_variation_matches_its_definition() {
    use rodyn::algorithm::derivatives::{ColumnVariation, SpatialVariation, VariationMap};
    let mut rng = Rng::new(13);
    let motion = |rng: &mut Rng| {
        let [a, b, c, d, e, f]: [f64; 6] = rng.vector(2.0);
        Motion::new(Vec3::new(a, b, c), Vec3::new(d, e, f))
    };
    let (mut closed, mut columns) = (
        SpatialVariation::ZERO,
        ColumnVariation::<f64, Spatial>::ZERO,
    );
    for _ in 0..5 {
        let body = rng.inertia().act(&rng.placement());
        let v = motion(&mut rng);
        closed.add_assign(&SpatialVariation::of_body(&body, &v));
        columns.add_assign(&ColumnVariation::of_body(&body, &v));
        for _ in 0..4 {
            let (delta, s) = (motion(&mut rng), motion(&mut rng));
            let (x, y) = (closed.mul_motion(&delta), columns.mul_motion(&delta));
            let scale = y.ang.norm().max(y.lin.norm()).max(1.0);
            assert!(
                (x - y).ang.norm() + (x - y).lin.norm() < 1e-12 * scale,
                "Ẏδ: {x:?} against {y:?}"
            );
            let (x, y) = (
                SpatialVariation::dot_row(&closed.row(&s), &delta),
                ColumnVariation::<f64, Spatial>::dot_row(&columns.row(&s), &delta),
            );
            assert!(
                (x - y).abs() < 1e-12 * y.abs().max(1.0),
                "sᵀẎδ: {x} against {y}"
            );
        }
    }
}

/// The multi-column solve behind `M⁻¹` against the one-column solve, column
/// by column, on a tree numbered out of depth-first order and on a
/// floating-base tree.
#[test]
fn multi_column_solve_matches_column_by_column() {
    use rodyn::algorithm::crba::crba;
    use rodyn::algorithm::ltdl::{ltdl_factor, ltdl_solve, ltdl_solve_columns};
    fn check<const NB: usize, const NQ: usize, const NV: usize>(
        model: &Model<f64, NB, NQ, NV>,
        rng: &mut Rng,
    ) {
        let mut data = Box::new(Data::<f64, NB, NV>::new());
        let q = random_configuration(model, rng);
        crba(model, &mut data, &q).unwrap();
        ltdl_factor(model, &mut data).unwrap();
        let mut columns: [[f64; NV]; NV] = core::array::from_fn(|_| rng.vector(3.0));
        let b = columns;
        ltdl_solve_columns(model, &data, &mut columns).unwrap();
        for c in 0..NV {
            let mut x: [f64; NV] = core::array::from_fn(|r| b[r][c]);
            ltdl_solve(model, &data, &mut x).unwrap();
            let scale = x.iter().fold(1.0f64, |m, v| m.max(v.abs()));
            for r in 0..NV {
                assert!(
                    (columns[r][c] - x[r]).abs() <= 1e-12 * scale,
                    "column {c}, row {r}: {} against {}",
                    columns[r][c],
                    x[r]
                );
            }
        }
    }
    let mut rng = Rng::new(17);
    check(&random_tree::<9>(&mut rng), &mut rng);
    check(&random_floating_tree::<8, 13, 12>(&mut rng), &mut rng);
}

/// A tree of one-degree-of-freedom joints with the given parents (random
/// axes, placements and inertias).
fn tree_with_parents<const N: usize>(
    rng: &mut Rng,
    parents: [Option<usize>; N],
) -> Model<f64, N, N, N> {
    Model::from_parts(
        Topology::new(parents, [1; N], [1; N], N),
        core::array::from_fn(|_| rng.one_dof_joint()),
        core::array::from_fn(|_| rng.placement()),
        core::array::from_fn(|_| rng.inertia()),
        gravity(),
    )
}

/// `aba_derivatives` against its plain form on trees deep enough (their
/// coordinates 15 moving bodies deep on average) that hosts form `M⁻¹` by
/// articulated-body sweeps: a 40-link chain, and a trunk of 20 links
/// carrying two branches of 12.
#[test]
fn deep_trees_match_the_plain_solves() {
    fn check<const N: usize>(what: &str, model: &Model<f64, N, N, N>, rng: &mut Rng) {
        assert!(
            model.topology().mean_support_depth >= 15,
            "{what}: not deep"
        );
        let mut data = Box::new(Data::<f64, N, N>::new());
        let mut deriv = Box::new(DerivativeData::<f64, N, N>::new());
        for state in 0..3 {
            let q = random_configuration(model, rng);
            let v: [f64; N] = rng.vector(2.0);
            let tau: [f64; N] = rng.vector(5.0);
            let f_ext: [Force<f64>; N] = core::array::from_fn(|_| rng.force());
            aba_derivatives(model, &mut data, &mut deriv, &q, &v, &tau, Some(&f_ext)).unwrap();
            let tuned = deriv.clone();
            aba_derivatives_by_solves(model, &mut data, &mut deriv, &q, &v, &tau, Some(&f_ext))
                .unwrap();
            let ctx = |x: &str| format!("{what} state {state}: {x} vs plain");
            assert_close(&ctx("M⁻¹"), &tuned.minv, &deriv.minv, 1e-12);
            assert_close(&ctx("dq"), &tuned.ddq_dq, &deriv.ddq_dq, 1e-12);
            assert_close(&ctx("dv"), &tuned.ddq_dv, &deriv.ddq_dv, 1e-12);
        }
    }
    let mut rng = Rng::new(40);
    let chain = tree_with_parents::<40>(&mut rng, core::array::from_fn(|i| i.checked_sub(1)));
    check("40-link chain", &chain, &mut rng);
    let branched = tree_with_parents::<44>(
        &mut rng,
        core::array::from_fn(|i| match i {
            0 => None,
            32 => Some(19),
            _ => Some(i - 1),
        }),
    );
    assert!(branched.topology().depth_first);
    check("trunk and two branches", &branched, &mut rng);
}
