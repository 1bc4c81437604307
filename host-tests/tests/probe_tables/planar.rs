//! The algorithms on a planar model (the compiled gait model: a floating
//! pelvis in the sagittal plane, seven hinges), each with the hostile
//! number in one input: `q[0]` is the pelvis' forward position.

use crate::{numbers, setting, state, Probe, Slot};
use rodyn::algorithm::aba::aba;
use rodyn::algorithm::centroidal::{
    centroidal_map, centroidal_momentum, com_jacobian, com_velocity_acceleration, CentroidalData,
};
use rodyn::algorithm::crba::{crba, crba_with, CrbaPass};
use rodyn::algorithm::derivatives::{
    aba_derivatives, aba_derivatives_by_solves, rnea_derivatives, DerivativeData,
};
use rodyn::algorithm::energy::{center_of_mass, kinetic_energy, potential_energy};
use rodyn::algorithm::forward_dynamics::{Crba, ForwardDynamics};
use rodyn::algorithm::frames::{
    frame_acceleration, frame_classical_acceleration, frame_placement, frame_velocity,
    ReferenceFrame,
};
use rodyn::algorithm::jacobian::{
    frame_jacobian, frame_jacobian_time_variation, joint_jacobians, joint_jacobians_time_variation,
    JacobianData,
};
use rodyn::algorithm::kinematics::{
    forward_kinematics, forward_kinematics_acceleration, forward_kinematics_velocity,
};
use rodyn::algorithm::ltdl::{ltdl_factor, ltdl_solve, ltdl_solve_columns};
use rodyn::algorithm::rnea::{gravity_torques, nonlinear_effects, rnea};
use rodyn::drive::{drive_forces, DriveForces, LinearSpring, Path};
use rodyn::planar::{Planar, PlanarForce, PlanarMotion, PlanarTransform, Vec2};
use rodyn::prelude::*;
use rodyn::sim::{Integrator, Rk4, State};
use rodyn::{Endpoint, Frame};

mod compiled {
    include!(concat!(env!("OUT_DIR"), "/gait_planar.rs"));
}
use compiled::gait_planar::{body, MODEL_F64, NB, NQ, NV};

type Gait<S> = Model<S, NB, NQ, NV, Planar>;
type GaitData<S> = Data<S, NB, NV, Planar>;

/// Standing, the pelvis 1 m up.
const Q0: [f64; NQ] = [0.0, 1.0, 0.0, 0.1, 0.2, -0.3, 0.1, -0.1, 0.4, 0.0];

fn vector<S: Scalar, M: VectorOps<S>>(m: &M) -> Vec<f64> {
    (0..3).map(|k| m.component(k).to_f64()).collect()
}

fn pose<S: Scalar>(x: &PlanarTransform<S>) -> Vec<f64> {
    numbers(&[x.cos, x.sin, x.trans.x, x.trans.y])
}

/// A frame on the right foot, its placement hostile in `Frame`.
fn foot_frame<S: Scalar>(x: f64, slot: Slot) -> Frame<S, Planar> {
    let d = if slot == Slot::Frame { x } else { 0.1 };
    Frame::new(
        body::R_FOOT,
        PlanarTransform::from_translation(Vec2::new(S::from_f64(d), S::from_f64(-0.05))),
    )
}

