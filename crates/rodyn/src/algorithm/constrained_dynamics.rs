//! Forward dynamics with rigid point contacts: the second seed's
//!
//! ```text
//! M q̈ + C q̇ + G = τ + J_cᵀ λ,    J_c q̈ + J̇_c q̇ = −K_p e − K_d J_c q̇,
//! ```
//!
//! for a set of contact points chosen at run time (a foot in swing is
//! simply left out of the slice). `λ` stacks the contact forces (N, world
//! axes at each point: Pinocchio's `LOCAL_WORLD_ALIGNED` 3-D contact), `e`
//! each point's offset from its anchor (m) and `J_c q̇` its velocity: the
//! right-hand side is Baumgarte's stabilisation (Baumgarte 1972), which
//! pulls drifting contacts back to their anchors; with zero gains the
//! contacts keep their current acceleration-level constraint only.
//!
//! Method: the KKT system by its Schur complement (Featherstone,
//! *Rigid Body Dynamics Algorithms*, §8.2, and Pinocchio's
//! `constraintDynamics` solve the same system): CRBA and the branch-aware
//! `Lᵀ D L` give `M⁻¹`, the Delassus matrix `G = J_c M⁻¹ J_cᵀ` is formed,
//! `(G + μ I) λ = −(J_c M⁻¹ (τ − h) + J̇_c q̇ + K_p e + K_d J_c q̇)` is solved
//! by a small Cholesky factorisation, and `q̈ = M⁻¹ (τ − h + J_cᵀ λ)`.
//!
//! Redundant contacts (a rank-deficient `J_c`, such as four coplanar feet
//! of a robot whose legs cannot hold them apart) make `G` singular: with
//! `μ = 0` that is [`Error::RedundantConstraints`] naming the row; a
//! damping `μ > 0` regularises it (Tikhonov: the `λ` of least norm
//! among the near-solutions, the constraint then met to `O(μ)`).
//!
//! Cost: one RNEA, one CRBA and factorisation, one `Lᵀ D L` solve per
//! constrained row, the joint Jacobians, and a dense `3k × 3k` solve.

use super::crba::crba;
use super::dense::{cholesky_in_place, cholesky_solve};
use super::frames::{
    frame_classical_acceleration, frame_placement, frame_velocity, ReferenceFrame,
};
use super::jacobian::{frame_jacobian, joint_jacobians, JacobianData};
use super::kinematics::forward_kinematics_acceleration;
use super::ltdl::{ltdl_factor, ltdl_solve};
use super::rnea::nonlinear_effects;
use crate::data::Data;
use crate::error::{Error, Quantity, Result};
use crate::frame::Frame;
use crate::model::{check_finite, check_result, Model};
use crate::space::{RigidTransform, VectorOps};
use crate::spatial::{Motion, Spatial, Vec3};
use crate::Scalar;

/// Relative size (of the Delassus matrix's largest diagonal entry, in
/// units of ε) below which a pivot counts as zero: the contacts are
/// redundant.
const PIVOT_TOLERANCE: f64 = 1e3;

/// A point of a body held by the environment: the origin of `frame` kept
/// at `anchor` (world frame, m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointContact<S: Scalar> {
    /// The contact point, as a frame on its body (only its origin counts).
    pub frame: Frame<S, Spatial>,
    /// Where the point should be, world frame (m): the Baumgarte term's
    /// reference. Set it where the contact was made.
    pub anchor: Vec3<S>,
}

/// The gains of the constraint solve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstraintSettings<S> {
    /// `K_p`, 1/s²: position feedback of the Baumgarte term.
    pub kp: S,
    /// `K_d`, 1/s: velocity feedback.
    pub kd: S,
    /// `μ` (m/N/s², the Delassus matrix's unit): damping of the contact
    /// solve, for redundant contacts.
    pub damping: S,
}

impl<S: Scalar> Default for ConstraintSettings<S> {
    /// No stabilisation, no damping: the exact KKT solution.
    fn default() -> Self {
        Self {
            kp: S::ZERO,
            kd: S::ZERO,
            damping: S::ZERO,
        }
    }
}

