//! The bad inputs of the reliability review (issue 22), tried on the public
//! algorithms, setters, drives, contacts and integrators: each gives `Err`
//! naming what is wrong, never `Ok` with a NaN or an infinity, and never a
//! panic.

use rodyn::algorithm::crba::crba;
use rodyn::algorithm::energy::{kinetic_energy, potential_energy};
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::algorithm::ltdl::{ltdl_factor, ltdl_solve};
use rodyn::algorithm::rnea::{nonlinear_effects, rnea};
use rodyn::drive::{drive_forces, DriveForces, ThelenMuscle};
use rodyn::error::{DriveProblem, ModelProblem, Quantity};
use rodyn::prelude::*;
use rodyn::sim::contact::{GroundContact, NormalLaw};
use rodyn::sim::{ExplicitEuler, Integrator, NoLoads, Rk4, SemiImplicitEuler, State};
use rodyn::Endpoint;
use rodyn_scenarios::muscle_robot::{self as robot, RobotForces};
use rodyn_scenarios::panda;
use std::panic::{catch_unwind, AssertUnwindSafe};

const NV: usize = panda::NV;
const Q: [f64; NV] = [0.1, -0.4, 0.3, -1.8, 0.2, 1.4, 0.6];

/// Runs `f`, fails the test on a panic, and returns its result.
fn no_panic<T>(what: &str, f: impl FnOnce() -> T) -> T {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or_else(|_| panic!("{what} panicked"))
}

/// The result is an error and not `Ok` with a non-finite value.
fn assert_err<T: std::fmt::Debug>(what: &str, result: rodyn::Result<T>) -> Error {
    match result {
        Ok(value) => panic!("{what}: Ok({value:?}) instead of an error"),
        Err(error) => error,
    }
}

#[test]
fn huge_velocities_are_errors_in_every_algorithm() {
    for speed in [1e154, 1e200, f64::MAX] {
        let model = panda::MODEL_F64;
        let mut data = Data::new();
        let v = [speed; NV];
        let zero = [0.0; NV];
        let errors = [
            assert_err(
                "rnea",
                no_panic("rnea", || {
                    rnea(&model, &mut data, &Q, &v, &zero, None).copied()
                }),
            ),
            assert_err(
                "aba",
                no_panic("aba", || {
                    Aba::forward_dynamics(&model, &mut data, &Q, &v, &zero, None).copied()
                }),
            ),
            assert_err(
                "crba fd",
                no_panic("crba fd", || {
                    Crba::forward_dynamics(&model, &mut data, &Q, &v, &zero, None).copied()
                }),
            ),
            assert_err(
                "nle",
                no_panic("nle", || {
                    nonlinear_effects(&model, &mut data, &Q, &v, None).copied()
                }),
            ),
            assert_err(
                "kinetic energy",
                no_panic("ke", || kinetic_energy(&model, &mut data, &Q, &v)),
            ),
        ];
        for error in errors {
            assert!(
                matches!(
                    error,
                    Error::NonFiniteResult { .. } | Error::MassMatrixNotPositiveDefinite { .. }
                ),
                "{speed:e}: {error:?}"
            );
        }
    }
}

#[test]
fn huge_f32_velocities_and_torques_are_errors() {
    let model = panda::MODEL_F32;
    let mut data = Data::new();
    let q = Q.map(|x| x as f32);
    let zero = [0.0_f32; NV];
    let v = [1e19_f32; NV];
    assert_err(
        "rnea f32",
        rnea(&model, &mut data, &q, &v, &zero, None).copied(),
    );
    assert_err(
        "aba f32",
        Aba::forward_dynamics(&model, &mut data, &q, &v, &zero, None).copied(),
    );
    assert_err(
        "crba fd f32",
        Crba::forward_dynamics(&model, &mut data, &q, &v, &zero, None).copied(),
    );
    assert_err(
        "nle f32",
        nonlinear_effects(&model, &mut data, &q, &v, None).copied(),
    );
    assert_eq!(
        kinetic_energy(&model, &mut data, &q, &v),
        Err(Error::NonFiniteResult {
            quantity: Quantity::Energy,
            index: 0
        })
    );
    let tau = [1e37_f32; NV];
    assert_err(
        "aba f32 torque",
        Aba::forward_dynamics(&model, &mut data, &q, &zero, &tau, None).copied(),
    );
    assert_err(
        "crba f32 torque",
        Crba::forward_dynamics(&model, &mut data, &q, &zero, &tau, None).copied(),
    );
}

