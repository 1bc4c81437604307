//! Kinetic and potential energy and the centre of mass.

use crate::algorithm::common::{check_state, velocity_pass};
use crate::algorithm::kinematics::forward_kinematics;
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
///
/// # Example
///
/// ```
/// use rodyn::algorithm::energy::kinetic_energy;
/// # use rodyn::prelude::*;
/// # // A 1 kg point mass on a massless 1 m link, pivot about z, gravity -y.
/// # const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
/// #     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
/// #     [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
/// #     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// # );
/// let mut data = Data::new();
/// // ½ m l² q̇² for a point mass at 1 m.
/// let t = kinetic_energy(&PENDULUM, &mut data, &[0.3], &[2.0])?;
/// assert!((t - 2.0).abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
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
///
/// # Example
///
/// ```
/// use rodyn::algorithm::energy::potential_energy;
/// # use rodyn::prelude::*;
/// # // A 1 kg point mass on a massless 1 m link, pivot about z, gravity -y.
/// # const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
/// #     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
/// #     [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
/// #     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// # );
/// let mut data = Data::new();
/// // m g y with the mass at height y = l sin q.
/// let q = 0.3;
/// let u = potential_energy(&PENDULUM, &mut data, &[q])?;
/// assert!((u - 9.81 * f64::sin(q)).abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
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
///
/// # Example
///
/// ```
/// use rodyn::algorithm::energy::center_of_mass;
/// # use rodyn::prelude::*;
/// # // Two 1 m links about z, 1 kg point masses at the tips, gravity -y.
/// # const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
/// # const DOUBLE: Model<f64, 2, 2, 2> = Model::new(
/// #     [None, Some(0)], [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
/// #     [Transform::IDENTITY, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))],
/// #     [LINK, LINK], Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// # );
/// let mut data = Data::new();
/// // Elbow bent 90°: masses at (1, 0) and (1, 1), centre of mass at (1, 0.5).
/// let (com, mass) = center_of_mass(&DOUBLE, &mut data, &[0.0, core::f64::consts::FRAC_PI_2])?;
/// assert!((mass - 2.0).abs() < 1e-12);
/// assert!((com.x - 1.0).abs() < 1e-12 && (com.y - 0.5).abs() < 1e-12 && com.z.abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
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
