//! Every public entry point of the core that returns numbers (the
//! algorithms on a 3-D and a planar model, the drives, the sensitivities,
//! the simulation's steps and contacts, the model updates), fed NaN,
//! ±infinity, 1e300, 1e154 (whose square overflows f64), a subnormal and
//! zero, in f64 and in f32: each call returns finite numbers or an error
//! whose message names something (no panic, no NaN as `Ok`, no anonymous
//! "gain N").
//!
//! The bad number goes into one input at a time (a configuration entry —
//! for a floating base its x position —, the whole velocity, the whole
//! acceleration or torque, a frame's placement, a setting). The entry
//! points are tables (here and in `probe_tables/`);
//! [`every_public_function_is_listed`] reads the `pub fn`s of the core's
//! algorithms, drives, sensitivities, simulation and updates and fails for
//! any that is neither probed nor listed with the reason it is not, so a
//! new API cannot skip the probe unnoticed.

mod probe_tables;

use rodyn::algorithm::aba::aba;
use rodyn::algorithm::centroidal::{
    centroidal_map, centroidal_map_time_variation, centroidal_momentum, CentroidalData,
};
use rodyn::algorithm::centroidal::{com_jacobian, com_velocity_acceleration};
use rodyn::algorithm::constrained_dynamics::{
    constrained_forward_dynamics, impulse_dynamics, ConstraintData, ConstraintSettings, Contact,
};
use rodyn::algorithm::constrained_dynamics::{constrained_forward_dynamics_with, ConstraintMethod};
use rodyn::algorithm::contact_inverse_dynamics::{
    contact_inverse_dynamics, ContactInverseDynamicsData, ContactInverseDynamicsSettings,
};
use rodyn::algorithm::crba::{
    crba, crba_planned, crba_planned_with, crba_with, CrbaPass, CrbaPlan,
};
use rodyn::algorithm::derivatives::aba_derivatives_by_solves;
use rodyn::algorithm::derivatives::{aba_derivatives, rnea_derivatives, DerivativeData};
use rodyn::algorithm::energy::{center_of_mass, kinetic_energy, potential_energy};
use rodyn::algorithm::forward_dynamics::{Crba, ForwardDynamics};
use rodyn::algorithm::frame_chain::{
    chain_jacobian, chain_kinematics, chains_jacobians, frame_jacobian_from_q,
    frame_kinematics_from_q, FrameChain, FrameMotion,
};
use rodyn::algorithm::frames::{
    frame_acceleration, frame_classical_acceleration, frame_placement, frame_velocity,
    ReferenceFrame,
};
use rodyn::algorithm::inverse_kinematics::{solve, IkData, IkSettings};
use rodyn::algorithm::inverse_kinematics::{solve_with_fallback, step};
use rodyn::algorithm::jacobian::{
    frame_jacobian, frame_jacobian_time_variation, joint_jacobians, joint_jacobians_time_variation,
    JacobianData,
};
use rodyn::algorithm::kinematics::{
    forward_kinematics, forward_kinematics_acceleration, forward_kinematics_velocity,
};
use rodyn::algorithm::ltdl::ltdl_solve_columns;
use rodyn::algorithm::ltdl::{ltdl_factor, ltdl_solve};
use rodyn::algorithm::rnea::{gravity_torques, nonlinear_effects, rnea};
use rodyn::prelude::*;
use rodyn::sim::manifold::configuration_rate;
use rodyn::sim::time_stepping::{time_step, TimeSteppingData, TimeSteppingSettings};
use rodyn::sim::State;
use rodyn::Frame;
use rodyn_host_tests::contact_fixture::{solo12, SOLO_NB, SOLO_NQ, SOLO_NV};
use rodyn_host_tests::fixture::Fixture;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// The bad numbers, as f64 (cast to the scalar under test).
const BAD: [f64; 8] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    1e300,
    1e154,
    -1e154,
    1e-310,
    0.0,
];

/// Which input gets the bad number.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Slot {
    /// `q[0]` (the base's x position on a floating base).
    Configuration,
    /// Every entry of `v`.
    Velocity,
    /// Every entry of `a` or `τ`.
    AccelerationOrTorque,
    /// A frame's (or a contact's) placement translation.
    Frame,
    /// A setting (a damping, a friction, a tolerance).
    Setting,
}

const SLOTS: [Slot; 5] = [
    Slot::Configuration,
    Slot::Velocity,
    Slot::AccelerationOrTorque,
    Slot::Frame,
    Slot::Setting,
];

