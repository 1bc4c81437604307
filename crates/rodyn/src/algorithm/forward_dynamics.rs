//! Forward dynamics behind one interface: ABA or CRBA, chosen by a type.
//!
//! ```
//! use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
//! # use rodyn::{Data, Model, joint::{Axis, Joint}, spatial::*};
//! # const M: Model<f64, 1, 1, 1> = Model::new([None], [Joint::revolute(Axis::Z)],
//! #     [Transform::IDENTITY], [Inertia::point_mass(1.0, Vec3::new(0.5, 0.0, 0.0))],
//! #     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)));
//! let mut data = Data::new();
//! let (q, v, tau) = ([0.3], [0.0], [0.0]);
//! let by_aba = Aba::forward_dynamics(&M, &mut data, &q, &v, &tau, None)?[0];
//! let by_crba = Crba::forward_dynamics(&M, &mut data, &q, &v, &tau, None)?[0];
//! assert!((by_aba - by_crba).abs() < 1e-12);
//! # Ok::<(), rodyn::Error>(())
//! ```
//!
//! CRBA forms `M` (O(n·depth)), factors it sparsely (`Lᵀ D L`) and solves;
//! ABA is O(n). [`Crba::forward_dynamics_planned`] takes CRBA's
//! [`CrbaPlan`](crba::CrbaPlan), faster on models with quarter-turn
//! placements. Which is faster depends on the model and the scalar type:
//! the workspace README charts the crossover.

use crate::algorithm::common::{check_external, check_state};
use crate::algorithm::rnea::nonlinear_effects;
use crate::algorithm::{aba::aba, crba, ltdl};
use crate::data::Data;
use crate::error::{Quantity, Result};
use crate::model::{check_finite, check_result, Model};
use crate::space::Space;
use crate::Scalar;

/// A forward-dynamics method: `q̈ = M(q)⁻¹ (τ - h(q, v) + Jᵀ f_ext)`.
pub trait ForwardDynamics {
    /// A short name for reports ("ABA", "CRBA").
    const NAME: &'static str;

    /// Joint accelerations for torques `tau` (NV) at state `(q, v)`, with
    /// optional external forces per body (body frames). Returns `data.ddq`.
    ///
    /// # Errors
    /// Non-finite inputs, invalid configurations, and the method's own
    /// breakdown: a singular articulated inertia (ABA) or a mass matrix that
    /// is not positive definite (CRBA).
    fn forward_dynamics<
        'd,
        S: Scalar,
        const NB: usize,
        const NQ: usize,
        const NV: usize,
        G: Space,
    >(
        model: &Model<S, NB, NQ, NV, G>,
        data: &'d mut Data<S, NB, NV, G>,
        q: &[S; NQ],
        v: &[S; NV],
        tau: &[S; NV],
        f_ext: Option<&[G::Force<S>; NB]>,
    ) -> Result<&'d [S; NV]>;
}

/// Forward dynamics by the articulated-body algorithm, O(n).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Aba;

/// Forward dynamics by the composite-rigid-body algorithm and a sparse
/// `Lᵀ D L` solve.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Crba;

impl ForwardDynamics for Aba {
    const NAME: &'static str = "ABA";
    #[inline]
    fn forward_dynamics<
        'd,
        S: Scalar,
        const NB: usize,
        const NQ: usize,
        const NV: usize,
        G: Space,
    >(
        model: &Model<S, NB, NQ, NV, G>,
        data: &'d mut Data<S, NB, NV, G>,
        q: &[S; NQ],
        v: &[S; NV],
        tau: &[S; NV],
        f_ext: Option<&[G::Force<S>; NB]>,
    ) -> Result<&'d [S; NV]> {
        aba(model, data, q, v, tau, f_ext)
    }
}

// Whether [`Crba`] runs the bias forces' passes and CRBA's together
// (`crba::bias_and_mass_lower`), instead of RNEA and then CRBA: out of
// order, faster on x86-64; in order, the Cortex-M4's pendulum ran more
// instructions fused, and the Panda's and the quadruped's calls took more
// stack. A choice of the tuning profile; figures:
// docs/sections/performance_notebook.md, "CRBA forward dynamics and the
// factorisation".
use crate::tuning::FUSED_PASSES;

impl ForwardDynamics for Crba {
    const NAME: &'static str = "CRBA";
    /// Leaves valid: everything [`rnea`](crate::algorithm::rnea::rnea) and
    /// [`crba`](crba::crba) leave, except the upper triangle of
    /// `mass_matrix` (not written: only the lower one is formed), and `h`
    /// (bias forces), the diagonal and upper triangle of `ltdl`, `ddq`.
    fn forward_dynamics<
        'd,
        S: Scalar,
        const NB: usize,
        const NQ: usize,
        const NV: usize,
        G: Space,
    >(
        model: &Model<S, NB, NQ, NV, G>,
        data: &'d mut Data<S, NB, NV, G>,
        q: &[S; NQ],
        v: &[S; NV],
        tau: &[S; NV],
        f_ext: Option<&[G::Force<S>; NB]>,
    ) -> Result<&'d [S; NV]> {
        solve(model, data, tau, |data| {
            bias_and_mass(model, data, q, v, f_ext)
        })
    }
}

