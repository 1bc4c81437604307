//! Forward dynamics with rigid contacts: the second seed's
//!
//! ```text
//! M q̈ + C q̇ + G = τ + J_cᵀ λ,    J_c q̈ + J̇_c q̇ = −K_p e − K_d J_c q̇,
//! ```
//!
//! for a set of contacts chosen at run time (a foot in swing is simply
//! left out of the slice). A [`Contact`] holds a point (three rows: `λ` a
//! force in world axes, Pinocchio's `CONTACT_3D` in `LOCAL_WORLD_ALIGNED`)
//! or a whole frame (six rows: `λ` a wrench in the frame's axes,
//! `CONTACT_6D` in `LOCAL`). `e` is each contact's error against its
//! anchor (the point's offset, m, or the frame's twist `−log6(ᶜX_anchor)`)
//! and `J_c q̇` its velocity: the right-hand side is Baumgarte's
//! stabilisation (Baumgarte 1972), which pulls drifting contacts back to
//! their anchors; with zero gains the contacts keep their current
//! acceleration-level constraint only.
//!
//! Two methods solve it behind one interface ([`ConstraintMethod`], as
//! [`forward_dynamics`](super::forward_dynamics) offers ABA and CRBA):
//!
//! - [`ConstraintMethod::Kkt`], the default: the KKT system by its Schur
//!   complement (Featherstone, *Rigid Body Dynamics Algorithms*, §8.2;
//!   Pinocchio's `constraintDynamics` solves the same system): CRBA and
//!   the branch-aware `Lᵀ D L` give `M⁻¹`, the Delassus matrix `G = J_c M⁻¹
//!   J_cᵀ` is formed, `(G + μ I) λ = −(J_c M⁻¹ (τ − h) + J̇_c q̇ + K_p e + K_d
//!   J_c q̇)` is solved by a small Cholesky factorisation, and `q̈ = M⁻¹ (τ −
//!   h + J_cᵀ λ)`.
//! - [`ConstraintMethod::ArticulatedBody`]: ABA, then `G` from unit test
//!   forces propagated through ABA's articulated inertias (see
//!   `articulated.rs`), never forming `M`.
//!
//! Redundant contacts (a rank-deficient `J_c`, such as four coplanar feet
//! of a robot whose legs cannot hold them apart) make `G` singular: with
//! `μ = 0` that is [`Error::RedundantConstraints`] naming the row and the
//! contact; a damping `μ > 0` regularises it (Tikhonov: the `λ` of least
//! norm among the near-solutions, the constraint then met to `O(μ)`).
//!
//! Cost of the KKT method: one RNEA, one CRBA and factorisation, one `Lᵀ D
//! L` solve per constrained row, the joint Jacobians, and a dense `m × m`
//! solve for `m` rows; of the articulated-body method: one ABA, one
//! kinematics pass, two sweeps per row and the same dense solve.

mod articulated;

use super::crba::crba;
use super::dense::{cholesky_in_place, cholesky_solve};
use super::frames::ReferenceFrame;
use super::jacobian::{
    frame_jacobian, joint_jacobians, joint_jacobians_from_transforms, JacobianData,
};
use super::ltdl::{ltdl_factor, ltdl_solve, solve_lower, solve_transposed_on_path};
use super::rnea::nonlinear_effects;
use crate::data::Data;
use crate::error::{Error, Quantity, Result};
use crate::frame::Frame;
use crate::model::{check_finite, check_result, Model};
use crate::space::{RigidTransform, VectorOps};
use crate::spatial::{log6, Motion, Spatial, Transform, Vec3};
use crate::Scalar;

/// Relative size (of the Delassus matrix's largest diagonal entry, in
/// units of ε) below which a pivot counts as zero: the contacts are
/// redundant.
const PIVOT_TOLERANCE: f64 = 1e3;