#[test]
fn setters_refuse_out_of_range_indices_without_panicking() {
    let mut model = panda::MODEL_F64;
    let inertia = *model.inertia(0);
    let placement = *model.placement(0);
    let error = no_panic("set_inertia", || model.set_inertia(panda::NB, inertia)).unwrap_err();
    assert_eq!(error, Error::BodyOutOfRange { body: panda::NB });
    let error = no_panic("set_placement", || model.set_placement(99, placement)).unwrap_err();
    assert_eq!(error, Error::BodyOutOfRange { body: 99 });
    assert!(error.to_string().contains("body 99"), "{error}");
}

#[test]
fn setters_name_what_is_wrong() {
    let mut model = panda::MODEL_F64;
    let invalid = |problem| Error::InvalidModel { body: 2, problem };
    let base = *model.inertia(2);

    // A centre of mass whose m |c|² overflows.
    let far = Inertia::new(base.mass, Vec3::new(1e200, 0.0, 0.0), base.rot_inertia);
    assert_eq!(
        model.set_inertia(2, far),
        Err(invalid(ModelProblem::Overflow))
    );
    // NaN is a non-finite parameter, not a bad mass.
    let nan = Inertia::new(base.mass, Vec3::new(f64::NAN, 0.0, 0.0), base.rot_inertia);
    assert_eq!(
        model.set_inertia(2, nan),
        Err(invalid(ModelProblem::NonFiniteParameter))
    );
    // Entries of 1.77e308 no longer overflow the eigenvalue test into a pass.
    let huge = Inertia::new(
        1.0,
        Vec3::ZERO,
        Sym3::diagonal(1.77e308, 1.77e308, 1.77e308),
    );
    assert!(model.set_inertia(2, huge).is_err());
    let huge_off = Inertia::new(
        1.0,
        Vec3::ZERO,
        Sym3::new(1.0, 1.77e308, 0.0, 1.0, 0.0, 1.0),
    );
    assert_eq!(
        model.set_inertia(2, huge_off),
        Err(invalid(ModelProblem::InvalidInertia))
    );
    // A mass of 1e300 kg: m² overflows in ABA's U Uᵀ; the setter names
    // the body instead of ABA reporting a singular joint 0.
    let heavy = Inertia::new(1e300, base.com, base.rot_inertia);
    assert_eq!(
        model.set_inertia(2, heavy),
        Err(invalid(ModelProblem::Overflow))
    );
    assert_eq!(
        *model.inertia(2),
        base,
        "a refused inertia leaves the model unchanged"
    );

    // A reflection: orthonormal, determinant -1.
    let mut reflection = *model.placement(2);
    reflection.rot = Mat3::from_rows([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]]);
    assert_eq!(
        model.set_placement(2, reflection),
        Err(invalid(ModelProblem::Reflection))
    );
    let mut nan_placement = *model.placement(2);
    nan_placement.trans.x = f64::NAN;
    assert_eq!(
        model.set_placement(2, nan_placement),
        Err(invalid(ModelProblem::NonFiniteParameter))
    );

    // A placement 1e300 m away: its |p|⁴ overflows, so the setter names the
    // body (ABA would read the overflow as a singular joint).
    let mut far_placement = *model.placement(2);
    far_placement.trans.x = 1e300;
    assert_eq!(
        model.set_placement(2, far_placement),
        Err(invalid(ModelProblem::Overflow))
    );
    // Just inside that bound (1e76 m) the placement is accepted, and every
    // algorithm returns a finite result, names an overflow, or reports the
    // mass matrix or an articulated inertia as numerically singular (its
    // pivots span more than 1e150): a true cause at that scale.
    far_placement.trans.x = 1e76;
    model.set_placement(2, far_placement).unwrap();
    let mut data = Data::new();
    let v = [1.0; NV];
    let zero = [0.0; NV];
    for (what, result) in [
        (
            "rnea far",
            rnea(&model, &mut data, &Q, &v, &zero, None).map(|t| t.to_vec()),
        ),
        (
            "kinetic energy far",
            kinetic_energy(&model, &mut data, &Q, &v).map(|e| vec![e]),
        ),
        (
            "crba fd far",
            Crba::forward_dynamics(&model, &mut data, &Q, &v, &zero, None).map(|a| a.to_vec()),
        ),
        (
            "aba far",
            Aba::forward_dynamics(&model, &mut data, &Q, &v, &zero, None).map(|a| a.to_vec()),
        ),
        (
            "nle far",
            nonlinear_effects(&model, &mut data, &Q, &v, None).map(|t| t.to_vec()),
        ),
        (
            "crba far",
            crba(&model, &mut data, &Q).map(|m| m.iter().flatten().copied().collect()),
        ),
    ] {
        match result {
            Ok(values) => assert!(values.iter().all(|x| x.is_finite()), "{what}: {values:?}"),
            Err(error) => assert!(
                match error {
                    Error::NonFiniteResult { .. } => true,
                    Error::MassMatrixNotPositiveDefinite { relative_pivot, .. } =>
                        relative_pivot.is_finite(),
                    Error::SingularArticulatedInertia { relative_pivot, .. } => {
                        relative_pivot.is_finite()
                    }
                    _ => false,
                },
                "{what}: {error:?}"
            ),
        }
    }
    // Bodies of 1e100 and 1e150 kg among 1 kg ones are accepted (m² is
    // finite): RNEA stays finite, and the mass ratio makes the mass matrix
    // and joint 0's articulated inertia numerically singular, which
    // forward dynamics reports as such with a finite relative pivot.
    let mut heavy_model = panda::MODEL_F64;
    for mass in [1e100, 1e150] {
        let heavy = Inertia::new(mass, base.com, base.rot_inertia);
        heavy_model.set_inertia(2, heavy).unwrap();
        let tau = rnea(&heavy_model, &mut data, &Q, &v, &zero, None).unwrap();
        assert!(tau.iter().all(|t| t.is_finite()), "{mass} kg: {tau:?}");
        match Aba::forward_dynamics(&heavy_model, &mut data, &Q, &v, &zero, None) {
            Ok(a) => assert!(a.iter().all(|x| x.is_finite())),
            Err(Error::SingularArticulatedInertia { relative_pivot, .. }) => {
                assert!(relative_pivot.is_finite() && relative_pivot < 1e-12);
            }
            Err(other) => panic!("aba, {mass} kg: {other:?}"),
        }
        match Crba::forward_dynamics(&heavy_model, &mut data, &Q, &v, &zero, None) {
            Ok(a) => assert!(a.iter().all(|x| x.is_finite())),
            Err(Error::MassMatrixNotPositiveDefinite { relative_pivot, .. }) => {
                assert!(relative_pivot.is_finite() && relative_pivot < 1e-12);
            }
            Err(other) => panic!("crba fd, {mass} kg: {other:?}"),
        }
    }
    {
        let mut model = panda::MODEL_F64;
        let mut data = Data::new();
        for mass in [1e100, 1e150, 1e154] {
            let heavy = Inertia::new(mass, base.com, base.rot_inertia);
            let set = model.set_inertia(2, heavy);
            println!("mass {mass}: {set:?}");
            if set.is_ok() {
                println!(
                    "  aba {:?}",
                    Aba::forward_dynamics(&model, &mut data, &Q, &v, &zero, None).map(|a| a[0])
                );
                println!(
                    "  crbafd {:?}",
                    Crba::forward_dynamics(&model, &mut data, &Q, &v, &zero, None).map(|a| a[0])
                );
                println!(
                    "  rnea {:?}",
                    rnea(&model, &mut data, &Q, &v, &zero, None).map(|a| a[0])
                );
            }
        }
    }
    // The potential energy stays finite there (m g z of about 1e301 J):
    // whatever is returned is finite or an error.
    match potential_energy(&model, &mut data, &Q) {
        Ok(energy) => assert!(energy.is_finite(), "{energy}"),
        Err(error) => assert!(matches!(error, Error::NonFiniteResult { .. }), "{error:?}"),
    }
}