impl Crba {
    /// [`Crba::forward_dynamics`] with CRBA in the frames of `plan`, which
    /// must be `model`'s ([`CrbaPlan::is_for`](crba::CrbaPlan::is_for),
    /// checked in debug builds): the same accelerations, faster on models
    /// whose placements are quarter turns. Leaves valid what
    /// [`Crba::forward_dynamics`] leaves, `ic` in the plan's turned frames.
    ///
    /// # Errors
    /// As [`ForwardDynamics::forward_dynamics`].
    #[allow(clippy::too_many_arguments)]
    pub fn forward_dynamics_planned<
        'd,
        S: Scalar,
        const NB: usize,
        const NQ: usize,
        const NV: usize,
        G: Space,
    >(
        model: &Model<S, NB, NQ, NV, G>,
        plan: &crba::CrbaPlan<S, NB, G>,
        data: &'d mut Data<S, NB, NV, G>,
        q: &[S; NQ],
        v: &[S; NV],
        tau: &[S; NV],
        f_ext: Option<&[G::Force<S>; NB]>,
    ) -> Result<&'d [S; NV]> {
        debug_assert!(plan.is_for(model), "a CRBA plan made for another model");
        solve(model, data, tau, |data| {
            bias_and_mass_planned(model, plan, data, q, v, f_ext)
        })
    }
}

/// `q̈ = M⁻¹ (τ - h)`, with `h` and `M`'s lower triangle from
/// `bias_and_mass`: CRBA forward dynamics after its first passes.
#[inline(always)]
fn solve<'d, S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &'d mut Data<S, NB, NV, G>,
    tau: &[S; NV],
    bias_and_mass: impl FnOnce(&mut Data<S, NB, NV, G>) -> Result<[S; NV]>,
) -> Result<&'d [S; NV]> {
    check_finite(tau, Quantity::Torque)?;
    data.h = bias_and_mass(data)?;
    ltdl::ltdl_factor(model, data)?;
    let mut rhs = [S::ZERO; NV];
    for (k, r) in rhs.iter_mut().enumerate() {
        *r = tau[k] - data.h[k];
    }
    ltdl::ltdl_solve(model, data, &mut rhs)?;
    data.ddq = rhs;
    Ok(&data.ddq)
}

/// The bias forces `h` (N m, N; also left in `data.tau`) and the lower
/// triangle of `M` (diagonal included; what the factorisation reads) at
/// `(q, v)`, by one fused pass where that pays ([`FUSED_PASSES`]) or RNEA
/// and then CRBA on its joint transforms. Leaves valid what
/// [`nonlinear_effects`] and [`crba::crba_lower`] leave (`li_m_i`, `v`,
/// `a_gf`, the lower triangle of `mass_matrix`).
///
/// # Errors
/// As [`nonlinear_effects`].
pub(crate) fn bias_and_mass<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    f_ext: Option<&[G::Force<S>; NB]>,
) -> Result<[S; NV]> {
    bias_and_mass_by(
        model,
        data,
        q,
        v,
        f_ext,
        |data| crba::bias_and_mass_lower(model, data, q, v, f_ext),
        |data| crba::crba_lower(model, data, None),
    )
}

/// [`bias_and_mass`] with CRBA in the frames of `plan`.
///
/// # Errors
/// As [`nonlinear_effects`].
pub(crate) fn bias_and_mass_planned<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    plan: &crba::CrbaPlan<S, NB, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    f_ext: Option<&[G::Force<S>; NB]>,
) -> Result<[S; NV]> {
    bias_and_mass_by(
        model,
        data,
        q,
        v,
        f_ext,
        |data| crba::bias_and_mass_lower_planned(model, plan, data, q, v, f_ext),
        |data| crba::crba_lower_planned(model, plan, data, None),
    )
}

/// [`bias_and_mass`]'s checks and order of passes, CRBA's own passes given:
/// `fused` forms `h` in `data.tau` and `M`'s lower triangle in one sweep,
/// `lower` the triangle from the joint transforms RNEA left.
#[inline(always)]
fn bias_and_mass_by<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    f_ext: Option<&[G::Force<S>; NB]>,
    fused: impl FnOnce(&mut Data<S, NB, NV, G>),
    lower: impl FnOnce(&mut Data<S, NB, NV, G>),
) -> Result<[S; NV]> {
    if FUSED_PASSES {
        check_state(model, q, Some(v))?;
        check_external(f_ext.map(|f| &f[..]))?;
        fused(data);
        check_result(&data.tau, Quantity::Torque)?;
        Ok(data.tau)
    } else {
        let h = *nonlinear_effects(model, data, q, v, f_ext)?;
        // RNEA left the joint transforms at q in `li_m_i`.
        lower(data);
        Ok(h)
    }
}

/// The method as a run-time value, for callers that switch while running.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Method {
    /// [`Aba`].
    #[default]
    Aba,
    /// [`Crba`].
    Crba,
}

impl Method {
    /// Dispatches to [`Aba`] or [`Crba`].
    ///
    /// # Errors
    /// As [`ForwardDynamics::forward_dynamics`].
    pub fn forward_dynamics<
        'd,
        S: Scalar,
        const NB: usize,
        const NQ: usize,
        const NV: usize,
        G: Space,
    >(
        self,
        model: &Model<S, NB, NQ, NV, G>,
        data: &'d mut Data<S, NB, NV, G>,
        q: &[S; NQ],
        v: &[S; NV],
        tau: &[S; NV],
        f_ext: Option<&[G::Force<S>; NB]>,
    ) -> Result<&'d [S; NV]> {
        match self {
            Self::Aba => Aba::forward_dynamics(model, data, q, v, tau, f_ext),
            Self::Crba => Crba::forward_dynamics(model, data, q, v, tau, f_ext),
        }
    }
    /// The method's short name.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Aba => Aba::NAME,
            Self::Crba => Crba::NAME,
        }
    }
}
