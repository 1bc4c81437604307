//! The public formulas that take numbers and return numbers: both
//! muscles' curves and activation dynamics, the tendon curve and its
//! inverse, the dense Cholesky solve, a Jacobian times rates and its
//! reordering, the inverse-kinematics pose error and an endpoint's world
//! position.
//!
//! The slots: `Configuration` is the curve's first argument (a normalised
//! length, a tendon length or force, an excitation) or the frame's
//! position; `Velocity` a velocity argument (a normalised fibre velocity,
//! a force-velocity multiplier, the joint rates); `AccelerationOrTorque`
//! the activation, or the right-hand side of a solve; `Frame` a point, a
//! target, a Jacobian's column or a factor's pivot; `Setting` the
//! muscles' shape parameters and time constants, or an off-diagonal entry
//! of a factor.

use crate::{numbers, panda, setting, state, Outcome, Probe, Slot, PANDA_Q0};
use rodyn::algorithm::dense::cholesky_solve;
use rodyn::algorithm::frames::ReferenceFrame;
use rodyn::algorithm::inverse_kinematics::pose_error;
use rodyn::algorithm::jacobian::JacobianData;
use rodyn::algorithm::jacobian::{frame_jacobian, joint_jacobians, mul_rates, to_linear_first};
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::drive::muscle_de_groote::{tendon_force_length, tendon_length_from_force};
use rodyn::drive::{DeGrooteMuscle, DeGrooteParameters, Path, ThelenMuscle, ThelenParameters};
use rodyn::prelude::*;
use rodyn::{Endpoint, Frame};

/// `x` in `slot`, `good` elsewhere.
fn pick<S: Scalar>(x: f64, slot: Slot, here: Slot, good: f64) -> S {
    S::from_f64(if slot == here { x } else { good })
}

/// Thelen's parameters, the curves' shape factors and the time constants
/// hostile in `Setting`.
fn thelen<S: Scalar>(x: f64, slot: Slot) -> ThelenParameters<S> {
    let mut p = ThelenParameters::thelen_2003_in(
        S::from_f64(300.0),
        S::from_f64(0.3),
        S::from_f64(0.3),
        S::from_f64(0.1),
    );
    p.active_shape_factor = setting(x, slot, 0.45);
    p.passive_shape_factor = setting(x, slot, 5.0);
    p.force_velocity_shape = setting(x, slot, 0.25);
    p.activation_time_constant = setting(x, slot, 0.01);
    p
}

/// De Groote's parameters, the passive curve's shape and the time
/// constants hostile in `Setting`.
fn de_groote<S: Scalar>(x: f64, slot: Slot) -> DeGrooteParameters<S> {
    let mut p = DeGrooteParameters::de_groote_2016_in(
        S::from_f64(300.0),
        S::from_f64(0.3),
        S::from_f64(0.3),
        S::from_f64(0.1),
    );
    p.passive_shape_factor = setting(x, slot, 4.0);
    p.activation_time_constant = setting(x, slot, 0.015);
    p.activation_smoothing = setting(x, slot, 10.0);
    p
}

/// A path for the muscles whose own `activation_rate` is probed.
fn path<S: Scalar>() -> Path<S, Spatial, 2> {
    Path::new([
        Endpoint::in_world(Vec3::ZERO),
        Endpoint::in_world(Vec3::new(S::from_f64(0.3), S::ZERO, S::ZERO)),
    ])
}

/// The curve arguments: a normalised length, a normalised velocity, an
/// excitation and an activation.
fn arguments<S: Scalar>(x: f64, slot: Slot) -> (S, S, S, S) {
    (
        pick(x, slot, Slot::Configuration, 1.1),
        pick(x, slot, Slot::Velocity, -0.3),
        pick(x, slot, Slot::Configuration, 0.7),
        pick(x, slot, Slot::AccelerationOrTorque, 0.2),
    )
}

