//! The drive elements, their forces and derivatives, and the
//! sensitivities to drive inputs, on the Panda: a spring, a cubic spring,
//! a damper, a motor and both muscles, the springs and muscles along paths
//! from the hand to the world or down the arm.
//!
//! The slots: `Configuration` is `q[0]` (and, for the elements' own
//! functions, the path length), `Velocity` the velocity (the lengthening
//! velocity), `AccelerationOrTorque` every drive input (the motor's
//! current, the muscles' activations), `Frame` a path point on the hand,
//! `Setting` every element's parameter (stiffness, damping, gear ratio,
//! maximal isometric force).

use crate::{numbers, panda, setting, state, Outcome, Probe, Slot, PANDA_Q0};
use rodyn::algorithm::derivatives::DerivativeData;
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::algorithm::jacobian::{joint_jacobians_time_variation, JacobianData};
use rodyn::algorithm::kinematics::forward_kinematics_velocity;
use rodyn::drive::{
    aba_derivatives_with_drives, drive_force_derivatives, drive_forces,
    forward_dynamics_with_drives, DeGrooteMuscle, DeGrooteParameters, DriveDerivativeState,
    DriveDerivatives, DriveForces, JointMotor, LinearDamper, LinearSpring, NonlinearSpring, Path,
    ThelenMuscle, ThelenParameters,
};
use rodyn::prelude::*;
use rodyn::sensitivity::{forward_dynamics_and_sensitivity, input_sensitivity};
use rodyn::Endpoint;

/// Drive inputs: the motor's current, the two muscles' activations.
const NU: usize = 3;

/// From a point on the hand (`Frame` moves it) to a point in the world.
fn hand_path<S: Scalar>(x: f64, slot: Slot) -> Path<S, Spatial, 2> {
    let tip = if slot == Slot::Frame { x } else { 0.05 };
    Path::new([
        Endpoint::on_body(6, Vec3::new(S::from_f64(tip), S::ZERO, S::from_f64(0.1))),
        Endpoint::in_world(Vec3::new(S::from_f64(0.3), S::ZERO, S::from_f64(0.8))),
    ])
}

/// Down the arm, from the upper arm to the hand (a muscle's path).
fn arm_path<S: Scalar>(x: f64, slot: Slot) -> Path<S, Spatial, 2> {
    let tip = if slot == Slot::Frame { x } else { 0.0 };
    Path::new([
        Endpoint::on_body(2, Vec3::new(S::ZERO, S::from_f64(0.05), S::ZERO)),
        Endpoint::on_body(6, Vec3::new(S::from_f64(tip), S::ZERO, S::ZERO)),
    ])
}

fn thelen<S: Scalar>(x: f64, slot: Slot) -> ThelenMuscle<S, Spatial, 2> {
    let params = ThelenParameters::thelen_2003_in(
        setting(x, slot, 300.0),
        S::from_f64(0.3),
        S::from_f64(0.3),
        S::from_f64(0.1),
    );
    ThelenMuscle::new(arm_path(x, slot), params, 1)
}

fn de_groote<S: Scalar>(x: f64, slot: Slot) -> DeGrooteMuscle<S, Spatial, 2> {
    let params = DeGrooteParameters::de_groote_2016_in(
        setting(x, slot, 300.0),
        S::from_f64(0.3),
        S::from_f64(0.3),
        S::from_f64(0.1),
    );
    DeGrooteMuscle::new(arm_path(x, slot), params, 2)
}

type Elements<S> = (
    LinearSpring<S, Spatial, 2>,
    NonlinearSpring<S, Spatial, 2>,
    LinearDamper<S, Spatial, 2>,
    JointMotor<S>,
    ThelenMuscle<S, Spatial, 2>,
    DeGrooteMuscle<S, Spatial, 2>,
);

/// Every element, each parameter from `setting`.
fn elements<S: Scalar>(x: f64, slot: Slot) -> Elements<S> {
    (
        LinearSpring::new(
            hand_path(x, slot),
            setting(x, slot, 200.0),
            S::from_f64(0.2),
        ),
        NonlinearSpring::new(
            hand_path(x, slot),
            setting(x, slot, 100.0),
            setting(x, slot, 1e3),
            S::from_f64(0.2),
        ),
        LinearDamper::new(hand_path(x, slot), setting(x, slot, 5.0)),
        JointMotor::new(
            3,
            0,
            setting(x, slot, 50.0),
            S::from_f64(0.02),
            S::from_f64(2e-5),
        ),
        thelen(x, slot),
        de_groote(x, slot),
    )
}

/// The drive inputs: every one hostile in `AccelerationOrTorque`.
fn inputs<S: Scalar>(x: f64, slot: Slot) -> [S; NU] {
    if slot == Slot::AccelerationOrTorque {
        [S::from_f64(x); NU]
    } else {
        [S::from_f64(0.5), S::from_f64(0.4), S::from_f64(0.6)]
    }
}

