//! A payload's inertial parameters identified from the torque residual by
//! least squares on the Newton–Euler regressor.
//!
//! A rigid payload on body `b` adds to the joint torques `Jᵦᵀ W(v, a) φ`:
//! `Jᵦ` is the body's Jacobian in its frame, `v` and `a` its spatial
//! velocity and acceleration (gravity included as a base acceleration, as
//! RNEA propagates them) and `φ` the payload's ten inertial parameters in
//! the body's frame (Featherstone §2.13, Atkeson, An & Hollerbach 1986):
//! mass `m` (kg), first moment `h = m c` (kg m) and rotational inertia about
//! the body's origin `I_o` (kg m², xx, yy, zz, xy, xz, yz). The body's
//! wrench is linear in `φ`:
//!
//! `n = I_o α + h × a_lin + ω × (I_o ω + h × v_lin) + v_lin × (m v_lin + ω × h)`,
//! `f = m a_lin + α × h + ω × (m v_lin + ω × h)`.
//!
//! So with the measured joint torques `τ` and the nominal model's RNEA
//! `τ₀(q, v, a)` (no payload), the residual is `r = τ - τ₀ = Y φ`, and each
//! column of the regressor `Y` is `Jᵦᵀ W eₖ`, formed without a Jacobian as
//! `τ₀ - RNEA(q, v, a, f_ext = W eₖ on b)`. The estimator sums the normal
//! equations `Σ YᵀY φ = Σ Yᵀ r` over the samples and solves them once
//! (Cholesky, with a ridge of 1e-9 of the mean diagonal, for directions
//! the motion does not excite). All ten parameters are fitted, so that the
//! payload's rotational inertia does not bias the mass and centre of mass;
//! only those two are kept ([`IdentifiedPayload`]), the rotational inertia
//! being poorly excited by a joint-space motion of a few tenths of a
//! radian.

use rodyn::algorithm::rnea::rnea;
use rodyn::spatial::{Force, Motion, Vec3};
use rodyn::{Data, Model, Result};

/// Number of inertial parameters of one rigid body.
pub const PARAMETERS: usize = 10;

/// The wrench (in the body's frame) that a body of inertial parameters
/// `phi` (`m`, `h`, `I_o` as in the [module](self)) needs for velocity `v`
/// and acceleration `a` (both in its frame, gravity included in `a`).
#[must_use]
#[inline]
pub fn payload_wrench(phi: &[f32; PARAMETERS], v: &Motion<f32>, a: &Motion<f32>) -> Force<f32> {
    let m = phi[0];
    let h = Vec3::new(phi[1], phi[2], phi[3]);
    let (xx, yy, zz, xy, xz, yz) = (phi[4], phi[5], phi[6], phi[7], phi[8], phi[9]);
    let i_o = |w: &Vec3<f32>| {
        Vec3::new(
            xx * w.x + xy * w.y + xz * w.z,
            xy * w.x + yy * w.y + yz * w.z,
            xz * w.x + yz * w.y + zz * w.z,
        )
    };
    let (omega, v_lin) = (v.ang, v.lin);
    let (alpha, a_lin) = (a.ang, a.lin);
    // Momentum I v = (I_o ω + h × v_lin, m v_lin + ω × h).
    let angular_momentum = i_o(&omega) + h.cross(&v_lin);
    let linear_momentum = v_lin.scale(m) + omega.cross(&h);
    // f = I a + v ×* (I v).
    let n = i_o(&alpha)
        + h.cross(&a_lin)
        + omega.cross(&angular_momentum)
        + v_lin.cross(&linear_momentum);
    let f = a_lin.scale(m) + alpha.cross(&h) + omega.cross(&linear_momentum);
    Force::new(n, f)
}

/// A payload's mass and centre of mass, identified.
#[derive(Clone, Copy, PartialEq)]
pub struct IdentifiedPayload {
    /// Mass (kg).
    pub mass: f32,
    /// Centre of mass in the body's frame (m).
    pub com: Vec3<f32>,
    /// All ten parameters as fitted (`m`, `h`, `I_o`, body frame).
    pub parameters: [f32; PARAMETERS],
}

