//! Joint motors: torque from current through the gearbox, and the rotor's
//! reflected inertia as the model's armature in CRBA, ABA, RNEA and the
//! kinetic energy.

// Row and column indices mirror the matrix equations being checked.
#![allow(clippy::needless_range_loop)]

use rodyn::algorithm::crba::crba;
use rodyn::algorithm::energy::kinetic_energy;
use rodyn::algorithm::forward_dynamics::{Aba, Crba};
use rodyn::algorithm::rnea::rnea;
use rodyn::drive::{forward_dynamics_with_drives, DriveForces, JointMotor};
use rodyn::error::DriveProblem;
use rodyn::prelude::*;
use rodyn::sensitivity::forward_dynamics_and_sensitivity;
use rodyn::Error;

/// A 100:1 gearbox, 0.05 N m/A, 2e-5 kg m² rotor: 0.2 kg m² reflected.
const MOTOR: JointMotor<f64> = JointMotor::new(0, 0, 100.0, 0.05, 2e-5);

fn arm() -> Model<f64, 3, 3, 3> {
    let link = |m: f64| {
        Inertia::new(
            m,
            Vec3::new(0.2, 0.0, 0.0),
            Sym3::diagonal(0.002, 0.01, 0.01),
        )
    };
    Model::new(
        [None, Some(0), Some(1)],
        [
            Joint::revolute(Axis::Z),
            Joint::revolute(Axis::Y),
            Joint::revolute(Axis::Z),
        ],
        [
            Transform::IDENTITY,
            Transform::from_translation(Vec3::new(0.4, 0.0, 0.0)),
            Transform::from_translation(Vec3::new(0.4, 0.0, 0.05)),
        ],
        [link(2.0), link(1.5), link(0.5)],
        Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
    )
}

#[test]
fn motor_torque_and_reflected_inertia() {
    assert_eq!(MOTOR.torque_per_current().unwrap(), 5.0);
    approx::assert_relative_eq!(
        MOTOR.reflected_inertia().unwrap(),
        0.2,
        max_relative = 1e-15
    );
    // One link about z, 1 kg at 0.5 m (0.25 kg m²), no gravity: with the
    // rotor, q̈ = N k_t i / (0.25 + N² J_r).
    let mut model: Model<f64, 1, 1, 1> = Model::new(
        [None],
        [Joint::revolute(Axis::Z)],
        [Transform::IDENTITY],
        [Inertia::point_mass(1.0, Vec3::new(0.5, 0.0, 0.0))],
        Motion::ZERO,
    );
    model
        .set_armature(0, MOTOR.reflected_inertia().unwrap())
        .unwrap();
    let mut forces = DriveForces::new();
    for current in [-2.0, 0.5, 3.0] {
        let expected = 5.0 * current / (0.25 + 0.2);
        for ddq in [
            forward_dynamics_with_drives::<Aba, _, _, _, 1, 1, 1>(
                &model,
                &mut Data::new(),
                &[0.3],
                &[1.0],
                &[0.0],
                &MOTOR,
                &[current],
                &mut forces,
            )
            .unwrap()[0],
            forward_dynamics_with_drives::<Crba, _, _, _, 1, 1, 1>(
                &model,
                &mut Data::new(),
                &[0.3],
                &[1.0],
                &[0.0],
                &MOTOR,
                &[current],
                &mut forces,
            )
            .unwrap()[0],
        ] {
            approx::assert_relative_eq!(ddq, expected, max_relative = 1e-14);
        }
        assert_eq!(forces.tau[0], 5.0 * current);
    }
}

#[test]
fn armature_enters_every_algorithm_consistently() {
    let plain = arm();
    let armature = [0.2, 0.05, 0.01];
    let model = plain.with_armature(armature);
    let (q, v, a) = ([0.3, -0.6, 1.1], [0.4, -1.2, 0.7], [1.5, -0.3, 2.0]);
    // CRBA: M changes by the armature on the diagonal, nowhere else.
    let m0 = *crba(&plain, &mut Data::new(), &q).unwrap();
    let m1 = *crba(&model, &mut Data::new(), &q).unwrap();
    for r in 0..3 {
        for c in 0..3 {
            let added = if r == c { armature[r] } else { 0.0 };
            approx::assert_relative_eq!(m1[r][c] - m0[r][c], added, epsilon = 1e-15);
        }
    }
    // RNEA adds armature · a; ABA and CRBA invert it.
    let tau0 = *rnea(&plain, &mut Data::new(), &q, &v, &a, None).unwrap();
    let tau = *rnea(&model, &mut Data::new(), &q, &v, &a, None).unwrap();
    for k in 0..3 {
        approx::assert_relative_eq!(tau[k] - tau0[k], armature[k] * a[k], epsilon = 1e-12);
    }
    use rodyn::algorithm::forward_dynamics::ForwardDynamics;
    let by_aba = *Aba::forward_dynamics(&model, &mut Data::new(), &q, &v, &tau, None).unwrap();
    let by_crba = *Crba::forward_dynamics(&model, &mut Data::new(), &q, &v, &tau, None).unwrap();
    for k in 0..3 {
        approx::assert_relative_eq!(by_aba[k], a[k], epsilon = 1e-10);
        approx::assert_relative_eq!(by_crba[k], a[k], epsilon = 1e-10);
    }
    // Kinetic energy = ½ vᵀ M v with the armature included.
    let ke = kinetic_energy(&model, &mut Data::new(), &q, &v).unwrap();
    let quad: f64 = (0..3)
        .map(|r| (0..3).map(|c| v[r] * m1[r][c] * v[c]).sum::<f64>())
        .sum();
    approx::assert_relative_eq!(ke, 0.5 * quad, max_relative = 1e-13);
}