/// A contact the environment holds: a point (three constrained rows) or a
/// whole frame (six).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Contact<S: Scalar> {
    /// The origin of `frame` kept at `anchor` (world frame, m). Its force
    /// `λ` (N) is in world axes at the point: Pinocchio's `CONTACT_3D` in
    /// `LOCAL_WORLD_ALIGNED`. A foot that may roll about its sole.
    Point {
        /// The contact point, as a frame on its body (only its origin counts).
        frame: Frame<S, Spatial>,
        /// Where the point should be, world frame (m): the Baumgarte
        /// term's reference. Set it where the contact was made.
        anchor: Vec3<S>,
    },
    /// `frame` kept at the placement `anchor` (world frame): position and
    /// orientation. Its wrench `λ` is in the frame's own axes about its
    /// origin, force (N) then moment (N m): Pinocchio's `CONTACT_6D` in
    /// `LOCAL`. A flat foot on the ground, a hand on a handle.
    Frame {
        /// The held frame.
        frame: Frame<S, Spatial>,
        /// Where the frame should be, world frame: the Baumgarte term's
        /// reference (its error is the twist `log6(ᶜX_anchor)`).
        anchor: Transform<S>,
    },
}

impl<S: Scalar> Contact<S> {
    /// A point contact (see [`Contact::Point`]).
    #[must_use]
    pub const fn point(frame: Frame<S, Spatial>, anchor: Vec3<S>) -> Self {
        Self::Point { frame, anchor }
    }

    /// A frame contact (see [`Contact::Frame`]).
    #[must_use]
    pub const fn frame(frame: Frame<S, Spatial>, anchor: Transform<S>) -> Self {
        Self::Frame { frame, anchor }
    }

    /// The contact in scalar type `T`.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> Contact<T> {
        match self {
            Self::Point { frame, anchor } => Contact::point(frame.cast(), anchor.cast()),
            Self::Frame { frame, anchor } => Contact::frame(frame.cast(), anchor.cast()),
        }
    }

    /// Constrained rows: 3 for a point, 6 for a frame.
    #[must_use]
    pub const fn rows(&self) -> usize {
        match self {
            Self::Point { .. } => 3,
            Self::Frame { .. } => 6,
        }
    }

    /// The held frame.
    #[must_use]
    pub const fn held_frame(&self) -> &Frame<S, Spatial> {
        match self {
            Self::Point { frame, .. } | Self::Frame { frame, .. } => frame,
        }
    }

    fn anchor_is_finite(&self) -> bool {
        match self {
            Self::Point { anchor, .. } => anchor.is_finite(),
            Self::Frame { anchor, .. } => anchor.is_finite(),
        }
    }

    /// The reference frame of the rows and of `λ`.
    const fn reference(&self) -> ReferenceFrame {
        match self {
            Self::Point { .. } => ReferenceFrame::LocalWorldAligned,
            Self::Frame { .. } => ReferenceFrame::Local,
        }
    }
}

/// The rows of all `contacts`: the sum of [`Contact::rows`].
#[must_use]
pub fn constrained_rows<S: Scalar>(contacts: &[Contact<S>]) -> usize {
    contacts.iter().map(Contact::rows).sum()
}

