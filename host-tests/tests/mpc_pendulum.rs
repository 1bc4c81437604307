//! Model-predictive control of the seed pendulum by iLQR on rodyn's
//! analytic derivatives (`rodyn_scenarios::pendulum_mpc`):
//!
//! * the discrete system's Jacobians against central differences (1e-6);
//! * the solver converges on the open-loop problem: the cost never rises,
//!   and at the optimum its gradient with respect to the controls
//!   (central differences of the rolled-out cost) vanishes;
//! * in closed loop, with the plant simulated at 1 kHz and the controller
//!   ticking every 20 ms, the pendulum follows the reference in f64 and in
//!   f32 (the firmware's arithmetic) within stated bounds, under the
//!   torque limit.

use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::drive::{forward_dynamics_with_drives, DriveForces, LinearSpring};
use rodyn::prelude::*;
use rodyn_scenarios::driven_system::DrivenModel;
use rodyn_scenarios::ilqr::{DiscreteSystem, Ilqr};
use rodyn_scenarios::pendulum::{MODEL_F32, MODEL_F64, RETURN_SPRING_F32, RETURN_SPRING_F64};
use rodyn_scenarios::pendulum_mpc::{
    cost, reference, PendulumMpc, HORIZON, NU, NX, STEP, TORQUE_LIMIT,
};

type Pendulum<'m, S> = DrivenModel<'m, S, Spatial, LinearSpring<S, Spatial, 2>, 1, 1, NX, NU>;

#[test]
fn linearization_matches_differences() {
    let mut system: Pendulum<f64> = DrivenModel::new(&MODEL_F64, &RETURN_SPRING_F64, &[], STEP);
    for (x, u) in [
        ([0.3, -1.0], [2.0]),
        ([1.4, 2.5], [-6.0]),
        ([-0.7, 0.1], [0.5]),
    ] {
        let (mut a, mut b) = ([[0.0; NX]; NX], [[0.0; NU]; NX]);
        system.linearize(&x, &u, &mut a, &mut b).unwrap();
        let h = 1e-6;
        for c in 0..NX + NU {
            let (mut xp, mut up, mut xm, mut um) = (x, u, x, u);
            if c < NX {
                xp[c] += h;
                xm[c] -= h;
            } else {
                up[c - NX] += h;
                um[c - NX] -= h;
            }
            let (plus, minus) = (
                system.step(&xp, &up).unwrap(),
                system.step(&xm, &um).unwrap(),
            );
            for r in 0..NX {
                let fd = (plus[r] - minus[r]) / (2.0 * h);
                let analytic = if c < NX { a[r][c] } else { b[r][c - NX] };
                assert!(
                    (analytic - fd).abs() < 1e-6 * fd.abs().max(1.0),
                    "∂x'{r}/∂{c} at {x:?}, {u:?}: {analytic} against {fd}"
                );
            }
        }
    }
}

/// The cost of rolling `controls` out from `x0` (the solver's own cost).
fn rolled_out_cost(
    system: &mut Pendulum<f64>,
    x0: &[f64; NX],
    controls: &[[f64; NU]; HORIZON],
) -> f64 {
    let c = cost::<f64>();
    let mut x = *x0;
    let mut total = 0.0;
    for (t, u) in controls.iter().enumerate() {
        let r = reference(0.5 + STEP * t as f64);
        total += 0.5 * (c.state[0] * (x[0] - r[0]).powi(2) + c.state[1] * (x[1] - r[1]).powi(2))
            + 0.5 * c.control[0] * u[0] * u[0];
        x = system.step(&x, u).unwrap();
    }
    let r = reference(0.5 + STEP * HORIZON as f64);
    total + 0.5 * (c.terminal[0] * (x[0] - r[0]).powi(2) + c.terminal[1] * (x[1] - r[1]).powi(2))
}

