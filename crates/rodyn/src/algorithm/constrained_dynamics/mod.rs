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
//! - [`ConstraintMethod::Kkt`], the default (`kkt.rs`): the KKT system by
//!   its Schur complement (Featherstone, *Rigid Body Dynamics Algorithms*,
//!   ch. 8; Pinocchio's `constraintDynamics` solves the same system): CRBA
//!   and the branch-aware `M = Lᵀ D L`, the Delassus matrix `G = J_c M⁻¹
//!   J_cᵀ`, `(G + μ I) λ = −(J_c M⁻¹ (τ − h) + J̇_c q̇ + K_p e + K_d J_c q̇)`
//!   by a small Cholesky factorisation, and `q̈ = M⁻¹ (τ − h + J_cᵀ λ)`.
//! - [`ConstraintMethod::ArticulatedBody`] (`articulated.rs`): ABA, then `G`
//!   from unit test forces propagated through ABA's articulated inertias,
//!   never forming `M`.
//!
//! Redundant contacts (a rank-deficient `J_c`, such as four coplanar feet
//! of a robot whose legs cannot hold them apart) make `G` singular: with
//! `μ = 0` that is [`Error::RedundantConstraints`] naming the row and the
//! contact; a damping `μ > 0` regularises it (Tikhonov: the `λ` of least
//! norm among the near-solutions, the constraint then met to `O(μ)`).
//!
//! Cost of the KKT method: the bias forces and CRBA in one pass (as CRBA
//! forward dynamics runs them), the factorisation, the joint Jacobians of
//! the contacts' paths (`frame_chain`), a half sweep of `Lᵀ D L` along its contact's path per
//! constrained row, one sweep for the response, and a dense `m × m` solve
//! for `m` rows; of the articulated-body method: one ABA, one kinematics
//! pass, two sweeps per row and the same dense solve. `contact.rs` holds
//! what a contact is and the right-hand side of its rows.

mod articulated;
mod contact;
mod kkt;

pub(crate) use contact::baumgarte_less_drift;
pub use contact::{constrained_rows, Contact};
pub(crate) use kkt::{add_response, form_delassus, prepare, Poses};

use super::dense::{cholesky_in_place, cholesky_solve_unchecked};
use super::jacobian::JacobianData;
use crate::data::Data;
use crate::error::{Error, Quantity, Result, Setting};
use crate::model::{check_finite, check_result, Model};
use crate::spatial::Spatial;
use crate::Scalar;

/// Relative size (of the pivot's own diagonal entry of the Delassus
/// matrix, in units of ε) below which a pivot counts as zero: the contacts
/// are redundant. Each row against its own entry, since a frame contact's
/// force rows (1/kg) and moment rows (1/(kg m²)) have different units (see
/// [`cholesky_in_place`]).
const PIVOT_TOLERANCE: f64 = 1e3;

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
///
/// `#[non_exhaustive]`: a later setting is not a breaking change. Build it
/// with [`ConstraintSettings::new`] (the exact solve),
/// [`ConstraintSettings::baumgarte`] and the `with_…` methods.
///
/// ```
/// use rodyn::algorithm::constrained_dynamics::ConstraintSettings;
///
/// let settings = ConstraintSettings::baumgarte(25.0, 7.0).with_damping(1e-8);
/// assert_eq!((settings.kp, settings.kd, settings.damping), (25.0, 7.0, 1e-8));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct ConstraintSettings<S> {
    /// `K_p`, 1/s²: position feedback of the Baumgarte term.
    pub kp: S,
    /// `K_d`, 1/s: velocity feedback.
    pub kd: S,
    /// `μ` (m/N/s², the Delassus matrix's unit): damping of the contact
    /// solve, for redundant contacts.
    pub damping: S,
}