/// How [`constrained_forward_dynamics_with`] solves the system (see the
/// [module](self)): the two give the same numbers to rounding.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ConstraintMethod {
    /// The KKT system's Schur complement on CRBA and `Lᵀ D L`.
    #[default]
    Kkt,
    /// ABA and test forces through its articulated inertias.
    ArticulatedBody,
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
/// constrained rows (three per point contact, six per frame contact). Its own type, so that a
/// firmware without contacts pays nothing for them.
#[derive(Clone, Debug)]
pub struct ConstraintData<S: Scalar, const NV: usize, const NC: usize> {
    /// The joint Jacobians of the last call.
    pub jacobians: JacobianData<S, NV, Spatial>,
    /// `J_c`, one row per constrained direction (the first [`rows`](Self::rows)).
    pub jc: [[S; NV]; NC],
    /// The method's responses to the rows of `J_cᵀ`, by rows: for the KKT
    /// method `W = D⁻¹ L⁻ᵀ J_cᵀ` (so `M⁻¹ J_cᵀ = L⁻¹ W`), for the
    /// articulated-body method `M⁻¹ J_cᵀ` itself.
    responses: [[S; NV]; NC],
    /// The Delassus matrix `J_c M⁻¹ J_cᵀ + μ I`, then its Cholesky factor.
    pub delassus: [[S; NC]; NC],
    /// The contact forces `λ`, in the contacts' order ([`Contact`] gives
    /// each one's rows, axes and units).
    pub lambda: [S; NC],
    /// The joint accelerations `q̈`.
    pub ddq: [S; NV],
    /// Rows in use by the contacts of the last call.
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
            responses: [[S::ZERO; NV]; NC],
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
/// forces `tau` (N m, N), with `contacts` held (see the module
/// documentation), by the KKT method. Returns `(q̈, λ)`, `λ` in
/// `contacts`' order: three entries per point contact, six per frame
/// contact ([`Contact`] gives their axes and units).
///
/// Leaves valid in `data`: what [`crba`], [`ltdl_factor`] and
/// [`joint_jacobians`] leave, `o_m_i`, `v` and `a` at `(q, v, 0)`; `tau`
/// holds the bias forces `h`. In `cdata`: every field.
///
/// # Errors
/// [`Error::TooManyConstraints`] for more than `NC` rows,
/// [`Error::InvalidGain`] for a negative or non-finite gain (index 0:
/// `kp`, 1: `kd`, 2: `damping`), [`Error::FrameBodyOutOfRange`] for a
/// contact on a body the model does not have, [`Error::NonFinite`] for a
/// non-finite anchor or contact frame (`Quantity::Contact`, the contact's
/// index) or input, [`Error::RedundantConstraints`] when the contacts are
/// redundant and `damping` is zero, and those of the algorithms it runs.
///
/// # Example
///
/// A 1 kg ball on a free flyer, held at its centre: the contact carries
/// its weight and it does not move (it could spin: no torque turns it).
///
/// ```
/// use rodyn::algorithm::constrained_dynamics::{
///     constrained_forward_dynamics, Contact, ConstraintData, ConstraintSettings,
/// };
/// use rodyn::joint::FreeFlyer;
/// use rodyn::prelude::*;
/// use rodyn::Frame;
/// const BALL: Model<f64, 1, 7, 6> = Model::new(
///     [None], [Joint::FreeFlyer(FreeFlyer)], [Transform::IDENTITY],
///     [Inertia::new(1.0, Vec3::ZERO, Sym3::diagonal(0.004, 0.004, 0.004))],
///     Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
/// );
/// let q = [0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
/// let held = [Contact::point(Frame::new(0, Transform::IDENTITY), Vec3::new(0.0, 0.0, 1.0))];
/// let (mut data, mut cdata) = (Data::new(), ConstraintData::<f64, 6, 3>::new());
/// let (ddq, lambda) = constrained_forward_dynamics(
///     &BALL, &mut data, &mut cdata, &q, &[0.0; 6], &[0.0; 6], &held,
///     &ConstraintSettings::default(),
/// )?;
/// assert!((lambda[2] - 9.81).abs() < 1e-12 && ddq.iter().all(|a| a.abs() < 1e-12));
/// # Ok::<(), rodyn::Error>(())
/// ```
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
    contacts: &[Contact<S>],
    settings: &ConstraintSettings<S>,
) -> Result<(&'c [S; NV], &'c [S])> {
    constrained_forward_dynamics_with(
        ConstraintMethod::Kkt,
        model,
        data,
        cdata,
        q,
        v,
        tau,
        contacts,
        settings,
    )
}

/// [`constrained_forward_dynamics`] by the chosen `method`. With
/// [`ConstraintMethod::ArticulatedBody`] it leaves in `data` what ABA and
/// `forward_kinematics_acceleration` at the unconstrained `q̈₀` leave, and
/// `cdata.jc` and `cdata.jacobians` are not written.
///
/// # Errors
/// As [`constrained_forward_dynamics`]; the articulated-body method
/// reports a singular articulated inertia where the KKT method reports a
/// mass matrix that is not positive definite.
#[allow(clippy::too_many_arguments)]
pub fn constrained_forward_dynamics_with<
    'c,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NC: usize,
