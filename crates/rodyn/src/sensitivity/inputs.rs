//! The sensitivity matrix `∂q̈/∂w` of the accelerations to the drive inputs.

use crate::algorithm::forward_dynamics::Aba;
use crate::data::Data;
use crate::drive::{forward_dynamics_with_drives, DriveForces, DriveState, ForceElement};
use crate::error::{Quantity, Result};
use crate::model::{check_finite, check_matrix_result, Model};
use crate::sensitivity::aba_response;
use crate::space::Space;
use crate::Scalar;

/// `∂q̈/∂w` (NV × NU, `out[i][k] = ∂q̈ᵢ/∂w_k`) at the state of the last
/// [`aba`](crate::algorithm::aba::aba) call, one `aba_response` per input.
///
/// Precondition: `aba` (or [`forward_dynamics_with_drives`] with
/// [`Aba`]) ran at this `(q, v)`, so `data` holds its kinematics and
/// articulated quantities. `data` is only read.
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) with
/// [`Quantity::DriveInput`] for a non-finite input `w`;
/// [`Error::InvalidDrive`](crate::Error::InvalidDrive) from the elements;
/// [`Error::NonFiniteResult`](crate::Error::NonFiniteResult) with
/// [`Quantity::Derivative`] for an entry of `out` that overflows.
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
    check_finite(w, Quantity::DriveInput)?;
    sensitivity_of_checked_inputs(model, data, q, v, elements, w, out)
}

/// [`input_sensitivity`] for inputs `w` already checked.
fn sensitivity_of_checked_inputs<
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
    check_matrix_result(out.as_flattened(), Quantity::Derivative)
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
    // `forward_dynamics_with_drives` has checked `w`.
    sensitivity_of_checked_inputs(model, data, q, v, elements, w, sensitivity)?;
    Ok(&data.ddq)
}
