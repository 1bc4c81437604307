//! A rodyn model with drives as a discrete-time system for
//! [`ilqr`](crate::ilqr): one semi-implicit Euler step of forward dynamics
//! per stage, linearised with rodyn's analytic derivatives.

use crate::ilqr::DiscreteSystem;
use rodyn::algorithm::derivatives::DerivativeData;
use rodyn::algorithm::derivatives::DerivativeSpace;
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::algorithm::jacobian::JacobianData;
use rodyn::drive::{
    aba_derivatives_with_drives, forward_dynamics_with_drives, DriveDerivatives, DriveForces,
    ForceElement, PointGeometry,
};
use rodyn::{Data, Model, Result, Scalar};

/// A model of `NV` one-coordinate joints (`q` and `v` of the same size)
/// with drive elements `E` at fixed drive inputs, actuated by joint torques:
/// state `x = (q, v)` (`NX = 2 NV`), control `u = τ` (`NU = NV`), and
///
/// ```text
/// v' = v + h q̈(q, v, τ),   q' = q + h v'
/// ```
///
/// (semi-implicit Euler, step `h`). Its Jacobians follow from
/// `∂q̈/∂(q, v, τ)`: `∂v'/∂q = h ∂q̈/∂q`, `∂v'/∂v = I + h ∂q̈/∂v`,
/// `∂v'/∂τ = h M⁻¹`, and `∂q'/∂· = h ∂v'/∂·` plus the identity on `q`.
pub struct DrivenModel<
    'm,
    S: Scalar,
    G: PointGeometry + DerivativeSpace,
    E,
    const NB: usize,
    const NV: usize,
    const NX: usize,
    const NU: usize,
> {
    model: &'m Model<S, NB, NV, NV, G>,
    elements: &'m E,
    /// The drive inputs (muscle activations, motor currents), held fixed.
    pub inputs: &'m [S],
    /// The step `h` (s).
    pub step: S,
    data: Data<S, NB, NV, G>,
    derivatives: DerivativeData<S, NB, NV, G>,
    jacobians: JacobianData<S, NV, G>,
    drive: DriveDerivatives<S, NV>,
    forces: DriveForces<S, G, NB, NV>,
}

impl<'m, S, G, E, const NB: usize, const NV: usize, const NX: usize, const NU: usize>
    DrivenModel<'m, S, G, E, NB, NV, NX, NU>
where
    S: Scalar,
    G: PointGeometry + DerivativeSpace,
    E: ForceElement<S, G, NB, NV>,
{
    /// `model` with `elements` at `inputs`, stepped by `step` seconds.
    /// `NX = 2 NV` and `NU = NV`, or this does not compile.
    #[must_use]
    pub fn new(
        model: &'m Model<S, NB, NV, NV, G>,
        elements: &'m E,
        inputs: &'m [S],
        step: S,
    ) -> Self {
        const { assert!(NX == 2 * NV && NU == NV, "x = (q, v) and u = τ") };
        Self {
            model,
            elements,
            inputs,
            step,
            data: Data::new(),
            derivatives: DerivativeData::new(),
            jacobians: JacobianData::new(),
            drive: DriveDerivatives::new(),
            forces: DriveForces::new(),
        }
    }

    fn split(x: &[S; NX]) -> ([S; NV], [S; NV]) {
        (
            core::array::from_fn(|k| x[k]),
            core::array::from_fn(|k| x[NV + k]),
        )
    }

    fn tau(u: &[S; NU]) -> [S; NV] {
        core::array::from_fn(|k| u[k])
    }
}

impl<S, G, E, const NB: usize, const NV: usize, const NX: usize, const NU: usize>
    DiscreteSystem<S, NX, NU> for DrivenModel<'_, S, G, E, NB, NV, NX, NU>
where
    S: Scalar,
    G: PointGeometry + DerivativeSpace,
    E: ForceElement<S, G, NB, NV>,
{
    fn step(&mut self, x: &[S; NX], u: &[S; NU]) -> Result<[S; NX]> {
        let (q, v) = Self::split(x);
        let ddq = *forward_dynamics_with_drives::<Aba, _, _, _, NB, NV, NV>(
            self.model,
            &mut self.data,
            &q,
            &v,
            &Self::tau(u),
            self.elements,
            self.inputs,
            &mut self.forces,
        )?;
        let h = self.step;
        let v_next: [S; NV] = core::array::from_fn(|k| v[k] + h * ddq[k]);
        Ok(core::array::from_fn(|k| {
            if k < NV {
                q[k] + h * v_next[k]
            } else {
                v_next[k - NV]
            }
        }))
    }

    fn linearize(
        &mut self,
        x: &[S; NX],
        u: &[S; NU],
        a: &mut [[S; NX]; NX],
        b: &mut [[S; NU]; NX],
    ) -> Result<()> {
        let (q, v) = Self::split(x);
        aba_derivatives_with_drives(
            self.model,
            &mut self.data,
            &mut self.derivatives,
            &mut self.jacobians,
            &mut self.drive,
            &q,
            &v,
            &Self::tau(u),
            self.elements,
            self.inputs,
        )?;
        let h = self.step;
        let d = &self.derivatives;
        for r in 0..NV {
            for c in 0..NV {
                let identity = if r == c { S::ONE } else { S::ZERO };
                // Rows of v' = v + h q̈, then of q' = q + h v'.
                let (dv_dq, dv_dv, dv_du) = (
                    h * d.ddq_dq[r][c],
                    identity + h * d.ddq_dv[r][c],
                    h * d.minv[r][c],
                );
                a[NV + r][c] = dv_dq;
                a[NV + r][NV + c] = dv_dv;
                b[NV + r][c] = dv_du;
                a[r][c] = identity + h * dv_dq;
                a[r][NV + c] = h * dv_dv;
                b[r][c] = h * dv_du;
            }
        }
        Ok(())
    }
}
