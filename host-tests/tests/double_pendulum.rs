//! A closed-form double pendulum against RNEA, CRBA and ABA.

use rodyn::algorithm::crba::crba;
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::algorithm::rnea::rnea;
use rodyn::prelude::*;

const L1: f64 = 0.7;
const L2: f64 = 0.5;
const M1: f64 = 1.3;
const M2: f64 = 0.8;
const G: f64 = 9.81;

/// Two point masses on massless rods, swinging about z in the x-y plane,
/// gravity along -y; q measured from the x axis.
const MODEL: Model<f64, 2, 2, 2> = Model::new(
    [None, Some(0)],
    [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
    [
        Transform::IDENTITY,
        Transform::from_translation(Vec3::new(L1, 0.0, 0.0)),
    ],
    [
        Inertia::point_mass(M1, Vec3::new(L1, 0.0, 0.0)),
        Inertia::point_mass(M2, Vec3::new(L2, 0.0, 0.0)),
    ],
    Motion::new(Vec3::ZERO, Vec3::new(0.0, -G, 0.0)),
);

/// Lagrange's equations for the same system.
fn closed_form(q: [f64; 2], v: [f64; 2], a: [f64; 2]) -> ([[f64; 2]; 2], [f64; 2]) {
    let c2 = q[1].cos();
    let s2 = q[1].sin();
    let m11 = (M1 + M2) * L1 * L1 + M2 * L2 * L2 + 2.0 * M2 * L1 * L2 * c2;
    let m12 = M2 * L2 * L2 + M2 * L1 * L2 * c2;
    let m22 = M2 * L2 * L2;
    let h1 = -M2 * L1 * L2 * s2 * (2.0 * v[0] * v[1] + v[1] * v[1])
        + (M1 + M2) * G * L1 * q[0].cos()
        + M2 * G * L2 * (q[0] + q[1]).cos();
    let h2 = M2 * L1 * L2 * s2 * v[0] * v[0] + M2 * G * L2 * (q[0] + q[1]).cos();
    let tau = [m11 * a[0] + m12 * a[1] + h1, m12 * a[0] + m22 * a[1] + h2];
    ([[m11, m12], [m12, m22]], tau)
}

#[test]
fn rnea_crba_aba_match_lagrange() {
    let mut data = Data::new();
    for (q, v, a) in [
        ([0.3, -0.7], [1.1, -0.4], [0.5, 2.0]),
        ([-1.2, 2.1], [-2.0, 3.0], [-1.0, 0.1]),
        ([0.0, 0.0], [0.0, 0.0], [0.0, 0.0]),
    ] {
        let (m, tau_ref) = closed_form(q, v, a);
        let tau = *rnea(&MODEL, &mut data, &q, &v, &a, None).unwrap();
        for k in 0..2 {
            approx::assert_relative_eq!(tau[k], tau_ref[k], epsilon = 1e-12, max_relative = 1e-12);
        }
        let mm = *crba(&MODEL, &mut data, &q).unwrap();
        for r in 0..2 {
            for c in 0..2 {
                approx::assert_relative_eq!(
                    mm[r][c],
                    m[r][c],
                    epsilon = 1e-12,
                    max_relative = 1e-12
                );
            }
        }
        let by_aba = *Aba::forward_dynamics(&MODEL, &mut data, &q, &v, &tau, None).unwrap();
        let by_crba = *Crba::forward_dynamics(&MODEL, &mut data, &q, &v, &tau, None).unwrap();
        for k in 0..2 {
            approx::assert_relative_eq!(by_aba[k], a[k], epsilon = 1e-10);
            approx::assert_relative_eq!(by_crba[k], a[k], epsilon = 1e-10);
        }
    }
}
