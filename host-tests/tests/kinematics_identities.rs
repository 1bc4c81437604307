//! Identities of the frame, Jacobian and centroidal algorithms on random
//! trees (fixed and floating base) and random states, in f64:
//!
//! * `J v` equals the frame's velocity, in each reference frame;
//! * `J̇ v` equals the derivative of `J(q(t)) v` along `q̇ = Q(q) v` (taken
//!   exactly with forward-mode dual numbers), with J̇'s columns in each
//!   reference frame, and as accelerations: in LOCAL the spatial
//!   acceleration at zero joint acceleration, in WORLD `Σ J̇ₖ vₖ`, in
//!   LOCAL_WORLD_ALIGNED the classical acceleration;
//! * `A_g v` equals the sum of the bodies' momenta about the centre of mass;
//!   `J_com v` equals the centre of mass's velocity, which equals the
//!   derivative of the centre of mass along the motion; `Ȧ_g v` equals the
//!   derivative of `A_g(q(t)) v`;
//! * a planar chain's Jacobians and centroidal map equal its 3-D twin's
//!   planar components.
//!
//! Tolerances: `‖x − y‖∞ ≤ tol · max(1, ‖y‖∞)`.

// Index loops over coordinates mirror the equations (`Σₖ A_gₖ vₖ`).
#![allow(clippy::needless_range_loop)]

use rodyn::algorithm::centroidal::{
    centroidal_map, centroidal_momentum, com_jacobian, com_velocity_acceleration, CentroidalData,
};
use rodyn::algorithm::frames::{
    frame_acceleration, frame_classical_acceleration, frame_velocity, ReferenceFrame,
};
use rodyn::algorithm::jacobian::{
    frame_jacobian, frame_jacobian_time_variation, joint_jacobians, joint_jacobians_time_variation,
    mul_rates, JacobianData,
};
use rodyn::algorithm::kinematics::forward_kinematics_acceleration;
use rodyn::planar::{Planar, PlanarMotion, PlanarTransform, Vec2};
use rodyn::prelude::*;
use rodyn::sim::manifold::configuration_rate;
use rodyn::Frame;
use rodyn_host_tests::random::{
    random_configuration, random_floating_tree, random_planar_chain, random_tree, Rng,
};

const TOL: f64 = 1e-11;

const REFERENCES: [ReferenceFrame; 3] = [
    ReferenceFrame::Local,
    ReferenceFrame::World,
    ReferenceFrame::LocalWorldAligned,
];

fn assert_close(what: &str, x: &[f64], y: &[f64], tol: f64) {
    let scale = y.iter().fold(1.0f64, |m, v| m.max(v.abs()));
    let err = x
        .iter()
        .zip(y)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(
        err <= tol * scale,
        "{what}: error {err:e} exceeds {tol:e} x {scale}\n  got  {x:?}\n  want {y:?}"
    );
}

fn m6(m: &Motion<f64>) -> Vec<f64> {
    m.to_linear_first().to_vec()
}

fn f6(f: &Force<f64>) -> Vec<f64> {
    f.to_linear_first().to_vec()
}

/// The derivative parts of a dual motion.
fn du6(m: &Motion<Dual>) -> Vec<f64> {
    m.to_linear_first().iter().map(|x| x.du).collect()
}

