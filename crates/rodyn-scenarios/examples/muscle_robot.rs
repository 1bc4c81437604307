//! The first seed's two-link robot driven by four Thelen muscles (its
//! figure 3): simulated forward for 2 s under given excitations, with the
//! sensitivity matrix ∂q̈/∂a of the joint accelerations to the muscle
//! activations printed along the trajectory.
//!
//! Run: `cargo run -p rodyn-scenarios --example muscle_robot`
//! (plots of the same run: `cargo run -p rodyn-drive-plots --release`).

use rodyn::Data;
use rodyn_scenarios::muscle_robot::{self as robot, NU, NV};

/// Excitations in [0, 1]: m1 and m2 alternate at the shoulder, m3 pulses
/// the elbow, m4 holds a steady tone.
fn excitation(t: f64) -> [f64; NU] {
    let s = (core::f64::consts::PI * t).sin();
    [
        0.35 + 0.3 * s,
        0.35 - 0.3 * s,
        0.1 + 0.06 * (2.0 * core::f64::consts::PI * t).sin(),
        0.12,
    ]
}

/// The state: joint angles, rates and the four activations.
#[derive(Clone, Copy)]
struct State {
    q: [f64; NV],
    v: [f64; NV],
    a: [f64; NU],
}

fn main() -> Result<(), rodyn::Error> {
    let model = robot::MODEL_F64;
    let muscles = robot::MUSCLES_F64;
    let mut data = Data::new();
    let mut forces = robot::RobotForces::new();

    let derivative = |data: &mut robot::RobotData<f64>,
                      forces: &mut robot::RobotForces<f64>,
                      t: f64,
                      x: &State|
     -> Result<State, rodyn::Error> {
        let ddq = *robot::forward_dynamics(&model, &muscles, data, &x.q, &x.v, &x.a, forces)?;
        Ok(State {
            q: x.v,
            v: ddq,
            a: robot::activation_rates(&muscles, &excitation(t), &x.a),
        })
    };
    let axpy = |x: &State, h: f64, d: &State| State {
        q: core::array::from_fn(|k| x.q[k] + h * d.q[k]),
        v: core::array::from_fn(|k| x.v[k] + h * d.v[k]),
        a: core::array::from_fn(|k| x.a[k] + h * d.a[k]),
    };

    let dt = 1e-3;
    let mut x = State {
        q: [0.0; NV],
        v: [0.0; NV],
        a: [0.05; NU],
    };
    println!(
        "{:>5} {:>8} {:>8} {:>6} {:>6} {:>6} {:>6} | d(qdd_shoulder)/da (rad/s^2)      | d(qdd_elbow)/da (rad/s^2)",
        "t s", "q1 rad", "q2 rad", "a1", "a2", "a3", "a4"
    );
    for step in 0..=2000 {
        let t = step as f64 * dt;
        if step % 200 == 0 {
            let mut s = [[0.0; NU]; NV];
            robot::sensitivity(
                &model,
                &muscles,
                &mut data,
                &x.q,
                &x.v,
                &x.a,
                &mut forces,
                &mut s,
            )?;
            println!(
                "{t:5.2} {:8.4} {:8.4} {:6.3} {:6.3} {:6.3} {:6.3} | {:7.1} {:7.1} {:7.1} {:7.1} | {:7.1} {:7.1} {:7.1} {:7.1}",
                x.q[0], x.q[1], x.a[0], x.a[1], x.a[2], x.a[3],
                s[0][0], s[0][1], s[0][2], s[0][3], s[1][0], s[1][1], s[1][2], s[1][3]
            );
        }
        // Classical RK4.
        let k1 = derivative(&mut data, &mut forces, t, &x)?;
        let k2 = derivative(
            &mut data,
            &mut forces,
            t + 0.5 * dt,
            &axpy(&x, 0.5 * dt, &k1),
        )?;
        let k3 = derivative(
            &mut data,
            &mut forces,
            t + 0.5 * dt,
            &axpy(&x, 0.5 * dt, &k2),
        )?;
        let k4 = derivative(&mut data, &mut forces, t + dt, &axpy(&x, dt, &k3))?;
        let sum = State {
            q: core::array::from_fn(|k| k1.q[k] + 2.0 * k2.q[k] + 2.0 * k3.q[k] + k4.q[k]),
            v: core::array::from_fn(|k| k1.v[k] + 2.0 * k2.v[k] + 2.0 * k3.v[k] + k4.v[k]),
            a: core::array::from_fn(|k| k1.a[k] + 2.0 * k2.a[k] + 2.0 * k3.a[k] + k4.a[k]),
        };
        x = axpy(&x, dt / 6.0, &sum);
    }
    Ok(())
}