/// The workspace of [`constrained_forward_dynamics`] for up to `NC`
/// constrained rows (three per point contact). Its own type, so that a
/// firmware without contacts pays nothing for them.
#[derive(Clone, Debug)]
pub struct ConstraintData<S: Scalar, const NV: usize, const NC: usize> {
    /// The joint Jacobians of the last call.
    pub jacobians: JacobianData<S, NV, Spatial>,
    /// `J_c`, one row per constrained direction (the first [`rows`](Self::rows)).
    pub jc: [[S; NV]; NC],
    /// `M⁻¹ J_cᵀ`, by rows (column r of `M⁻¹ J_cᵀ` in row r).
    pub minv_jt: [[S; NV]; NC],
    /// The Delassus matrix `J_c M⁻¹ J_cᵀ + μ I`, then its Cholesky factor.
    pub delassus: [[S; NC]; NC],
    /// The contact forces `λ` (N), world axes, three per contact.
    pub lambda: [S; NC],
    /// The joint accelerations `q̈`.
    pub ddq: [S; NV],
    /// Rows in use: three times the contacts of the last call.
    pub rows: usize,
    columns: [Motion<S>; NV],
}

impl<S: Scalar, const NV: usize, const NC: usize> ConstraintData<S, NV, NC> {
    /// A zeroed workspace (usable in `const`).
    #[must_use]
    pub const fn new() -> Self {
        Self {
            jacobians: JacobianData::new(),
            jc: [[S::ZERO; NV]; NC],
            minv_jt: [[S::ZERO; NV]; NC],
            delassus: [[S::ZERO; NC]; NC],
            lambda: [S::ZERO; NC],
            ddq: [S::ZERO; NV],
            rows: 0,
            columns: [Motion::ZERO; NV],
        }
    }
}

impl<S: Scalar, const NV: usize, const NC: usize> Default for ConstraintData<S, NV, NC> {
    fn default() -> Self {
        Self::new()
    }
}

/// `q̈` and the contact forces `λ` of `model` at `(q, v)` under joint
/// forces `tau` (N m, N), with the points of `contacts` held (see the
/// module documentation). Returns `(q̈, λ)`, `λ` three entries per contact
/// in `contacts`' order.
///
/// Leaves valid in `data`: what [`crba`], [`ltdl_factor`] and
/// [`joint_jacobians`] leave, `o_m_i`, `v` and `a` at `(q, v, 0)`; `tau`
/// holds the bias forces `h`. In `cdata`: every field.
///
/// # Errors
/// [`Error::TooManyConstraints`] for more than `NC / 3` contacts,
/// [`Error::InvalidGain`] for a negative or non-finite gain (index 0:
/// `kp`, 1: `kd`, 2: `damping`), [`Error::FrameBodyOutOfRange`] for a
/// contact on a body the model does not have, [`Error::NonFinite`] for a
/// non-finite anchor (`Quantity::Contact`, the contact's index) or
/// input, [`Error::RedundantConstraints`] when the contacts are redundant
/// and `damping` is zero, and those of the algorithms it runs.
#[allow(clippy::too_many_arguments)]
pub fn constrained_forward_dynamics<
    'c,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NC: usize,