/// Sums of the normal equations of the payload's parameters on body
/// `body`.
#[derive(Clone, Copy)]
pub struct PayloadEstimator {
    body: usize,
    /// `Σ YᵀY`.
    normal: [[f64; PARAMETERS]; PARAMETERS],
    /// `Σ Yᵀ r`.
    rhs: [f64; PARAMETERS],
    samples: u32,
}

impl PayloadEstimator {
    /// No samples yet, for a payload on `body`.
    #[must_use]
    #[inline]
    pub const fn new(body: usize) -> Self {
        Self {
            body,
            normal: [[0.0; PARAMETERS]; PARAMETERS],
            rhs: [0.0; PARAMETERS],
            samples: 0,
        }
    }

    /// Samples taken.
    #[must_use]
    #[inline]
    pub const fn samples(&self) -> u32 {
        self.samples
    }

    /// Adds one sample: joint angles `q` (rad), rates `v` (rad/s),
    /// accelerations `a` (rad/s²) and the torques `tau` (N m) that the
    /// drives applied there. `nominal` is the model without the payload;
    /// `data` is scratch.
    ///
    /// # Errors
    /// RNEA's (a non-finite sample, naming the entry).
    #[inline]
    pub fn add_sample<const NB: usize, const NQ: usize, const NV: usize>(
        &mut self,
        nominal: &Model<f32, NB, NQ, NV>,
        data: &mut Data<f32, NB, NV>,
        q: &[f32; NQ],
        v: &[f32; NV],
        a: &[f32; NV],
        tau: &[f32; NV],
    ) -> Result<()> {
        let tau_0 = *rnea(nominal, data, q, v, a, None)?;
        let Some((body_v, body_a)) = data.v.get(self.body).zip(data.a_gf.get(self.body)) else {
            return Err(rodyn::Error::BodyOutOfRange { body: self.body });
        };
        let (body_v, body_a) = (*body_v, *body_a);
        let mut f_ext = [Force::new(Vec3::ZERO, Vec3::ZERO); NB];
        let mut y = [[0.0f64; PARAMETERS]; NV];
        for k in 0..PARAMETERS {
            let mut unit = [0.0; PARAMETERS];
            unit[k] = 1.0;
            f_ext[self.body] = payload_wrench(&unit, &body_v, &body_a);
            let tau_k = rnea(nominal, data, q, v, a, Some(&f_ext))?;
            for j in 0..NV {
                y[j][k] = f64::from(tau_0[j] - tau_k[j]);
            }
        }
        for j in 0..NV {
            let r = f64::from(tau[j] - tau_0[j]);
            for k in 0..PARAMETERS {
                self.rhs[k] += y[j][k] * r;
                for l in 0..PARAMETERS {
                    self.normal[k][l] += y[j][k] * y[j][l];
                }
            }
        }
        self.samples += 1;
        Ok(())
    }

    /// The least-squares parameters, or `None` before a sample, when the
    /// normal equations are not positive definite, or when the mass found
    /// is not positive.
    #[must_use]
    #[inline]
    pub fn solve(&self) -> Option<IdentifiedPayload> {
        let mut a = self.normal;
        let mean_diagonal = (0..PARAMETERS).map(|k| a[k][k]).sum::<f64>() / PARAMETERS as f64;
        for (k, row) in a.iter_mut().enumerate() {
            row[k] += 1e-9 * mean_diagonal;
        }
        let phi = cholesky_solve(a, self.rhs)?;
        let parameters = core::array::from_fn(|k| phi[k] as f32);
        let mass = parameters[0];
        if mass.is_nan() || mass <= 0.0 {
            return None;
        }
        let com = Vec3::new(parameters[1], parameters[2], parameters[3]).scale(1.0 / mass);
        Some(IdentifiedPayload {
            mass,
            com,
            parameters,
        })
    }
}

