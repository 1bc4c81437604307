//! Inverse and forward dynamics, the mass matrix, energies.

use super::check::Input;
use super::padded::{Padded, Scratch};
use super::{copy_matrix, RuntimeError, RuntimeModel, Workspace};
use rodyn::algorithm::aba::aba;
use rodyn::algorithm::crba::crba_planned;
use rodyn::algorithm::energy::{kinetic_energy, potential_energy};
use rodyn::algorithm::forward_dynamics::Crba;
use rodyn::algorithm::rnea::{gravity_torques, nonlinear_effects, rnea};

fn q_input(q: &[f64]) -> Input<'_> {
    Input {
        name: "q",
        values: q,
    }
}

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
        self.check_q(q)?;
        self.check_nv("v", v)?;
        self.check_nv("a", a)?;
        self.check_nv("tau", tau)?;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            let s = &mut **s;
            s.set_q(q);
            s.set_v(v);
            s.set_a(a);
            match rnea(&m.model, &mut s.data, &s.q, &s.v, &s.a, None) {
                Ok(out) => {
                    tau.copy_from_slice(&out[..tau.len()]);
                    Ok(())
                }
                Err(e) => Err(self.explain(
                    "rnea",
                    &e,
                    &[
                        q_input(q),
                        Input {
                            name: "v",
                            values: v,
                        },
                        Input {
                            name: "a",
                            values: a,
                        },
                    ],
                )),
            }
        })
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
        self.check_q(q)?;
        self.check_nv("v", v)?;
        self.check_nv("tau", tau)?;
        self.check_nv("a_out", a_out)?;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            let s = &mut **s;
            s.set_q(q);
            s.set_v(v);
            s.set_a(tau);
            match aba(&m.model, &mut s.data, &s.q, &s.v, &s.a, None) {
                Ok(out) => {
                    a_out.copy_from_slice(&out[..a_out.len()]);
                    Ok(())
                }
                Err(e) => Err(self.explain(
                    "aba",
                    &e,
                    &[
                        q_input(q),
                        Input {
                            name: "v",
                            values: v,
                        },
                        Input {
                            name: "tau",
                            values: tau,
                        },
                    ],
                )),
            }
        })
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
        self.check_q(q)?;
        self.check_nv("v", v)?;
        self.check_nv("tau", tau)?;
        self.check_nv("a_out", a_out)?;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            let s = &mut **s;
            s.set_q(q);
            s.set_v(v);
            s.set_a(tau);
            match Crba::forward_dynamics_planned(
                &m.model,
                &m.plan,
                &mut s.data,
                &s.q,
                &s.v,
                &s.a,
                None,
            ) {
                Ok(out) => {
                    a_out.copy_from_slice(&out[..a_out.len()]);
                    Ok(())
                }
                Err(e) => Err(self.explain(
                    "forward dynamics (CRBA)",
                    &e,
                    &[
                        q_input(q),
                        Input {
                            name: "v",
                            values: v,
                        },
                        Input {
                            name: "tau",
                            values: tau,
                        },
                    ],
                )),
            }
        })
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
        self.check_q(q)?;
        self.check_matrix("m_out", m_out, self.nv)?;
        let nv = self.nv;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            class_crba(m, s, q, nv, m_out).map_err(|e| self.explain("crba", &e, &[q_input(q)]))
        })
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
        self.check_q(q)?;
        self.check_nv("out", out)?;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            let s = &mut **s;
            s.set_q(q);
            match gravity_torques(&m.model, &mut s.data, &s.q) {
                Ok(g) => {
                    out.copy_from_slice(&g[..out.len()]);
                    Ok(())
                }
                Err(e) => Err(self.explain("gravity", &e, &[q_input(q)])),
            }
        })
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
        self.check_q(q)?;
        self.check_nv("v", v)?;
        self.check_nv("out", out)?;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            let s = &mut **s;
            s.set_q(q);
            s.set_v(v);
            match nonlinear_effects(&m.model, &mut s.data, &s.q, &s.v, None) {
                Ok(h) => {
                    out.copy_from_slice(&h[..out.len()]);
                    Ok(())
                }
                Err(e) => Err(self.explain(
                    "nonlinear effects",
                    &e,
                    &[
                        q_input(q),
                        Input {
                            name: "v",
                            values: v,
                        },
                    ],
                )),
            }
        })
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
        self.check_q(q)?;
        self.check_nv("v", v)?;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            let s = &mut **s;
            s.set_q(q);
            s.set_v(v);
            kinetic_energy(&m.model, &mut s.data, &s.q, &s.v).map_err(|e| {
                self.explain(
                    "kinetic energy",
                    &e,
                    &[
                        q_input(q),
                        Input {
                            name: "v",
                            values: v,
                        },
                    ],
                )
            })
        })
    }

    /// Potential energy of gravity (J), zero at the world's origin.
    ///
    /// # Errors
    /// As [`rnea`](Self::rnea).
    pub fn potential_energy(&self, ws: &mut Workspace, q: &[f64]) -> Result<f64, RuntimeError> {
        self.check_q(q)?;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            let s = &mut **s;
            s.set_q(q);
            potential_energy(&m.model, &mut s.data, &s.q)
                .map_err(|e| self.explain("potential energy", &e, &[q_input(q)]))
        })
    }
}

/// One class's CRBA, `q` in and the file's `nv × nv` block of `M` out
/// (`m_out` holds `nv²` entries). A function of its own per class rather than
/// code inlined into the dispatch: each class's pass is then optimised as
/// a unit, as the compiled model's is.
#[inline(never)]
fn class_crba<const NB: usize, const NQ: usize, const NV: usize>(
    m: &Padded<NB, NQ, NV>,
    s: &mut Scratch<NB, NQ, NV>,
    q: &[f64],
    nv: usize,
    m_out: &mut [f64],
) -> rodyn::Result<()> {
    s.set_q(q);
    let mass = crba_planned(&m.model, &m.plan, &mut s.data, &s.q)?;
    copy_matrix(&mass[..nv], nv, m_out);
    Ok(())
}