>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    cdata: &'c mut ConstraintData<S, NV, NC>,
    q: &[S; NQ],
    v: &[S; NV],
    tau: &[S; NV],
    contacts: &[PointContact<S>],
    settings: &ConstraintSettings<S>,
) -> Result<(&'c [S; NV], &'c [S])> {
    check_input(contacts, settings, NB, NC)?;
    let rows = 3 * contacts.len();
    check_finite(tau, Quantity::Torque)?;

    // Unconstrained: M x₀ = τ − h; then J_c, M⁻¹ J_cᵀ and the Delassus
    // matrix's factor.
    let h = *nonlinear_effects(model, data, q, v, None)?;
    prepare(model, data, cdata, q, contacts, settings.damping)?;
    let mut x0: [S; NV] = core::array::from_fn(|k| tau[k] - h[k]);
    ltdl_solve(model, data, &mut x0)?;

    // The right-hand side: −(J_c x₀ + J̇_c q̇ + K_p e + K_d J_c q̇).
    let mut rhs = [S::ZERO; NC];
    for (c, contact) in contacts.iter().enumerate() {
        let position = frame_placement(data, &contact.frame)?.trans;
        let error = (position - contact.anchor).to_array();
        for axis in 0..3 {
            rhs[3 * c + axis] = -settings.kp * error[axis];
        }
    }
    forward_kinematics_acceleration(model, data, q, v, &[S::ZERO; NV])?;
    for (c, contact) in contacts.iter().enumerate() {
        let drift =
            frame_classical_acceleration(data, &contact.frame, ReferenceFrame::LocalWorldAligned)?
                .lin
                .to_array();
        let velocity = frame_velocity(data, &contact.frame, ReferenceFrame::LocalWorldAligned)?
            .lin
            .to_array();
        for axis in 0..3 {
            let r = 3 * c + axis;
            rhs[r] -= drift[axis] + settings.kd * velocity[axis] + dot(&cdata.jc[r], &x0);
        }
    }
    cdata.lambda = rhs;
    cholesky_solve(&cdata.delassus, rows, &mut cdata.lambda);

    // q̈ = x₀ + M⁻¹ J_cᵀ λ.
    add_response(cdata, rows, &x0);
    check_result(&cdata.lambda[..rows], Quantity::Contact)?;
    check_result(&cdata.ddq, Quantity::Acceleration)?;
    data.tau = h;
    Ok((&cdata.ddq, &cdata.lambda[..rows]))
}

/// The velocities just after an impact at configuration `q`: the points
/// of `contacts` meet the ground with velocity `J_c v⁻` and leave with
/// `−e J_c v⁻` (`e`, `restitution`, in `[0, 1]`; 0 for a plastic impact
/// that stops them), by the impulses `Λ` (N s, world axes, three per
/// contact) of `M (v⁺ − v⁻) = J_cᵀ Λ` (Pinocchio's `impulseDynamics`).
/// An impact with `e ≤ 1` never adds kinetic energy. Returns `(v⁺, Λ)`;
/// `damping` regularises redundant contacts as in
/// [`constrained_forward_dynamics`].
///
/// Leaves valid in `data`: what [`crba`], [`ltdl_factor`] and
/// [`joint_jacobians`] leave. In `cdata`: every field (`ddq` holds `v⁺`,
/// `lambda` holds `Λ`).
///
/// # Errors
/// As [`constrained_forward_dynamics`]; [`Error::InvalidGain`] with index
/// 0 for a restitution outside `[0, 1]`, 2 for a bad damping.
#[allow(clippy::too_many_arguments)]
pub fn impulse_dynamics<
    'c,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NC: usize,
>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    cdata: &'c mut ConstraintData<S, NV, NC>,
    q: &[S; NQ],
    v_before: &[S; NV],
    contacts: &[PointContact<S>],
    restitution: S,
    damping: S,
) -> Result<(&'c [S; NV], &'c [S])> {
    let e = restitution.to_f64();
    if !(0.0..=1.0).contains(&e) {
        return Err(Error::InvalidGain { index: 0 });
    }
    let settings = ConstraintSettings {
        kp: S::ZERO,
        kd: S::ZERO,
        damping,
    };
    check_input(contacts, &settings, NB, NC)?;
    check_finite(v_before, Quantity::Velocity)?;
    prepare(model, data, cdata, q, contacts, damping)?;
    let rows = cdata.rows;
    for r in 0..rows {
        cdata.lambda[r] = -(S::ONE + restitution) * dot(&cdata.jc[r], v_before);
    }
    cholesky_solve(&cdata.delassus, rows, &mut cdata.lambda);
    // v⁺ = v⁻ + M⁻¹ J_cᵀ Λ.
    add_response(cdata, rows, v_before);
    check_result(&cdata.lambda[..rows], Quantity::Contact)?;
    check_result(&cdata.ddq, Quantity::Velocity)?;
    Ok((&cdata.ddq, &cdata.lambda[..rows]))
}

