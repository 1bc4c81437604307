//! Inverse dynamics with contacts, for control: the joint torques `τ` and
//! contact forces `λ` that give a floating-base robot a wanted
//! acceleration while its contacts hold,
//!
//! ```text
//! M q̈ + h = Sᵀ τ + J_cᵀ λ,    J_c q̈ + J̇_c q̇ = −K_p e − K_d J_c q̇,
//! ```
//!
//! where `S` selects the actuated coordinates: the first `nu` velocity
//! coordinates (a free-flying base's six) have no actuator, so the contacts
//! alone must supply their share.
//!
//! Method (after the floating-base inverse dynamics of Mistry, Buchli &
//! Schaal 2010, with the projections done in the mass matrix's metric):
//!
//! 1. **Consistent acceleration**: the wanted `q̈*` is moved, by the least
//!    kinetic-metric change, onto the accelerations the contacts allow:
//!    `q̈ = q̈* + M⁻¹ J_cᵀ G⁻¹ (a_c* − J_c q̈* − J̇_c q̇)` with `G = J_c M⁻¹
//!    J_cᵀ` and `a_c*` the Baumgarte term (zero gains: the contacts keep
//!    their acceleration). A stance foot's wanted acceleration is thus
//!    overridden, a swing foot (not in `contacts`) keeps its own.
//! 2. **Total forces**: `τ_full = M q̈ + h` by RNEA.
//! 3. **Force distribution**: the unactuated rows `τ_full,u = (J_cᵀ λ)_u`
//!    are solved for `λ` in the damped least-squares sense, `(Aᵀ A + ε I) λ
//!    = Aᵀ τ_full,u` with `A` the unactuated rows of `J_cᵀ`: with more
//!    contact rows than unactuated
//!    coordinates (a robot on three or four feet), `ε → 0` gives the `λ` of
//!    least norm; with fewer (one point foot under a free base), the best
//!    fit, and what the contacts cannot supply is reported as the residual.
//! 4. **Torques**: `τ = τ_full − J_cᵀ λ` on the actuated rows.
//!
//! The least-norm distribution knows nothing of friction: each point
//! contact's force is then checked against its cone (`λ_z ≥ 0`, `‖λ_xy‖ ≤
//! μ λ_z`, ground normal `z`), and the ones outside are reported, not
//! clipped. A wanted motion the contacts cannot produce (pulling on the
//! ground, a moment two feet cannot make) shows up in the residual and the
//! cone report, not as an error.

use super::constrained_dynamics::{
    add_response, baumgarte_less_drift, check_input, dot, prepare, ConstraintData,
    ConstraintSettings, Contact, Poses,
};
use super::dense::{cholesky_in_place, cholesky_solve_unchecked};
use super::kinematics::forward_kinematics_acceleration;
use super::rnea::rnea;
use crate::data::Data;
use crate::error::{Error, Quantity, Result, Setting};
use crate::model::{check_finite, check_result, Model};
use crate::spatial::Spatial;
use crate::Scalar;

/// The most unactuated coordinates: a free-flying base's.
const UNACTUATED_MAX: usize = 6;

/// The settings of [`contact_inverse_dynamics`].
///
/// `#[non_exhaustive]`: a later setting is not a breaking change. Build it
/// with [`ContactInverseDynamicsSettings::floating_base`] or
/// [`ContactInverseDynamicsSettings::fixed_base`] and the `with_…` methods.
///
/// ```
/// use rodyn::algorithm::contact_inverse_dynamics::ContactInverseDynamicsSettings;
///
/// let settings = ContactInverseDynamicsSettings::floating_base(0.7).with_regularisation(1e-10);
/// assert_eq!((settings.unactuated, settings.friction, settings.regularisation), (6, 0.7, 1e-10));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct ContactInverseDynamicsSettings<S> {
    /// `nu`: the leading velocity coordinates without actuators (6 for a
    /// free-flying base, 0 for a fixed one).
    pub unactuated: usize,
    /// `ε` (> 0): the damping of the force distribution, relative to the
    /// largest diagonal entry of `A Aᵀ`. It keeps an impossible motion's
    /// forces finite and barely changes a possible one's.
    pub regularisation: S,
    /// `μ`: Coulomb's coefficient for the cone check of point contacts.
    pub friction: S,
}

impl<S: Scalar> ContactInverseDynamicsSettings<S> {
    /// A free-flying base (`nu = 6`), `ε` a thousand rounding errors of
    /// `S` (2e-13 in f64, 1e-4 in f32), friction `μ`.
    #[must_use]
    pub fn floating_base(friction: S) -> Self {
        Self {
            unactuated: 6,
            regularisation: S::from_f64(1e3 * S::EPSILON),
            friction,
        }
    }

    /// A fixed base (`nu = 0`: every coordinate actuated), otherwise as
    /// [`ContactInverseDynamicsSettings::floating_base`].
    ///
    /// ```
    /// use rodyn::algorithm::contact_inverse_dynamics::ContactInverseDynamicsSettings;
    ///
    /// let settings = ContactInverseDynamicsSettings::<f64>::fixed_base(0.5);
    /// assert_eq!(settings.unactuated, 0);
    /// ```
    #[must_use]
    pub fn fixed_base(friction: S) -> Self {
        Self::floating_base(friction).with_unactuated(0)
    }

