//! The integrators of `rodyn::sim`: order of accuracy, energy behaviour,
//! stiff stability, the floating base on its manifold, and error handling.

use rodyn::algorithm::energy::{kinetic_energy, potential_energy};
use rodyn::algorithm::forward_dynamics::{Aba, Crba};
use rodyn::prelude::*;
use rodyn::sim::{
    ExplicitEuler, ImplicitEuler, Integrator, Loads, NoLoads, Rk4, SemiImplicitEuler, State,
};

/// A rod pendulum, 1 kg, 0.5 m to the centre of mass, about y, gravity -z.
fn pendulum() -> Model<f64, 1, 1, 1> {
    Model::new(
        [None],
        [Joint::revolute(Axis::Y)],
        [Transform::IDENTITY],
        [Inertia::new(
            1.0,
            Vec3::new(0.0, 0.0, -0.5),
            Sym3::diagonal(0.02, 0.02, 0.001),
        )],
        Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
    )
}

fn run<I: Integrator>(mut integrator: I, dt: f64, duration: f64, q0: f64) -> State<f64, 1, 1> {
    let model = pendulum();
    let mut data = Data::new();
    let mut state = State::new([q0], [0.0]);
    let steps = (duration / dt).round() as usize;
    for _ in 0..steps {
        integrator
            .step(Aba, &model, &mut data, &mut state, dt, &mut NoLoads)
            .unwrap();
    }
    state
}

fn energy(state: &State<f64, 1, 1>) -> f64 {
    let model = pendulum();
    let mut data = Data::new();
    kinetic_energy(&model, &mut data, &state.q, &state.v).unwrap()
        + potential_energy(&model, &mut data, &state.q).unwrap()
}

#[test]
fn convergence_orders_match_theory() {
    let reference = run(Rk4::default(), 1e-4, 1.0, 1.0);
    let error = |dt: f64, rk4: bool| {
        let s = if rk4 {
            run(Rk4::default(), dt, 1.0, 1.0)
        } else {
            run(SemiImplicitEuler::default(), dt, 1.0, 1.0)
        };
        (s.q[0] - reference.q[0]).abs()
    };
    let rk4_ratio = error(0.02, true) / error(0.01, true);
    assert!(
        (12.0..20.0).contains(&rk4_ratio),
        "RK4 halving ratio {rk4_ratio} (expect 16)"
    );
    let euler_ratio = error(0.002, false) / error(0.001, false);
    assert!(
        (1.6..2.5).contains(&euler_ratio),
        "Euler halving ratio {euler_ratio} (expect 2)"
    );
}

#[test]
fn symplectic_euler_bounds_energy_explicit_euler_gains_it() {
    let e0 = energy(&State::new([1.0], [0.0]));
    // Energy scale: the swing's potential energy range, m g l (1 - cos 1).
    let scale = 9.81 * 0.5 * (1.0 - 1.0f64.cos());
    let symplectic = energy(&run(SemiImplicitEuler::default(), 1e-2, 20.0, 1.0));
    let explicit = energy(&run(ExplicitEuler::default(), 1e-2, 20.0, 1.0));
    let implicit = energy(&run(ImplicitEuler::default(), 1e-2, 20.0, 1.0));
    assert!(
        ((symplectic - e0) / scale).abs() < 0.03,
        "symplectic drift {}",
        (symplectic - e0) / scale
    );
    assert!(
        (explicit - e0) / scale > 0.5,
        "explicit Euler should gain energy: {}",
        (explicit - e0) / scale
    );
    assert!(
        (implicit - e0) / scale < -0.2,
        "implicit Euler should lose energy: {}",
        (implicit - e0) / scale
    );
}

/// A 1 kg slider on a spring of stiffness `k` (N/m), no gravity.
fn slider() -> Model<f64, 1, 1, 1> {
    Model::new(
        [None],
        [Joint::prismatic(Axis::Z)],
        [Transform::IDENTITY],
        [Inertia::point_mass(1.0, Vec3::ZERO)],
        Motion::new(Vec3::ZERO, Vec3::ZERO),
    )
}

fn spring(k: f64) -> impl Loads<f64, 1, 1, 1, rodyn::spatial::Spatial> {
    move |_: &Model<f64, 1, 1, 1>,
          _: &mut Data<f64, 1, 1>,
          _: f64,
          q: &[f64; 1],
          _: &[f64; 1],
          tau: &mut [f64; 1],
          _: &mut [Force<f64>; 1]| {
        tau[0] -= k * q[0];
        Ok(())
    }
}

