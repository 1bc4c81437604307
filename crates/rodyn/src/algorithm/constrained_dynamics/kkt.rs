//! The KKT method: CRBA and the branch-aware `M = Lᵀ D L`, the Delassus
//! matrix `G = Yᵀ D⁻¹ Y` with `Y = L⁻ᵀ J_cᵀ` (one half sweep per row along
//! its contact's path), its Cholesky factor, and `q̈ = M⁻¹ (τ − h) + L⁻¹
//! D⁻¹ Y λ` (one sweep for all rows). The time stepping and the inverse
//! dynamics with contacts reuse its pieces.

use super::{
    baumgarte_less_drift, constrained_rows, dot, factor_delassus, weighted_rows, ConstraintData,
    ConstraintSettings, Contact,
};
use crate::algorithm::crba::{crba, crba_lower};
use crate::algorithm::dense::cholesky_solve_unchecked;
use crate::algorithm::forward_dynamics::bias_and_mass;
use crate::algorithm::frame_chain::union;
use crate::algorithm::frames::frame_placement;
use crate::algorithm::jacobian::joint_jacobians_from_transforms;
use crate::algorithm::ltdl::{
    ltdl_factor, solve_lower, solve_transposed, solve_transposed_on_path,
};
use crate::data::Data;
use crate::error::Result;
use crate::model::Model;
use crate::space::RigidTransform;
use crate::spatial::Spatial;
use crate::Scalar;

/// The KKT method into `cdata.ddq` and `cdata.lambda`.
#[allow(clippy::too_many_arguments)]
pub(super) fn kkt_solve<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NC: usize,
>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    cdata: &mut ConstraintData<S, NV, NC>,
    q: &[S; NQ],
    v: &[S; NV],
    tau: &[S; NV],
    contacts: &[Contact<S>],
    settings: &ConstraintSettings<S>,
) -> Result<()> {
    // J_c, W = D⁻¹ L⁻ᵀ J_cᵀ and the Delassus matrix's factor; z = L⁻ᵀ (τ −
    // h), half of the unconstrained solve x₀ = M⁻¹ (τ − h) = L⁻¹ D⁻¹ z.
    let h = bias_and_mass(model, data, q, v, None)?;
    prepare(
        model,
        data,
        cdata,
        q,
        contacts,
        settings.damping,
        Poses::FromJointTransformsAndMass,
    )?;
    let rows = cdata.rows.min(NC);
    let mut z: [S; NV] = core::array::from_fn(|k| tau[k] - h[k]);
    solve_transposed(model, data, &mut z);

    // The right-hand side: the Baumgarte term less the drift J̇_c q̇ and
    // J_c x₀ = Wᵀ z. The bodies' accelerations at q̈ = 0 are RNEA's, which
    // leaves them less gravity (a − ⁱX₀ g) in `a_gf`; CRBA and the
    // Jacobians (poses) left that and the velocities alone.
    let gravity = *model.gravity();
    for contact in contacts {
        let i = contact.held_frame().body;
        // `check_input` refused a body past the end; a test, not a panic path.
        if i < NB {
            data.a[i] = data.a_gf[i] + data.o_m_i[i].act_inv_motion(&gravity);
        }
    }
    let mut rhs = [S::ZERO; NC];
    let mut row = 0;
    for contact in contacts {
        let n = contact.rows();
        // Within `NC` (`check_input`); `get` says so without a panic path.
        let Some(rhs) = rhs.get_mut(row..row + n) else {
            break;
        };
        baumgarte_less_drift(data, contact, settings, rhs)?;
        for (value, response) in rhs.iter_mut().zip(cdata.responses.iter().skip(row)) {
            *value -= dot(response, &z);
        }
        row += n;
    }
    cdata.lambda = rhs;
    cholesky_solve_unchecked(&cdata.delassus, rows, &mut cdata.lambda);

    // q̈ = L⁻¹ (D⁻¹ z + W λ): one sweep for the free motion and the
    // contacts' together.
    for (k, zk) in z.iter_mut().enumerate() {
        *zk /= data.ltdl[k][k];
    }
    sweep_with_response(model, data, cdata, z);
    data.tau = h;
    Ok(())
}

