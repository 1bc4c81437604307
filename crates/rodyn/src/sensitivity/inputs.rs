//! The sensitivity matrix `∂q̈/∂w` of the accelerations to the drive inputs.

use crate::algorithm::forward_dynamics::Aba;
use crate::data::Data;
use crate::drive::{forward_dynamics_with_drives, DriveForces, DriveState, ForceElement};
use crate::error::Result;
use crate::model::Model;
use crate::sensitivity::aba_response;
use crate::space::Space;
use crate::Scalar;

/// `∂q̈/∂w` (NV × NU, `out[i][k] = ∂q̈ᵢ/∂w_k`) at the state of the last
/// [`aba`](crate::algorithm::aba::aba) call, one [`aba_response`] per input.
///
/// Precondition: `aba` (or [`forward_dynamics_with_drives`] with
/// [`Aba`]) ran at this `(q, v)`, so `data` holds its kinematics and
/// articulated quantities. `data` is only read.
///
/// # Errors
/// [`Error::InvalidDrive`](crate::Error::InvalidDrive) from the elements.
pub fn input_sensitivity<
    S,
    G,
    E,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NU: usize,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    elements: &E,
    w: &[S; NU],
    out: &mut [[S; NU]; NV],
) -> Result<()>
where
    S: Scalar,
    G: Space,
    E: ForceElement<S, G, NB, NV> + ?Sized,
{
    let state = DriveState { data, q: &q[..], v };
    let mut d_forces = DriveForces::<S, G, NB, NV>::new();
    let mut column = [S::ZERO; NV];
    for k in 0..NU {
        d_forces.clear();
        elements.add_input_derivative(&state, w, k, &mut d_forces)?;
        aba_response(
            model,
            data,
            &d_forces.tau,
            Some(&d_forces.f_ext),
            &mut column,
        );
        for (row, value) in out.iter_mut().zip(&column) {
            row[k] = *value;
        }
    }
    Ok(())
}

/// Forward dynamics by ABA under drives and the sensitivity matrix
/// `∂q̈/∂w` in one call: [`forward_dynamics_with_drives`] then
/// [`input_sensitivity`]. Returns `data.ddq`; `forces` holds the drive
/// forces, `sensitivity` the matrix.
///
/// # Errors
/// As [`forward_dynamics_with_drives`].
#[allow(clippy::too_many_arguments)]
pub fn forward_dynamics_and_sensitivity<
    'd,
    S,
    G,
    E,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NU: usize,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    tau: &[S; NV],
    elements: &E,
    w: &[S; NU],
    forces: &mut DriveForces<S, G, NB, NV>,
    sensitivity: &mut [[S; NU]; NV],
) -> Result<&'d [S; NV]>
where
    S: Scalar,
    G: Space,
    E: ForceElement<S, G, NB, NV> + ?Sized,
{
    forward_dynamics_with_drives::<Aba, _, _, _, NB, NQ, NV>(
        model, data, q, v, tau, elements, w, forces,
    )?;
    input_sensitivity(model, data, q, v, elements, w, sensitivity)?;
    Ok(&data.ddq)
}