impl<S: Scalar> ConstraintSettings<S> {
    /// No stabilisation, no damping: the exact KKT solution (the same as
    /// `default()`, usable in a `const`).
    ///
    /// ```
    /// use rodyn::algorithm::constrained_dynamics::ConstraintSettings;
    ///
    /// const EXACT: ConstraintSettings<f32> = ConstraintSettings::new();
    /// assert_eq!((EXACT.kp, EXACT.kd, EXACT.damping), (0.0, 0.0, 0.0));
    /// ```
    #[must_use]
    pub const fn new() -> Self {
        Self {
            kp: S::ZERO,
            kd: S::ZERO,
            damping: S::ZERO,
        }
    }

    /// Baumgarte stabilisation with position gain `kp` (1/s²) and velocity
    /// gain `kd` (1/s), no damping. `kd = 2 √kp` damps the drift critically.
    ///
    /// ```
    /// use rodyn::algorithm::constrained_dynamics::ConstraintSettings;
    ///
    /// let settings = ConstraintSettings::baumgarte(25.0, 10.0);
    /// assert_eq!((settings.kp, settings.kd, settings.damping), (25.0, 10.0, 0.0));
    /// ```
    #[must_use]
    pub const fn baumgarte(kp: S, kd: S) -> Self {
        Self::new().with_kp(kp).with_kd(kd)
    }

    /// These settings with position gain `kp` (1/s²).
    ///
    /// ```
    /// use rodyn::algorithm::constrained_dynamics::ConstraintSettings;
    ///
    /// assert_eq!(ConstraintSettings::new().with_kp(4.0).kp, 4.0);
    /// ```
    #[must_use]
    pub const fn with_kp(mut self, kp: S) -> Self {
        self.kp = kp;
        self
    }

    /// These settings with velocity gain `kd` (1/s).
    ///
    /// ```
    /// use rodyn::algorithm::constrained_dynamics::ConstraintSettings;
    ///
    /// assert_eq!(ConstraintSettings::new().with_kd(4.0).kd, 4.0);
    /// ```
    #[must_use]
    pub const fn with_kd(mut self, kd: S) -> Self {
        self.kd = kd;
        self
    }

    /// These settings with damping `μ` of the contact solve (m/N/s²), for
    /// redundant contacts.
    ///
    /// ```
    /// use rodyn::algorithm::constrained_dynamics::ConstraintSettings;
    ///
    /// assert_eq!(ConstraintSettings::new().with_damping(1e-6).damping, 1e-6);
    /// ```
    #[must_use]
    pub const fn with_damping(mut self, damping: S) -> Self {
        self.damping = damping;
        self
    }
}

impl<S: Scalar> Default for ConstraintSettings<S> {
    /// No stabilisation, no damping: the exact KKT solution.
    fn default() -> Self {
        Self::new()
    }
}

/// The workspace of [`constrained_forward_dynamics`] for up to `NC`
/// constrained rows (three per point contact, six per frame contact). Its own type, so that a
/// firmware without contacts pays nothing for them.
#[derive(Clone, Debug)]
pub struct ConstraintData<S: Scalar, const NV: usize, const NC: usize> {
    /// The joint Jacobians' world columns of the last call: only those of
    /// the contacts' support paths (the others are stale).
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
/// Leaves valid in `data`: the lower triangle of `mass_matrix` (diagonal
/// included) and what [`ltdl_factor`](crate::algorithm::ltdl::ltdl_factor)
/// leaves, `li_m_i`, `o_m_i` and `v` at `(q, v)`, and `a` at `(q, v, 0)` for
/// the contacts' bodies; `tau` holds the bias forces `h`. In `cdata`:
/// every field (`jacobians`: the columns of the contacts' paths).
///
/// # Errors
/// [`Error::TooManyConstraints`] for more than `NC` rows,
/// [`Error::InvalidSetting`] for a negative or non-finite gain or damping
/// (naming `kp`, `kd` or `damping`), [`Error::FrameBodyOutOfRange`] for a
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
        ConstraintMethod::Kkt => kkt::kkt_solve(model, data, cdata, q, v, tau, contacts, settings)?,
        ConstraintMethod::ArticulatedBody => {
            let ddq0 =
                articulated::form_delassus(model, data, cdata, q, v, tau, contacts, settings)?;
            factor_delassus(cdata, contacts, settings.damping)?;
            let rows = cdata.rows.min(NC);
            cholesky_solve_unchecked(&cdata.delassus, rows, &mut cdata.lambda);
            articulated::accelerations(cdata, &ddq0);
        }
    }
    let rows = cdata.rows.min(NC);
    check_result(&cdata.lambda[..rows], Quantity::Contact)?;
    check_result(&cdata.ddq, Quantity::Acceleration)?;
    Ok((&cdata.ddq, &cdata.lambda[..rows]))
}

