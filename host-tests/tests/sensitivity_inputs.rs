//! ∂q̈/∂w, the sensitivity of the joint accelerations to the drive inputs,
//! against central finite differences, the dual-number route and an
//! independent mass-matrix route (CRBA + RNEA).

// Row and column indices mirror the matrix equations being checked.
#![allow(clippy::needless_range_loop)]

use rodyn::algorithm::crba::crba;
use rodyn::algorithm::forward_dynamics::{Aba, Crba};
use rodyn::algorithm::rnea::rnea;
use rodyn::drive::{
    forward_dynamics_with_drives, DriveForces, JointMotor, LinearSpring, Path, ThelenMuscle,
    ThelenParameters,
};
use rodyn::prelude::*;
use rodyn::sensitivity::forward_dynamics_and_sensitivity;
use rodyn::Endpoint;
use rodyn_scenarios::muscle_robot::{self as robot, NU, NV};

struct Rng(u64);
impl Rng {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let x = (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * x
    }
}

/// Random states of the muscle robot with activations inside (0, 1).
fn robot_states(n: usize) -> Vec<([f64; NV], [f64; NV], [f64; NU])> {
    let mut rng = Rng(0xDEAD_BEEF_1234_5678);
    (0..n)
        .map(|_| {
            (
                [rng.uniform(-0.8, 1.2), rng.uniform(-0.5, 1.8)],
                [rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)],
                core::array::from_fn(|_| rng.uniform(0.05, 0.95)),
            )
        })
        .collect()
}

#[test]
fn muscle_robot_sensitivity_matches_central_differences() {
    let model = robot::MODEL_F64;
    let muscles = robot::MUSCLES_F64;
    let mut data = Data::new();
    let mut forces = DriveForces::new();
    let ddq_at = |data: &mut robot::RobotData<f64>, q: &[f64; NV], v: &[f64; NV], a: &[f64; NU]| {
        let mut forces = DriveForces::new();
        *robot::forward_dynamics(&model, &muscles, data, q, v, a, &mut forces).unwrap()
    };
    for (q, v, a) in robot_states(25) {
        let mut s = [[0.0; NU]; NV];
        robot::sensitivity(&model, &muscles, &mut data, &q, &v, &a, &mut forces, &mut s).unwrap();
        let scale = s.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
        for k in 0..NU {
            let h = 1e-6;
            let (mut ap, mut am) = (a, a);
            ap[k] += h;
            am[k] -= h;
            let (dp, dm) = (
                ddq_at(&mut data, &q, &v, &ap),
                ddq_at(&mut data, &q, &v, &am),
            );
            for i in 0..NV {
                let fd = (dp[i] - dm[i]) / (2.0 * h);
                approx::assert_relative_eq!(s[i][k], fd, epsilon = 1e-6 * scale);
            }
        }
    }
}

#[test]
fn muscle_robot_sensitivity_matches_dual_numbers() {
    let model = robot::MODEL_F64;
    let muscles = robot::MUSCLES_F64;
    let dual_model = model.cast::<Dual>().unwrap();
    let dual_muscles = muscles.map(|m| m.cast::<Dual>());
    let mut data = Data::new();
    let mut dual_data = Data::new();
    let mut forces = DriveForces::new();
    let mut dual_forces = DriveForces::new();
    for (q, v, a) in robot_states(25) {
        let mut s = [[0.0; NU]; NV];
        robot::sensitivity(&model, &muscles, &mut data, &q, &v, &a, &mut forces, &mut s).unwrap();
        for k in 0..NU {
            let ad: [Dual; NU] = core::array::from_fn(|j| Dual {
                re: a[j],
                du: if j == k { 1.0 } else { 0.0 },
            });
            let qd = q.map(Dual::constant);
            let vd = v.map(Dual::constant);
            let ddq = robot::forward_dynamics(
                &dual_model,
                &dual_muscles,
                &mut dual_data,
                &qd,
                &vd,
                &ad,
                &mut dual_forces,
            )
            .unwrap();
            for i in 0..NV {
                approx::assert_relative_eq!(
                    s[i][k],
                    ddq[i].du,
                    epsilon = 1e-9,
                    max_relative = 1e-10
                );
            }
        }
    }
}

