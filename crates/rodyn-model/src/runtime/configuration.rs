//! Configurations: the neutral one, random ones, integration on the
//! joints' manifolds, and the body poses the drawing tools read.

use super::{RuntimeError, RuntimeModel, Workspace};
use crate::description::JointType;
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::space::RigidTransform;
use rodyn::spatial::{Transform, Vec3};

/// A small deterministic generator (SplitMix64): the same seed gives the
/// same configuration on every machine.
struct SplitMix64(u64);

impl SplitMix64 {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[lo, hi)`.
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        // The top 53 bits: every double in [0, 1) a multiple of 2⁻⁵³.
        let unit = (self.next() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }
}

impl RuntimeModel {
    pub(super) fn compute_neutral(&self) -> Vec<f64> {
        let mut q = Vec::with_capacity(self.nq);
        for b in &self.description.bodies {
            match b.joint {
                JointType::FreeFlyer | JointType::PlanarFloating => {
                    q.extend_from_slice(&[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
                }
                _ => q.push(0.0),
            }
        }
        q
    }

    /// The neutral configuration: every angle and displacement zero, every
    /// free-flyer at the origin with the identity quaternion `[0 0 0 1]`.
    #[must_use]
    pub fn neutral(&self) -> Vec<f64> {
        self.neutral.clone()
    }

    /// A random configuration from `seed` (the same on every machine):
    /// angles uniform in `[-π, π)`, displacements and free-flyer positions
    /// uniform in `[-1, 1)` m, free-flyer orientations uniform on the unit
    /// quaternions. The files carry no joint limits the model keeps, so
    /// the ranges are these fixed ones.
    #[must_use]
    pub fn random_configuration(&self, seed: u64) -> Vec<f64> {
        let mut rng = SplitMix64(seed);
        let mut q = Vec::with_capacity(self.nq);
        for b in &self.description.bodies {
            match b.joint {
                JointType::FreeFlyer | JointType::PlanarFloating => {
                    for _ in 0..3 {
                        q.push(rng.uniform(-1.0, 1.0));
                    }
                    // Shoemake's uniform unit quaternion.
                    let (u1, u2, u3) = (
                        rng.uniform(0.0, 1.0),
                        rng.uniform(0.0, std::f64::consts::TAU),
                        rng.uniform(0.0, std::f64::consts::TAU),
                    );
                    let (a, b) = ((1.0 - u1).sqrt(), u1.sqrt());
                    q.extend_from_slice(&[a * u2.sin(), a * u2.cos(), b * u3.sin(), b * u3.cos()]);
                }
                JointType::Revolute { .. } => {
                    q.push(rng.uniform(-std::f64::consts::PI, std::f64::consts::PI));
                }
                JointType::Prismatic { .. } => q.push(rng.uniform(-1.0, 1.0)),
            }
        }
        q
    }

    /// `q ⊕ v dt` into `out`: each joint moved along its manifold (a
    /// free-flyer's velocity in its local frame, its quaternion kept unit).
    ///
    /// # Errors
    /// A wrong length, a non-finite entry, a quaternion not of unit length.
    pub fn integrate(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        dt: f64,
        out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        class_call!(self, ws, "integrate",
            inputs: [q, "v" => v],
            checks: [
                super::check::length("out", out.len(), self.nq, "nq"),
                if dt.is_finite() {
                    Ok(())
                } else {
                    Err(RuntimeError::invalid_input(format!("dt is {dt}")))
                },
            ],
            |m, s| m.model.integrate(&s.q, &s.v, dt)
                .map(|next| out.copy_from_slice(&next[..self.nq])))
    }

    /// The padded configuration of a configuration in the file's own
    /// layout (`[x y θ]` for a planar floating base), as the drawing tools
    /// read trajectories; missing entries are zero.
    #[must_use]
    pub fn configuration_from_file_layout(&self, file_q: &[f64]) -> Vec<f64> {
        let mut q = self.neutral.clone();
        let (mut k, mut iq) = (0, 0);
        let take = |n: usize, k: &mut usize| {
            let values: Vec<f64> = (0..n)
                .map(|j| file_q.get(*k + j).copied().unwrap_or(0.0))
                .collect();
            *k += n;
            values
        };
        for b in &self.description.bodies {
            match b.joint {
                JointType::PlanarFloating => {
                    let v = take(3, &mut k);
                    let (s, c) = (0.5 * v[2]).sin_cos();
                    q[iq..iq + 7].copy_from_slice(&[v[0], v[1], 0.0, 0.0, 0.0, s, c]);
                    iq += 7;
                }
                JointType::FreeFlyer => {
                    let v = take(7, &mut k);
                    if v[3..].iter().any(|x| *x != 0.0) {
                        q[iq..iq + 7].copy_from_slice(&v);
                    } else {
                        q[iq..iq + 3].copy_from_slice(&v[..3]);
                    }
                    iq += 7;
                }
                _ => {
                    q[iq] = take(1, &mut k)[0];
                    iq += 1;
                }
            }
        }
        q
    }

    /// World poses of the file's bodies at `file_q`, a configuration in
    /// the file's own layout ([`configuration_from_file_layout`](Self::configuration_from_file_layout)).
    ///
    /// # Errors
    /// An invalid configuration (a quaternion that is not of unit length).
    pub fn body_poses(&self, file_q: &[f64]) -> Result<Vec<Transform<f64>>, RuntimeError> {
        let q = self.configuration_from_file_layout(file_q);
        let mut ws = self.workspace();
        let nb = self.nb();
        class_call!(self, ws, "forward kinematics",
            inputs: [&q],
            checks: [],
            |m, s| forward_kinematics(&m.model, &mut s.data, &s.q)
                .map(|()| s.data.o_m_i[..nb].to_vec()))
    }

    /// World positions of every endpoint at the body poses `o_m_i`.
    #[must_use]
    pub fn endpoint_positions(&self, o_m_i: &[Transform<f64>]) -> Vec<Vec3<f64>> {
        let vec3 = |p: &[f64; 3]| Vec3::new(p[0], p[1], p[2]);
        self.description
            .endpoints
            .iter()
            .map(|e| match e.body.and_then(|b| o_m_i.get(b)) {
                Some(pose) => pose.act_point(&vec3(&e.position)),
                None => vec3(&e.position),
            })
            .collect()
    }
}