/// The probes on the planar gait model in scalar `S`.
#[allow(clippy::too_many_lines)]
pub fn probes<S: Scalar>() -> Vec<Probe> {
    let model: Gait<S> = MODEL_F64.cast::<S>().unwrap();
    let mut probes: Vec<Probe> = Vec::new();
    macro_rules! probe {
        ($name:literal, |$model:ident, $data:ident, $q:ident, $v:ident, $a:ident, $x:ident, $slot:ident| $body:expr) => {{
            probes.push((
                $name,
                Box::new(move |$x: f64, $slot: Slot| {
                    let $model = &model;
                    let $data: &mut GaitData<S> = &mut Box::new(Data::new());
                    let ($q, $v, $a) = state::<S, NQ, NV>(&Q0, $x, $slot);
                    let _ = (&$q, &$v, &$a, $x, &$data);
                    $body
                }),
            ));
        }};
    }
    probe!("forward_kinematics", |model, data, q, v, a, x, slot| {
        forward_kinematics(model, data, &q)?;
        Ok(data.o_m_i.iter().flat_map(pose).collect())
    });
    probe!(
        "forward_kinematics_velocity",
        |model, data, q, v, a, x, slot| {
            forward_kinematics_velocity(model, data, &q, &v)?;
            Ok(data.v.iter().flat_map(vector).collect())
        }
    );
    probe!(
        "forward_kinematics_acceleration",
        |model, data, q, v, a, x, slot| {
            forward_kinematics_acceleration(model, data, &q, &v, &a)?;
            Ok(data.a.iter().flat_map(vector).collect())
        }
    );
    probe!("rnea", |model, data, q, v, a, x, slot| Ok(numbers(rnea(
        model, data, &q, &v, &a, None
    )?)));
    probe!("nonlinear_effects", |model, data, q, v, a, x, slot| Ok(
        numbers(nonlinear_effects(model, data, &q, &v, None)?)
    ));
    probe!("gravity_torques", |model, data, q, v, a, x, slot| Ok(
        numbers(gravity_torques(model, data, &q)?)
    ));
    probe!("crba", |model, data, q, v, a, x, slot| Ok(crba(
        model, data, &q
    )?
    .iter()
    .flat_map(|r| numbers(r))
    .collect()));
    probe!("crba_with", |model, data, q, v, a, x, slot| Ok(crba_with(
        model,
        data,
        &q,
        CrbaPass::RootFrame
    )?
    .iter()
    .flat_map(|r| numbers(r))
    .collect()));
    probe!("ltdl_solve", |model, data, q, v, a, x, slot| {
        crba(model, data, &q)?;
        ltdl_factor(model, data)?;
        let mut b = a;
        ltdl_solve(model, data, &mut b)?;
        Ok(numbers(&b))
    });
    probe!("ltdl_solve_columns", |model, data, q, v, a, x, slot| {
        crba(model, data, &q)?;
        ltdl_factor(model, data)?;
        let mut b: [[S; 2]; NV] = core::array::from_fn(|k| [a[k], v[k]]);
        ltdl_solve_columns(model, data, &mut b)?;
        Ok(b.iter().flat_map(|r| numbers(r)).collect())
    });
    probe!("aba", |model, data, q, v, a, x, slot| Ok(numbers(aba(
        model, data, &q, &v, &a, None
    )?)));
    probe!("forward_dynamics", |model, data, q, v, a, x, slot| {
        let f_ext = [PlanarForce::new(S::ZERO, Vec2::new(a[0], S::ZERO)); NB];
        Ok(numbers(Crba::forward_dynamics(
            model,
            data,
            &q,
            &v,
            &a,
            Some(&f_ext),
        )?))
    });
    probe!("kinetic_energy", |model, data, q, v, a, x, slot| Ok(vec![
        kinetic_energy(model, data, &q, &v)?.to_f64()
    ]));
    probe!("potential_energy", |model, data, q, v, a, x, slot| Ok(
        vec![potential_energy(model, data, &q)?.to_f64()]
    ));
    probe!("center_of_mass", |model, data, q, v, a, x, slot| {
        let (c, mass) = center_of_mass(model, data, &q)?;
        Ok(numbers(&[c.x, c.y, mass]))
    });
    probe!("frame_placement", |model, data, q, v, a, x, slot| {
        forward_kinematics(model, data, &q)?;
        Ok(pose(&frame_placement(data, &foot_frame(x, slot))?))
    });
    probe!("frame_velocity", |model, data, q, v, a, x, slot| {
        forward_kinematics_acceleration(model, data, &q, &v, &a)?;
        let frame = foot_frame(x, slot);
        let mut out = Vec::new();
        for reference in [
            ReferenceFrame::Local,
            ReferenceFrame::World,
            ReferenceFrame::LocalWorldAligned,
        ] {
            out.extend(vector(&frame_velocity(data, &frame, reference)?));
            out.extend(vector(&frame_acceleration(data, &frame, reference)?));
            out.extend(vector(&frame_classical_acceleration(
                data, &frame, reference,
            )?));
        }
        Ok(out)
    });
    probe!("frame_jacobian", |model, data, q, v, a, x, slot| {
        let mut jac = Box::new(JacobianData::new());
        joint_jacobians(model, data, &mut jac, &q)?;
        let mut out = [PlanarMotion::ZERO; NV];
        frame_jacobian(
            model,
            data,
            &jac,
            &foot_frame(x, slot),
            ReferenceFrame::LocalWorldAligned,
            &mut out,
        )?;
        let mut numbers_out: Vec<f64> = jac.j.iter().flat_map(vector).collect();
        numbers_out.extend(out.iter().flat_map(vector));
        Ok(numbers_out)
    });
    probe!(
        "frame_jacobian_time_variation",
        |model, data, q, v, a, x, slot| {
            let mut jac = Box::new(JacobianData::new());
            joint_jacobians_time_variation(model, data, &mut jac, &q, &v)?;
            let mut out = [PlanarMotion::ZERO; NV];
            frame_jacobian_time_variation(
                model,
                data,
                &jac,
                &foot_frame(x, slot),
                ReferenceFrame::World,
                &mut out,
            )?;
            let mut numbers_out: Vec<f64> = jac.dj.iter().flat_map(vector).collect();
            numbers_out.extend(out.iter().flat_map(vector));
            Ok(numbers_out)
        }
    );
    probe!("rnea_derivatives", |model, data, q, v, a, x, slot| {
        let mut deriv = Box::new(DerivativeData::<S, NB, NV, Planar>::new());
        rnea_derivatives(model, data, &mut deriv, &q, &v, &a, None)?;
        Ok(deriv
            .dtau_dq
            .iter()
            .chain(&deriv.dtau_dv)
            .flat_map(|r| numbers(r))
            .collect())
    });
    probe!("aba_derivatives", |model, data, q, v, a, x, slot| {
        let mut deriv = Box::new(DerivativeData::<S, NB, NV, Planar>::new());
        aba_derivatives(model, data, &mut deriv, &q, &v, &a, None)?;
        Ok(deriv
            .ddq_dq
            .iter()
            .chain(&deriv.ddq_dv)
            .chain(&deriv.minv)
            .flat_map(|r| numbers(r))
            .collect())
    });
    probe!(
        "aba_derivatives_by_solves",
        |model, data, q, v, a, x, slot| {
            let mut deriv = Box::new(DerivativeData::<S, NB, NV, Planar>::new());
            aba_derivatives_by_solves(model, data, &mut deriv, &q, &v, &a, None)?;
            Ok(deriv
                .ddq_dq
                .iter()
                .chain(&deriv.ddq_dv)
                .chain(&deriv.minv)
                .flat_map(|r| numbers(r))
                .collect())
        }
    );
    probe!("centroidal_map", |model, data, q, v, a, x, slot| {
        let mut cd = Box::new(CentroidalData::new());
        centroidal_map(model, data, &mut cd, &q)?;
        let mut com = [Vec2::new(S::ZERO, S::ZERO); NV];
        com_jacobian(&cd, &mut com);
        let mut out: Vec<f64> = cd.ag.iter().flat_map(vector).collect();
        out.extend(com.iter().flat_map(|c| numbers(&[c.x, c.y])));
        Ok(out)
    });
    probe!("centroidal_momentum", |model, data, q, v, a, x, slot| {
        let mut cd = Box::new(CentroidalData::new());
        centroidal_momentum(model, data, &mut cd, &q, &v, &a)?;
        let (c_dot, c_ddot) = com_velocity_acceleration(&cd);
        let mut out = vector(&cd.hg);
        out.extend(vector(&cd.dhg));
        out.extend(numbers(&[c_dot.x, c_dot.y, c_ddot.x, c_ddot.y]));
        Ok(out)
    });
    probe!("drive_forces", |model, data, q, v, a, x, slot| {
        // A spring from the right foot to a point ahead on the ground.
        let d = if slot == Slot::Frame { x } else { 0.1 };
        let path = Path::new([
            Endpoint::on_body(body::R_FOOT, Vec2::new(S::from_f64(d), S::ZERO)),
            Endpoint::in_world(Vec2::new(S::from_f64(0.5), S::ZERO)),
        ]);
        let spring = LinearSpring::new(path, setting(x, slot, 300.0), S::from_f64(0.2));
        let mut out = DriveForces::new();
        drive_forces(model, data, &q, &v, &spring, &[], &mut out)?;
        let mut numbers_out = numbers(&out.tau);
        numbers_out.extend(out.f_ext.iter().flat_map(vector));
        Ok(numbers_out)
    });
    probe!("step", |model, data, q, v, a, x, slot| {
        let mut s = State::new(q, v);
        Rk4::default().step(
            rodyn::algorithm::forward_dynamics::Aba,
            model,
            data,
            &mut s,
            setting(x, slot, 1e-3),
            &mut rodyn::sim::NoLoads,
        )?;
        let mut out = numbers(&s.q);
        out.extend(numbers(&s.v));
        Ok(out)
    });
    probes
}
