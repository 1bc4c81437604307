//! The seed's gait example, checked: the socket load that RNEA's joint force
//! gives equals (a) the Newton-Euler balance of the prosthesis segments
//! alone over the synthetic cycle and (b) hand-computed statics; f32 agrees
//! with f64; the 3-D twin of the model gives the same torques; the input
//! data balance body weight over the cycle.

#[allow(dead_code)]
mod gait_support;

use gait_support::data::{data_dir, FootLoad, GaitCycle, GroundReaction};
use gait_support::gait_planar::{body, endpoint, ENDPOINTS_F64, MODEL_F32, MODEL_F64, NB, NQ, NV};
use gait_support::inverse_dynamics::{
    foot_force, gait_inverse_dynamics, sole_point, GaitData, GaitModel, InterfaceLoad,
};
use rodyn::algorithm::kinematics::{forward_kinematics, forward_kinematics_acceleration};
use rodyn::algorithm::rnea::rnea;
use rodyn::planar::Vec2;
use rodyn::prelude::*;

const G: f64 = 9.81;

fn inputs() -> (GaitCycle, Vec<GroundReaction>) {
    let cycle = GaitCycle::read(&data_dir().join("joint_fourier.csv")).unwrap();
    let reactions = GroundReaction::read_all(&data_dir().join("ground_reaction.csv")).unwrap();
    (cycle, reactions)
}

fn weight() -> f64 {
    MODEL_F64.total_mass() * G
}

/// `ω ẑ × p` in the plane.
fn cross_z(w: f64, p: [f64; 2]) -> [f64; 2] {
    [-w * p[1], w * p[0]]
}

/// `a × b` (z component) in the plane.
fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

/// The socket load from Newton's and Euler's laws for the prosthesis
/// (right shank and foot) alone, in world coordinates, from the segments'
/// centre-of-mass accelerations: what the thigh must exert on them at the
/// knee is `Σ m (a_c − g) − GRF` and the matching moment about the knee.
fn socket_load_by_newton_euler(
    q: &[f64; NQ],
    v: &[f64; NV],
    a: &[f64; NV],
    right: &FootLoad,
) -> InterfaceLoad<f64> {
    let mut data = Box::new(GaitData::<f64>::new());
    forward_kinematics_acceleration(&MODEL_F64, &mut data, q, v, a).unwrap();
    let pos = |b: usize, p: Vec2<f64>| {
        let w = data.o_m_i[b].act_point(&p);
        [w.x, w.y]
    };
    let rot = |b: usize, p: [f64; 2]| {
        let w = data.o_m_i[b].rotate(&Vec2::new(p[0], p[1]));
        [w.x, w.y]
    };
    let knee = pos(body::R_SHANK, Vec2::new(0.0, 0.0));
    let mut force = [0.0; 2];
    let mut moment = 0.0;
    for b in [body::R_SHANK, body::R_FOOT] {
        let inertia = MODEL_F64.inertia(b);
        let (m, c) = (inertia.mass, [inertia.com.x, inertia.com.y]);
        let (omega, v_o) = (data.v[b].ang, [data.v[b].lin.x, data.v[b].lin.y]);
        let (alpha, a_o) = (data.a[b].ang, [data.a[b].lin.x, data.a[b].lin.y]);
        // Classical acceleration of the centre of mass from the spatial one.
        let v_c = [v_o[0] + cross_z(omega, c)[0], v_o[1] + cross_z(omega, c)[1]];
        let a_c = [
            a_o[0] + cross_z(alpha, c)[0] + cross_z(omega, v_c)[0],
            a_o[1] + cross_z(alpha, c)[1] + cross_z(omega, v_c)[1],
        ];
        let needed = rot(b, a_c).map(|x| m * x);
        let net = [needed[0], needed[1] + m * G]; // m a_c − m g
        let arm = sub(pos(b, Vec2::new(c[0], c[1])), knee);
        force = [force[0] + net[0], force[1] + net[1]];
        moment += cross(arm, net) + inertia.izz * alpha;
    }
    let cop = sub(pos(body::R_FOOT, sole_point(right.cop)), knee);
    let on_shank = [force[0] - right.force[0], force[1] - right.force[1]];
    let moment_on_shank = moment - cross(cop, right.force);
    // The reaction on the thigh, reduced to the socket, in the thigh frame.
    let socket = pos(body::R_THIGH, ENDPOINTS_F64[endpoint::SOCKET].position);
    let on_thigh = on_shank.map(|x| -x);
    let torque = -moment_on_shank + cross(sub(knee, socket), on_thigh);
    let local = data.o_m_i[body::R_THIGH].rotate_inv(&Vec2::new(on_thigh[0], on_thigh[1]));
    InterfaceLoad {
        torque,
        normal: local.y,
        shear: local.x,
    }
}