/// The checks shared by both solves: capacity, gains, bodies, anchors.
fn check_input<S: Scalar>(
    contacts: &[PointContact<S>],
    settings: &ConstraintSettings<S>,
    nb: usize,
    capacity: usize,
) -> Result<()> {
    let rows = 3 * contacts.len();
    if rows > capacity {
        return Err(Error::TooManyConstraints { rows, capacity });
    }
    let gains = [settings.kp, settings.kd, settings.damping];
    if let Some(index) = gains
        .iter()
        .position(|g| !(g.is_finite() && g.to_f64() >= 0.0))
    {
        return Err(Error::InvalidGain { index });
    }
    for (index, c) in contacts.iter().enumerate() {
        if c.frame.body >= nb {
            return Err(Error::FrameBodyOutOfRange { body: c.frame.body });
        }
        if !(c.anchor.is_finite() && c.frame.placement.is_finite()) {
            return Err(Error::NonFinite {
                quantity: Quantity::Contact,
                index,
            });
        }
    }
    Ok(())
}

/// CRBA and its factorisation, `J_c` (world axes at each point),
/// `M⁻¹ J_cᵀ` and the Cholesky factor of `J_c M⁻¹ J_cᵀ + μ I`.
fn prepare<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, const NC: usize>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    cdata: &mut ConstraintData<S, NV, NC>,
    q: &[S; NQ],
    contacts: &[PointContact<S>],
    damping: S,
) -> Result<()> {
    let rows = 3 * contacts.len();
    cdata.rows = rows;
    crba(model, data, q)?;
    ltdl_factor(model, data)?;
    joint_jacobians(model, data, &mut cdata.jacobians, q)?;
    for (c, contact) in contacts.iter().enumerate() {
        frame_jacobian(
            model,
            data,
            &cdata.jacobians,
            &contact.frame,
            ReferenceFrame::LocalWorldAligned,
            &mut cdata.columns,
        )?;
        for (axis, row) in cdata.jc[3 * c..3 * c + 3].iter_mut().enumerate() {
            for (entry, column) in row.iter_mut().zip(&cdata.columns) {
                *entry = column.lin.to_array()[axis];
            }
        }
    }
    for r in 0..rows {
        cdata.minv_jt[r] = cdata.jc[r];
        ltdl_solve(model, data, &mut cdata.minv_jt[r])?;
    }
    for r in 0..rows {
        for s in 0..=r {
            let g = dot(&cdata.jc[r], &cdata.minv_jt[s]);
            cdata.delassus[r][s] = g;
            cdata.delassus[s][r] = g;
        }
        cdata.delassus[r][r] += damping;
    }
    cholesky_in_place(&mut cdata.delassus, rows, PIVOT_TOLERANCE)
        .map_err(|row| Error::RedundantConstraints { row })
}

/// `cdata.ddq = base + M⁻¹ J_cᵀ λ` from the rows of `M⁻¹ J_cᵀ` and `λ`.
fn add_response<S: Scalar, const NV: usize, const NC: usize>(
    cdata: &mut ConstraintData<S, NV, NC>,
    rows: usize,
    base: &[S; NV],
) {
    cdata.ddq = *base;
    for (row, l) in cdata.minv_jt[..rows].iter().zip(&cdata.lambda[..rows]) {
        for (a, y) in cdata.ddq.iter_mut().zip(row) {
            *a += *y * *l;
        }
    }
}

fn dot<S: Scalar, const N: usize>(a: &[S; N], b: &[S; N]) -> S {
    a.iter().zip(b).fold(S::ZERO, |acc, (x, y)| acc + *x * *y)
}
