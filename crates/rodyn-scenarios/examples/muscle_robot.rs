//! The first seed's two-link robot driven by four Thelen muscles (its
//! figure 3): simulated forward for 2 s under given excitations, with the
//! sensitivity matrix ∂q̈/∂a of the joint accelerations to the muscle
//! activations printed along the trajectory.
//!
//! Run: `cargo run -p rodyn-scenarios --example muscle_robot`
//! (plots of the same run: `cargo run -p rodyn-drive-plots --release`).

use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::sim::{Integrator, Rk4};
use rodyn_cli::no_arguments;
use rodyn_scenarios::muscle_robot::{
    self as robot, example_excitation, RobotForces, RobotLoads, INITIAL_ACTIVATION, NU, NV,
};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    no_arguments("muscle_robot", "prints a fixed 2 s run")?;
    let model = robot::MODEL_F64;
    let muscles = robot::MUSCLES_F64;
    let mut data = rodyn::Data::new();
    let mut forces = RobotForces::new();
    let mut loads = RobotLoads::new(&muscles, example_excitation::<f64>);
    let mut rk4 = Rk4::default();
    let dt = 1e-3;
    let mut x = robot::rest_state(INITIAL_ACTIVATION);
    rodyn_cli::outln!(
        "{:>5} {:>8} {:>8} {:>6} {:>6} {:>6} {:>6} | d(qdd_shoulder)/da (rad/s^2)      | d(qdd_elbow)/da (rad/s^2)",
        "t s", "q1 rad", "q2 rad", "a1", "a2", "a3", "a4"
    );
    for step in 0..=2000 {
        if step % 200 == 0 {
            let mut s = [[0.0; NU]; NV];
            robot::sensitivity(
                &model,
                &muscles,
                &mut data,
                &x.q,
                &x.v,
                &x.z,
                &mut forces,
                &mut s,
            )?;
            let a = x.z;
            rodyn_cli::outln!(
                "{:5.2} {:8.4} {:8.4} {:6.3} {:6.3} {:6.3} {:6.3} | {:7.1} {:7.1} {:7.1} {:7.1} | {:7.1} {:7.1} {:7.1} {:7.1}",
                x.t, x.q[0], x.q[1], a[0], a[1], a[2], a[3],
                s[0][0], s[0][1], s[0][2], s[0][3], s[1][0], s[1][1], s[1][2], s[1][3]
            );
        }
        rk4.step(Aba, &model, &mut data, &mut x, dt, &mut loads)?;
    }
    Ok(())
}