fn assert_load_close(got: &InterfaceLoad<f64>, want: &InterfaceLoad<f64>, tol: f64, at: &str) {
    let scale = weight(); // N, and N m per metre
    for (name, g, w) in [
        ("torque", got.torque, want.torque),
        ("normal", got.normal, want.normal),
        ("shear", got.shear, want.shear),
    ] {
        assert!((g - w).abs() <= tol * scale, "{at}: {name} {g} vs {w}");
    }
}

#[test]
fn socket_load_equals_newton_euler_of_the_prosthesis_over_the_cycle() {
    let (cycle, reactions) = inputs();
    assert_eq!(reactions.len(), 101);
    let mut data = Box::new(GaitData::<f64>::new());
    for r in &reactions {
        let (q, v, a) = cycle.state(r.time);
        let frame =
            gait_inverse_dynamics(&MODEL_F64, &mut data, (&q, &v, &a), &r.right, &r.left).unwrap();
        let want = socket_load_by_newton_euler(&q, &v, &a, &r.right);
        assert_load_close(&frame.interface, &want, 1e-9, &format!("{} %", r.percent));
        // The load is not trivially small: the prosthesis carries weight in stance.
        if (15.0..=45.0).contains(&r.percent) {
            assert!(
                frame.interface.normal > 0.5 * weight(),
                "{} %: {:?}",
                r.percent,
                frame.interface
            );
        }
    }
}

/// Standing upright (q = 0) on the prosthesis with 600 N under the heel:
/// F_p = 600 N − (3.4875 + 1.0875) kg · 9.81 m/s² = 555.119 N; the moment
/// about the socket (on the thigh's axis) is the heel force's lever
/// −0.0665 m · 600 N plus the foot's weight at x = 0.0798 m:
/// −39.9 − 0.0798 · 10.668375 = −40.751336 N m; no shear.
#[test]
fn standing_statics_by_hand() {
    let heel = FootLoad {
        force: [0.0, 600.0],
        cop: -0.0665,
    };
    let left = FootLoad {
        force: [0.0, weight() - 600.0],
        cop: 0.0,
    };
    let mut data = Box::new(GaitData::<f64>::new());
    let frame = gait_inverse_dynamics(
        &MODEL_F64,
        &mut data,
        (&[0.0; NQ], &[0.0; NV], &[0.0; NV]),
        &heel,
        &left,
    )
    .unwrap();
    let want = InterfaceLoad {
        torque: -39.9 - 0.0798 * 1.0875 * G,
        normal: 600.0 - 4.575 * G,
        shear: 0.0,
    };
    assert_load_close(&frame.interface, &want, 1e-12, "standing");
    assert!((want.normal - 555.119_25).abs() < 1e-9 && (want.torque + 40.751_336).abs() < 1e-6);
}

