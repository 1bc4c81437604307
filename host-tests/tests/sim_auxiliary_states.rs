//! Auxiliary first-order states in `rodyn::sim`: a drive with a state of
//! its own (a first-order lag `ż = (u − z) / T` whose output is a joint
//! force), carried by every integrator in `State::z`.
//!
//! The model is a 1 kg slider without gravity. Under a step `u = U` from
//! rest the lag and the slider have the closed form
//! `z = U (1 − e^{−t/T})`, `v = U (t − T (1 − e^{−t/T}))`,
//! `q = U (t²/2 − T t + T² (1 − e^{−t/T}))`.

use rodyn::algorithm::forward_dynamics::{Aba, Crba};
use rodyn::error::Quantity;
use rodyn::prelude::*;
use rodyn::sim::{
    AuxiliaryLoads, ExplicitEuler, ImplicitEuler, Integrator, Rk4, SemiImplicitEuler, State,
};
use rodyn::spatial::Spatial;

/// A 1 kg slider along z, no gravity.
fn slider() -> Model<f64, 1, 1, 1> {
    Model::new(
        [None],
        [Joint::prismatic(Axis::Z)],
        [Transform::IDENTITY],
        [Inertia::point_mass(1.0, Vec3::ZERO)],
        Motion::new(Vec3::ZERO, Vec3::ZERO),
    )
}

/// A lagged force on the slider: `τ = z − k q`, `ż = (u − c v − z) / T`.
/// With `k = c = 0` it is the pure lag of the closed form.
#[derive(Clone, Copy)]
struct LaggedForce {
    /// Lag time constant T (s).
    time_constant: f64,
    /// Input u (N).
    input: f64,
    /// Spring stiffness k (N/m) on the slider.
    stiffness: f64,
    /// Velocity feedback c (N s/m) into the lag's input.
    feedback: f64,
}

impl LaggedForce {
    fn step_input(time_constant: f64, input: f64) -> Self {
        Self {
            time_constant,
            input,
            stiffness: 0.0,
            feedback: 0.0,
        }
    }
}

impl AuxiliaryLoads<f64, 1, 1, 1, 1, Spatial> for LaggedForce {
    fn loads_and_rates(
        &mut self,
        _model: &Model<f64, 1, 1, 1>,
        _data: &mut Data<f64, 1, 1>,
        _t: f64,
        q: &[f64; 1],
        v: &[f64; 1],
        z: &[f64; 1],
        tau: &mut [f64; 1],
        _f_ext: &mut [Force<f64>; 1],
        z_rate: &mut [f64; 1],
    ) -> rodyn::Result<()> {
        tau[0] += z[0] - self.stiffness * q[0];
        z_rate[0] = (self.input - self.feedback * v[0] - z[0]) / self.time_constant;
        Ok(())
    }
}

/// The closed form `(q, v, z)` at time `t` under a step `u = U` from rest.
fn closed_form(time_constant: f64, input: f64, t: f64) -> [f64; 3] {
    let decay = 1.0 - (-t / time_constant).exp();
    [
        input * (0.5 * t * t - time_constant * t + time_constant * time_constant * decay),
        input * (t - time_constant * decay),
        input * decay,
    ]
}

fn run<I: Integrator>(
    mut integrator: I,
    loads: &mut LaggedForce,
    dt: f64,
    duration: f64,
) -> State<f64, 1, 1, 1> {
    let model = slider();
    let mut data = Data::new();
    let mut state = State::with_auxiliary([0.0], [0.0], [0.0]);
    for _ in 0..(duration / dt).round() as usize {
        integrator
            .step(Aba, &model, &mut data, &mut state, dt, loads)
            .expect("the lagged slider steps without error");
    }
    state
}

/// The largest error over `(q, v, z)` after 1 s of a lag with T = 0.1 s
/// and U = 2 N, against the closed form.
fn error_after_one_second<I: Integrator>(integrator: I, dt: f64) -> f64 {
    let mut loads = LaggedForce::step_input(0.1, 2.0);
    let end = run(integrator, &mut loads, dt, 1.0);
    let exact = closed_form(0.1, 2.0, 1.0);
    assert!((end.t - 1.0).abs() < 1e-12, "t = {}", end.t);
    [end.q[0], end.v[0], end.z[0]]
        .iter()
        .zip(exact)
        .map(|(x, e)| (x - e).abs())
        .fold(0.0, f64::max)
}