/// A floating torso with two revolute limbs on separate branches, two
/// motors, a spring and a muscle spanning both branches.
fn floating_model() -> Model<f64, 3, 9, 8> {
    let body =
        |m: f64, c: Vec3<f64>| Inertia::new(m, c, Sym3::diagonal(0.05 * m, 0.04 * m, 0.03 * m));
    Model::new(
        [None, Some(0), Some(0)],
        [
            Joint::free_flyer(),
            Joint::revolute(Axis::Y),
            Joint::revolute(Axis::Z),
        ],
        [
            Transform::IDENTITY,
            Transform::from_translation(Vec3::new(0.2, 0.1, 0.0)),
            Transform::from_translation(Vec3::new(-0.2, 0.0, 0.1)),
        ],
        [
            body(5.0, Vec3::new(0.0, 0.0, 0.05)),
            body(1.0, Vec3::new(0.15, 0.0, 0.0)),
            body(0.7, Vec3::new(0.0, 0.12, 0.0)),
        ],
        Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
    )
}

type FloatingDrives = (
    [JointMotor<f64>; 2],
    LinearSpring<f64, Spatial, 2>,
    ThelenMuscle<f64, Spatial, 3>,
);

fn floating_drives() -> FloatingDrives {
    (
        [
            JointMotor::new(6, 0, 50.0, 0.03, 1e-5),
            JointMotor::new(7, 1, 30.0, 0.05, 2e-5),
        ],
        LinearSpring::new(
            Path::new([
                Endpoint::on_body(0, Vec3::new(0.1, 0.1, 0.1)),
                Endpoint::on_body(1, Vec3::new(0.2, 0.0, 0.05)),
            ]),
            300.0,
            0.1,
        ),
        ThelenMuscle::new(
            Path::new([
                Endpoint::on_body(1, Vec3::new(0.25, 0.02, 0.0)),
                Endpoint::on_body(0, Vec3::new(0.0, 0.1, 0.15)),
                Endpoint::on_body(2, Vec3::new(0.03, 0.2, 0.0)),
            ]),
            // A slack length that keeps the fibre within the force law's
            // range (two optimal lengths) over the random states.
            ThelenParameters::<f64>::thelen_2003(500.0, 0.3, 0.3, 0.2),
            2,
        ),
    )
}

#[test]
fn floating_base_sensitivity_matches_the_mass_matrix_route_and_differences() {
    let model = floating_model();
    let drives = floating_drives();
    // The mass-matrix route needs the model without gravity for Jᵀ δf.
    let mut no_gravity = model;
    no_gravity.set_gravity(Motion::ZERO).unwrap();
    let mut rng = Rng(777);
    let mut data = Data::new();
    let mut forces = DriveForces::new();
    for _ in 0..20 {
        let quat: [f64; 4] = core::array::from_fn(|_| rng.uniform(-1.0, 1.0));
        let n = quat.iter().map(|x| x * x).sum::<f64>().sqrt();
        let q = [
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            rng.uniform(-1.0, 1.0),
            quat[0] / n,
            quat[1] / n,
            quat[2] / n,
            quat[3] / n,
            rng.uniform(-1.5, 1.5),
            rng.uniform(-1.5, 1.5),
        ];
        let v: [f64; 8] = core::array::from_fn(|_| rng.uniform(-1.0, 1.0));
        let w = [
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
            rng.uniform(0.1, 0.9),
        ];
        let tau = [0.0; 8];
        let mut s = [[0.0; 3]; 8];
        forward_dynamics_and_sensitivity(
            &model,
            &mut data,
            &q,
            &v,
            &tau,
            &drives,
            &w,
            &mut forces,
            &mut s,
        )
        .unwrap();

        // M⁻¹ (∂τ/∂w_k + Jᵀ ∂f/∂w_k) with M from CRBA and Jᵀ f from RNEA.
        let m = *crba(&model, &mut Data::new(), &q).unwrap();
        for k in 0..3 {
            let mut d = DriveForces::<f64, Spatial, 3, 8>::new();
            let mut kin = Data::new();
            rodyn::algorithm::kinematics::forward_kinematics_velocity(&model, &mut kin, &q, &v)
                .unwrap();
            let state = rodyn::drive::DriveState {
                data: &kin,
                q: &q,
                v: &v,
            };
            rodyn::drive::ForceElement::add_input_derivative(&drives, &state, &w, k, &mut d)
                .unwrap();
            let zero = [0.0; 8];
            let minus_jt_f = *rnea(
                &no_gravity,
                &mut Data::new(),
                &q,
                &zero,
                &zero,
                Some(&d.f_ext),
            )
            .unwrap();
            let rhs: [f64; 8] = core::array::from_fn(|i| d.tau[i] - minus_jt_f[i]);
            let x = solve(m, rhs);
            for i in 0..8 {
                approx::assert_relative_eq!(s[i][k], x[i], epsilon = 1e-9, max_relative = 1e-9);
            }
            // And central differences through CRBA forward dynamics.
            let h = 1e-6;
            let ddq = |wk: f64| {
                let mut wp = w;
                wp[k] = wk;
                let mut f = DriveForces::new();
                *forward_dynamics_with_drives::<Crba, _, _, _, 3, 9, 8>(
                    &model,
                    &mut Data::new(),
                    &q,
                    &v,
                    &tau,
                    &drives,
                    &wp,
                    &mut f,
                )
                .unwrap()
            };
            let (p, mm) = (ddq(w[k] + h), ddq(w[k] - h));
            // The difference quotient's rounding error is about
            // ε κ(M) |q̈| / h: up to ~6e-8 relative on this floating base
            // (entries of s reach ~300), hence a relative bound; the exact
            // route above holds s to 1e-9.
            for i in 0..8 {
                approx::assert_relative_eq!(
                    s[i][k],
                    (p[i] - mm[i]) / (2.0 * h),
                    epsilon = 1e-5,
                    max_relative = 1e-6
                );
            }
        }
        // The forward dynamics under the same drives agree between methods.
        let by_aba = *forward_dynamics_with_drives::<Aba, _, _, _, 3, 9, 8>(
            &model,
            &mut Data::new(),
            &q,
            &v,
            &tau,
            &drives,
            &w,
            &mut forces,
        )
        .unwrap();
        let by_crba = *forward_dynamics_with_drives::<Crba, _, _, _, 3, 9, 8>(
            &model,
            &mut Data::new(),
            &q,
            &v,
            &tau,
            &drives,
            &w,
            &mut forces,
        )
        .unwrap();
        for i in 0..8 {
            approx::assert_relative_eq!(by_aba[i], by_crba[i], epsilon = 1e-9);
        }
    }
}