/// A bent posture at rest: hip φ, knee κ, ankle β (pelvis level), a slanted
/// ground force under the forefoot. The prosthesis' statics by hand with
/// segment lengths from the model file: F_p→thigh = GRF + Σ m g and its
/// moment about the socket, resolved along the thigh (angle φ).
#[test]
fn bent_posture_statics_by_hand() {
    let (phi, kappa, beta) = (0.4_f64, -0.7_f64, 0.25_f64);
    let grf = [-80.0, 450.0];
    let cop = 0.12;
    let mut q = [0.0; NQ];
    q[gait_support::gait_planar::q::R_HIP] = phi;
    q[gait_support::gait_planar::q::R_KNEE] = kappa;
    q[gait_support::gait_planar::q::R_ANKLE] = beta;
    let load = FootLoad { force: grf, cop };
    let mut data = Box::new(GaitData::<f64>::new());
    let got = gait_inverse_dynamics(
        &MODEL_F64,
        &mut data,
        (&q, &[0.0; NV], &[0.0; NV]),
        &load,
        &FootLoad::default(),
    )
    .unwrap()
    .interface;

    // Hand geometry, hip at the origin: R(θ)(x, y) = (x cos θ − y sin θ, x sin θ + y cos θ).
    let rot = |th: f64, p: [f64; 2]| {
        [
            p[0] * th.cos() - p[1] * th.sin(),
            p[0] * th.sin() + p[1] * th.cos(),
        ]
    };
    let add = |a: [f64; 2], b: [f64; 2]| [a[0] + b[0], a[1] + b[1]];
    let (shank_angle, foot_angle) = (phi + kappa, phi + kappa + beta);
    let socket = rot(phi, [0.0, -0.2573]);
    let knee = rot(phi, [0.0, -0.4288]);
    let ankle = add(knee, rot(shank_angle, [0.0, -0.4305]));
    let shank_com = add(knee, rot(shank_angle, [0.0, -0.1864]));
    let foot_com = add(ankle, rot(foot_angle, [0.0798, -0.0273]));
    let pressure = add(ankle, rot(foot_angle, [cop, -0.0683]));
    let (w_shank, w_foot) = ([0.0, -3.4875 * G], [0.0, -1.0875 * G]);
    let force = [grf[0], grf[1] + w_shank[1] + w_foot[1]];
    let torque = cross(sub(pressure, socket), grf)
        + cross(sub(shank_com, socket), w_shank)
        + cross(sub(foot_com, socket), w_foot);
    let want = InterfaceLoad {
        torque,
        normal: -force[0] * phi.sin() + force[1] * phi.cos(),
        shear: force[0] * phi.cos() + force[1] * phi.sin(),
    };
    assert_load_close(&got, &want, 1e-12, "bent posture");
}

/// The synthetic inputs balance body weight over the cycle: the world-frame
/// residual at the pelvis averages to zero (periodic motion has no net
/// momentum change), though not at each instant.
#[test]
fn pelvis_residual_averages_to_zero_over_the_cycle() {
    let (cycle, reactions) = inputs();
    let mut data = Box::new(GaitData::<f64>::new());
    let mut mean = [0.0; 2];
    let n = reactions.len() - 1; // 0 % and 100 % are the same instant
    for r in &reactions[..n] {
        let (q, v, a) = cycle.state(r.time);
        let tau = gait_inverse_dynamics(&MODEL_F64, &mut data, (&q, &v, &a), &r.right, &r.left)
            .unwrap()
            .tau;
        let world = data.o_m_i[body::PELVIS].rotate(&Vec2::new(tau[0], tau[1]));
        mean = [mean[0] + world.x / n as f64, mean[1] + world.y / n as f64];
    }
    assert!(
        mean[0].abs() < 0.01 * weight() && mean[1].abs() < 0.01 * weight(),
        "{mean:?}"
    );
}

/// f32 (the MCU scalar) against f64 over the cycle: torques and socket
/// loads within 1e-5 of body weight (N, or N m per metre).
#[test]
fn f32_agrees_with_f64_over_the_cycle() {
    let (cycle, reactions) = inputs();
    let mut d64 = Box::new(GaitData::<f64>::new());
    let mut d32 = Box::new(GaitData::<f32>::new());
    let mut worst = 0.0_f64;
    for r in &reactions {
        let (q, v, a) = cycle.state(r.time);
        let f64_frame =
            gait_inverse_dynamics(&MODEL_F64, &mut d64, (&q, &v, &a), &r.right, &r.left).unwrap();
        let c = |x: &[f64; NV]| x.map(|x| x as f32);
        let f32_frame = gait_inverse_dynamics(
            &MODEL_F32,
            &mut d32,
            (&c(&q), &c(&v), &c(&a)),
            &r.right,
            &r.left,
        )
        .unwrap();
        let (i64, i32) = (f64_frame.interface, f32_frame.interface);
        let pairs = f64_frame
            .tau
            .iter()
            .zip(&f32_frame.tau)
            .map(|(x, y)| (*x, *y))
            .chain([
                (i64.torque, i32.torque),
                (i64.normal, i32.normal),
                (i64.shear, i32.shear),
            ]);
        for (x, y) in pairs {
            worst = worst.max((x - f64::from(y)).abs() / weight());
        }
    }
    println!("f32 vs f64: largest difference {worst:.2e} of body weight");
    assert!(worst < 1e-5, "{worst}");
}