#[test]
fn ltdl_solve_refuses_a_nan_right_hand_side() {
    let model = panda::MODEL_F64;
    let mut data = Data::new();
    crba(&model, &mut data, &Q).unwrap();
    ltdl_factor(&model, &mut data).unwrap();
    let mut b = [1.0; NV];
    b[3] = f64::NAN;
    let error = ltdl_solve(&model, &data, &mut b).unwrap_err();
    assert_eq!(
        error,
        Error::NonFinite {
            quantity: Quantity::Acceleration,
            index: 3
        }
    );
}

#[test]
fn integrators_refuse_a_nan_time_or_step() {
    let model = panda::MODEL_F64;
    let mut data = Data::new();
    for (t, dt) in [(f64::NAN, 1e-3), (0.0, f64::NAN), (f64::INFINITY, 1e-3)] {
        let start = State::new(Q, [0.0; NV]);
        let mut state = State { t, ..start };
        let before = state;
        let results = [
            ExplicitEuler::default().step(Aba, &model, &mut data, &mut state, dt, &mut NoLoads),
            SemiImplicitEuler::default().step(Aba, &model, &mut data, &mut state, dt, &mut NoLoads),
            Rk4::default().step(Aba, &model, &mut data, &mut state, dt, &mut NoLoads),
        ];
        for result in results {
            assert_eq!(
                result,
                Err(Error::NonFinite {
                    quantity: Quantity::Time,
                    index: 0
                }),
                "t {t}, dt {dt}"
            );
        }
        assert!(
            state.q == before.q && state.v == before.v,
            "a failed step leaves the state"
        );
    }
}