#[test]
fn ilqr_converges_on_the_open_loop_problem() {
    let mut system: Pendulum<f64> = DrivenModel::new(&MODEL_F64, &RETURN_SPRING_F64, &[], STEP);
    let limit = TORQUE_LIMIT;
    let mut solver = Ilqr::<f64, NX, NU, HORIZON>::new([-limit], [limit], 1e-6);
    let references: [[f64; NX]; HORIZON] =
        core::array::from_fn(|k| reference(0.5 + STEP * k as f64));
    let last = reference(0.5 + STEP * HORIZON as f64);
    let x0 = [0.0, 0.0];
    let mut costs = Vec::new();
    for _ in 0..40 {
        let report = solver
            .solve(&mut system, &cost(), &x0, &references, &last, 1)
            .unwrap();
        costs.push(report.cost);
    }
    assert!(
        costs.windows(2).all(|w| w[1] <= w[0]),
        "the cost rose: {costs:?}"
    );
    assert!(costs[39] < costs[0], "no progress: {costs:?}");
    // At the optimum (no torque at its limit here), the cost is stationary
    // in every control.
    let controls = solver.controls;
    assert!(
        controls.iter().all(|u| u[0].abs() < 0.99 * limit),
        "{controls:?}"
    );
    let scale = rolled_out_cost(&mut system, &x0, &controls);
    for t in 0..HORIZON {
        let h = 1e-5;
        let (mut plus, mut minus) = (controls, controls);
        plus[t][0] += h;
        minus[t][0] -= h;
        let gradient = (rolled_out_cost(&mut system, &x0, &plus)
            - rolled_out_cost(&mut system, &x0, &minus))
            / (2.0 * h);
        assert!(
            gradient.abs() < 1e-4 * scale.max(1.0),
            "∂J/∂u{t} = {gradient} at the optimum (J = {scale})"
        );
    }
}

/// Tracking error (max, RMS after the start, rad), final error and the
/// largest torque, from a closed-loop run of 4.5 s.
fn closed_loop<S: Scalar>(
    model: &Model<S, 1, 1, 1>,
    spring: &LinearSpring<S, Spatial, 2>,
) -> (f64, f64, f64, f64) {
    const PLANT_STEPS_PER_TICK: usize = 20;
    let dt = S::from_f64(STEP / PLANT_STEPS_PER_TICK as f64);
    let mut mpc = PendulumMpc::new(model, spring);
    let mut data = Data::new();
    let mut forces = DriveForces::new();
    let (mut q, mut v) = ([S::ZERO], [S::ZERO]);
    let (mut max_error, mut sum_squares, mut samples, mut max_torque) = (0.0f64, 0.0, 0, 0.0f64);
    let ticks = (4.5 / STEP).round() as usize;
    for tick in 0..ticks {
        let t = STEP * tick as f64;
        let (tau, _) = mpc.tick(S::from_f64(t), &[q[0], v[0]]).unwrap();
        max_torque = max_torque.max(tau.to_f64().abs());
        for _ in 0..PLANT_STEPS_PER_TICK {
            let ddq = *forward_dynamics_with_drives::<Aba, _, _, _, 1, 1, 1>(
                model,
                &mut data,
                &q,
                &v,
                &[tau],
                spring,
                &[],
                &mut forces,
            )
            .unwrap();
            v[0] += dt * ddq[0];
            q[0] += dt * v[0];
        }
        let error = (q[0].to_f64() - reference::<f64>(t + STEP)[0]).abs();
        max_error = max_error.max(error);
        sum_squares += error * error;
        samples += 1;
    }
    let final_error = (q[0].to_f64() - reference::<f64>(4.5)[0]).abs();
    (
        max_error,
        (sum_squares / samples as f64).sqrt(),
        final_error,
        max_torque,
    )
}

#[test]
fn closed_loop_follows_the_reference_in_f64_and_f32() {
    for (name, (max_error, rms, final_error, max_torque)) in [
        ("f64", closed_loop(&MODEL_F64, &RETURN_SPRING_F64)),
        ("f32", closed_loop(&MODEL_F32, &RETURN_SPRING_F32)),
    ] {
        println!("{name}: max error {max_error:.4} rad, rms {rms:.4} rad, final {final_error:.2e} rad, largest torque {max_torque:.2} N m");
        // About three times what the test prints for both scalars.
        assert!(max_error < 0.01, "{name}: max error {max_error}");
        assert!(rms < 0.005, "{name}: rms {rms}");
        assert!(final_error < 0.002, "{name}: final error {final_error}");
        assert!(
            max_torque <= TORQUE_LIMIT + 1e-6,
            "{name}: torque {max_torque}"
        );
    }
}