#[test]
fn implicit_euler_is_stable_where_rk4_is_not() {
    // ω = 1000 rad/s, dt = 10 ms: ω dt = 10, far beyond RK4's 2.78.
    let (k, dt) = (1.0e6, 1.0e-2);
    let model = slider();
    let mut data = Data::new();
    let mut implicit = State::new([0.01], [0.0]);
    let mut rk4 = implicit;
    let mut rk4_failed = false;
    for _ in 0..100 {
        ImplicitEuler::default()
            .step(Crba, &model, &mut data, &mut implicit, dt, &mut spring(k))
            .unwrap();
        if !rk4_failed {
            rk4_failed = Rk4::default()
                .step(Crba, &model, &mut data, &mut rk4, dt, &mut spring(k))
                .is_err();
        }
    }
    assert!(
        implicit.q[0].abs() < 1e-4,
        "implicit Euler decays: {}",
        implicit.q[0]
    );
    // RK4 either reported a non-finite step or grew without bound; its
    // state is finite in both cases (a failing step leaves it unchanged).
    assert!(rk4.q[0].is_finite());
    assert!(rk4_failed || rk4.q[0].abs() > 1e10, "RK4 {:?}", rk4.q[0]);
}

#[test]
fn a_failing_step_returns_the_error_and_keeps_the_state() {
    let model = pendulum();
    let mut data = Data::new();
    let start = State::new([0.3], [0.1]);
    let mut state = start;
    let mut nan_torque = |_: &Model<f64, 1, 1, 1>,
                          _: &mut Data<f64, 1, 1>,
                          _: f64,
                          _: &[f64; 1],
                          _: &[f64; 1],
                          tau: &mut [f64; 1],
                          _: &mut [Force<f64>; 1]| {
        tau[0] = f64::NAN;
        Ok(())
    };
    for result in [
        Rk4::default().step(Aba, &model, &mut data, &mut state, 1e-3, &mut nan_torque),
        ExplicitEuler::default().step(Crba, &model, &mut data, &mut state, 1e-3, &mut nan_torque),
        ImplicitEuler::default().step(Aba, &model, &mut data, &mut state, 1e-3, &mut nan_torque),
    ] {
        assert!(
            matches!(
                result,
                Err(Error::NonFinite {
                    quantity: rodyn::error::Quantity::Torque,
                    index: 0
                })
            ),
            "{result:?}"
        );
        assert_eq!(state, start);
    }
}

/// A free box spinning about a principal axis while falling: the exact
/// solution is a parabola and a constant-rate rotation.
#[test]
fn floating_base_falls_and_spins_on_its_manifold() {
    let model: Model<f64, 1, 7, 6> = Model::new(
        [None],
        [Joint::free_flyer()],
        [Transform::IDENTITY],
        [Inertia::new(
            2.0,
            Vec3::ZERO,
            Sym3::diagonal(0.01, 0.02, 0.03),
        )],
        Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
    );
    let omega = 3.0;
    let (t_end, dt) = (1.0, 1e-3);
    let exact_z = -0.5 * 9.81 * t_end * t_end;
    let exact_quat = [
        0.0,
        0.0,
        (omega * t_end / 2.0).sin(),
        (omega * t_end / 2.0).cos(),
    ];
    let mut data = Data::new();
    for update in [
        rodyn::sim::ConfigurationUpdate::ExponentialMap,
        rodyn::sim::ConfigurationUpdate::Embedded { renormalize: true },
    ] {
        let mut state = State::new(
            [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0],
            [0.0, 0.0, 0.0, 0.0, 0.0, omega],
        );
        let mut rk4 = Rk4 { update };
        for _ in 0..1000 {
            rk4.step(Aba, &model, &mut data, &mut state, dt, &mut NoLoads)
                .unwrap();
        }
        assert!((state.t - t_end).abs() < 1e-12);
        // Gravity is along world z, the spin about body z: the fall is
        // independent of the spin.
        assert!(
            (state.q[2] - exact_z).abs() < 1e-9,
            "{update:?}: z {}",
            state.q[2]
        );
        for (got, exact) in state.q[3..].iter().zip(exact_quat) {
            assert!(
                (got - exact).abs() < 1e-9,
                "{update:?}: quaternion {:?}",
                &state.q[3..]
            );
        }
    }
}
