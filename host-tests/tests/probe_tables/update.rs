//! Model updates: each kind of parameter change, a batch of them and the
//! double buffer's staging, on the Panda, with the hostile number in the
//! change (`Setting`: a mass, an armature, a gear ratio, gravity; `Frame`:
//! a placement's or a payload frame's translation). A change either is
//! refused, naming what is wrong, or leaves a model whose parameters are
//! finite and whose mass matrix CRBA computes.

use crate::{numbers, panda, pose, setting, Outcome, Probe, Slot, PANDA_Q0};
use rodyn::algorithm::crba::crba;
use rodyn::drive::JointMotor;
use rodyn::prelude::*;
use rodyn::update::{DoubleBuffered, ModelUpdate, ParameterChange};
use rodyn::Frame;

type Panda<S> = Model<S, 7, 7, 7>;

/// Every parameter of `model`, then its mass matrix at the probe's `q`.
fn parameters<S: Scalar>(model: &Panda<S>) -> Outcome {
    let mut out = Vec::new();
    for i in 0..7 {
        let inertia = model.inertia(i);
        out.push(inertia.mass.to_f64());
        out.extend(numbers(&inertia.com.to_array()));
        let r = &inertia.rot_inertia;
        out.extend(numbers(&[r.xx, r.yy, r.zz, r.xy, r.xz, r.yz]));
        out.extend(pose(model.placement(i)));
    }
    out.extend(numbers(model.armature()));
    out.extend(crate::motion(model.gravity()));
    let mut data = Box::new(Data::new());
    let m = crba(model, &mut data, &PANDA_Q0.map(S::from_f64))?;
    out.extend(m.iter().flat_map(|r| numbers(r)));
    Ok(out)
}

/// A translation, hostile in `Frame`.
fn offset<S: Scalar>(x: f64, slot: Slot) -> Vec3<S> {
    let d = if slot == Slot::Frame { x } else { 0.05 };
    Vec3::new(S::from_f64(d), S::ZERO, S::from_f64(0.1))
}

/// One change of each kind, the hostile number in each.
fn changes<S: Scalar>(x: f64, slot: Slot) -> [ParameterChange<S>; 6] {
    let box_inertia = |mass: S| {
        let side = S::from_f64(0.01);
        Inertia::new(mass, Vec3::ZERO, Sym3::diagonal(side, side, side))
    };
    [
        ParameterChange::Inertia {
            body: 5,
            inertia: box_inertia(setting(x, slot, 1.5)),
        },
        ParameterChange::Payload {
            frame: Frame::new(6, Transform::from_translation(offset(x, slot))),
            inertia: box_inertia(setting(x, slot, 0.5)),
        },
        ParameterChange::Placement {
            body: 4,
            placement: Transform::from_translation(offset(x, slot)),
        },
        ParameterChange::Armature {
            dof: 2,
            armature: setting(x, slot, 0.1),
        },
        ParameterChange::Motor(JointMotor::new(
            3,
            0,
            setting(x, slot, 50.0),
            S::from_f64(0.02),
            setting(x, slot, 2e-5),
        )),
        ParameterChange::Gravity(Motion::new(
            Vec3::ZERO,
            Vec3::new(S::ZERO, S::ZERO, setting(x, slot, -9.81)),
        )),
    ]
}

/// The probes of the model updates in scalar `S`.
pub fn probes<S: Scalar>() -> Vec<Probe> {
    let model = panda::<S>();
    let mut probes: Vec<Probe> = Vec::new();
    for k in 0..6 {
        probes.push((
            "apply_to",
            Box::new(move |x, slot| {
                let mut updated = model;
                changes::<S>(x, slot)[k].apply_to(&mut updated)?;
                parameters(&updated)
            }),
        ));
    }
    probes.push((
        "apply",
        Box::new(move |x, slot| {
            let mut updated = model;
            ModelUpdate::new(changes::<S>(x, slot)).apply(&mut updated)?;
            parameters(&updated)
        }),
    ));
    probes.push((
        "write_into",
        Box::new(move |x, slot| {
            let mut staging = model;
            ModelUpdate::new(changes::<S>(x, slot)).write_into(&mut staging)?;
            parameters(&staging)
        }),
    ));
    probes.push((
        "stage_update",
        Box::new(move |x, slot| {
            let mut buffered = Box::new(DoubleBuffered::new(model));
            {
                let (_reader, mut writer) = buffered.split();
                writer.stage_update(&ModelUpdate::new(changes::<S>(x, slot)))?;
                writer.publish();
            }
            parameters(buffered.active())
        }),
    ));
    probes
}