    /// These settings with the first `unactuated` velocity coordinates
    /// without actuators.
    ///
    /// ```
    /// use rodyn::algorithm::contact_inverse_dynamics::ContactInverseDynamicsSettings;
    ///
    /// // A planar base: three unactuated coordinates.
    /// let settings = ContactInverseDynamicsSettings::<f64>::floating_base(0.5).with_unactuated(3);
    /// assert_eq!(settings.unactuated, 3);
    /// ```
    #[must_use]
    pub const fn with_unactuated(mut self, unactuated: usize) -> Self {
        self.unactuated = unactuated;
        self
    }

    /// These settings with the relative damping `ε` (> 0) of the force
    /// distribution.
    ///
    /// ```
    /// use rodyn::algorithm::contact_inverse_dynamics::ContactInverseDynamicsSettings;
    ///
    /// let settings = ContactInverseDynamicsSettings::floating_base(0.5).with_regularisation(1e-9);
    /// assert_eq!(settings.regularisation, 1e-9);
    /// ```
    #[must_use]
    pub const fn with_regularisation(mut self, regularisation: S) -> Self {
        self.regularisation = regularisation;
        self
    }

    /// These settings with Coulomb's coefficient `μ` for the cone check.
    ///
    /// ```
    /// use rodyn::algorithm::contact_inverse_dynamics::ContactInverseDynamicsSettings;
    ///
    /// let settings = ContactInverseDynamicsSettings::floating_base(0.5).with_friction(0.9);
    /// assert_eq!(settings.friction, 0.9);
    /// ```
    #[must_use]
    pub const fn with_friction(mut self, friction: S) -> Self {
        self.friction = friction;
        self
    }
}

/// The workspace and results of [`contact_inverse_dynamics`].
#[derive(Clone, Debug)]
pub struct ContactInverseDynamicsData<S: Scalar, const NV: usize, const NC: usize> {
    /// The constraint workspace: `J_c`, `M⁻¹ J_cᵀ`, and `λ` (in
    /// `constraint.lambda`, the contacts' order and units of
    /// [`Contact`]).
    pub constraint: ConstraintData<S, NV, NC>,
    /// The joint forces `τ` (N m, N); zero on the unactuated coordinates.
    pub tau: [S; NV],
    /// The consistent acceleration `q̈` that `τ` and `λ` produce.
    pub ddq: [S; NV],
    /// The unactuated rows' residual `τ_full,u − (J_cᵀ λ)_u` (N, N m): what
    /// the contacts could not supply. Zero (to rounding and `ε`) when the
    /// wanted motion is possible.
    pub residual: [S; NV],
    /// Entry `c` true: point contact `c` needs a force outside its friction
    /// cone, or pulls on the ground (the first `contacts.len()` entries).
    pub outside_cone: [bool; NC],
}

impl<S: Scalar, const NV: usize, const NC: usize> ContactInverseDynamicsData<S, NV, NC> {
    /// A zeroed workspace (usable in `const`).
    #[must_use]
    pub const fn new() -> Self {
        Self {
            constraint: ConstraintData::new(),
            tau: [S::ZERO; NV],
            ddq: [S::ZERO; NV],
            residual: [S::ZERO; NV],
            outside_cone: [false; NC],
        }
    }

    /// The largest entry of the residual (N or N m).
    #[must_use]
    pub fn residual_norm(&self) -> S {
        self.residual.iter().fold(S::ZERO, |m, r| m.max(r.abs()))
    }
}

impl<S: Scalar, const NV: usize, const NC: usize> Default
    for ContactInverseDynamicsData<S, NV, NC>
{
    fn default() -> Self {
        Self::new()
    }
}

/// The joint torques and contact forces that give `model` at `(q, v)` the
/// acceleration `ddq_wanted` as nearly as `contacts` allow (see the
/// [module](self)). Results in `iddata`: `tau`, `ddq`, `constraint.lambda`
/// (the first [`constrained_rows`](super::constrained_dynamics::constrained_rows)
/// entries), `residual`, `outside_cone`.
///
/// Leaves valid in `data`: what [`rnea`] leaves at `(q, v, q̈)`.
///
/// # Errors
/// As [`constrained_forward_dynamics`](super::constrained_dynamics::constrained_forward_dynamics)
/// for the contacts and `constraint` (use a damping for redundant
/// contacts); [`Error::InvalidSetting`] naming `unactuated` (above 6 or
/// `NV`), `regularisation` (not positive or not finite) or `friction`
/// (negative or not finite); [`Error::NonFinite`] for a non-finite wanted
/// acceleration.
#[allow(clippy::too_many_arguments)]
pub fn contact_inverse_dynamics<
    'd,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NC: usize,