#[test]
fn drives_refuse_nan_inputs_and_bad_muscle_parameters() {
    let model = robot::MODEL_F64;
    let mut data = Data::new();
    let mut forces = RobotForces::new();
    let (q, v) = ([0.3, 0.5], [0.1, -0.2]);
    let muscles = robot::MUSCLES_F64;
    let error = drive_forces(
        &model,
        &mut data,
        &q,
        &v,
        &muscles,
        &[0.2, f64::NAN, 0.1, 0.1],
        &mut forces,
    )
    .unwrap_err();
    assert_eq!(
        error,
        Error::NonFinite {
            quantity: Quantity::DriveInput,
            index: 1
        }
    );

    // Bad parameters: `validate` names the field; the forces of a law they
    // break are an error, not NaN.
    for (field, value) in [(1, 0.0), (4, 0.0), (5, -0.01), (11, 0.5)] {
        let mut bad: [ThelenMuscle<f64, _, 3>; 4] = muscles;
        let p = &mut bad[2].params;
        match field {
            1 => p.optimal_fiber_length = value,
            4 => p.max_contraction_velocity = value,
            5 => p.activation_time_constant = value,
            _ => p.max_lengthening_force = value,
        }
        assert_eq!(
            bad[2].params.validate(),
            Err(Error::InvalidDrive {
                problem: DriveProblem::MuscleParameter { index: field }
            })
        );
        let forces_result = drive_forces(&model, &mut data, &q, &v, &bad, &[0.2; 4], &mut forces);
        if field == 1 || field == 4 {
            let error = forces_result.unwrap_err();
            assert!(matches!(error, Error::NonFiniteResult { .. }), "{error:?}");
        }
    }

    // A motor's NaN current.
    let panda_model = panda::MODEL_F64;
    let mut panda_data = Data::new();
    let mut motor_forces: DriveForces<f64, Spatial, { panda::NB }, NV> = DriveForces::new();
    let motors = [panda::MOTOR1_F64];
    let error = drive_forces(
        &panda_model,
        &mut panda_data,
        &Q,
        &[0.0; NV],
        &motors,
        &[f64::NAN; 7],
        &mut motor_forces,
    )
    .unwrap_err();
    assert!(
        matches!(
            error,
            Error::NonFinite {
                quantity: Quantity::DriveInput,
                ..
            }
        ),
        "{error:?}"
    );
}