/// CRBA and its factorisation, `J_c`, the responses and the Cholesky
/// factor of `J_c M⁻¹ J_cᵀ + μ I`.
pub(crate) fn prepare<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NC: usize,
>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    cdata: &mut ConstraintData<S, NV, NC>,
    q: &[S; NQ],
    contacts: &[Contact<S>],
    damping: S,
    poses: Poses,
) -> Result<()> {
    form_delassus(model, data, cdata, q, contacts, damping, None, poses)?;
    factor_delassus(cdata, contacts, S::ZERO)
}

/// CRBA and its factorisation, `J_c` (each contact's rows in its reference
/// frame), `M⁻¹ J_cᵀ` and the Delassus matrix `J_c M⁻¹ J_cᵀ + μ I` itself
/// (not factored: the friction solver of
/// [`sim::time_stepping`](crate::sim::time_stepping) works on it). With
/// `added_diagonal`, `M` is replaced by `M + diag(added_diagonal)` before
/// the factorisation (time stepping's implicit joint damping).
#[allow(clippy::too_many_arguments)]
pub(crate) fn form_delassus<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NC: usize,
>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    cdata: &mut ConstraintData<S, NV, NC>,
    q: &[S; NQ],
    contacts: &[Contact<S>],
    damping: S,
    added_diagonal: Option<&[S; NV]>,
    poses: Poses,
) -> Result<()> {
    // `check_input` refused more rows than `NC`; the clamp, which changes
    // nothing then, lets the optimiser see it.
    let rows = constrained_rows(contacts).min(NC);
    cdata.rows = rows;
    // M's lower triangle, which is all the factorisation reads.
    match poses {
        Poses::Compute => {
            crba(model, data, q)?;
        }
        // From the known joint transforms, as CRBA forward dynamics does.
        Poses::FromKinematics => crba_lower(model, data, None),
        Poses::FromJointTransformsAndMass => {}
    }
    if let Some(added) = added_diagonal {
        for (k, d) in added.iter().enumerate() {
            data.mass_matrix[k][k] += *d;
        }
    }
    ltdl_factor(model, data)?;
    // J_c along the contacts' support paths only (`frame_chain`): the
    // world columns of the paths' union once, each from its body's pose
    // (cheaper per column than forming each contact's columns from the
    // joints' subspaces, performance_notebook.md, "Constrained dynamics"),
    // then each contact's columns moved into its reference frame straight
    // into its rows.
    let mut on_paths = [false; NB];
    for contact in contacts {
        let mut body = Some(contact.held_frame().body);
        // The contact's body is the caller's (`get`: past the end ends the
        // walk); the parents are in range.
        while let Some(i) = body.filter(|&i| on_paths.get(i) == Some(&false)) {
            on_paths[i] = true;
            body = model.parent(i);
        }
    }
    match poses {
        Poses::Compute => {
            union::union_world_columns(model, data, q, &on_paths, &mut cdata.jacobians.j);
        }
        // After RNEA the joints' transforms are known: the poses need only
        // be composed (all of them: the callers leave every pose valid).
        Poses::FromJointTransformsAndMass => {
            joint_jacobians_from_transforms(model, data, &mut cdata.jacobians, &on_paths);
        }
        Poses::FromKinematics => {
            union::union_world_columns_from_poses(model, data, &on_paths, &mut cdata.jacobians.j);
        }
    }
    let mut row = 0;
    for contact in contacts {
        let frame = contact.held_frame();
        let o_m_f = frame_placement(data, frame)?;
        let Some(jc_rows) = cdata.jc.get_mut(row..row + contact.rows()) else {
            break;
        };
        for jc_row in jc_rows.iter_mut() {
            *jc_row = [S::ZERO; NV];
        }
        let world = &cdata.jacobians.j;
        union::for_each_path_column(
            model,
            frame.body,
            &o_m_f,
            contact.reference(),
            world,
            |k, c| {
                let (lin, ang) = (c.lin.to_array(), c.ang.to_array());
                for (r, jc_row) in jc_rows.iter_mut().enumerate() {
                    // A contact has at most six rows: the clamp changes nothing.
                    jc_row[k] = if r < 3 { lin[r] } else { ang[(r - 3).min(2)] };
                }
            },
        );
        row += contact.rows();
    }
    // G = J_c L⁻¹ D⁻¹ L⁻ᵀ J_cᵀ = Yᵀ D⁻¹ Y with Y = L⁻ᵀ J_cᵀ: one sweep per
    // row, along the path of its contact's body only (a row is zero off
    // it), and W = D⁻¹ Y kept for the response. The pivots are inverted
    // once: a division costs several multiplications.
    let d_inv: [S; NV] = core::array::from_fn(|k| S::ONE / data.ltdl[k][k]);
    let mut row = 0;
    for contact in contacts {
        let body = contact.held_frame().body;
        let rows = row..row + contact.rows();
        let (Some(responses), Some(jc)) =
            (cdata.responses.get_mut(rows.clone()), cdata.jc.get(rows))
        else {
            break;
        };
        responses.copy_from_slice(jc);
        solve_transposed_on_path(model, data, body, responses);
        for w in responses {
            for (wk, dk) in w.iter_mut().zip(&d_inv) {
                *wk *= *dk;
            }
        }
        row += contact.rows();
    }
    // Dense sums: over a few tens of coordinates they vectorise, which
    // gathering a row's path does not (performance_notebook.md,
    // "Constrained dynamics").
    for r in 0..rows {
        let d_w: [S; NV] = core::array::from_fn(|k| data.ltdl[k][k] * cdata.responses[r][k]);
        // `0..r + 1`, not `0..=r`: the optimiser then bounds `s` by `rows`.
        for s in 0..r + 1 {
            let g = dot(&d_w, &cdata.responses[s]);
            cdata.delassus[r][s] = g;
            cdata.delassus[s][r] = g;
        }
        cdata.delassus[r][r] += damping;
    }
    Ok(())
}