#[test]
fn motor_sensitivity_is_the_inverse_mass_matrix_column_times_torque_per_amp() {
    let motors = [
        JointMotor::new(0, 0, 100.0, 0.05, 2e-5),
        JointMotor::new(1, 1, 80.0, 0.04, 1e-5),
        JointMotor::new(2, 2, 50.0, 0.02, 1e-5),
    ];
    let mut model = arm();
    for m in &motors {
        model
            .set_armature(m.dof, m.reflected_inertia().unwrap())
            .unwrap();
    }
    let (q, v) = ([0.3, -0.6, 1.1], [0.4, -1.2, 0.7]);
    let mut s = [[0.0; 3]; 3];
    let mut data = Data::new();
    forward_dynamics_and_sensitivity(
        &model,
        &mut data,
        &q,
        &v,
        &[0.0; 3],
        &motors,
        &[1.0, -1.0, 0.5],
        &mut DriveForces::new(),
        &mut s,
    )
    .unwrap();
    // M S = diag(N k_t): check M times the sensitivity matrix.
    let m = *crba(&model, &mut Data::new(), &q).unwrap();
    for r in 0..3 {
        for c in 0..3 {
            let ms: f64 = (0..3).map(|k| m[r][k] * s[k][c]).sum();
            let expected = if r == c {
                motors[r].torque_per_current().unwrap()
            } else {
                0.0
            };
            approx::assert_relative_eq!(ms, expected, epsilon = 1e-11);
        }
    }
}

#[test]
fn bad_indices_are_reported() {
    let model = arm();
    let mut forces = DriveForces::new();
    let far = JointMotor::new(5, 0, 1.0, 1.0, 0.0);
    assert_eq!(
        forward_dynamics_with_drives::<Aba, _, _, _, 3, 3, 3>(
            &model,
            &mut Data::new(),
            &[0.0; 3],
            &[0.0; 3],
            &[0.0; 3],
            &far,
            &[1.0],
            &mut forces,
        )
        .unwrap_err(),
        Error::InvalidDrive {
            problem: DriveProblem::DofOutOfRange { dof: 5 }
        }
    );
    let missing_input = JointMotor::new(0, 3, 1.0, 1.0, 0.0);
    assert_eq!(
        forward_dynamics_with_drives::<Aba, _, _, _, 3, 3, 3>(
            &model,
            &mut Data::new(),
            &[0.0; 3],
            &[0.0; 3],
            &[0.0; 3],
            &missing_input,
            &[1.0],
            &mut forces,
        )
        .unwrap_err(),
        Error::InvalidDrive {
            problem: DriveProblem::InputOutOfRange { input: 3 }
        }
    );
    let mut m = model;
    assert!(m.set_armature(3, 0.1).is_err());
    assert!(m.set_armature(0, -0.1).is_err());
    assert!(m.set_armature(0, f64::NAN).is_err());
}

/// ABA skips the row and column a coordinate-axis revolute joint projects
/// out only when that joint has no armature; with armature on some joints
/// and not on others, both paths run in one call and must still invert RNEA.
#[test]
fn armature_on_some_joints_only_keeps_aba_the_inverse_of_rnea() {
    use rodyn::algorithm::forward_dynamics::ForwardDynamics;
    let (q, v, a) = ([0.3, -0.6, 1.1], [0.4, -1.2, 0.7], [1.5, -0.3, 2.0]);
    for armature in [[0.0, 0.05, 0.0], [0.2, 0.0, 0.01], [0.0, 0.0, 0.0]] {
        let model = arm().with_armature(armature);
        let tau = *rnea(&model, &mut Data::new(), &q, &v, &a, None).unwrap();
        let by_aba = *Aba::forward_dynamics(&model, &mut Data::new(), &q, &v, &tau, None).unwrap();
        let by_crba =
            *Crba::forward_dynamics(&model, &mut Data::new(), &q, &v, &tau, None).unwrap();
        for k in 0..3 {
            approx::assert_relative_eq!(by_aba[k], a[k], epsilon = 1e-12);
            approx::assert_relative_eq!(by_aba[k], by_crba[k], epsilon = 1e-12);
        }
    }
}