#[test]
fn ground_contact_refuses_nan_and_missing_bodies() {
    let model = panda::MODEL_F64;
    let mut data = Data::new();
    let mut f_ext = [Force::ZERO; panda::NB];
    let good = GroundContact {
        normal: NormalLaw::LinearSpringDamper {
            stiffness: 1e4,
            damping: 50.0,
        },
        friction: 0.8,
        slip_scale: 0.01,
    };
    // A NaN height is not "no contact"; a NaN slip velocity is named too.
    assert_eq!(
        good.force_at(&Vec3::new(0.0, 0.0, f64::NAN), &Vec3::ZERO),
        Err(Error::NonFinite {
            quantity: Quantity::ContactPoint,
            index: 2
        })
    );
    assert_eq!(
        good.force_at(&Vec3::new(0.0, 0.0, -0.01), &Vec3::new(f64::NAN, 0.0, 0.0)),
        Err(Error::NonFinite {
            quantity: Quantity::ContactPoint,
            index: 3
        })
    );
    let nan_stiffness = GroundContact {
        normal: NormalLaw::LinearSpringDamper {
            stiffness: f64::NAN,
            damping: 50.0,
        },
        ..good
    };
    assert_eq!(
        nan_stiffness.force_at(&Vec3::new(0.0, 0.0, -0.01), &Vec3::ZERO),
        Err(Error::NonFinite {
            quantity: Quantity::Contact,
            index: 0
        })
    );
    // Finite, but k δ overflows.
    assert_eq!(
        good.force_at(&Vec3::new(0.0, 0.0, -1e305), &Vec3::ZERO),
        Err(Error::NonFiniteResult {
            quantity: Quantity::Contact,
            index: 0
        })
    );

    let on_body = |body| [Endpoint::on_body(body, Vec3::new(0.0, 0.0, -2.0))];
    let v = [0.0; NV];
    let error = no_panic("contact on a missing body", || {
        good.add_forces(
            &model,
            &mut data,
            &Q,
            &v,
            &on_body(panda::NB),
            &mut f_ext,
            None,
        )
    })
    .unwrap_err();
    assert_eq!(error, Error::BodyOutOfRange { body: panda::NB });

    let nan_point = [Endpoint::on_body(6, Vec3::new(f64::NAN, 0.0, 0.0))];
    let error = good
        .add_forces(&model, &mut data, &Q, &v, &nan_point, &mut f_ext, None)
        .unwrap_err();
    assert_eq!(
        error,
        Error::NonFinite {
            quantity: Quantity::Contact,
            index: 0
        }
    );

    for (bad, index) in [
        (
            GroundContact {
                friction: f64::NAN,
                ..good
            },
            2,
        ),
        (
            GroundContact {
                slip_scale: 0.0,
                ..good
            },
            3,
        ),
        (
            GroundContact {
                normal: NormalLaw::HuntCrossley {
                    stiffness: f64::NAN,
                    damping: 1.0,
                },
                ..good
            },
            0,
        ),
    ] {
        let error = bad
            .add_forces(&model, &mut data, &Q, &v, &on_body(6), &mut f_ext, None)
            .unwrap_err();
        assert_eq!(
            error,
            Error::NonFinite {
                quantity: Quantity::Contact,
                index
            }
        );
    }
    good.add_forces(&model, &mut data, &Q, &v, &on_body(6), &mut f_ext, None)
        .expect("finite inputs are accepted");
}

/// `Model::normalize` turns a quaternion whose squared norm overflows
/// (1e200) or underflows (subnormal) into the unit quaternion it stands
/// for, not into zeros; a zero or NaN quaternion is an error naming the
/// joint, and `q` is left as it was.
#[test]
fn normalize_survives_huge_and_subnormal_quaternions() {
    use rodyn::joint::ConfigurationError;
    for scale in [1e200, 1e-310, 1.0] {
        let mut q = [0.1, 0.2, 0.3, 0.0, 0.6 * scale, 0.0, 0.8 * scale];
        BALL.normalize(&mut q).unwrap();
        // A subnormal input holds only about 13 significant digits.
        assert!(
            (q[4] - 0.6).abs() < 1e-12 && (q[6] - 0.8).abs() < 1e-12,
            "{scale:e}: {q:?}"
        );
        let norm = (q[4] * q[4] + q[6] * q[6]).sqrt();
        assert!((norm - 1.0).abs() < 1e-15, "{scale:e}: norm {norm}");
        assert_eq!(q[..3], [0.1, 0.2, 0.3]);
    }
    let mut zero = [0.0; 7];
    assert_eq!(
        BALL.normalize(&mut zero),
        Err(Error::InvalidConfiguration {
            joint: 0,
            reason: ConfigurationError::QuaternionNotUnit { norm: 0.0 }
        })
    );
    assert_eq!(zero, [0.0; 7]);
    let mut nan = [0.0, 0.0, 0.0, 0.0, 0.0, f64::NAN, 1.0];
    assert_eq!(
        BALL.normalize(&mut nan),
        Err(Error::InvalidConfiguration {
            joint: 0,
            reason: ConfigurationError::NonFinite
        })
    );
}

