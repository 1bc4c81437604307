//! Pinocchio's configuration layout, which the Python model speaks.
//!
//! rodyn and Pinocchio agree on every joint's coordinates (a free-flyer's
//! `[x y z qx qy qz qw]`, its velocity in the body frame with the linear
//! part first) except one: a URDF `continuous` joint is one angle `θ` in
//! rodyn and the pair `(cos θ, sin θ)` in Pinocchio. The layout maps a
//! Python `q` to rodyn's and back; for a model without continuous joints it
//! is the identity and `q` is read in place.

use rodyn::joint::angle_from_cos_sin;

/// How a Python (Pinocchio) configuration maps to rodyn's.
#[derive(Clone, Debug)]
pub struct ConfigurationLayout {
    /// For each continuous joint, in body order: the index of `θ` in
    /// rodyn's `q` and of `cos θ` in Pinocchio's (`sin θ` follows it).
    continuous: Vec<(usize, usize)>,
    rodyn_nq: usize,
}

/// What is wrong with a Python configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairOffCircle {
    /// The index of `cos θ` in the Python `q`.
    pub index: usize,
    /// `cos² + sin²`.
    pub norm_squared: f64,
}

impl ConfigurationLayout {
    /// The layout of a model whose joints, in body order, have `rodyn_nq`
    /// configuration coordinates each and are continuous or not.
    pub fn new(joints: impl IntoIterator<Item = (usize, bool)>) -> Self {
        let (mut continuous, mut rodyn_nq, mut pinocchio_nq) = (Vec::new(), 0, 0);
        for (nq, is_continuous) in joints {
            if is_continuous {
                continuous.push((rodyn_nq, pinocchio_nq));
                pinocchio_nq += 1;
            }
            rodyn_nq += nq;
            pinocchio_nq += nq;
        }
        Self {
            continuous,
            rodyn_nq,
        }
    }

    /// Whether the two layouts are the same (no continuous joint).
    pub fn is_identity(&self) -> bool {
        self.continuous.is_empty()
    }

    /// Length of rodyn's `q`.
    pub fn rodyn_nq(&self) -> usize {
        self.rodyn_nq
    }

    /// Length of Pinocchio's `q`.
    pub fn pinocchio_nq(&self) -> usize {
        self.rodyn_nq + self.continuous.len()
    }

    /// rodyn's `q` (`out`, of length [`rodyn_nq`](Self::rodyn_nq)) from
    /// Pinocchio's `q` (finite entries).
    ///
    /// # Errors
    /// A `(cos, sin)` pair off the unit circle by more than rounding.
    pub fn to_rodyn(&self, q: &[f64], out: &mut [f64]) -> Result<(), PairOffCircle> {
        let (mut from, mut to) = (0, 0);
        for &(theta, cos) in &self.continuous {
            let run = theta - to;
            out[to..theta].copy_from_slice(&q[from..from + run]);
            out[theta] = angle_from_cos_sin(q[cos], q[cos + 1]).map_err(|_| PairOffCircle {
                index: cos,
                norm_squared: q[cos] * q[cos] + q[cos + 1] * q[cos + 1],
            })?;
            (from, to) = (cos + 2, theta + 1);
        }
        out[to..].copy_from_slice(&q[from..]);
        Ok(())
    }

    /// Pinocchio's `q` from rodyn's.
    pub fn to_pinocchio(&self, q: &[f64]) -> Vec<f64> {
        let mut out = Vec::with_capacity(self.pinocchio_nq());
        let mut from = 0;
        for &(theta, _) in &self.continuous {
            out.extend_from_slice(&q[from..theta]);
            // rodyn's own configurations (neutral, random) are finite.
            let (sin, cos) = q[theta].sin_cos();
            out.extend_from_slice(&[cos, sin]);
            from = theta + 1;
        }
        out.extend_from_slice(&q[from..]);
        out
    }
}