/// Halving the step from 10 ms to 5 ms and to 2.5 ms: every scheme
/// converges to the closed form at its order, so `z` is integrated by each
/// scheme's own rule and feeds the force. Measured error ratios per
/// halving: 2.00 for explicit, semi-implicit and implicit Euler (errors
/// 1.0e-2, 8.0e-3, 1.0e-2 at 10 ms); RK4 16.7, 16.3 (8.2e-10 at 10 ms,
/// 3.0e-12 at 2.5 ms). A `z` integrated at a lower order than its scheme
/// would pull RK4 down to that order, since `q` and `v` integrate `z`.
#[test]
fn every_scheme_converges_to_the_closed_form_at_its_order() {
    fn ratios<I: Integrator + Copy>(integrator: I) -> [f64; 2] {
        let errors = [1e-2, 5e-3, 2.5e-3].map(|dt| error_after_one_second(integrator, dt));
        [errors[0] / errors[1], errors[1] / errors[2]]
    }
    for (name, pair) in [
        ("explicit Euler", ratios(ExplicitEuler::default())),
        ("semi-implicit Euler", ratios(SemiImplicitEuler::default())),
        ("implicit Euler", ratios(ImplicitEuler::default())),
    ] {
        for ratio in pair {
            assert!(
                (1.9..2.1).contains(&ratio),
                "{name}: halving the step divided the error by {ratio:.3}"
            );
        }
    }
    for ratio in ratios(Rk4::default()) {
        assert!(
            (15.0..18.0).contains(&ratio),
            "RK4: halving the step divided the error by {ratio:.2}"
        );
    }
    // And the errors are small in absolute terms: RK4 at 2.5 ms.
    let rk4 = error_after_one_second(Rk4::default(), 2.5e-3);
    assert!(rk4 < 1e-11, "RK4 at 2.5 ms is {rk4:.2e} off");
}