>(
    method: ConstraintMethod,
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    cdata: &'c mut ConstraintData<S, NV, NC>,
    q: &[S; NQ],
    v: &[S; NV],
    tau: &[S; NV],
    contacts: &[Contact<S>],
    settings: &ConstraintSettings<S>,
) -> Result<(&'c [S; NV], &'c [S])> {
    check_input(contacts, settings, NB, NC)?;
    check_finite(tau, Quantity::Torque)?;
    match method {
        ConstraintMethod::Kkt => kkt_solve(model, data, cdata, q, v, tau, contacts, settings)?,
        ConstraintMethod::ArticulatedBody => {
            let ddq0 =
                articulated::form_delassus(model, data, cdata, q, v, tau, contacts, settings)?;
            factor_delassus(cdata, contacts, settings.damping)?;
            let rows = cdata.rows;
            cholesky_solve(&cdata.delassus, rows, &mut cdata.lambda);
            articulated::accelerations(cdata, &ddq0);
        }
    }
    let rows = cdata.rows;
    check_result(&cdata.lambda[..rows], Quantity::Contact)?;
    check_result(&cdata.ddq, Quantity::Acceleration)?;
    Ok((&cdata.ddq, &cdata.lambda[..rows]))
}

/// The KKT method into `cdata.ddq` and `cdata.lambda`.
#[allow(clippy::too_many_arguments)]
fn kkt_solve<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, const NC: usize>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    cdata: &mut ConstraintData<S, NV, NC>,
    q: &[S; NQ],
    v: &[S; NV],
    tau: &[S; NV],
    contacts: &[Contact<S>],
    settings: &ConstraintSettings<S>,
) -> Result<()> {
    // Unconstrained: M x₀ = τ − h; then J_c, M⁻¹ J_cᵀ and the Delassus
    // matrix's factor.
    let h = *nonlinear_effects(model, data, q, v, None)?;
    prepare(
        model,
        data,
        cdata,
        q,
        contacts,
        settings.damping,
        Poses::FromJointTransforms,
    )?;
    let rows = cdata.rows;
    let mut x0: [S; NV] = core::array::from_fn(|k| tau[k] - h[k]);
    ltdl_solve(model, data, &mut x0)?;

    // The right-hand side: the Baumgarte term less the drift J̇_c q̇ and
    // J_c x₀. The bodies' accelerations at q̈ = 0 are RNEA's, which leaves
    // them less gravity (a − ⁱX₀ g) in `a_gf`; CRBA and the Jacobians
    // (poses) left that and the velocities alone.
    let gravity = *model.gravity();
    for i in 0..NB {
        data.a[i] = data.a_gf[i] + data.o_m_i[i].act_inv_motion(&gravity);
    }
    let mut rhs = [S::ZERO; NC];
    let mut row = 0;
    for contact in contacts {
        let n = contact.rows();
        baumgarte_less_drift(data, contact, settings, &mut rhs[row..row + n])?;
        for (r, value) in rhs[row..row + n].iter_mut().enumerate() {
            *value -= dot(&cdata.jc[row + r], &x0);
        }
        row += n;
    }
    cdata.lambda = rhs;
    cholesky_solve(&cdata.delassus, rows, &mut cdata.lambda);

    // q̈ = x₀ + M⁻¹ J_cᵀ λ.
    add_response(model, data, cdata, &x0);
    data.tau = h;
    Ok(())
}