/// The element functions' own inputs: a path length (hostile in
/// `Configuration`), a lengthening velocity (`Velocity`) and an
/// activation (`AccelerationOrTorque`).
fn element_inputs(x: f64, slot: Slot) -> (f64, f64, f64) {
    let pick = |s: Slot, good: f64| if slot == s { x } else { good };
    (
        pick(Slot::Configuration, 0.45),
        pick(Slot::Velocity, 0.1),
        pick(Slot::AccelerationOrTorque, 0.5),
    )
}

fn forces<S: Scalar>(f: &DriveForces<S, Spatial, 7, 7>) -> Vec<f64> {
    let mut out = numbers(&f.tau);
    for force in &f.f_ext {
        out.extend(crate::motion(force));
    }
    out
}

fn derivatives<S: Scalar>(d: &DriveDerivatives<S, 7>) -> Vec<f64> {
    let mut out = numbers(&d.tau);
    out.extend(d.dtau_dq.iter().chain(&d.dtau_dv).flat_map(|r| numbers(r)));
    out
}

/// The probes of the drives and sensitivities in scalar `S`.
#[allow(clippy::too_many_lines)]
pub fn probes<S: Scalar>() -> Vec<Probe> {
    let model = panda::<S>();
    let mut probes: Vec<Probe> = Vec::new();
    let mut add = |name: &'static str, call: fn(&Model<S, 7, 7, 7>, f64, Slot) -> Outcome| {
        probes.push((name, Box::new(move |x, slot| call(&model, x, slot))));
    };
    add("kinematics", |model, x, slot| {
        let mut data = Box::new(Data::new());
        let (q, v, _) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
        forward_kinematics_velocity(model, &mut data, &q, &v)?;
        let kin = hand_path::<S>(x, slot).kinematics(&data)?;
        let mut out = numbers(&[kin.length, kin.lengthening_velocity]);
        for p in kin.points.iter().chain(&kin.unit_forces) {
            out.extend(numbers(&p.to_array()));
        }
        Ok(out)
    });
    add("add_tension", |model, x, slot| {
        let mut data = Box::new(Data::new());
        let (q, v, _) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
        forward_kinematics_velocity(model, &mut data, &q, &v)?;
        let path = hand_path::<S>(x, slot);
        let kin = path.kinematics(&data)?;
        let mut f_ext = [Force::ZERO; 7];
        path.add_tension(&kin, setting(x, slot, 50.0), &data, &mut f_ext)?;
        Ok(f_ext.iter().flat_map(crate::motion).collect())
    });
    add("length_derivatives", |model, x, slot| {
        let mut data = Box::new(Data::new());
        let mut jac = Box::new(JacobianData::new());
        let (q, v, _) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
        joint_jacobians_time_variation(model, &mut data, &mut jac, &q, &v)?;
        let state = DriveDerivativeState {
            data: &data,
            columns: &jac.j,
            topology: model.topology(),
            v: &v,
        };
        let d = hand_path::<S>(x, slot).length_derivatives(&state)?;
        let mut out = numbers(&[d.length, d.lengthening_velocity]);
        out.extend(numbers(&d.gradient));
        out.extend(d.hessian.iter().flat_map(|r| numbers(r)));
        Ok(out)
    });
    add("tension", |_, x, slot| {
        let (length, _, _) = element_inputs(x, slot);
        let (linear, cubic, ..) = elements::<S>(x, slot);
        let length = S::from_f64(length);
        Ok(numbers(&[linear.tension(length)?, cubic.tension(length)?]))
    });
    add("potential_energy", |_, x, slot| {
        let (length, _, _) = element_inputs(x, slot);
        let (linear, cubic, ..) = elements::<S>(x, slot);
        let length = S::from_f64(length);
        Ok(numbers(&[
            linear.potential_energy(length)?,
            cubic.potential_energy(length)?,
        ]))
    });
    add("stiffness_at", |_, x, slot| {
        let (length, _, _) = element_inputs(x, slot);
        let (_, cubic, ..) = elements::<S>(x, slot);
        Ok(numbers(&[cubic.stiffness_at(S::from_f64(length))?]))
    });
    add("torque_per_current", |_, x, slot| {
        let (.., motor, _, _) = elements::<S>(x, slot);
        Ok(numbers(&[motor.torque_per_current()?]))
    });
    add("reflected_inertia", |_, x, slot| {
        // The rotor inertia hostile too: N² J_r overflows from either.
        let mut motor = elements::<S>(x, slot).3;
        motor.rotor_inertia = setting(x, slot, 2e-5);
        Ok(numbers(&[motor.reflected_inertia()?]))
    });
    add("state", |_, x, slot| {
        let (length, rate, activation) = element_inputs(x, slot);
        let (l, r, a) = (
            S::from_f64(length),
            S::from_f64(rate),
            S::from_f64(activation),
        );
        let t = thelen::<S>(x, slot).state(l, r, a)?;
        let d = de_groote::<S>(x, slot).state(l, r, a)?;
        let mut out = numbers(&[
            t.fiber_length,
            t.fiber_velocity,
            t.cos_pennation,
            t.normalized_velocity,
            t.active_force_length,
            t.passive_force_length,
            t.force_velocity,
            t.tension,
            t.tension_per_activation,
        ]);
        out.extend(numbers(&[d.tension, d.tension_per_activation]));
        Ok(out)
    });
    add("state_on", |model, x, slot| {
        let mut data = Box::new(Data::new());
        let (q, v, _) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
        forward_kinematics_velocity(model, &mut data, &q, &v)?;
        let muscle = thelen::<S>(x, slot);
        let kin = muscle.path.kinematics(&data)?;
        let activation = S::from_f64(element_inputs(x, slot).2);
        let t = muscle.state_on(&kin, activation)?;
        Ok(numbers(&[t.tension, t.tension_per_activation]))
    });
    add("tension_partials", |_, x, slot| {
        let (length, rate, activation) = element_inputs(x, slot);
        let (t, dl, dv) = thelen::<S>(x, slot).tension_partials(
            S::from_f64(length),
            S::from_f64(rate),
            S::from_f64(activation),
        )?;
        Ok(numbers(&[t, dl, dv]))
    });
    add("drive_forces", |model, x, slot| {
        let mut data = Box::new(Data::new());
        let (q, v, _) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
        let mut out = DriveForces::new();
        let w = inputs::<S>(x, slot);
        drive_forces(model, &mut data, &q, &v, &elements(x, slot), &w, &mut out)?;
        Ok(forces(&out))
    });
    add("forward_dynamics_with_drives", |model, x, slot| {
        let mut data = Box::new(Data::new());
        let (q, v, _) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
        let mut out = DriveForces::new();
        let w = inputs::<S>(x, slot);
        let ddq = *forward_dynamics_with_drives::<Aba, _, _, _, 7, 7, 7>(
            model,
            &mut data,
            &q,
            &v,
            &[S::ZERO; 7],
            &elements(x, slot),
            &w,
            &mut out,
        )?;
        let mut numbers_out = numbers(&ddq);
        numbers_out.extend(forces(&out));
        Ok(numbers_out)
    });
    add("drive_force_derivatives", |model, x, slot| {
        let mut data = Box::new(Data::new());
        let mut jac = Box::new(JacobianData::new());
        let (q, v, _) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
        let mut out = Box::new(DriveDerivatives::new());
        let w = inputs::<S>(x, slot);
        drive_force_derivatives(
            model,
            &mut data,
            &mut jac,
            &q,
            &v,
            &elements(x, slot),
            &w,
            &mut out,
        )?;
        Ok(derivatives(&out))
    });
    add("aba_derivatives_with_drives", |model, x, slot| {
        let mut data = Box::new(Data::new());
        let mut jac = Box::new(JacobianData::new());
        let mut deriv = Box::new(DerivativeData::<S, 7, 7>::new());
        let mut drive = Box::new(DriveDerivatives::new());
        let (q, v, _) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
        let w = inputs::<S>(x, slot);
        aba_derivatives_with_drives(
            model,
            &mut data,
            &mut deriv,
            &mut jac,
            &mut drive,
            &q,
            &v,
            &[S::ZERO; 7],
            &elements(x, slot),
            &w,
        )?;
        let mut out = derivatives(&drive);
        out.extend(
            deriv
                .ddq_dq
                .iter()
                .chain(&deriv.ddq_dv)
                .flat_map(|r| numbers(r)),
        );
        Ok(out)
    });
    add("forward_dynamics_and_sensitivity", |model, x, slot| {
        let mut data = Box::new(Data::new());
        let (q, v, a) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
        let mut out = DriveForces::new();
        let mut sensitivity = [[S::ZERO; NU]; 7];
        let w = inputs::<S>(x, slot);
        let ddq = *forward_dynamics_and_sensitivity(
            model,
            &mut data,
            &q,
            &v,
            &a,
            &elements(x, slot),
            &w,
            &mut out,
            &mut sensitivity,
        )?;
        let mut result = numbers(&ddq);
        result.extend(sensitivity.iter().flat_map(|r| numbers(r)));
        Ok(result)
    });
    add("input_sensitivity", |model, x, slot| {
        let mut data = Box::new(Data::new());
        let (q, v, a) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
        rodyn::algorithm::aba::aba(model, &mut data, &q, &v, &a, None)?;
        let mut sensitivity = [[S::ZERO; NU]; 7];
        let w = inputs::<S>(x, slot);
        input_sensitivity(
            model,
            &data,
            &q,
            &v,
            &elements(x, slot),
            &w,
            &mut sensitivity,
        )?;
        Ok(sensitivity.iter().flat_map(|r| numbers(r)).collect())
    });
    probes
}