fn check_model<const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<f64, NB, NQ, NV>,
    rng: &mut Rng,
    states: usize,
) {
    let dual_model = model.cast::<Dual>().unwrap();
    let mut data = Data::<f64, NB, NV>::new();
    let mut dual_data = Data::<Dual, NB, NV>::new();
    let mut jac = JacobianData::<f64, NV>::new();
    let mut dual_jac = JacobianData::<Dual, NV>::new();
    let mut cd = CentroidalData::<f64, NB, NV>::new();
    let mut dual_cd = CentroidalData::<Dual, NB, NV>::new();
    let mut cols = [Motion::ZERO; NV];
    let mut dual_cols = [Motion::<Dual>::ZERO; NV];
    for _ in 0..states {
        let q = random_configuration(model, rng);
        let v: [f64; NV] = rng.vector(2.0);
        let zero = [0.0; NV];
        // q(t) = q + t q̇ to first order, which is all a derivative sees.
        let q_dot = configuration_rate(model, &q, &v).unwrap();
        let q_dual: [Dual; NQ] = core::array::from_fn(|k| Dual {
            re: q[k],
            du: q_dot[k],
        });
        let v_dual = v.map(Dual::constant);

        joint_jacobians_time_variation(model, &mut data, &mut jac, &q, &v).unwrap();
        joint_jacobians(&dual_model, &mut dual_data, &mut dual_jac, &q_dual).unwrap();
        let frames: Vec<Frame<f64>> = (0..NB).map(|b| Frame::new(b, rng.placement())).collect();
        forward_kinematics_acceleration(model, &mut data, &q, &v, &zero).unwrap();
        for f in &frames {
            let dual_frame = Frame::new(f.body, f.placement.cast::<Dual>());
            for reference in REFERENCES {
                frame_jacobian(model, &data, &jac, f, reference, &mut cols).unwrap();
                let jv = mul_rates::<f64, NV, Spatial>(&cols, &v).unwrap();
                let vel = frame_velocity(&data, f, reference).unwrap();
                assert_close(
                    &format!("J v, body {} {reference:?}", f.body),
                    &m6(&jv),
                    &m6(&vel),
                    TOL,
                );

                frame_jacobian(
                    &dual_model,
                    &dual_data,
                    &dual_jac,
                    &dual_frame,
                    reference,
                    &mut dual_cols,
                )
                .unwrap();
                let d_jv = du6(&mul_rates::<Dual, NV, Spatial>(&dual_cols, &v_dual).unwrap());
                let mut dj = [Motion::ZERO; NV];
                frame_jacobian_time_variation(model, &data, &jac, f, reference, &mut dj).unwrap();
                let dj_v = mul_rates::<f64, NV, Spatial>(&dj, &v).unwrap();
                assert_close(
                    &format!("J-dot columns times v, body {} {reference:?}", f.body),
                    &m6(&dj_v),
                    &d_jv,
                    TOL,
                );
                let jdot_v = match reference {
                    ReferenceFrame::Local => frame_acceleration(&data, f, reference).unwrap(),
                    ReferenceFrame::World => dj_v,
                    ReferenceFrame::LocalWorldAligned => {
                        frame_classical_acceleration(&data, f, reference).unwrap()
                    }
                };
                assert_close(
                    &format!("J-dot v, body {} {reference:?}", f.body),
                    &m6(&jdot_v),
                    &d_jv,
                    TOL,
                );
            }
        }

        centroidal_momentum(model, &mut data, &mut cd, &q, &v, &zero).unwrap();
        let mut ag_v = Force::ZERO;
        for k in 0..NV {
            ag_v += cd.ag[k] * v[k];
        }
        // The bodies' momenta, summed in the world and moved to the CoM.
        let mut h = Force::ZERO;
        for i in 0..NB {
            h += data.o_m_i[i].act_force(&model.inertia(i).mul_motion(&data.v[i]));
        }
        let h_g = Transform::from_translation(cd.com()).act_inv_force(&h);
        assert_close("A_g v", &f6(&ag_v), &f6(&h_g), TOL);
        let mut jcom = [Vec3::ZERO; NV];
        com_jacobian(&cd, &mut jcom);
        let mut jcom_v = Vec3::ZERO;
        for k in 0..NV {
            jcom_v += jcom[k] * v[k];
        }
        let (vcom, _) = com_velocity_acceleration(&cd);
        assert_close("J_com v", &jcom_v.to_array(), &vcom.to_array(), TOL);

        centroidal_map(&dual_model, &mut dual_data, &mut dual_cd, &q_dual).unwrap();
        let dcom = dual_cd.com().to_array().map(|x| x.du);
        assert_close("com velocity = d com / dt", &vcom.to_array(), &dcom, TOL);
        let mut d_ag_v = Force::<Dual>::ZERO;
        for k in 0..NV {
            d_ag_v += dual_cd.ag[k] * v_dual[k];
        }
        let d_ag_v: Vec<f64> = d_ag_v.to_linear_first().iter().map(|x| x.du).collect();
        assert_close("A_g-dot v", &f6(&cd.dhg), &d_ag_v, TOL);
    }
}

#[test]
fn fixed_base_trees() {
    let mut rng = Rng::new(0x5EED_0024);
    for _ in 0..4 {
        check_model(&random_tree::<1>(&mut rng), &mut rng, 3);
        check_model(&random_tree::<4>(&mut rng), &mut rng, 3);
        check_model(&random_tree::<9>(&mut rng), &mut rng, 3);
    }
}

