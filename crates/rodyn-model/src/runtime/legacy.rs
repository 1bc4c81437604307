//! The first run-time model: one padded capacity for every file, kept for
//! the callers that want rodyn's `Model` itself ([`PaddedRuntimeModel::model`]);
//! [`RuntimeModel`](super::RuntimeModel) is the fast one with every
//! algorithm.
//!
//! rodyn's sizes are const parameters, so a run-time model uses fixed
//! capacities ([`MAX_BODIES`], [`MAX_NV`], [`MAX_FREE_FLYERS`]) and fills
//! what the file does not use with massless padding bodies hanging from the
//! world: free-flyers and revolute joints that soak up the unused
//! coordinates (always at their neutral configuration), then fixed bodies.
//! Padding never moves and carries no mass, so the file's bodies see exactly
//! the dynamics of the compiled model. A planar model is built as its 3-D
//! equivalent (joints about z; the planar floating base as a free-flyer).

use crate::description::{JointType, ModelDescription};
use crate::diagnostic::{Diagnostic, Location, Result};
use crate::geometry::snap_signed_permutation;
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::joint::{Axis, Joint};
use rodyn::space::RigidTransform;
use rodyn::spatial::{Inertia, Mat3, Motion, Sym3, Transform, Vec3};
use rodyn::{Data, Model};

/// Most bodies a run-time model holds (padding included).
pub const MAX_BODIES: usize = 160;
/// Most velocity coordinates.
pub const MAX_NV: usize = 128;
/// Most free-flyers (each adds one more configuration than velocity coordinate).
pub const MAX_FREE_FLYERS: usize = 2;
/// Configuration coordinates of the padded model.
pub const MAX_NQ: usize = MAX_NV + MAX_FREE_FLYERS;

/// The padded rodyn model type.
pub type PaddedModel = Model<f64, MAX_BODIES, MAX_NQ, MAX_NV>;

/// A model file's model, built at run time.
pub struct PaddedRuntimeModel {
    /// The padded model; bodies `0..nb` are the file's.
    pub model: Box<PaddedModel>,
    /// The file's description.
    pub description: ModelDescription,
}

fn vec3(v: &[f64; 3]) -> Vec3<f64> {
    Vec3::new(v[0], v[1], v[2])
}

fn axis(a: &[f64; 3]) -> Axis<f64> {
    match a {
        [1.0, 0.0, 0.0] => Axis::X,
        [0.0, 1.0, 0.0] => Axis::Y,
        [0.0, 0.0, 1.0] => Axis::Z,
        _ => Axis::Unit(vec3(a)),
    }
}