>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    iddata: &'d mut ContactInverseDynamicsData<S, NV, NC>,
    q: &[S; NQ],
    v: &[S; NV],
    ddq_wanted: &[S; NV],
    contacts: &[Contact<S>],
    constraint: &ConstraintSettings<S>,
    settings: &ContactInverseDynamicsSettings<S>,
) -> Result<&'d [S; NV]> {
    check_input(contacts, constraint, NB, NC)?;
    let nu = settings.unactuated;
    if nu > NV.min(UNACTUATED_MAX) {
        return Err(Error::InvalidSetting {
            setting: Setting::Unactuated,
        });
    }
    let eps = settings.regularisation;
    if !(eps.is_finite() && eps.to_f64() > 0.0) {
        return Err(Error::InvalidSetting {
            setting: Setting::Regularisation,
        });
    }
    if !(settings.friction.is_finite() && settings.friction.to_f64() >= 0.0) {
        return Err(Error::InvalidSetting {
            setting: Setting::Friction,
        });
    }
    check_finite(ddq_wanted, Quantity::Acceleration)?;

    // 1. q̈ = q̈* + M⁻¹ J_cᵀ G⁻¹ (a_c* − J̇_c q̇ − J_c q̈*). The kinematics at
    // q̈ = 0 first (the drift): the Jacobians then read their columns off
    // its poses, and CRBA runs on its joint transforms.
    forward_kinematics_acceleration(model, data, q, v, &[S::ZERO; NV])?;
    prepare(
        model,
        data,
        &mut iddata.constraint,
        q,
        contacts,
        constraint.damping,
        Poses::FromKinematics,
    )?;
    let cdata = &mut iddata.constraint;
    let rows = cdata.rows.min(NC);
    let mut row = 0;
    for contact in contacts {
        let n = contact.rows();
        // Within `NC` (`check_input`); `get` says so without a panic path.
        let Some(lambda) = cdata.lambda.get_mut(row..row + n) else {
            break;
        };
        baumgarte_less_drift(data, contact, constraint, lambda)?;
        row += n;
    }
    for r in 0..rows {
        cdata.lambda[r] -= dot(&cdata.jc[r], ddq_wanted);
    }
    cholesky_solve_unchecked(&cdata.delassus, rows, &mut cdata.lambda);
    add_response(model, data, cdata, ddq_wanted);
    iddata.ddq = cdata.ddq;

    // 2. τ_full = M q̈ + h.
    let full = *rnea(model, data, q, v, &iddata.ddq, None)?;

    // 3. λ = Aᵀ (A Aᵀ + ε I)⁻¹ τ_full,u with A = (J_cᵀ)_u, nu × rows.
    let mut aat = [[S::ZERO; UNACTUATED_MAX]; UNACTUATED_MAX];
    for i in 0..nu {
        for j in 0..=i {
            let a = (0..rows).fold(S::ZERO, |acc, r| acc + cdata.jc[r][i] * cdata.jc[r][j]);
            aat[i][j] = a;
            aat[j][i] = a;
        }
    }
    let scale = (0..nu).fold(S::ZERO, |m, i| m.max(aat[i][i]));
    for (i, row) in aat.iter_mut().enumerate().take(nu) {
        row[i] += eps * scale.max(S::ONE);
    }
    let mut y = [S::ZERO; UNACTUATED_MAX];
    y[..nu].copy_from_slice(&full[..nu]);
    // ε > 0 makes it positive definite; a failure means overflow.
    cholesky_in_place(&mut aat, nu, 0.0).map_err(|row| Error::NonFinite {
        quantity: Quantity::Contact,
        index: row,
    })?;
    cholesky_solve_unchecked(&aat, nu, &mut y);
    for r in 0..rows {
        cdata.lambda[r] = (0..nu).fold(S::ZERO, |acc, i| acc + cdata.jc[r][i] * y[i]);
    }

    // 4. τ = τ_full − J_cᵀ λ; the unactuated rows are the residual.
    for k in 0..NV {
        let supplied = (0..rows).fold(S::ZERO, |acc, r| acc + cdata.jc[r][k] * cdata.lambda[r]);
        let rest = full[k] - supplied;
        if k < nu {
            iddata.residual[k] = rest;
            iddata.tau[k] = S::ZERO;
        } else {
            iddata.residual[k] = S::ZERO;
            iddata.tau[k] = rest;
        }
    }
    check_result(&cdata.lambda[..rows], Quantity::Contact)?;
    check_result(&iddata.tau, Quantity::Torque)?;

    iddata.outside_cone = [false; NC];
    let mut row = 0;
    for (c, contact) in contacts.iter().enumerate() {
        if let Contact::Point { .. } = contact {
            // Within `NC` (`check_input`); `get` says so without a panic path.
            let Some(&[lx, ly, lz]) = cdata.lambda.get(row..).and_then(|l| l.first_chunk()) else {
                break;
            };
            let tangential = (lx * lx + ly * ly).sqrt();
            if lz < S::ZERO || tangential > settings.friction * lz {
                if let Some(outside) = iddata.outside_cone.get_mut(c) {
                    *outside = true;
                }
            }
        }
        row += contact.rows();
    }
    Ok(&iddata.tau)
}