/// `−K_p e − K_d v_c − a_drift` of one contact, in its rows' order
/// (linear before angular): `e` the contact's error against its anchor,
/// `v_c` its velocity and `a_drift` its acceleration at `q̈ = 0`, all in the
/// contact's reference frame. Reads `data` after
/// `forward_kinematics_acceleration` at `q̈ = 0`.
pub(crate) fn baumgarte_less_drift<S: Scalar, const NB: usize, const NV: usize>(
    data: &Data<S, NB, NV, Spatial>,
    contact: &Contact<S>,
    settings: &ConstraintSettings<S>,
    out: &mut [S],
) -> Result<()> {
    let frame = contact.held_frame();
    let body = frame.body;
    let (Some(o_m_b), Some(v_b), Some(a_b)) =
        (data.o_m_i.get(body), data.v.get(body), data.a.get(body))
    else {
        return Err(Error::FrameBodyOutOfRange { body });
    };
    // The frame's pose once, then its velocity and acceleration in its own
    // axes at its origin (what `frames` computes, without forming the pose
    // three times).
    let placement = o_m_b.compose(&frame.placement);
    let v = frame.placement.act_inv_motion(v_b);
    let a = frame.placement.act_inv_motion(a_b);
    let (error, velocity, drift) = match contact {
        // World axes at the point; the classical acceleration a + ω × v.
        Contact::Point { anchor, .. } => {
            let to_world = |x: Vec3<S>| placement.rot.mul_vec(&x);
            let error = Motion::new(Vec3::ZERO, placement.trans - *anchor);
            let velocity = Motion::new(Vec3::ZERO, to_world(v.lin));
            let drift = Motion::new(Vec3::ZERO, to_world(a.lin + v.ang.cross(&v.lin)));
            (error, velocity, drift)
        }
        // Pinocchio's corrector: e = −log6(ᶜX_anchor), in the frame's axes;
        // the frame's spatial (not classical) acceleration, as its rows are
        // the frame's local Jacobian.
        Contact::Frame { anchor, .. } => {
            let error = -log6(&placement.inverse().compose(anchor));
            (error, v, a)
        }
    };
    let target =
        |e: Vec3<S>, v: Vec3<S>, a: Vec3<S>| (-(e * settings.kp) - v * settings.kd - a).to_array();
    let lin = target(error.lin, velocity.lin, drift.lin);
    out[..3].copy_from_slice(&lin);
    if out.len() == 6 {
        let ang = target(error.ang, velocity.ang, drift.ang);
        out[3..].copy_from_slice(&ang);
    }
    Ok(())
}

/// The velocities just after an impact at configuration `q`: the contacts
/// meet the environment with velocity `J_c v⁻` and leave with `−e J_c v⁻`
/// (`e`, `restitution`, in `[0, 1]`; 0 for a plastic impact that stops
/// them), by the impulses `Λ` (N s and N m s, axes as [`Contact`]'s `λ`)
/// of `M (v⁺ − v⁻) = J_cᵀ Λ` (Pinocchio's `impulseDynamics`). An impact
/// with `e ≤ 1` never adds kinetic energy. Returns `(v⁺, Λ)`; `damping`
/// regularises redundant contacts as in [`constrained_forward_dynamics`].
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
    contacts: &[Contact<S>],
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
    prepare(model, data, cdata, q, contacts, damping, Poses::Compute)?;
    let rows = cdata.rows;
    for r in 0..rows {
        cdata.lambda[r] = -(S::ONE + restitution) * dot(&cdata.jc[r], v_before);
    }
    cholesky_solve(&cdata.delassus, rows, &mut cdata.lambda);
    // v⁺ = v⁻ + M⁻¹ J_cᵀ Λ.
    add_response(model, data, cdata, v_before);
    check_result(&cdata.lambda[..rows], Quantity::Contact)?;
    check_result(&cdata.ddq, Quantity::Velocity)?;
    Ok((&cdata.ddq, &cdata.lambda[..rows]))
}

/// The checks shared by both solves: capacity, gains, bodies, anchors.
pub(crate) fn check_input<S: Scalar>(
    contacts: &[Contact<S>],
    settings: &ConstraintSettings<S>,
    nb: usize,
    capacity: usize,
) -> Result<()> {
    let rows = constrained_rows(contacts);
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
        let frame = c.held_frame();
        if frame.body >= nb {
            return Err(Error::FrameBodyOutOfRange { body: frame.body });
        }
        if !(c.anchor_is_finite() && frame.placement.is_finite()) {
            return Err(Error::NonFinite {
                quantity: Quantity::Contact,
                index,
            });
        }
    }
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

/// Adds `damping` to the Delassus matrix's diagonal and factors it.
fn factor_delassus<S: Scalar, const NV: usize, const NC: usize>(
    cdata: &mut ConstraintData<S, NV, NC>,
    contacts: &[Contact<S>],
    damping: S,
) -> Result<()> {
    for r in 0..cdata.rows {
        cdata.delassus[r][r] += damping;
    }
    cholesky_in_place(&mut cdata.delassus, cdata.rows, PIVOT_TOLERANCE).map_err(|row| {
        Error::RedundantConstraints {
            row,
            contact: contact_of_row(contacts, row),
        }
    })
}

