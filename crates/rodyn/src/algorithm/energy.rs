//! Kinetic and potential energy and the centre of mass.

use crate::algorithm::kinematics::{check_state, forward_kinematics, velocity_pass};
use crate::data::Data;
use crate::error::{Quantity, Result};
use crate::model::{check_result, Model};
use crate::space::{BodyInertia, MotionVector, Space};
use crate::Scalar;

/// Kinetic energy `½ Σ vᵢ · Iᵢ vᵢ` (J).
///
/// Inputs: `q` (NQ), `v` (NV). Leaves valid: `li_m_i`, `v`, `c`; `o_m_i` is
/// not written.
///
/// # Errors
/// Invalid or non-finite inputs.
pub fn kinetic_energy<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
) -> Result<S> {
    check_state(model, q, Some(v))?;
    velocity_pass(model, data, q, v);
    let mut twice = S::ZERO;
    for i in 0..NB {
        twice += data.v[i].dot(&model.inertia(i).mul_motion(&data.v[i]));
    }
    for (armature, v) in model.armature().iter().zip(v) {
        twice += *armature * *v * *v;
    }
    let energy = twice * S::from_f64(0.5);
    check_result(&[energy], Quantity::Energy)?;
    Ok(energy)
}

/// Potential energy in the gravity field, `-Σ mᵢ g · cᵢ` (J), zero when
/// every centre of mass is at the world origin's height.
///
/// Inputs: `q` (NQ). Leaves valid: `li_m_i`, `o_m_i`.
///
/// # Errors
/// An invalid configuration.
pub fn potential_energy<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
) -> Result<S> {
    forward_kinematics(model, data, q)?;
    let mut energy = S::ZERO;
    for i in 0..NB {
        energy += model
            .inertia(i)
            .act(&data.o_m_i[i])
            .potential_energy(model.gravity());
    }
    check_result(&[energy], Quantity::Energy)?;
    Ok(energy)
}

/// Centre of mass of the whole model in the world frame (m), and the total mass.
///
/// Inputs: `q` (NQ). Leaves valid: `li_m_i`, `o_m_i`.
///
/// # Errors
/// An invalid configuration.
pub fn center_of_mass<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
) -> Result<(G::Point<S>, S)> {
    forward_kinematics(model, data, q)?;
    let mut total = G::Inertia::<S>::ZERO;
    for i in 0..NB {
        total = total.combine(&model.inertia(i).act(&data.o_m_i[i]));
    }
    Ok((total.com(), total.mass()))
}