#[test]
fn floating_base_trees() {
    let mut rng = Rng::new(0x5EED_0025);
    for _ in 0..4 {
        check_model(&random_floating_tree::<3, 8, 7>(&mut rng), &mut rng, 3);
        check_model(&random_floating_tree::<10, 15, 14>(&mut rng), &mut rng, 3);
    }
}

/// A planar motion as its 3-D twin's (angular about z, linear in x-y).
fn planar_as_3d(m: &PlanarMotion<f64>) -> Vec<f64> {
    vec![m.lin.x, m.lin.y, m.ang]
}

fn planar_part(m: &Motion<f64>) -> Vec<f64> {
    vec![m.lin.x, m.lin.y, m.ang.z]
}

#[test]
fn planar_chains_match_their_3d_twins() {
    let mut rng = Rng::new(0x5EED_0026);
    for _ in 0..5 {
        let (planar, spatial) = random_planar_chain::<6>(&mut rng);
        let q: [f64; 6] = rng.vector(3.0);
        let v: [f64; 6] = rng.vector(2.0);
        let a: [f64; 6] = rng.vector(2.0);
        let (mut d2, mut d3) = (Data::<f64, 6, 6, Planar>::new(), Data::<f64, 6, 6>::new());
        let (mut j2, mut j3) = (
            JacobianData::<f64, 6, Planar>::new(),
            JacobianData::<f64, 6>::new(),
        );
        joint_jacobians_time_variation(&planar, &mut d2, &mut j2, &q, &v).unwrap();
        joint_jacobians_time_variation(&spatial, &mut d3, &mut j3, &q, &v).unwrap();
        for k in 0..6 {
            assert_close(
                "joint Jacobian",
                &planar_as_3d(&j2.j[k]),
                &planar_part(&j3.j[k]),
                TOL,
            );
            assert_close(
                "its derivative",
                &planar_as_3d(&j2.dj[k]),
                &planar_part(&j3.dj[k]),
                TOL,
            );
        }
        let (angle, offset) = (
            rng.uniform(-3.0, 3.0),
            Vec2::new(rng.uniform(-0.3, 0.3), 0.2),
        );
        let f2 = Frame::<f64, Planar>::new(5, PlanarTransform::from_angle(angle, offset));
        let f3 = Frame::<f64>::new(
            5,
            Transform::new(
                Mat3::from_axis_angle(&Vec3::new(0.0, 0.0, 1.0), angle),
                Vec3::new(offset.x, offset.y, 0.0),
            ),
        );
        let (mut c2, mut c3) = ([PlanarMotion::ZERO; 6], [Motion::ZERO; 6]);
        forward_kinematics_acceleration(&planar, &mut d2, &q, &v, &a).unwrap();
        forward_kinematics_acceleration(&spatial, &mut d3, &q, &v, &a).unwrap();
        for reference in REFERENCES {
            frame_jacobian(&planar, &d2, &j2, &f2, reference, &mut c2).unwrap();
            frame_jacobian(&spatial, &d3, &j3, &f3, reference, &mut c3).unwrap();
            for k in 0..6 {
                assert_close(
                    "frame Jacobian",
                    &planar_as_3d(&c2[k]),
                    &planar_part(&c3[k]),
                    TOL,
                );
            }
            let a2 = frame_classical_acceleration(&d2, &f2, reference).unwrap();
            let a3 = frame_classical_acceleration(&d3, &f3, reference).unwrap();
            assert_close(
                "classical acceleration",
                &planar_as_3d(&a2),
                &planar_part(&a3),
                TOL,
            );
        }
        let (mut k2, mut k3) = (
            CentroidalData::<f64, 6, 6, Planar>::new(),
            CentroidalData::<f64, 6, 6>::new(),
        );
        centroidal_momentum(&planar, &mut d2, &mut k2, &q, &v, &a).unwrap();
        centroidal_momentum(&spatial, &mut d3, &mut k3, &q, &v, &a).unwrap();
        for k in 0..6 {
            let (p, s) = (k2.ag[k], k3.ag[k]);
            assert_close(
                "A_g",
                &[p.lin.x, p.lin.y, p.ang],
                &[s.lin.x, s.lin.y, s.ang.z],
                TOL,
            );
        }
        let (p, s) = (k2.dhg, k3.dhg);
        assert_close(
            "h_G rate",
            &[p.lin.x, p.lin.y, p.ang],
            &[s.lin.x, s.lin.y, s.ang.z],
            TOL,
        );
    }
}