impl PaddedRuntimeModel {
    /// Builds the model of `description`.
    ///
    /// # Errors
    /// A model larger than the capacities above.
    pub fn new(description: ModelDescription) -> Result<Self> {
        let nb = description.bodies.len();
        let free = description
            .bodies
            .iter()
            .filter(|b| matches!(b.joint, JointType::FreeFlyer | JointType::PlanarFloating))
            .count();
        // Velocity coordinates of the 3-D equivalent (a planar floating base is a free-flyer).
        let nv: usize = description
            .bodies
            .iter()
            .map(|b| {
                if b.joint == JointType::PlanarFloating {
                    6
                } else {
                    b.joint.nv()
                }
            })
            .sum();
        let pad_free = MAX_FREE_FLYERS.saturating_sub(free);
        let too_big = free > MAX_FREE_FLYERS
            || nv + 6 * pad_free > MAX_NV
            || nb + pad_free + (MAX_NV - nv - 6 * pad_free) > MAX_BODIES;
        if too_big {
            return Err(Diagnostic::error(
                description.bodies.first().map_or_else(|| Location::start_of("".as_ref()), |b| b.location.clone()),
                format!("the model is too large for the run-time tools (at most {MAX_NV} velocity coordinates and {MAX_FREE_FLYERS} floating bases)"),
            ));
        }
        let pad_revolute = MAX_NV - nv - 6 * pad_free;
        let mut parents = [None; MAX_BODIES];
        let mut joints = [Joint::Fixed; MAX_BODIES];
        let mut placements = [Transform::IDENTITY; MAX_BODIES];
        let mut inertias = [Inertia::new(0.0, Vec3::ZERO, Sym3::ZERO); MAX_BODIES];
        for (i, b) in description.bodies.iter().enumerate() {
            parents[i] = b.parent;
            joints[i] = match b.joint {
                JointType::Revolute { axis: a } => Joint::revolute(axis(&a)),
                JointType::Prismatic { axis: a } => Joint::prismatic(axis(&a)),
                JointType::FreeFlyer | JointType::PlanarFloating => Joint::free_flyer(),
            };
            // Quarter turns exact, as the generated code has them.
            let rot = snap_signed_permutation(&b.placement.rot, description.snap_tolerance())
                .unwrap_or(b.placement.rot);
            placements[i] = Transform::new(Mat3::from_rows(rot), vec3(&b.placement.trans));
            let r = &b.inertia.inertia;
            inertias[i] = Inertia::new(
                b.inertia.mass,
                vec3(&b.inertia.com),
                Sym3::new(r[0][0], r[0][1], r[0][2], r[1][1], r[1][2], r[2][2]),
            );
        }
        for (k, joint) in joints
            .iter_mut()
            .enumerate()
            .skip(nb)
            .take(pad_free + pad_revolute)
        {
            *joint = if k < nb + pad_free {
                Joint::free_flyer()
            } else {
                Joint::revolute(Axis::Z)
            };
        }
        let g = vec3(&description.gravity);
        let model = Model::try_new(
            parents,
            joints,
            placements,
            inertias,
            Motion::new(Vec3::ZERO, g),
        )
        .map_err(|e| {
            let location = description.bodies.first().map_or_else(
                || Location::start_of(std::path::Path::new("")),
                |b| b.location.clone(),
            );
            Diagnostic::error(location, format!("rodyn refuses the model's tree: {e}"))
        })?;
        let model = Box::new(model);
        Ok(Self { model, description })
    }

    /// The padded configuration for the file's `q` (its own layout:
    /// `[x y θ]` for a planar floating base); missing entries are zero.
    #[must_use]
    pub fn configuration(&self, q: &[f64]) -> [f64; MAX_NQ] {
        let mut out = self.model.neutral_configuration();
        let topology = self.model.topology();
        let mut k = 0;
        for (i, b) in self.description.bodies.iter().enumerate() {
            let iq = topology.idx_q[i];
            let mut take = |n: usize| {
                let values = (0..n)
                    .map(|j| q.get(k + j).copied().unwrap_or(0.0))
                    .collect::<Vec<_>>();
                k += n;
                values
            };
            match b.joint {
                JointType::PlanarFloating => {
                    let v = take(3);
                    let (s, c) = (0.5 * v[2]).sin_cos();
                    out[iq..iq + 7].copy_from_slice(&[v[0], v[1], 0.0, 0.0, 0.0, s, c]);
                }
                JointType::FreeFlyer => {
                    let v = take(7);
                    if v[3..].iter().any(|x| *x != 0.0) {
                        out[iq..iq + 7].copy_from_slice(&v);
                    } else {
                        out[iq..iq + 3].copy_from_slice(&v[..3]);
                    }
                }
                _ => out[iq] = take(1)[0],
            }
        }
        out
    }

    /// World poses of the file's bodies at `q` (file layout).
    ///
    /// # Errors
    /// An invalid configuration (a quaternion that is not of unit length).
    pub fn body_poses(&self, q: &[f64]) -> std::result::Result<Vec<Transform<f64>>, rodyn::Error> {
        let mut data: Box<Data<f64, MAX_BODIES, MAX_NV>> = Box::default();
        forward_kinematics(&self.model, &mut data, &self.configuration(q))?;
        Ok(data.o_m_i[..self.description.bodies.len()].to_vec())
    }

    /// World positions of every endpoint at the body poses `o_m_i`.
    #[must_use]
    pub fn endpoint_positions(&self, o_m_i: &[Transform<f64>]) -> Vec<Vec3<f64>> {
        self.description
            .endpoints
            .iter()
            .map(|e| match e.body {
                Some(b) => o_m_i[b].act_point(&vec3(&e.position)),
                None => vec3(&e.position),
            })
            .collect()
    }
}