/// The velocities just after an impact at configuration `q`: the contacts
/// meet the environment with velocity `J_c v⁻` and leave with `−e J_c v⁻`
/// (`e`, `restitution`, in `[0, 1]`; 0 for a plastic impact that stops
/// them), by the impulses `Λ` (N s and N m s, axes as [`Contact`]'s `λ`)
/// of `M (v⁺ − v⁻) = J_cᵀ Λ` (Pinocchio's `impulseDynamics`). An impact
/// with `e ≤ 1` never adds kinetic energy. Returns `(v⁺, Λ)`; `damping`
/// regularises redundant contacts as in [`constrained_forward_dynamics`].
///
/// Leaves valid in `data`: what [`crba`](crate::algorithm::crba::crba)
/// and [`ltdl_factor`](crate::algorithm::ltdl::ltdl_factor) leave, and the
/// poses `o_m_i` of the bodies on the contacts' support paths (only those
/// bodies' transforms are formed for the contacts' Jacobians). In `cdata`:
/// every field (`ddq` holds `v⁺`, `lambda` holds `Λ`, `jacobians` the
/// columns of the contacts' paths).
///
/// # Errors
/// As [`constrained_forward_dynamics`]; [`Error::InvalidSetting`] for a
/// restitution outside `[0, 1]` or a negative or non-finite damping.
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
        return Err(Error::InvalidSetting {
            setting: Setting::Restitution,
        });
    }
    let settings = ConstraintSettings::new().with_damping(damping);
    check_input(contacts, &settings, NB, NC)?;
    check_finite(v_before, Quantity::Velocity)?;
    prepare(model, data, cdata, q, contacts, damping, Poses::Compute)?;
    let rows = cdata.rows.min(NC);
    for r in 0..rows {
        cdata.lambda[r] = -(S::ONE + restitution) * dot(&cdata.jc[r], v_before);
    }
    cholesky_solve_unchecked(&cdata.delassus, rows, &mut cdata.lambda);
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
    let gains = [
        (settings.kp, Setting::PositionGain),
        (settings.kd, Setting::VelocityGain),
        (settings.damping, Setting::ContactDamping),
    ];
    if let Some(&(_, setting)) = gains
        .iter()
        .find(|(g, _)| !(g.is_finite() && g.to_f64() >= 0.0))
    {
        return Err(Error::InvalidSetting { setting });
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

/// Adds `damping` to the Delassus matrix's diagonal and factors it.
pub(crate) fn factor_delassus<S: Scalar, const NV: usize, const NC: usize>(
    cdata: &mut ConstraintData<S, NV, NC>,
    contacts: &[Contact<S>],
    damping: S,
) -> Result<()> {
    for r in 0..cdata.rows.min(NC) {
        cdata.delassus[r][r] += damping;
    }
    cholesky_in_place(&mut cdata.delassus, cdata.rows, PIVOT_TOLERANCE).map_err(|row| {
        Error::RedundantConstraints {
            row,
            contact: contact_of_row(contacts, row),
        }
    })
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

/// `out += Σ_r λ_r rows[r]` over the first `n` rows.
pub(crate) fn weighted_rows<S: Scalar, const NV: usize, const NC: usize>(
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