// `Debug` by hand and inlined, as every function of this module: nothing
// of it is compiled into `rodyn-scenarios` itself, so the firmware images
// that do not use it keep their code (the crate's own copies changed how
// the optimiser inlined the other images; docs/sections/performance_notebook.md,
// "Model updates").
impl core::fmt::Debug for IdentifiedPayload {
    #[inline]
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("IdentifiedPayload")
            .field("mass", &self.mass)
            .field("com", &self.com)
            .field("parameters", &self.parameters)
            .finish()
    }
}

impl core::fmt::Debug for PayloadEstimator {
    #[inline]
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("PayloadEstimator")
            .field("body", &self.body)
            .field("samples", &self.samples)
            .finish_non_exhaustive()
    }
}

/// `x` with `A x = b` for a symmetric positive definite `A` (`A = L Lᵀ`),
/// `None` when a pivot is not positive.
#[inline]
fn cholesky_solve<const N: usize>(mut a: [[f64; N]; N], mut b: [f64; N]) -> Option<[f64; N]> {
    for k in 0..N {
        for p in 0..k {
            a[k][k] -= a[k][p] * a[k][p];
        }
        if a[k][k].is_nan() || a[k][k] <= 0.0 {
            return None;
        }
        a[k][k] = rodyn::Scalar::sqrt(a[k][k]);
        for i in k + 1..N {
            for p in 0..k {
                a[i][k] -= a[i][p] * a[k][p];
            }
            a[i][k] /= a[k][k];
        }
    }
    for i in 0..N {
        for p in 0..i {
            b[i] -= a[i][p] * b[p];
        }
        b[i] /= a[i][i];
    }
    for i in (0..N).rev() {
        for p in i + 1..N {
            b[i] -= a[p][i] * b[p];
        }
        b[i] /= a[i][i];
    }
    Some(b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rodyn::space::BodyInertia;
    use rodyn::spatial::{Inertia, Sym3};

    /// The regressor's wrench equals rodyn's `I a + v ×* I v` for the same
    /// body given as mass, centre of mass and inertia about it.
    #[test]
    fn wrench_matches_the_inertia_s_net_force() {
        let (m, c) = (1.7f32, Vec3::new(0.03, -0.05, 0.11));
        let i_c = Sym3::new(0.004, 0.0003, -0.0002, 0.005, 0.0001, 0.003);
        let body = Inertia::new(m, c, i_c);
        let i_o = i_c + Sym3::parallel_axis(&c).scale(m);
        let phi = [
            m,
            m * c.x,
            m * c.y,
            m * c.z,
            i_o.xx,
            i_o.yy,
            i_o.zz,
            i_o.xy,
            i_o.xz,
            i_o.yz,
        ];
        let v = Motion::new(Vec3::new(0.4, -1.2, 2.0), Vec3::new(0.3, 0.1, -0.7));
        let a = Motion::new(Vec3::new(-3.0, 1.5, 0.5), Vec3::new(0.2, -0.4, 9.81));
        let expected = body.net_force(&v, &a);
        let got = payload_wrench(&phi, &v, &a);
        for (g, e) in [got.ang, got.lin].iter().zip([expected.ang, expected.lin]) {
            assert!((*g - e).norm() < 1e-5, "{g:?} against {e:?}");
        }
    }

    /// The solver on a small known system.
    #[test]
    fn cholesky_solves_a_known_system() {
        let a = [[4.0, 2.0, 0.4], [2.0, 5.0, 1.0], [0.4, 1.0, 3.0]];
        let x = [1.0, -2.0, 0.5];
        let b = core::array::from_fn(|i| (0..3).map(|j| a[i][j] * x[j]).sum());
        let solved = cholesky_solve(a, b).unwrap();
        for (s, e) in solved.iter().zip(x) {
            assert!((s - e).abs() < 1e-12);
        }
        assert!(cholesky_solve([[1.0, 2.0], [2.0, 1.0]], [0.0; 2]).is_none());
    }
}
