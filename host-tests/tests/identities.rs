//! Identities that every correct implementation satisfies, on random trees
//! and random states:
//!
//! * `ABA(q, v, RNEA(q, v, a)) = a` (with and without external forces);
//! * `M a + h = RNEA(q, v, a)`;
//! * `M` symmetric positive definite, and CRBA forward dynamics equal to ABA;
//! * with no external force, `d/dt (T + V) = v · τ`.
//!
//! Tolerances are relative to the size of the compared vector,
//! `‖x - y‖∞ ≤ tol · max(1, ‖y‖∞)`, in f64.

use rodyn::algorithm::crba::crba;
use rodyn::algorithm::energy::{kinetic_energy, potential_energy};
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::algorithm::rnea::{nonlinear_effects, rnea};
use rodyn::prelude::*;
use rodyn_host_tests::random::{random_configuration, random_floating_tree, random_tree, Rng};

fn assert_close(what: &str, x: &[f64], y: &[f64], tol: f64) {
    let scale = y.iter().fold(1.0f64, |m, v| m.max(v.abs()));
    let err = x
        .iter()
        .zip(y)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(
        err <= tol * scale,
        "{what}: error {err:e} exceeds {tol:e} x {scale}\n  got  {x:?}\n  want {y:?}"
    );
}

/// Runs every identity on one model for `states` random states.
fn check_model<const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<f64, NB, NQ, NV>,
    rng: &mut Rng,
    states: usize,
) {
    model.validate().expect("random model is physical");
    let mut data = Box::new(Data::<f64, NB, NV>::new());
    for _ in 0..states {
        let q = random_configuration(model, rng);
        let v: [f64; NV] = rng.vector(2.0);
        let a: [f64; NV] = rng.vector(3.0);
        let f_ext: [Force<f64>; NB] = core::array::from_fn(|_| rng.force());

        for fext in [None, Some(&f_ext)] {
            let tau = *rnea(model, &mut data, &q, &v, &a, fext).unwrap();
            let by_aba = *Aba::forward_dynamics(model, &mut data, &q, &v, &tau, fext).unwrap();
            assert_close("ABA(RNEA(a)) = a", &by_aba, &a, 1e-9);
            let by_crba = *Crba::forward_dynamics(model, &mut data, &q, &v, &tau, fext).unwrap();
            assert_close("CRBA-FD(RNEA(a)) = a", &by_crba, &a, 1e-9);
        }

        let tau = *rnea(model, &mut data, &q, &v, &a, None).unwrap();
        let h = *nonlinear_effects(model, &mut data, &q, &v, None).unwrap();
        let m = *crba(model, &mut data, &q).unwrap();
        let m_a_plus_h: Vec<f64> = (0..NV)
            .map(|r| (0..NV).map(|c| m[r][c] * a[c]).sum::<f64>() + h[r])
            .collect();
        assert_close("M a + h = RNEA", &m_a_plus_h, &tau, 1e-10);

        for (r, row) in m.iter().enumerate() {
            for (c, entry) in row.iter().enumerate() {
                assert_eq!(*entry, m[c][r], "M not symmetric at ({r}, {c})");
            }
        }
        let eigen = nalgebra::DMatrix::from_fn(NV, NV, |r, c| m[r][c]).symmetric_eigen();
        let min = eigen.eigenvalues.min();
        assert!(
            min > 0.0,
            "M not positive definite: smallest eigenvalue {min:e}"
        );

        check_power_balance(model, &mut data, &q, &v, &tau);
    }
}

/// `d/dt (T + V) = v · τ` along the motion that `τ` produces, by a central
/// difference of step `ε` along `q(t) = q ⊕ (v t + ½ q̈ t²)`, `v(t) = v + q̈ t`.
fn check_power_balance<const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<f64, NB, NQ, NV>,
    data: &mut Data<f64, NB, NV>,
    q: &[f64; NQ],
    v: &[f64; NV],
    tau: &[f64; NV],
) {
    let ddq = *Aba::forward_dynamics(model, data, q, v, tau, None).unwrap();
    let eps = 1e-5;
    let mut energy = |t: f64| {
        let dq: [f64; NV] = core::array::from_fn(|k| v[k] * t + 0.5 * ddq[k] * t * t);
        let q_t = model.integrate(q, &dq, 1.0).unwrap();
        let v_t: [f64; NV] = core::array::from_fn(|k| v[k] + ddq[k] * t);
        kinetic_energy(model, data, &q_t, &v_t).unwrap()
            + potential_energy(model, data, &q_t).unwrap()
    };
    let rate = (energy(eps) - energy(-eps)) / (2.0 * eps);
    let power: f64 = v.iter().zip(tau).map(|(a, b)| a * b).sum();
    let scale = 1.0 + power.abs() + v.iter().zip(tau).map(|(a, b)| (a * b).abs()).sum::<f64>();
    assert!(
        (rate - power).abs() <= 1e-6 * scale,
        "d/dt(T+V) = {rate} but v.tau = {power}"
    );
}

#[test]
fn chains_and_trees() {
    let mut rng = Rng::new(0x5EED_0001);
    for _ in 0..4 {
        check_model(&random_tree::<1>(&mut rng), &mut rng, 5);
        check_model(&random_tree::<2>(&mut rng), &mut rng, 5);
        check_model(&random_tree::<7>(&mut rng), &mut rng, 5);
        check_model(&random_tree::<15>(&mut rng), &mut rng, 3);
    }
}

#[test]
fn floating_base_trees_with_a_fixed_joint() {
    let mut rng = Rng::new(0x5EED_0002);
    for _ in 0..6 {
        check_model(&random_floating_tree::<3, 8, 7>(&mut rng), &mut rng, 4);
        check_model(&random_floating_tree::<13, 18, 17>(&mut rng), &mut rng, 3);
    }
}