/// What [`form_delassus`] finds in `data`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Poses {
    /// Nothing at `q`: it runs CRBA, and forms the poses of the contacts'
    /// support paths only.
    Compute,
    /// The joint transforms and `M`'s lower triangle at `q` (left by
    /// `bias_and_mass`): neither is formed again.
    FromJointTransformsAndMass,
    /// The joint transforms and the poses at `q` (left by a
    /// forward-kinematics pass): CRBA runs on the transforms, and the
    /// contacts' columns are read off the poses.
    FromKinematics,
}

/// `cdata.ddq = base + M⁻¹ J_cᵀ λ` after the KKT method's
/// [`form_delassus`]: `L⁻¹ (W λ)`, one sweep for all rows.
pub(crate) fn add_response<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NC: usize,
>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &Data<S, NB, NV, Spatial>,
    cdata: &mut ConstraintData<S, NV, NC>,
    base: &[S; NV],
) {
    sweep_with_response(model, data, cdata, [S::ZERO; NV]);
    for (a, b) in cdata.ddq.iter_mut().zip(base) {
        *a += *b;
    }
}

/// `cdata.ddq = L⁻¹ (z + W λ)`: a motion given by its `D⁻¹ L⁻ᵀ` half and
/// the contacts' response, in one sweep.
fn sweep_with_response<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NC: usize,
>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &Data<S, NB, NV, Spatial>,
    cdata: &mut ConstraintData<S, NV, NC>,
    mut z: [S; NV],
) {
    weighted_rows(&cdata.responses, &cdata.lambda, cdata.rows.min(NC), &mut z);
    solve_lower(model, data, &mut z);
    cdata.ddq = z;
}