/// Gaussian elimination with partial pivoting for the small test systems.
fn solve<const N: usize>(mut a: [[f64; N]; N], mut b: [f64; N]) -> [f64; N] {
    for c in 0..N {
        let p = (c..N)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap();
        a.swap(c, p);
        b.swap(c, p);
        for r in c + 1..N {
            let f = a[r][c] / a[c][c];
            for k in c..N {
                a[r][k] -= f * a[c][k];
            }
            b[r] -= f * b[c];
        }
    }
    let mut x = [0.0; N];
    for r in (0..N).rev() {
        let s: f64 = (r + 1..N).map(|k| a[r][k] * x[k]).sum();
        x[r] = (b[r] - s) / a[r][r];
    }
    x
}

/// The firmware's scalar: the f32 muscle robot agrees with f64.
#[test]
fn muscle_robot_in_f32_agrees_with_f64() {
    let (model, muscles) = (robot::MODEL_F64, robot::MUSCLES_F64);
    let (model32, muscles32) = (robot::MODEL_F32, robot::MUSCLES_F32);
    for (q, v, a) in robot_states(10) {
        let mut s = [[0.0; NU]; NV];
        let mut s32 = [[0.0f32; NU]; NV];
        let ddq = *robot::sensitivity(
            &model,
            &muscles,
            &mut Data::new(),
            &q,
            &v,
            &a,
            &mut DriveForces::new(),
            &mut s,
        )
        .unwrap();
        let ddq32 = *robot::sensitivity(
            &model32,
            &muscles32,
            &mut Data::new(),
            &q.map(|x| x as f32),
            &v.map(|x| x as f32),
            &a.map(|x| x as f32),
            &mut DriveForces::new(),
            &mut s32,
        )
        .unwrap();
        let scale = s.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
        for i in 0..NV {
            approx::assert_relative_eq!(
                ddq32[i] as f64,
                ddq[i],
                epsilon = 1e-4 * ddq[i].abs().max(10.0)
            );
            for k in 0..NU {
                approx::assert_relative_eq!(s32[i][k] as f64, s[i][k], epsilon = 1e-4 * scale);
            }
        }
    }
}