/// One free-floating 1 kg ball.
const BALL: Model<f64, 1, 7, 6> = Model::new(
    [None],
    [rodyn::joint::Joint::FreeFlyer(rodyn::joint::FreeFlyer)],
    [Transform::IDENTITY],
    [Inertia::point_mass(1.0, Vec3::ZERO)],
    Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
);

/// `Model::integrate` names a non-finite input, reports finite inputs
/// that overflow, and refuses a zero quaternion it cannot move.
#[test]
fn integrate_names_bad_inputs_and_overflow() {
    use rodyn::joint::ConfigurationError;
    let q0 = BALL.neutral_configuration();
    let v = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
    assert!(BALL.integrate(&q0, &v, 1e-3).is_ok());
    let mut nan_q = q0;
    nan_q[1] = f64::NAN;
    let mut nan_v = v;
    nan_v[4] = f64::NAN;
    for (result, quantity, index) in [
        (BALL.integrate(&nan_q, &v, 1e-3), Quantity::Configuration, 1),
        (BALL.integrate(&q0, &nan_v, 1e-3), Quantity::Velocity, 4),
        (BALL.integrate(&q0, &v, f64::NAN), Quantity::Time, 0),
        (BALL.integrate(&q0, &v, f64::INFINITY), Quantity::Time, 0),
    ] {
        assert_eq!(result, Err(Error::NonFinite { quantity, index }));
    }
    // Finite, but ω × ρ overflows.
    let error = BALL.integrate(&q0, &[1e200; 6], 1.0).unwrap_err();
    assert!(
        matches!(
            error,
            Error::NonFiniteResult {
                quantity: Quantity::Configuration,
                ..
            }
        ),
        "{error:?}"
    );
    // A revolute angle that overflows.
    let model = panda::MODEL_F64;
    assert_eq!(
        model.integrate(&Q, &[1e308; NV], 10.0),
        Err(Error::NonFiniteResult {
            quantity: Quantity::Configuration,
            index: 0
        })
    );
    let mut zero = q0;
    zero[6] = 0.0;
    assert_eq!(
        BALL.integrate(&zero, &v, 1e-3),
        Err(Error::InvalidConfiguration {
            joint: 0,
            reason: ConfigurationError::QuaternionNotUnit { norm: 0.0 }
        })
    );
}