/// The 3-D twin: free-flyer pelvis with the same pitch as a quaternion about
/// z, every joint revolute about z, the same masses and placements. Its RNEA
/// torques equal the planar model's over the cycle.
#[test]
fn spatial_twin_gives_the_same_torques() {
    const NQ3: usize = NQ + 4;
    const NV3: usize = NV + 3;
    let planar: &GaitModel<f64> = &MODEL_F64;
    let v3 = |x: Vec2<f64>| Vec3::new(x.x, x.y, 0.0);
    let spatial = Model::<f64, NB, NQ3, NV3>::new(
        core::array::from_fn(|i| planar.parent(i)),
        core::array::from_fn(|i| {
            if i == 0 {
                Joint::free_flyer()
            } else {
                Joint::revolute(Axis::Z)
            }
        }),
        core::array::from_fn(|i| {
            let x = planar.placement(i);
            let rot = Mat3::from_rows([[x.cos, -x.sin, 0.0], [x.sin, x.cos, 0.0], [0.0, 0.0, 1.0]]);
            Transform::new(rot, v3(x.trans))
        }),
        core::array::from_fn(|i| {
            let b = planar.inertia(i);
            Inertia::new(b.mass, v3(b.com), Sym3::diagonal(b.izz, b.izz, b.izz))
        }),
        Motion::new(Vec3::ZERO, Vec3::new(0.0, -G, 0.0)),
    );
    spatial.validate().unwrap();
    let (cycle, reactions) = inputs();
    let mut dp = Box::new(GaitData::<f64>::new());
    let mut ds = Box::new(Data::<f64, NB, NV3>::new());
    for r in reactions.iter().step_by(5) {
        let (q, v, a) = cycle.state(r.time);
        let tau_p = gait_inverse_dynamics(planar, &mut dp, (&q, &v, &a), &r.right, &r.left)
            .unwrap()
            .tau;
        forward_kinematics(planar, &mut dp, &q).unwrap();
        let mut f_ext = [Force::new(Vec3::ZERO, Vec3::ZERO); NB];
        for (b, load) in [(body::R_FOOT, r.right), (body::L_FOOT, r.left)] {
            let f = foot_force(&dp.o_m_i[b], &load);
            f_ext[b] = Force::new(Vec3::new(0.0, 0.0, f.ang), v3(f.lin));
        }
        let (half_sin, half_cos) = (0.5 * q[2]).sin_cos();
        let q3: [f64; NQ3] = core::array::from_fn(|k| match k {
            0 | 1 => q[k],
            5 => half_sin,
            6 => half_cos,
            2..=4 => 0.0,
            _ => q[k - 4],
        });
        let lift = |x: &[f64; NV]| -> [f64; NV3] {
            core::array::from_fn(|k| match k {
                0 | 1 => x[k],
                5 => x[2],
                2..=4 => 0.0,
                _ => x[k - 3],
            })
        };
        let tau_s = *rnea(&spatial, &mut ds, &q3, &lift(&v), &lift(&a), Some(&f_ext)).unwrap();
        let lifted = lift(&tau_p);
        for k in 0..NV3 {
            assert!(
                (tau_s[k] - lifted[k]).abs() <= 1e-9 * weight(),
                "{} %: tau[{k}] {} vs {}",
                r.percent,
                tau_s[k],
                lifted[k]
            );
        }
    }
}