/// The probes of the formulas in scalar `S`.
#[allow(clippy::too_many_lines)]
pub fn probes<S: Scalar>() -> Vec<Probe> {
    let mut probes: Vec<Probe> = Vec::new();
    let mut add = |name: &'static str, call: fn(f64, Slot) -> Outcome| {
        probes.push((name, Box::new(call)));
    };
    add("active_force_length", |x, slot| {
        let (l, ..) = arguments::<S>(x, slot);
        let t = thelen::<S>(x, slot).active_force_length(l)?;
        let (d, slope) = de_groote::<S>(x, slot).active_force_length(l)?;
        Ok(numbers(&[t, d, slope]))
    });
    add("passive_force_length", |x, slot| {
        let (l, ..) = arguments::<S>(x, slot);
        let t = thelen::<S>(x, slot).passive_force_length(l)?;
        let (d, slope) = de_groote::<S>(x, slot).passive_force_length(l)?;
        Ok(numbers(&[t, d, slope]))
    });
    add("force_velocity", |x, slot| {
        let (_, v, ..) = arguments::<S>(x, slot);
        let (t, t_slope) = thelen::<S>(x, slot).force_velocity(v)?;
        let (d, d_slope) = de_groote::<S>(x, slot).force_velocity(v)?;
        Ok(numbers(&[t, t_slope, d, d_slope]))
    });
    add("velocity_from_force_multiplier", |x, slot| {
        let f_v = pick::<S>(x, slot, Slot::Velocity, 0.8);
        Ok(numbers(&[
            de_groote::<S>(x, slot).velocity_from_force_multiplier(f_v)?
        ]))
    });
    add("activation_rate", |x, slot| {
        let (.., u, a) = arguments::<S>(x, slot);
        let (t, d) = (thelen::<S>(x, slot), de_groote::<S>(x, slot));
        let mut out = numbers(&[t.activation_rate(u, a)?, d.activation_rate(u, a)?]);
        // The muscles' own, which forward to their parameters'.
        out.extend(numbers(&[
            ThelenMuscle::new(path(), t, 0).activation_rate(u, a)?,
            DeGrooteMuscle::new(path(), d, 0).activation_rate(u, a)?,
        ]));
        Ok(out)
    });
    add("activation_rate_partials", |x, slot| {
        let (.., u, a) = arguments::<S>(x, slot);
        let (rate, d_du, d_da) = de_groote::<S>(x, slot).activation_rate_partials(u, a)?;
        Ok(numbers(&[rate, d_du, d_da]))
    });
    add("tendon_force_length", |x, slot| {
        let (f, slope) = tendon_force_length(pick::<S>(x, slot, Slot::Configuration, 1.02))?;
        Ok(numbers(&[f, slope]))
    });
    add("tendon_length_from_force", |x, slot| {
        let f_t = pick::<S>(x, slot, Slot::Configuration, 0.7);
        Ok(numbers(&[tendon_length_from_force(f_t)?]))
    });
    add("cholesky_solve", |x, slot| {
        // The factor of [[4, 2], [2, 3]]: its pivot hostile in `Frame`,
        // its off-diagonal entry in `Setting`.
        let l = [
            [S::from_f64(2.0), S::ZERO],
            [
                pick(x, slot, Slot::Setting, 1.0),
                pick(x, slot, Slot::Frame, 2f64.sqrt()),
            ],
        ];
        let mut b = [pick(x, slot, Slot::AccelerationOrTorque, 2.0), S::ONE];
        cholesky_solve(&l, 2, &mut b)?;
        Ok(numbers(&b))
    });
    add("mul_rates", |x, slot| {
        let column = |k: usize| {
            let c = S::from_f64(0.1 * (k + 1) as f64);
            Motion::new(Vec3::new(c, S::ZERO, c), Vec3::new(S::ZERO, c, c))
        };
        let mut columns: [Motion<S>; 3] = core::array::from_fn(column);
        columns[1].lin.x = pick(x, slot, Slot::Frame, 0.2);
        let v = [pick(x, slot, Slot::Velocity, 0.3); 3];
        Ok(crate::motion(&mul_rates::<S, 3, Spatial>(&columns, &v)?))
    });
    add("to_linear_first", |x, slot| {
        // The Panda's flange Jacobian from the checked readers (NaN and
        // infinity stop there); a finite hostile number is also written
        // into a column directly: a reordering keeps 1e300, subnormals
        // and zero finite.
        let model = panda::<S>();
        let mut data = Box::new(Data::new());
        let mut jac = Box::new(JacobianData::new());
        let (q, ..) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
        joint_jacobians(&model, &mut data, &mut jac, &q)?;
        let frame = Frame::new(6, Transform::IDENTITY);
        let mut columns = [Motion::ZERO; 7];
        frame_jacobian(
            &model,
            &data,
            &jac,
            &frame,
            ReferenceFrame::LocalWorldAligned,
            &mut columns,
        )?;
        // (1e300 is infinite in f32 before the call: that is the cast's.)
        let entry = S::from_f64(x);
        if slot == Slot::Frame && entry.is_finite() {
            columns[3].ang.y = entry;
        }
        Ok(to_linear_first(&columns)
            .iter()
            .flat_map(|r| numbers(r))
            .collect())
    });
    add("pose_error", |x, slot| {
        let target = Transform::from_translation(Vec3::new(
            pick(x, slot, Slot::Frame, 0.4),
            S::from_f64(0.1),
            S::from_f64(0.5),
        ));
        let frame = Transform::from_translation(Vec3::new(
            pick(x, slot, Slot::Configuration, 0.3),
            S::ZERO,
            S::from_f64(0.6),
        ));
        Ok(crate::motion(&pose_error(&frame, &target)?))
    });
    add("world_position", |x, slot| {
        let model = panda::<S>();
        let mut data = Box::new(Data::new());
        let (q, ..) = state::<S, 7, 7>(&PANDA_Q0, x, slot);
        forward_kinematics(&model, &mut data, &q)?;
        let point = Vec3::new(pick(x, slot, Slot::Frame, 0.05), S::ZERO, S::from_f64(0.1));
        let on_hand = Endpoint::<S>::on_body(6, point).world_position(&data.o_m_i)?;
        let in_world = Endpoint::<S>::in_world(point).world_position(&data.o_m_i)?;
        let mut out = numbers(&on_hand.to_array());
        out.extend(numbers(&in_world.to_array()));
        // Poses without forward kinematics: a body whose pose is hostile.
        let mut poses = data.o_m_i;
        poses[6].trans.x = pick(x, slot, Slot::Setting, 0.2);
        out.extend(numbers(
            &Endpoint::<S>::on_body(6, point)
                .world_position(&poses)?
                .to_array(),
        ));
        Ok(out)
    });
    probes
}