/// CRBA and its factorisation, `J_c` (each contact's rows in its reference
/// frame), `M⁻¹ J_cᵀ` and the Delassus matrix `J_c M⁻¹ J_cᵀ + μ I` itself
/// (not factored: the friction solver of
/// [`sim::time_stepping`](crate::sim::time_stepping) works on it). With
/// `added_diagonal`, `M` is replaced by `M + diag(added_diagonal)` before
/// the factorisation (time stepping's implicit joint damping).
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
    let rows = constrained_rows(contacts);
    cdata.rows = rows;
    crba(model, data, q)?;
    if let Some(added) = added_diagonal {
        for (k, d) in added.iter().enumerate() {
            data.mass_matrix[k][k] += *d;
        }
    }
    ltdl_factor(model, data)?;
    // J_c from the joint Jacobians. (Forming each contact's columns along
    // its path from the joints' subspaces instead measured slower on
    // Solo12: the joint Jacobians' own pass is cheaper per column.) After
    // RNEA the joints' transforms are known: the poses need only be
    // composed.
    match poses {
        Poses::Compute => joint_jacobians(model, data, &mut cdata.jacobians, q)?,
        Poses::FromJointTransforms => {
            joint_jacobians_from_transforms(model, data, &mut cdata.jacobians);
        }
    }
    let mut row = 0;
    for contact in contacts {
        frame_jacobian(
            model,
            data,
            &cdata.jacobians,
            contact.held_frame(),
            contact.reference(),
            &mut cdata.columns,
        )?;
        for (r, jc_row) in cdata.jc[row..row + contact.rows()].iter_mut().enumerate() {
            for (entry, column) in jc_row.iter_mut().zip(&cdata.columns) {
                *entry = if r < 3 {
                    column.lin.to_array()[r]
                } else {
                    column.ang.to_array()[r - 3]
                };
            }
        }
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
        for r in row..row + contact.rows() {
            let w = &mut cdata.responses[r];
            *w = cdata.jc[r];
            solve_transposed_on_path(model, data, body, w);
            for (wk, dk) in w.iter_mut().zip(&d_inv) {
                *wk *= *dk;
            }
        }
        row += contact.rows();
    }
    // Dense sums: over a few tens of coordinates they vectorise, which
    // gathering a row's path does not (measured slower on Solo12).
    for r in 0..rows {
        let d_w: [S; NV] = core::array::from_fn(|k| data.ltdl[k][k] * cdata.responses[r][k]);
        for s in 0..=r {
            let g = dot(&d_w, &cdata.responses[s]);
            cdata.delassus[r][s] = g;
            cdata.delassus[s][r] = g;
        }
        cdata.delassus[r][r] += damping;
    }
    Ok(())
}

/// Where [`form_delassus`] takes the bodies' poses from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Poses {
    /// Forward kinematics at `q`.
    Compute,
    /// Composed from `data.li_m_i`, valid at `q` (after RNEA there).
    FromJointTransforms,
}

/// The index of the contact that constrained row `row` belongs to.
fn contact_of_row<S: Scalar>(contacts: &[Contact<S>], row: usize) -> usize {
    let mut end = 0;
    contacts
        .iter()
        .position(|c| {
            end += c.rows();
            row < end
        })
        .unwrap_or(contacts.len())
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
    let mut z = [S::ZERO; NV];
    weighted_rows(&cdata.responses, &cdata.lambda, cdata.rows, &mut z);
    solve_lower(model, data, &mut z);
    cdata.ddq = core::array::from_fn(|k| base[k] + z[k]);
}

/// `out += Σ_r λ_r rows[r]` over the first `n` rows.
fn weighted_rows<S: Scalar, const NV: usize, const NC: usize>(
    rows: &[[S; NV]; NC],
    lambda: &[S; NC],
    n: usize,
    out: &mut [S; NV],
) {
    for (row, l) in rows[..n].iter().zip(&lambda[..n]) {
        for (a, y) in out.iter_mut().zip(row) {
            *a += *y * *l;
        }
    }
}

pub(crate) fn dot<S: Scalar, const N: usize>(a: &[S; N], b: &[S; N]) -> S {
    a.iter().zip(b).fold(S::ZERO, |acc, (x, y)| acc + *x * *y)
}
