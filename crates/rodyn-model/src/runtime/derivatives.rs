//! The analytic derivatives of inverse and forward dynamics.

use super::check::Input;
use super::{copy_matrix, RuntimeError, RuntimeModel, Workspace};
use rodyn::algorithm::derivatives::{aba_derivatives, rnea_derivatives};

impl RuntimeModel {
    /// The derivatives of inverse dynamics at `(q, v, a)`: `∂τ/∂q`,
    /// `∂τ/∂v` and `∂τ/∂a = M`, each `nv × nv` row-major (`q`'s variation
    /// in the tangent space; Pinocchio's `computeRNEADerivatives`).
    ///
    /// # Errors
    /// As [`rnea`](Self::rnea).
    #[allow(clippy::too_many_arguments)]
    pub fn rnea_derivatives(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        a: &[f64],
        dtau_dq: &mut [f64],
        dtau_dv: &mut [f64],
        dtau_da: &mut [f64],
    ) -> Result<(), RuntimeError> {
        self.check_q(q)?;
        self.check_nv("v", v)?;
        self.check_nv("a", a)?;
        for (name, out) in [
            ("dtau_dq", &*dtau_dq),
            ("dtau_dv", &*dtau_dv),
            ("dtau_da", &*dtau_da),
        ] {
            self.check_matrix(name, out, self.nv)?;
        }
        let nv = self.nv;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            let s = &mut **s;
            s.set_q(q);
            s.set_v(v);
            s.set_a(a);
            match rnea_derivatives(
                &m.model,
                &mut s.data,
                &mut s.derivatives,
                &s.q,
                &s.v,
                &s.a,
                None,
            ) {
                Ok(()) => {
                    copy_matrix(&s.derivatives.dtau_dq[..nv], nv, dtau_dq);
                    copy_matrix(&s.derivatives.dtau_dv[..nv], nv, dtau_dv);
                    copy_matrix(&s.data.mass_matrix[..nv], nv, dtau_da);
                    Ok(())
                }
                Err(e) => Err(self.explain(
                    "rnea derivatives",
                    &e,
                    &[
                        Input {
                            name: "q",
                            values: q,
                        },
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

    /// The derivatives of forward dynamics at `(q, v, τ)`: `∂q̈/∂q`,
    /// `∂q̈/∂v` and `∂q̈/∂τ = M⁻¹`, each `nv × nv` row-major (Pinocchio's
    /// `computeABADerivatives`).
    ///
    /// # Errors
    /// As [`aba`](Self::aba).
    #[allow(clippy::too_many_arguments)]
    pub fn aba_derivatives(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        tau: &[f64],
        ddq_dq: &mut [f64],
        ddq_dv: &mut [f64],
        minv: &mut [f64],
    ) -> Result<(), RuntimeError> {
        self.check_q(q)?;
        self.check_nv("v", v)?;
        self.check_nv("tau", tau)?;
        for (name, out) in [("ddq_dq", &*ddq_dq), ("ddq_dv", &*ddq_dv), ("minv", &*minv)] {
            self.check_matrix(name, out, self.nv)?;
        }
        let nv = self.nv;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            let s = &mut **s;
            s.set_q(q);
            s.set_v(v);
            s.set_a(tau);
            match aba_derivatives(
                &m.model,
                &mut s.data,
                &mut s.derivatives,
                &s.q,
                &s.v,
                &s.a,
                None,
            ) {
                Ok(()) => {
                    copy_matrix(&s.derivatives.ddq_dq[..nv], nv, ddq_dq);
                    copy_matrix(&s.derivatives.ddq_dv[..nv], nv, ddq_dv);
                    copy_matrix(&s.derivatives.minv[..nv], nv, minv);
                    Ok(())
                }
                Err(e) => Err(self.explain(
                    "aba derivatives",
                    &e,
                    &[
                        Input {
                            name: "q",
                            values: q,
                        },
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
}
