//! The simulation's steps and its compliant ground contact: each
//! integrator on the Panda (a hostile step in `Setting`, torques from the
//! loads in `AccelerationOrTorque`), and the contact law on Solo12's feet.

use crate::{numbers, panda, setting, state, Outcome, Probe, Slot, PANDA_Q0};
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::prelude::*;
use rodyn::sim::contact::{GroundContact, NormalLaw};
use rodyn::sim::{ExplicitEuler, ImplicitEuler, Integrator, Rk4, SemiImplicitEuler, State};
use rodyn::Endpoint;
use rodyn_host_tests::contact_fixture::{solo12, SOLO_NQ, SOLO_NV};

/// One step of `integrator` from the probe's state, the torques `a` as
/// the loads, the step `dt` from `Setting`.
fn step_with<I: Integrator, S: Scalar>(
    mut integrator: I,
    model: &Model<S, 7, 7, 7>,
    x: f64,
    slot: Slot,
) -> Outcome {
    let mut data = Box::new(Data::new());
    let (q, v, tau) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
    let mut s = State::new(q, v);
    let mut loads = |_: &Model<S, 7, 7, 7>,
                     _: &mut Data<S, 7, 7>,
                     _: S,
                     _: &[S; 7],
                     _: &[S; 7],
                     t: &mut [S; 7],
                     _: &mut [Force<S>; 7]|
     -> rodyn::Result<()> {
        *t = tau;
        Ok(())
    };
    integrator.step(
        Aba,
        model,
        &mut data,
        &mut s,
        setting(x, slot, 1e-3),
        &mut loads,
    )?;
    let mut out = numbers(&s.q);
    out.extend(numbers(&s.v));
    out.push(s.t.to_f64());
    Ok(out)
}

/// The ground: stiffness, damping, friction and slip scale from `Setting`.
fn ground<S: Scalar>(x: f64, slot: Slot) -> GroundContact<S> {
    GroundContact {
        normal: NormalLaw::HuntCrossley {
            stiffness: setting(x, slot, 1e4),
            damping: setting(x, slot, 1.0),
        },
        friction: setting(x, slot, 0.8),
        slip_scale: setting(x, slot, 0.01),
    }
}

/// A probe's call on the Panda.
type PandaCall<S> = fn(&Model<S, 7, 7, 7>, f64, Slot) -> Outcome;

/// The probes of the simulation in scalar `S`.
pub fn probes<S: Scalar>() -> Vec<Probe> {
    let model = panda::<S>();
    let mut probes: Vec<Probe> = Vec::new();
    // `Integrator::step`, a trait method, under the name of its `fn`.
    let integrators: [PandaCall<S>; 4] = [
        |m, x, slot| step_with(ExplicitEuler::default(), m, x, slot),
        |m, x, slot| step_with(SemiImplicitEuler::default(), m, x, slot),
        |m, x, slot| step_with(ImplicitEuler::default(), m, x, slot),
        |m, x, slot| step_with(Rk4::default(), m, x, slot),
    ];
    for call in integrators {
        probes.push(("step", Box::new(move |x, slot| call(&model, x, slot))));
    }
    probes.push((
        "force_at",
        Box::new(|x, slot| {
            // A foot 1 mm into the ground (hostile height in
            // `Configuration`), sliding (hostile in `Velocity`).
            let pick = |s: Slot, good: f64| S::from_f64(if slot == s { x } else { good });
            let p = Vec3::new(S::from_f64(0.1), S::ZERO, pick(Slot::Configuration, -1e-3));
            let p_dot = Vec3::new(pick(Slot::Velocity, 0.2), S::ZERO, S::from_f64(-0.1));
            Ok(numbers(
                &ground::<S>(x, slot).force_at(&p, &p_dot)?.to_array(),
            ))
        }),
    ));
    let solo = solo12().cast::<S>().unwrap();
    let mut q0 = [0.0; SOLO_NQ];
    q0[2] = 0.3;
    q0[6] = 1.0;
    probes.push((
        "add_forces",
        Box::new(move |x, slot| {
            let mut data = Box::new(Data::new());
            let (mut q, v, _) = state::<S, SOLO_NQ, SOLO_NV>(&q0, x, slot);
            let _ = solo.normalize(&mut q);
            let offset = if slot == Slot::Frame { x } else { 0.0 };
            let feet: [Endpoint<S>; 4] = core::array::from_fn(|k| {
                Endpoint::on_body(3 * k + 3, Vec3::new(S::from_f64(offset), S::ZERO, S::ZERO))
            });
            let mut f_ext = [Force::ZERO; 13];
            ground::<S>(x, slot).add_forces(&solo, &mut data, &q, &v, &feet, &mut f_ext, None)?;
            Ok(f_ext.iter().flat_map(crate::motion).collect())
        }),
    ));
    probes
}