/// A call's outcome: its numbers, or its error.
type Outcome = Result<Vec<f64>, Error>;
/// One entry point: its name (as in the source) and the call, given the
/// bad number and where it goes.
type Probe = (&'static str, Box<dyn Fn(f64, Slot) -> Outcome>);

const PANDA_NB: usize = 7;
/// The Panda's configuration the probes start from.
const PANDA_Q0: [f64; 7] = [0.1, -0.4, 0.2, -1.8, 0.1, 1.5, 0.7];

/// The Panda (a fixed-base arm, seven hinges) in `S`.
fn panda<S: Scalar>() -> Model<S, 7, 7, 7> {
    Fixture::load_named("panda")
        .unwrap()
        .model::<7, 7, 7>()
        .unwrap()
        .cast::<S>()
        .unwrap()
}

fn motion<M: VectorOps<S>, S: Scalar>(m: &M) -> Vec<f64> {
    (0..6).map(|k| m.component(k).to_f64()).collect()
}

fn numbers<S: Scalar>(x: &[S]) -> Vec<f64> {
    x.iter().map(|v| v.to_f64()).collect()
}

fn pose<S: Scalar>(t: &Transform<S>) -> Vec<f64> {
    let mut out = numbers(&t.trans.to_array());
    for row in t.rot.m {
        out.extend(numbers(&row));
    }
    out
}

/// The state with the bad number in its slot.
fn state<S: Scalar, const NQ: usize, const NV: usize>(
    q0: &[f64; NQ],
    x: f64,
    slot: Slot,
) -> ([S; NQ], [S; NV], [S; NV]) {
    let mut q = q0.map(S::from_f64);
    let mut v = core::array::from_fn(|k| S::from_f64(0.3 - 0.05 * k as f64));
    let mut a = core::array::from_fn(|k| S::from_f64(0.2 + 0.1 * k as f64));
    match slot {
        Slot::Configuration => q[0] = S::from_f64(x),
        Slot::Velocity => v = [S::from_f64(x); NV],
        Slot::AccelerationOrTorque => a = [S::from_f64(x); NV],
        Slot::Frame | Slot::Setting => {}
    }
    (q, v, a)
}

fn frame_at<S: Scalar>(body: usize, x: f64, slot: Slot) -> Frame<S> {
    let offset = if slot == Slot::Frame { x } else { 0.1 };
    Frame::new(
        body,
        Transform::from_translation(Vec3::new(S::from_f64(offset), S::ZERO, S::from_f64(0.1))),
    )
}

fn setting<S: Scalar>(x: f64, slot: Slot, good: f64) -> S {
    S::from_f64(if slot == Slot::Setting { x } else { good })
}

/// The probes on the Panda (fixed base) in scalar `S`.
#[allow(clippy::too_many_lines)]
fn panda_probes<S: Scalar>() -> Vec<Probe> {
    let model = panda::<S>();
    let q0 = PANDA_Q0;
    let m = move || model;
    let mut probes: Vec<Probe> = Vec::new();
    macro_rules! probe {
        ($name:literal, |$model:ident, $data:ident, $q:ident, $v:ident, $a:ident, $x:ident, $slot:ident| $body:expr) => {{
            let model = m();
            probes.push((
                $name,
                Box::new(move |$x: f64, $slot: Slot| {
                    let $model = &model;
                    let $data = &mut Box::new(Data::<S, 7, 7>::new());
                    let ($q, $v, $a) = state::<S, 7, 7>(&q0, $x, $slot);
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
            Ok(data.v.iter().flat_map(motion).collect())
        }
    );
    probe!(
        "forward_kinematics_acceleration",
        |model, data, q, v, a, x, slot| {
            forward_kinematics_acceleration(model, data, &q, &v, &a)?;
            Ok(data.a.iter().flat_map(motion).collect())
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
    for pass in [CrbaPass::Local, CrbaPass::RootFrame] {
        let model = m();
        probes.push((
            "crba_with",
            Box::new(move |x, slot| {
                let mut data = Box::new(Data::new());
                let (q, _, _) = state::<S, 7, 7>(&q0, x, slot);
                Ok(crba_with(&model, &mut data, &q, pass)?
                    .iter()
                    .flat_map(|r| numbers(r))
                    .collect())
            }),
        ));
    }
    probe!("crba_planned", |model, data, q, v, a, x, slot| {
        let plan = CrbaPlan::new(model);
        Ok(crba_planned(model, &plan, data, &q)?
            .iter()
            .flat_map(|r| numbers(r))
            .collect())
    });
    probe!("crba_planned_with", |model, data, q, v, a, x, slot| {
        let plan = CrbaPlan::new(model);
        Ok(
            crba_planned_with(model, &plan, data, &q, CrbaPass::RootFrame)?
                .iter()
                .flat_map(|r| numbers(r))
                .collect(),
        )
    });
    // The textbook CRBA, under its `fn`'s name.
    probe!("crba", |model, data, q, v, a, x, slot| Ok(
        rodyn::algorithm::crba::textbook::crba(model, &q)?
            .iter()
            .flat_map(|r| numbers(r))
            .collect()
    ));
    probe!(
        "forward_dynamics_planned",
        |model, data, q, v, a, x, slot| {
            let plan = CrbaPlan::new(model);
            Ok(numbers(Crba::forward_dynamics_planned(
                model, &plan, data, &q, &v, &a, None,
            )?))
        }
    );
    probe!("ltdl_solve_columns", |model, data, q, v, a, x, slot| {
        crba(model, data, &q)?;
        ltdl_factor(model, data)?;
        let mut b: [[S; 2]; 7] = core::array::from_fn(|k| [a[k], v[k]]);
        ltdl_solve_columns(model, data, &mut b)?;
        Ok(b.iter().flat_map(|r| numbers(r)).collect())
    });
    probe!("ltdl_factor", |model, data, q, v, a, x, slot| {
        crba(model, data, &q)?;
        ltdl_factor(model, data)?;
        Ok(data.ltdl.iter().flat_map(|r| numbers(r)).collect())
    });
    probe!("ltdl_solve", |model, data, q, v, a, x, slot| {
        crba(model, data, &q)?;
        ltdl_factor(model, data)?;
        let mut b = a;
        ltdl_solve(model, data, &mut b)?;
        Ok(numbers(&b))
    });
    probe!("aba", |model, data, q, v, a, x, slot| Ok(numbers(aba(
        model, data, &q, &v, &a, None
    )?)));
    probe!("forward_dynamics", |model, data, q, v, a, x, slot| Ok(
        numbers(Crba::forward_dynamics(model, data, &q, &v, &a, None)?)
    ));
    probe!("kinetic_energy", |model, data, q, v, a, x, slot| Ok(vec![
        kinetic_energy(model, data, &q, &v)?.to_f64()
    ]));
    probe!("potential_energy", |model, data, q, v, a, x, slot| Ok(
        vec![potential_energy(model, data, &q)?.to_f64()]
    ));
    probe!("center_of_mass", |model, data, q, v, a, x, slot| {
        let (c, mass) = center_of_mass(model, data, &q)?;
        let mut out = numbers(&c.to_array());
        out.push(mass.to_f64());
        Ok(out)
    });
    // The frame chain: the frame's placement (a hostile value in its
    // placement) and q, v from the state.
    let lwa = ReferenceFrame::LocalWorldAligned;
    let kinematics = |m: FrameMotion<S>| {
        let mut out = pose(&m.placement);
        out.extend(motion(&m.velocity));
        out.extend(motion(&m.dj_v));
        out
    };
    probe!("frame_jacobian_from_q", |model, data, q, v, a, x, slot| {
        let mut j = [Motion::ZERO; 7];
        let placement = frame_jacobian_from_q(model, &q, &frame_at(6, x, slot), lwa, &mut j)?;
        let mut out = pose(&placement);
        out.extend(j.iter().flat_map(motion));
        Ok(out)
    });
    probe!("try_new", |model, data, q, v, a, x, slot| {
        let chain = FrameChain::try_new(model, &frame_at(6, x, slot))?;
        let mut j = [Motion::ZERO; 7];
        let placement = chain_jacobian(model, &q, &chain, lwa, &mut j)?;
        let mut out = pose(&placement);
        out.extend(j.iter().flat_map(motion));
        Ok(out)
    });
    probe!("chain_jacobian", |model, data, q, v, a, x, slot| {
        let chain = FrameChain::try_new(model, &frame_at(6, x, slot))?;
        let mut j = [Motion::ZERO; 7];
        let placement = chain_jacobian(model, &q, &chain, ReferenceFrame::World, &mut j)?;
        let mut out = pose(&placement);
        out.extend(j.iter().flat_map(motion));
        Ok(out)
    });
    probe!(
        "frame_kinematics_from_q",
        |model, data, q, v, a, x, slot| {
            let mut j = [Motion::ZERO; 7];
            let m = frame_kinematics_from_q(model, &q, &v, &frame_at(6, x, slot), lwa, &mut j)?;
            Ok(kinematics(m))
        }
    );
    probe!("chain_kinematics", |model, data, q, v, a, x, slot| {
        let chain = FrameChain::try_new(model, &frame_at(6, x, slot))?;
        let mut j = [Motion::ZERO; 7];
        let m = chain_kinematics(model, &q, &v, &chain, ReferenceFrame::Local, &mut j)?;
        Ok(kinematics(m))
    });
    probe!("chains_jacobians", |model, data, q, v, a, x, slot| {
        let chains = [
            FrameChain::try_new(model, &frame_at(6, x, slot))?,
            FrameChain::try_new(model, &frame_at(3, 0.0, slot))?,
        ];
        let mut j = [[Motion::ZERO; 7]; 2];
        let placements = chains_jacobians(model, data, &q, &chains, lwa, &mut j)?;
        let mut out: Vec<f64> = placements.iter().flat_map(pose).collect();
        out.extend(j.iter().flatten().flat_map(motion));
        Ok(out)
    });
    probe!("frame_placement", |model, data, q, v, a, x, slot| {
        forward_kinematics(model, data, &q)?;
        Ok(pose(&frame_placement(data, &frame_at(6, x, slot))?))
    });
    for (name, which) in [
        ("frame_velocity", 0),
        ("frame_acceleration", 1),
        ("frame_classical_acceleration", 2),
    ] {
        let model = m();
        probes.push((
            name,
            Box::new(move |x, slot| {
                let mut data = Box::new(Data::new());
                let (q, v, a) = state::<S, 7, 7>(&q0, x, slot);
                forward_kinematics_acceleration(&model, &mut data, &q, &v, &a)?;
                let frame = frame_at(6, x, slot);
                let mut out = Vec::new();
                for reference in [
                    ReferenceFrame::Local,
                    ReferenceFrame::World,
                    ReferenceFrame::LocalWorldAligned,
                ] {
                    let m = match which {
                        0 => frame_velocity(&data, &frame, reference)?,
                        1 => frame_acceleration(&data, &frame, reference)?,
                        _ => frame_classical_acceleration(&data, &frame, reference)?,
                    };
                    out.extend(motion(&m));
                }
                Ok(out)
            }),
        ));
    }
    probe!("joint_jacobians", |model, data, q, v, a, x, slot| {
        let mut jac = Box::new(JacobianData::new());
        joint_jacobians(model, data, &mut jac, &q)?;
        Ok(jac.j.iter().flat_map(motion).collect())
    });
    probe!(
        "joint_jacobians_time_variation",
        |model, data, q, v, a, x, slot| {
            let mut jac = Box::new(JacobianData::new());
            joint_jacobians_time_variation(model, data, &mut jac, &q, &v)?;
            Ok(jac.dj.iter().flat_map(motion).collect())
        }
    );
    probe!("frame_jacobian", |model, data, q, v, a, x, slot| {
        let mut jac = Box::new(JacobianData::new());
        joint_jacobians(model, data, &mut jac, &q)?;
        let mut out = [Motion::ZERO; 7];
        frame_jacobian(
            model,
            data,
            &jac,
            &frame_at(6, x, slot),
            ReferenceFrame::LocalWorldAligned,
            &mut out,
        )?;
        Ok(out.iter().flat_map(motion).collect())
    });
    probe!(
        "frame_jacobian_time_variation",
        |model, data, q, v, a, x, slot| {
            let mut jac = Box::new(JacobianData::new());
            joint_jacobians_time_variation(model, data, &mut jac, &q, &v)?;
            let mut out = [Motion::ZERO; 7];
            frame_jacobian_time_variation(
                model,
                data,
                &jac,
                &frame_at(6, x, slot),
                ReferenceFrame::Local,
                &mut out,
            )?;
            Ok(out.iter().flat_map(motion).collect())
        }
    );
    probe!("rnea_derivatives", |model, data, q, v, a, x, slot| {
        let mut deriv = Box::new(DerivativeData::<S, PANDA_NB, 7>::new());
        rnea_derivatives(model, data, &mut deriv, &q, &v, &a, None)?;
        Ok(deriv
            .dtau_dq
            .iter()
            .chain(&deriv.dtau_dv)
            .flat_map(|r| numbers(r))
            .collect())
    });
    probe!("aba_derivatives", |model, data, q, v, a, x, slot| {
        let mut deriv = Box::new(DerivativeData::<S, PANDA_NB, 7>::new());
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
            let mut deriv = Box::new(DerivativeData::<S, PANDA_NB, 7>::new());
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
    probe!("step", |model, data, q, v, a, x, slot| {
        let mut ws = Box::new(IkData::new());
        let mut q = q;
        let e = step(
            model,
            data,
            &mut ws,
            &frame_at(6, x, slot),
            &ik_target(x, slot),
            setting(x, slot, 1e-2),
            &mut q,
        )?;
        let mut out = numbers(&q);
        out.extend(motion(&e));
        Ok(out)
    });
    probe!("solve_with_fallback", |model, data, q, v, a, x, slot| {
        let mut ws = Box::new(IkData::new());
        let settings = IkSettings::new()
            .with_tolerance(setting(x, slot, 1e-3))
            .with_damping(setting(x, slot, 1e-2));
        let mut q = q;
        let home = PANDA_Q0.map(S::from_f64);
        solve_with_fallback(
            model,
            data,
            &mut ws,
            &frame_at(6, x, slot),
            &ik_target(x, slot),
            &settings,
            &home,
            &mut q,
        )?;
        Ok(numbers(&q))
    });
    probe!("solve", |model, data, q, v, a, x, slot| {
        let mut ws = Box::new(IkData::new());
        let settings = IkSettings::new().with_tolerance(setting(x, slot, 1e-3));
        let mut q = q;
        solve(
            model,
            data,
            &mut ws,
            &frame_at(6, x, slot),
            &ik_target(x, slot),
            &settings,
            &mut q,
        )?;
        Ok(numbers(&q))
    });
    probes
}

/// An inverse-kinematics target within the Panda's reach, its position
/// hostile in `Frame`.
fn ik_target<S: Scalar>(x: f64, slot: Slot) -> Transform<S> {
    let reach = if slot == Slot::Frame { x } else { 0.4 };
    Transform::from_translation(Vec3::new(
        S::from_f64(reach),
        S::from_f64(0.1),
        S::from_f64(0.5),
    ))
}

/// Solo12's four feet as point contacts (bodies 3, 6, 9, 12).
fn contacts<S: Scalar>(x: f64, slot: Slot) -> Vec<Contact<S>> {
    [3, 6, 9, 12]
        .iter()
        .map(|&b| Contact::point(frame_at(b, x, slot), Vec3::ZERO))
        .collect()
}

/// The probes on Solo12 (a floating base, feet as contacts) in `S`.
#[allow(clippy::too_many_lines)]
fn solo_probes<S: Scalar>() -> Vec<Probe> {
    let model = solo12().cast::<S>().unwrap();
    let mut q0 = [0.0; SOLO_NQ];
    q0[2] = 0.3;
    q0[6] = 1.0;
    for (k, entry) in q0[7..].iter_mut().enumerate() {
        *entry = 0.3 * ((k % 3) as f64 - 1.0);
    }
    let mut probes: Vec<Probe> = Vec::new();
    macro_rules! probe {
        ($name:literal, |$model:ident, $data:ident, $q:ident, $v:ident, $a:ident, $x:ident, $slot:ident| $body:expr) => {{
            let model = model;
            probes.push((
                $name,
                Box::new(move |$x: f64, $slot: Slot| {
                    let $model = &model;
                    let $data = &mut Box::new(Data::new());
                    let ($q, $v, $a) = state::<S, SOLO_NQ, SOLO_NV>(&q0, $x, $slot);
                    let mut q = $q;
                    // A bad base orientation is `Configuration`'s business
                    // only through the position: keep the quaternion unit.
                    let _ = $model.normalize(&mut q);
                    let $q = q;
                    let _ = (&$q, &$v, &$a, $x);
                    $body
                }),
            ));
        }};
    }
    probe!("centroidal_map", |model, data, q, v, a, x, slot| {
        let mut cd = Box::new(CentroidalData::new());
        centroidal_map(model, data, &mut cd, &q)?;
        Ok(cd.ag.iter().flat_map(motion).collect())
    });
    probe!("com_jacobian", |model, data, q, v, a, x, slot| {
        let mut cd = Box::new(CentroidalData::new());
        centroidal_map(model, data, &mut cd, &q)?;
        let mut jc = [Vec3::ZERO; SOLO_NV];
        com_jacobian(&cd, &mut jc);
        Ok(jc.iter().flat_map(|c| numbers(&c.to_array())).collect())
    });
    probe!("centroidal_momentum", |model, data, q, v, a, x, slot| {
        let mut cd = Box::new(CentroidalData::new());
        centroidal_momentum(model, data, &mut cd, &q, &v, &a)?;
        let mut out = motion(&cd.hg);
        out.extend(motion(&cd.dhg));
        Ok(out)
    });
    probe!(
        "com_velocity_acceleration",
        |model, data, q, v, a, x, slot| {
            let mut cd = Box::new(CentroidalData::new());
            centroidal_momentum(model, data, &mut cd, &q, &v, &a)?;
            let (c_dot, c_ddot) = com_velocity_acceleration(&cd);
            let mut out = numbers(&c_dot.to_array());
            out.extend(numbers(&c_ddot.to_array()));
            Ok(out)
        }
    );
    probe!(
        "centroidal_map_time_variation",
        |model, data, q, v, a, x, slot| {
            let mut cd = Box::new(CentroidalData::new());
            let mut dag = [Force::ZERO; SOLO_NV];
            centroidal_map_time_variation(model, data, &mut cd, &q, &v, &mut dag)?;
            Ok(dag.iter().flat_map(motion).collect())
        }
    );
    probe!(
        "constrained_forward_dynamics",
        |model, data, q, v, a, x, slot| {
            let mut cdata = Box::new(ConstraintData::<S, SOLO_NV, 12>::new());
            let settings = ConstraintSettings::new().with_damping(setting(x, slot, 0.0));
            let (ddq, lambda) = constrained_forward_dynamics(
                model,
                data,
                &mut cdata,
                &q,
                &v,
                &a,
                &contacts(x, slot),
                &settings,
            )?;
            Ok(numbers(ddq).into_iter().chain(numbers(lambda)).collect())
        }
    );
    for method in [ConstraintMethod::Kkt, ConstraintMethod::ArticulatedBody] {
        probes.push((
            "constrained_forward_dynamics_with",
            Box::new(move |x, slot| {
                let mut data = Box::new(Data::new());
                let (mut q, v, a) = state::<S, SOLO_NQ, SOLO_NV>(&q0, x, slot);
                let _ = model.normalize(&mut q);
                let mut cdata = Box::new(ConstraintData::<S, SOLO_NV, 12>::new());
                let settings = ConstraintSettings::new().with_damping(setting(x, slot, 0.0));
                let (ddq, lambda) = constrained_forward_dynamics_with(
                    method,
                    &model,
                    &mut data,
                    &mut cdata,
                    &q,
                    &v,
                    &a,
                    &contacts(x, slot),
                    &settings,
                )?;
                Ok(numbers(ddq).into_iter().chain(numbers(lambda)).collect())
            }),
        ));
    }
    probe!("impulse_dynamics", |model, data, q, v, a, x, slot| {
        let mut cdata = Box::new(ConstraintData::<S, SOLO_NV, 12>::new());
        let (v_plus, impulses) = impulse_dynamics(
            model,
            data,
            &mut cdata,
            &q,
            &v,
            &contacts(x, slot),
            setting(x, slot, 0.5),
            S::ZERO,
        )?;
        Ok(numbers(v_plus)
            .into_iter()
            .chain(numbers(impulses))
            .collect())
    });
    probe!(
        "contact_inverse_dynamics",
        |model, data, q, v, a, x, slot| {
            let mut iddata = Box::new(ContactInverseDynamicsData::<S, SOLO_NV, 12>::new());
            let settings = ContactInverseDynamicsSettings::floating_base(setting(x, slot, 0.8));
            let tau = contact_inverse_dynamics(
                model,
                data,
                &mut iddata,
                &q,
                &v,
                &a,
                &contacts(x, slot),
                &ConstraintSettings::default(),
                &settings,
            )?;
            Ok(numbers(tau))
        }
    );
    probe!("configuration_rate", |model, data, q, v, a, x, slot| {
        // The base's quaternion turns v's angular part into q̇.
        let _: &mut Box<Data<S, SOLO_NB, SOLO_NV>> = data;
        Ok(numbers(&configuration_rate(model, &q, &v)?))
    });
    probe!("time_step", |model, data, q, v, a, x, slot| {
        let mut sdata = Box::new(TimeSteppingData::<S, SOLO_NV, 12, 4>::new());
        let points: [Frame<S>; 4] = core::array::from_fn(|k| frame_at(3 * k + 3, x, slot));
        let settings = TimeSteppingSettings::with_friction(setting(x, slot, 0.8));
        let mut s = State::new(q, v);
        time_step(
            model,
            data,
            &mut sdata,
            &mut s,
            &a,
            &[S::ZERO; SOLO_NV],
            &points,
            &settings,
            S::from_f64(1e-3),
        )?;
        Ok(numbers(&s.q).into_iter().chain(numbers(&s.v)).collect())
    });
    probes
}

/// Runs every probe with every bad number in every slot: the failures,
/// and how many calls answered with numbers and with errors.
fn run(probes: &[Probe], precision: &str) -> (Vec<String>, usize, usize) {
    let mut failures = Vec::new();
    let (mut answered, mut refused) = (0, 0);
    for (name, call) in probes {
        for x in BAD {
            for slot in SLOTS {
                let outcome = catch_unwind(AssertUnwindSafe(|| call(x, slot)));
                let what = format!("{name} ({precision}) with {x:e} in {slot:?}");
                match outcome {
                    Err(_) => failures.push(format!("{what}: panicked")),
                    Ok(Ok(numbers)) => {
                        answered += 1;
                        if let Some(k) = numbers.iter().position(|v| !v.is_finite()) {
                            failures.push(format!("{what}: Ok with entry {k} = {}", numbers[k]));
                        }
                    }
                    Ok(Err(error)) => {
                        refused += 1;
                        let message = error.to_string();
                        if message.contains("gain ") || message.len() < 12 {
                            failures.push(format!("{what}: unclear error \"{message}\""));
                        }
                    }
                }
            }
        }
    }
    (failures, answered, refused)
}

/// A table of probes: its name, and its probes in f64 and in f32.
type Table<'a> = (&'a str, fn() -> Vec<Probe>, fn() -> Vec<Probe>);

/// Runs `tables` in f64 and in f32 and fails on any finding.
fn probe_all(tables: &[Table<'_>]) {
    let mut failures = Vec::new();
    for (table, in_f64, in_f32) in tables {
        for (found, answered, refused) in [run(&in_f64(), "f64"), run(&in_f32(), "f32")] {
            eprintln!("{table}: {answered} calls answered with finite numbers, {refused} refused");
            // Both kinds occur: the bad numbers reach the calls (NaN is
            // always refused), and the good slots let them answer (zero,
            // subnormals).
            assert!(answered > 0 && refused > 0, "{table}");
            failures.extend(found);
        }
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn every_entry_point_gives_finite_numbers_or_a_named_error() {
    probe_all(&[
        ("panda", panda_probes::<f64>, panda_probes::<f32>),
        ("solo12", solo_probes::<f64>, solo_probes::<f32>),
    ]);
}

#[test]
fn the_planar_algorithms_give_finite_numbers_or_a_named_error() {
    use probe_tables::planar::probes;
    probe_all(&[("planar gait", probes::<f64>, probes::<f32>)]);
}

#[test]
fn the_drives_and_sensitivities_give_finite_numbers_or_a_named_error() {
    use probe_tables::drives::probes;
    probe_all(&[("drives", probes::<f64>, probes::<f32>)]);
}

#[test]
fn the_formulas_give_finite_numbers_or_a_named_error() {
    use probe_tables::formulas::probes;
    probe_all(&[("formulas", probes::<f64>, probes::<f32>)]);
}

#[test]
fn the_simulation_gives_finite_numbers_or_a_named_error() {
    use probe_tables::sim::probes;
    probe_all(&[("simulation", probes::<f64>, probes::<f32>)]);
}

#[test]
fn model_updates_give_finite_parameters_or_a_named_error() {
    use probe_tables::update::probes;
    probe_all(&[("updates", probes::<f64>, probes::<f32>)]);
}

/// Why a public function is not probed: it returns no numbers, or it
/// takes no input a caller could make hostile.
const NO_NUMBERS: &str = "returns no numbers";

/// Public functions of the core that the probe does not call, each with
/// the reason. A new `pub fn` that returns numbers belongs in the probe
/// tables, not here.
const NOT_PROBED: &[(&str, &str)] = &[
    ("new", "constructors of workspaces, plans and settings"),
    ("default_for", "a settings constructor (a CRBA pass)"),
    ("with_friction", "a settings constructor"),
    ("floating_base", "a settings constructor"),
    ("fixed_base", "a settings constructor"),
    (
        "thelen_2003_in",
        "a parameter constructor; validate checks it",
    ),
    (
        "de_groote_2016_in",
        "a parameter constructor; validate checks it",
    ),
    ("cast", "a scalar conversion of caller values"),
    ("clear", "resets a workspace to zero"),
    ("is_for", "a plan's bookkeeping (bool)"),
    ("constrained_rows", "a count of rows"),
    ("check", NO_NUMBERS),
    ("check_problem", NO_NUMBERS),
    ("check_finite", NO_NUMBERS),
    ("validate", NO_NUMBERS),
    (
        "mass",
        "a reader of CentroidalData, probed through centroidal_map",
    ),
    (
        "com",
        "a reader of CentroidalData, probed through centroidal_map",
    ),
    ("residual_norm", "a reader of ContactInverseDynamicsData"),
    (
        "active",
        "the double buffer's active model, read by stage_update's probe",
    ),
    ("split", "the double buffer's protocol: no numbers"),
    (
        "read",
        "the double buffer's protocol: runs the caller's closure",
    ),
    (
        "stage",
        "the double buffer's protocol: runs the caller's update, probed as stage_update",
    ),
    ("publish", "the double buffer's protocol (bool)"),
    (
        "cholesky_in_place",
        "dense algebra on a caller's matrix, its Err the failing column; the KKT and \
         contact solvers that call it check their results",
    ),
    (
        "act_forces",
        "a CRBA step on caller values (crate-internal use)",
    ),
    ("after", "a CRBA step on caller values (crate-internal use)"),
    ("cos_sin_in", "a CRBA frame helper on caller values"),
    ("rotate_inertia", "a CRBA step on caller values"),
    ("translation", "a CRBA step on caller values"),
    ("turn_about", "a CRBA step on caller values"),
];

/// The probed names.
fn probed() -> Vec<&'static str> {
    let mut names: Vec<&str> = [
        panda_probes::<f64>(),
        solo_probes::<f64>(),
        probe_tables::planar::probes::<f64>(),
        probe_tables::drives::probes::<f64>(),
        probe_tables::formulas::probes::<f64>(),
        probe_tables::sim::probes::<f64>(),
        probe_tables::update::probes::<f64>(),
    ]
    .iter()
    .flatten()
    .map(|(n, _)| *n)
    .collect();
    names.sort_unstable();
    names.dedup();
    names
}

/// Where the core's public functions live: the algorithms (and CRBA's
/// turned frames, which stand with the geometry below them), the drives,
/// the sensitivities, the simulation, the model updates, frames and
/// endpoints.
const SOURCES: [&str; 8] = [
    "algorithm",
    "space/turned_frame.rs",
    "drive",
    "sensitivity",
    "sim",
    "update",
    "frame.rs",
    "endpoint.rs",
];

/// Every `pub fn` of [`SOURCES`] is probed or listed in [`NOT_PROBED`];
/// the listed ones all exist, and none is both.
#[test]
fn every_public_function_is_listed() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../crates/rodyn/src");
    let mut found = std::collections::BTreeSet::new();
    let mut dirs = Vec::new();
    let mut files = Vec::new();
    for source in SOURCES {
        let path = root.join(source);
        if path.is_dir() {
            dirs.push(path);
        } else {
            files.push(path);
        }
    }
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                files.push(path);
            }
        }
    }
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        // Unit tests at the end of a file are not API.
        let text = text.split("#[cfg(test)]").next().unwrap_or("");
        let text = text.split("#[cfg(all(test").next().unwrap_or("");
        for line in text.lines() {
            let line = line.trim_start();
            if let Some(rest) = line.strip_prefix("pub fn ") {
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                found.insert(name);
            }
        }
    }
    let probed = probed();
    let listed: Vec<&str> = NOT_PROBED.iter().map(|(n, _)| *n).collect();
    let missing: Vec<&String> = found
        .iter()
        .filter(|n| !probed.contains(&n.as_str()) && !listed.contains(&n.as_str()))
        .collect();
    assert!(
        missing.is_empty(),
        "public functions neither probed nor listed in NOT_PROBED: {missing:?}"
    );
    let stale: Vec<&&str> = listed
        .iter()
        .chain(&probed)
        .filter(|n| !found.contains(**n))
        .collect();
    assert!(stale.is_empty(), "listed but not found: {stale:?}");
    let both: Vec<&&str> = listed.iter().filter(|n| probed.contains(n)).collect();
    assert!(both.is_empty(), "probed and listed as not probed: {both:?}");
    eprintln!(
        "{} public function names: {} probed, {} listed as not probed",
        found.len(),
        probed.len(),
        listed.len()
    );
}
