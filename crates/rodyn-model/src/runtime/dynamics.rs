//! Inverse and forward dynamics, the mass matrix, energies.

use super::padded::{Padded, Scratch};
use super::{copy_matrix, RuntimeError, RuntimeModel, Workspace};
use rodyn::algorithm::aba::aba;
use rodyn::algorithm::crba::crba_planned;
use rodyn::algorithm::energy::{kinetic_energy, potential_energy};
use rodyn::algorithm::forward_dynamics::Crba;
use rodyn::algorithm::rnea::{gravity_torques, nonlinear_effects, rnea};

impl RuntimeModel {
    /// Inverse dynamics (RNEA): `τ = M(q) a + h(q, v)` into `tau`.
    ///
    /// # Errors
    /// A slice of the wrong length, a non-finite entry (named), a
    /// quaternion not of unit length, a workspace of another model.
    pub fn rnea(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        a: &[f64],
        tau: &mut [f64],
    ) -> Result<(), RuntimeError> {
        class_call!(self, ws, "rnea",
            inputs: [q, "v" => v, "a" => a],
            checks: [self.check_nv("tau", tau)],
            |m, s| rnea(&m.model, &mut s.data, &s.q, &s.v, &s.a, None)
                .map(|out| tau.copy_from_slice(&out[..tau.len()])))
    }

    /// Forward dynamics (ABA): `q̈ = M(q)⁻¹ (τ − h(q, v))` into `a_out`.
    ///
    /// # Errors
    /// As [`rnea`](Self::rnea); a singular articulated inertia.
    pub fn aba(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        tau: &[f64],
        a_out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        class_call!(self, ws, "aba",
            inputs: [q, "v" => v, "tau" => tau],
            checks: [self.check_nv("a_out", a_out)],
            |m, s| aba(&m.model, &mut s.data, &s.q, &s.v, &s.a, None)
                .map(|out| a_out.copy_from_slice(&out[..a_out.len()])))
    }

    /// Forward dynamics by CRBA and the sparse `Lᵀ D L` solve (the same
    /// `q̈` as [`aba`](Self::aba), faster on some models).
    ///
    /// # Errors
    /// As [`aba`](Self::aba); a mass matrix that is not positive definite.
    pub fn forward_dynamics_crba(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        tau: &[f64],
        a_out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        class_call!(self, ws, "forward dynamics (CRBA)",
            inputs: [q, "v" => v, "tau" => tau],
            checks: [self.check_nv("a_out", a_out)],
            |m, s| Crba::forward_dynamics_planned(&m.model, &m.plan, &mut s.data, &s.q, &s.v, &s.a, None)
                .map(|out| a_out.copy_from_slice(&out[..a_out.len()])))
    }

    /// The joint-space inertia matrix `M(q)` (CRBA, rotor inertias
    /// included) into `m_out`: `nv × nv`, row-major, both triangles.
    ///
    /// # Errors
    /// As [`rnea`](Self::rnea).
    pub fn crba(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        m_out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        let nv = self.nv;
        class_call!(self, ws, "crba",
            inputs: [q],
            checks: [self.check_matrix("m_out", m_out, nv)],
            |m, s| class_crba(m, s, nv, m_out))
    }

    /// The generalized gravity `g(q)` (the torques that hold `q` at rest)
    /// into `out`.
    ///
    /// # Errors
    /// As [`rnea`](Self::rnea).
    pub fn gravity(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        class_call!(self, ws, "gravity",
            inputs: [q],
            checks: [self.check_nv("out", out)],
            |m, s| gravity_torques(&m.model, &mut s.data, &s.q)
                .map(|g| out.copy_from_slice(&g[..out.len()])))
    }

    /// The nonlinear effects `h(q, v)`: Coriolis, centrifugal and gravity
    /// torques, into `out`.
    ///
    /// # Errors
    /// As [`rnea`](Self::rnea).
    pub fn nonlinear_effects(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        class_call!(self, ws, "nonlinear effects",
            inputs: [q, "v" => v],
            checks: [self.check_nv("out", out)],
            |m, s| nonlinear_effects(&m.model, &mut s.data, &s.q, &s.v, None)
                .map(|h| out.copy_from_slice(&h[..out.len()])))
    }

    /// Kinetic energy `½ vᵀ M v` (J), rotor inertias included.
    ///
    /// # Errors
    /// As [`rnea`](Self::rnea).
    pub fn kinetic_energy(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
    ) -> Result<f64, RuntimeError> {
        class_call!(self, ws, "kinetic energy",
            inputs: [q, "v" => v],
            checks: [],
            |m, s| kinetic_energy(&m.model, &mut s.data, &s.q, &s.v))
    }

    /// Potential energy of gravity (J), zero at the world's origin.
    ///
    /// # Errors
    /// As [`rnea`](Self::rnea).
    pub fn potential_energy(&self, ws: &mut Workspace, q: &[f64]) -> Result<f64, RuntimeError> {
        class_call!(self, ws, "potential energy",
            inputs: [q],
            checks: [],
            |m, s| potential_energy(&m.model, &mut s.data, &s.q))
    }
}

/// One class's CRBA on the `q` already copied in, the file's `nv × nv`
/// block of `M` out (`m_out` holds `nv²` entries). A function of its own per class rather than
/// code inlined into the dispatch: each class's pass is then optimised as
/// a unit, as the compiled model's is.
#[inline(never)]
fn class_crba<const NB: usize, const NQ: usize, const NV: usize>(
    m: &Padded<NB, NQ, NV>,
    s: &mut Scratch<NB, NQ, NV>,
    nv: usize,
    m_out: &mut [f64],
) -> rodyn::Result<()> {
    let mass = crba_planned(&m.model, &m.plan, &mut s.data, &s.q)?;
    copy_matrix(&mass[..nv], nv, m_out);
    Ok(())
}