/// `(I − dt A)⁻¹ x` for the 3 × 3 matrix `I − dt A` by Cramer's rule.
fn backward_euler_step(a: [[f64; 3]; 3], dt: f64, x: [f64; 3]) -> [f64; 3] {
    let m: [[f64; 3]; 3] =
        core::array::from_fn(|r| core::array::from_fn(|c| f64::from(r == c) - dt * a[r][c]));
    let det = |m: &[[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(&m);
    core::array::from_fn(|col| {
        let mut with_x = m;
        for r in 0..3 {
            with_x[r][col] = x[r];
        }
        det(&with_x) / d
    })
}

/// On a linear system the linearly implicit Euler is backward Euler
/// exactly, so one step must match `(I − dt A)⁻¹ x₀` up to the
/// finite-difference Jacobian's rounding. The lag here feeds back the
/// slider's velocity and the slider sits on a spring, so every block of the
/// Jacobian is non-zero: `∂q̈/∂q`, `∂q̈/∂z`, `∂ż/∂v`, `∂ż/∂z` (and `∂ż/∂q`
/// through `x₀`'s velocity term). Measured: equal to within 3e-16
/// (forward differences of a linear function lose almost nothing).
#[test]
fn implicit_euler_takes_the_backward_euler_step_of_a_linear_system() {
    let mut loads = LaggedForce {
        time_constant: 0.02,
        input: 1.5,
        stiffness: 400.0,
        feedback: 30.0,
    };
    // State x = (q, v, z), ẋ = A x + b with b = (0, 0, u / T).
    let (k, c, t_lag, u) = (400.0, 30.0, 0.02, 1.5);
    let a = [
        [0.0, 1.0, 0.0],
        [-k, 0.0, 1.0],
        [0.0, -c / t_lag, -1.0 / t_lag],
    ];
    let dt = 0.05;
    let x0 = [0.01, -0.2, 0.3];
    // Backward Euler: (I − dt A) x₁ = x₀ + dt b.
    let expected = backward_euler_step(a, dt, [x0[0], x0[1], x0[2] + dt * u / t_lag]);
    let model = slider();
    let mut data = Data::new();
    for crba in [false, true] {
        let mut state = State::with_auxiliary([x0[0]], [x0[1]], [x0[2]]);
        let mut implicit = ImplicitEuler::default();
        if crba {
            implicit.step(Crba, &model, &mut data, &mut state, dt, &mut loads)
        } else {
            implicit.step(Aba, &model, &mut data, &mut state, dt, &mut loads)
        }
        .unwrap();
        for (got, want) in [state.q[0], state.v[0], state.z[0]].iter().zip(expected) {
            assert!(
                (got - want).abs() <= 1e-12 * want.abs().max(1.0),
                "implicit Euler gave {got}, backward Euler {want} (crba: {crba})"
            );
        }
    }
}

/// A lag a hundred times faster than the step (T = 0.1 ms, dt = 10 ms):
/// explicit Euler multiplies `z`'s error by |1 − dt/T| = 99 per step, blows
/// up and reports it (measured: the step from t = 1.53 s, after 153 steps,
/// would overflow z); implicit Euler, with `z` in its linearisation,
/// settles on the exact steady state, as it would on a stiff spring.
#[test]
fn implicit_euler_is_stable_on_a_lag_much_faster_than_the_step() {
    let (model, dt) = (slider(), 1e-2);
    let mut data = Data::new();
    let mut loads = LaggedForce::step_input(1e-4, 2.0);
    let mut implicit = State::with_auxiliary([0.0], [0.0], [0.0]);
    for _ in 0..100 {
        ImplicitEuler::default()
            .step(Aba, &model, &mut data, &mut implicit, dt, &mut loads)
            .unwrap();
    }
    assert!((implicit.z[0] - 2.0).abs() < 1e-9, "z = {}", implicit.z[0]);

    let mut explicit = State::with_auxiliary([0.0], [0.0], [0.0]);
    let mut failure = None;
    for _ in 0..1000 {
        let before = explicit;
        if let Err(e) =
            ExplicitEuler::default().step(Aba, &model, &mut data, &mut explicit, dt, &mut loads)
        {
            assert_eq!(explicit, before, "a failed step leaves the state as it was");
            failure = Some(e);
            break;
        }
    }
    let failure = failure.expect("explicit Euler must report the blow-up");
    // The non-finite entry is the lag's state z[0].
    assert_eq!(
        failure,
        Error::NonFinite {
            quantity: Quantity::AuxiliaryState,
            index: 0
        }
    );
    assert!(explicit.t < 2.0, "blew up only at t = {}", explicit.t);
    assert!(explicit.z[0].is_finite() && explicit.q[0].is_finite());
}

/// Loads that fail, or rates that are not finite, part-way through a run:
/// every scheme propagates the error and leaves the state as it was.
#[test]
fn a_failing_step_leaves_the_state_unchanged() {
    /// Normal lag until `fail_after` (s), then NaN rates (`nan`) or an
    /// error from the loads.
    struct FailingLag {
        fail_after: f64,
        nan: bool,
    }
    impl AuxiliaryLoads<f64, 1, 1, 1, 1, Spatial> for FailingLag {
        fn loads_and_rates(
            &mut self,
            _model: &Model<f64, 1, 1, 1>,
            _data: &mut Data<f64, 1, 1>,
            t: f64,
            _q: &[f64; 1],
            _v: &[f64; 1],
            z: &[f64; 1],
            tau: &mut [f64; 1],
            _f_ext: &mut [Force<f64>; 1],
            z_rate: &mut [f64; 1],
        ) -> rodyn::Result<()> {
            tau[0] += z[0];
            if t <= self.fail_after {
                z_rate[0] = 1.0 - z[0];
            } else if self.nan {
                z_rate[0] = f64::NAN;
            } else {
                return Err(LOADS_FAILURE);
            }
            Ok(())
        }
    }
    /// What the failing loads report (a made-up but recognisable error).
    const LOADS_FAILURE: Error = Error::NonFinite {
        quantity: Quantity::ExternalForce,
        index: 0,
    };
    fn check<I: Integrator + Copy>(integrator: I, nan_error: Error) {
        let model = slider();
        let mut data = Data::new();
        for nan in [false, true] {
            let mut loads = FailingLag {
                fail_after: 0.0105,
                nan,
            };
            let mut state = State::with_auxiliary([0.0], [0.0], [0.0]);
            let mut result = Ok(());
            let mut before = state;
            for _ in 0..20 {
                before = state;
                let mut stepper = integrator;
                result = stepper.step(Aba, &model, &mut data, &mut state, 1e-3, &mut loads);
                if result.is_err() {
                    break;
                }
            }
            let name = I::NAME;
            let expected = if nan { nan_error } else { LOADS_FAILURE };
            assert_eq!(result, Err(expected), "{name} (nan: {nan})");
            assert_eq!(state, before, "{name} (nan: {nan}) changed the state");
            assert!(
                state.z[0] > 0.0,
                "{name}: the lag has moved before the failure"
            );
        }
    }
    // A NaN rate is caught where it first shows: by the final check of a
    // one-stage scheme (the auxiliary state z[0]), by the dynamics when
    // RK4's next stage turns it into a NaN force, and by the pivot of the
    // implicit scheme's z block (index NV + 0 = 1).
    let nan_in = |quantity, index| Error::NonFinite { quantity, index };
    check(
        ExplicitEuler::default(),
        nan_in(Quantity::AuxiliaryState, 0),
    );
    check(
        SemiImplicitEuler::default(),
        nan_in(Quantity::AuxiliaryState, 0),
    );
    check(Rk4::default(), nan_in(Quantity::Torque, 0));
    check(ImplicitEuler::default(), nan_in(Quantity::Acceleration, 1));
}

/// Without auxiliary states a `State` is `(t, q, v)` and nothing more.
#[test]
fn a_state_without_auxiliary_states_costs_nothing() {
    assert_eq!(
        core::mem::size_of::<State<f32, 7, 6>>(),
        core::mem::size_of::<[f32; 14]>()
    );
}