/// The Thelen muscle's own API: a NaN length is no longer a short path
/// with a finite 22.65 N, and a 10 m path is no longer 4e236 N.
#[test]
fn muscle_state_names_bad_inputs_and_refuses_absurd_lengths() {
    use rodyn::drive::muscle::MAX_NORMALIZED_FIBER_LENGTH;
    let muscle = robot::MUSCLES_F64[2];
    let input = muscle.input;
    let p = muscle.params;
    let optimal = p.tendon_slack_length + p.optimal_fiber_length;
    assert!(muscle.state(optimal, 0.1, 0.5).is_ok());
    let nan = |quantity| Error::NonFinite {
        quantity,
        index: input,
    };
    for (result, expected) in [
        (muscle.state(f64::NAN, 0.0, 0.5), nan(Quantity::PathLength)),
        (
            muscle.state(optimal, f64::NAN, 0.5),
            nan(Quantity::PathVelocity),
        ),
        (
            muscle.state(optimal, f64::INFINITY, 0.5),
            nan(Quantity::PathVelocity),
        ),
        (
            muscle.state(optimal, 0.0, f64::NAN),
            nan(Quantity::DriveInput),
        ),
    ] {
        assert_eq!(result, Err(expected));
    }
    let too_long = Error::OutOfRange {
        quantity: Quantity::PathLength,
        index: input,
    };
    // Just inside and just past the range, a 10 m path and one whose
    // square overflows.
    let longest = p.tendon_slack_length + MAX_NORMALIZED_FIBER_LENGTH * p.optimal_fiber_length;
    let inside = muscle.state(longest - 1e-9, 0.0, 1.0).unwrap();
    assert!(inside.tension.is_finite() && inside.tension < 20.0 * p.max_isometric_force);
    for length in [longest + 1e-9, 10.0, 1e200, f64::MAX] {
        assert_eq!(muscle.state(length, 0.0, 0.5), Err(too_long), "{length}");
        assert_eq!(
            muscle.tension_partials(length, 0.0, 0.5),
            Err(too_long),
            "{length}"
        );
    }
    assert_eq!(
        muscle.tension_partials(f64::NAN, 0.0, 0.5),
        Err(nan(Quantity::PathLength))
    );
    // A huge but finite velocity stays on the bounded force-velocity curve.
    let fast = muscle.state(optimal, 1e300, 1.0).unwrap();
    assert!(fast.tension.is_finite(), "{fast:?}");
    // Run-time parameters that break the force law: a non-finite tension
    // is an error on the direct API too.
    let mut broken = muscle;
    broken.params.max_contraction_velocity = 0.0;
    assert_eq!(
        broken.state(optimal, 0.1, 0.5),
        Err(Error::NonFiniteResult {
            quantity: Quantity::ExternalForce,
            index: input
        })
    );
}

/// Gravity: a NaN is refused by the setter; a finite but huge one is
/// reported by the algorithms as an overflow.
#[test]
fn gravity_setter_and_huge_gravity() {
    let mut model = panda::MODEL_F64;
    let mut data = Data::new();
    let nan = Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, f64::NAN));
    assert_eq!(
        model.set_gravity(nan),
        Err(Error::NonFinite {
            quantity: Quantity::ModelParameter,
            index: 0
        })
    );
    model
        .set_gravity(Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1e308)))
        .unwrap();
    let (v, zero) = ([1.0; NV], [0.0; NV]);
    for (what, result) in [
        (
            "rnea",
            rnea(&model, &mut data, &Q, &v, &zero, None).map(|t| t.to_vec()),
        ),
        (
            "aba",
            Aba::forward_dynamics(&model, &mut data, &Q, &v, &zero, None).map(|a| a.to_vec()),
        ),
        (
            "crba fd",
            Crba::forward_dynamics(&model, &mut data, &Q, &v, &zero, None).map(|a| a.to_vec()),
        ),
        (
            "potential energy",
            potential_energy(&model, &mut data, &Q).map(|e| vec![e]),
        ),
    ] {
        let error = assert_err(what, no_panic(what, || result));
        assert!(
            matches!(error, Error::NonFiniteResult { .. }),
            "{what}: {error:?}"
        );
    }
}

/// Ground contact: a NaN joint velocity and a NaN damping are named.
#[test]
fn ground_contact_names_nan_velocity_and_damping() {
    let model = panda::MODEL_F64;
    let mut data = Data::new();
    let mut f_ext = [Force::ZERO; panda::NB];
    let good = GroundContact {
        normal: NormalLaw::LinearSpringDamper {
            stiffness: 1e4,
            damping: 50.0,
        },
        friction: 0.8,
        slip_scale: 0.01,
    };
    let points = [Endpoint::on_body(6, Vec3::new(0.0, 0.0, -2.0))];
    let mut v = [0.0; NV];
    v[2] = f64::NAN;
    assert_eq!(
        good.add_forces(&model, &mut data, &Q, &v, &points, &mut f_ext, None),
        Err(Error::NonFinite {
            quantity: Quantity::Velocity,
            index: 2
        })
    );
    let nan_damping = GroundContact {
        normal: NormalLaw::LinearSpringDamper {
            stiffness: 1e4,
            damping: f64::NAN,
        },
        ..good
    };
    assert_eq!(
        nan_damping.add_forces(&model, &mut data, &Q, &[0.0; NV], &points, &mut f_ext, None),
        Err(Error::NonFinite {
            quantity: Quantity::Contact,
            index: 1
        })
    );
}
