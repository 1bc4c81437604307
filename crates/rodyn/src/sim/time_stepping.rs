//! Rigid contact with Coulomb friction by time stepping: points of the
//! robot against the ground plane `z = 0`, each one free, sticking or
//! sliding as the friction cone decides, at a constant cost per step.
//!
//! One step of length `h` from `(q, v)` under joint forces `τ` is the
//! velocity-level scheme of Moreau and Jean (Moreau 1988; Anitescu &
//! Potra 1997 for the cone; MuJoCo and Pinocchio 3 solve the same
//! problem with other solvers):
//!
//! ```text
//! M̃ = M + h D
//! v_free = v + h M̃⁻¹ (τ − b(q, v) − D v)
//! v⁺     = v_free + M̃⁻¹ J_cᵀ Λ
//! q⁺     = q ⊕ h v⁺
//! ```
//!
//! where `b` is the bias force (Coriolis, centrifugal, gravity), `Λ`
//! stacks the contact impulses (N s, world axes, the normal `z` last) and
//! `D` is a diagonal joint damping (N m s/rad, N s/m) taken implicitly, at
//! `v⁺`: the `−D q̇` of a PD controller or of viscous joints, which on
//! light limbs would need far shorter steps explicitly (MuJoCo treats
//! joint damping the same way). Pass zeros for none. For each contact `c` with gap `φ_c` (the point's height, m) and
//! velocity after the step `u_c = J_c v⁺ + (φ_c / h) e_z` (a gap closes
//! at most by itself in one step):
//!
//! - `Λ_c,z ≥ 0`, `u_c,z ≥ 0`, `Λ_c,z u_c,z = 0`: the ground only pushes,
//!   and only on a point that would otherwise go below it;
//! - `‖Λ_c,xy‖ ≤ μ Λ_c,z`, and a sliding point's tangential impulse
//!   opposes its slip: Coulomb's cone with maximal dissipation.
//!
//! A point already below the ground (`φ < 0`, a drift of the integration)
//! is pushed back by the fraction `β` of its depth per step instead of all
//! of it, so that recovering from a drift does not throw the robot.
//!
//! **Solver**: projected Gauss–Seidel on the Delassus matrix `G = J_c M⁻¹
//! J_cᵀ` with a fixed number of sweeps and a warm start from the last
//! step's impulses: per contact, the normal impulse is projected on
//! `Λ_z ≥ 0`, then the tangential impulse on the disc of radius `μ Λ_z`
//! (after the same slip direction: see `projected_gauss_seidel`). The
//! cost per step is one RNEA, one CRBA and factorisation, the Jacobians of the contacts' paths, the KKT method's
//! half sweeps for the Delassus matrix, one `Lᵀ D L` solve, and `sweeps ×
//! rows²` for the solver: constant for a given number of candidate points,
//! as an MCU needs. Points farther than `margin` above the ground are left out
//! (a foot in swing costs nothing).
//!
//! **What it conserves**: nothing is gained from the contacts: with the
//! exact solution of the cone problem the contact impulses only remove
//! kinetic energy (plastic impacts, friction); the gap term and `β` add
//! what is needed to stay out of the ground. The sweeps end before full
//! convergence; the step reports the last sweep's largest change of an
//! impulse so that a user can see how far from converged it stopped.

use crate::algorithm::common::pose_pass;
use crate::algorithm::constrained_dynamics::{
    add_response, dot, form_delassus, ConstraintData, Contact, Poses,
};
use crate::algorithm::forward_dynamics::bias_and_mass;
use crate::algorithm::frames::frame_placement;
use crate::algorithm::ltdl::ltdl_solve;
use crate::data::Data;
use crate::error::{Error, Quantity, Result, Setting};
use crate::frame::Frame;
use crate::model::{check_finite, check_result, Model};
use crate::sim::integrator::check_time;
use crate::sim::State;
use crate::spatial::{Spatial, Transform, Vec3};
use crate::Scalar;

/// The settings of [`time_step`].
///
/// `#[non_exhaustive]`: a later setting is not a breaking change. Build it
/// with [`TimeSteppingSettings::with_friction`] and the `with_…` methods.
///
/// ```
/// use rodyn::sim::time_stepping::TimeSteppingSettings;
///
/// let settings = TimeSteppingSettings::with_friction(0.8).with_sweeps(50).with_margin(0.01);
/// assert_eq!((settings.friction, settings.sweeps, settings.margin), (0.8, 50, 0.01));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct TimeSteppingSettings<S> {
    /// Coulomb's friction coefficient `μ` (dimensionless, ≥ 0).
    pub friction: S,
    /// Projected Gauss–Seidel sweeps per step (at least 1).
    pub sweeps: usize,
    /// `β`, in `[0, 1]`: the fraction of a penetration removed per step.
    pub depth_recovery: S,
    /// Points higher than this above the ground (m, ≥ 0) are left out of
    /// the step's contacts. Must exceed the distance a falling point
    /// covers in one step, or it would pass through the ground unseen.
    pub margin: S,
}

impl<S: Scalar> TimeSteppingSettings<S> {
    /// Friction `μ`, 30 sweeps, `β = 0.2`, a 5 mm margin.
    #[must_use]
    pub fn with_friction(friction: S) -> Self {
        Self {
            friction,
            sweeps: 30,
            depth_recovery: S::from_f64(0.2),
            margin: S::from_f64(0.005),
        }
    }

    /// These settings with `sweeps` projected Gauss–Seidel sweeps per step
    /// (at least 1).
    ///
    /// ```
    /// use rodyn::sim::time_stepping::TimeSteppingSettings;
    ///
    /// assert_eq!(TimeSteppingSettings::with_friction(0.5).with_sweeps(10).sweeps, 10);
    /// ```
    #[must_use]
    pub const fn with_sweeps(mut self, sweeps: usize) -> Self {
        self.sweeps = sweeps;
        self
    }

    /// These settings removing the fraction `β` (in `[0, 1]`) of a
    /// penetration per step.
    ///
    /// ```
    /// use rodyn::sim::time_stepping::TimeSteppingSettings;
    ///
    /// let settings = TimeSteppingSettings::with_friction(0.5).with_depth_recovery(0.1);
    /// assert_eq!(settings.depth_recovery, 0.1);
    /// ```
    #[must_use]
    pub const fn with_depth_recovery(mut self, depth_recovery: S) -> Self {
        self.depth_recovery = depth_recovery;
        self
    }

    /// These settings with a contact margin of `margin` (m, ≥ 0) above
    /// the ground.
    ///
    /// ```
    /// use rodyn::sim::time_stepping::TimeSteppingSettings;
    ///
    /// assert_eq!(TimeSteppingSettings::with_friction(0.5).with_margin(0.02).margin, 0.02);
    /// ```
    #[must_use]
    pub const fn with_margin(mut self, margin: S) -> Self {
        self.margin = margin;
        self
    }

    /// # Errors
    /// [`Error::InvalidSetting`] naming the friction, the sweeps (none),
    /// the depth recovery (`β` outside `[0, 1]`) or the margin (negative
    /// or not finite).
    fn validate(&self) -> Result<()> {
        let fine = |x: S| x.is_finite() && x.to_f64() >= 0.0;
        let problem = if !fine(self.friction) {
            Some(Setting::Friction)
        } else if self.sweeps == 0 {
            Some(Setting::Sweeps)
        } else if !(fine(self.depth_recovery) && self.depth_recovery.to_f64() <= 1.0) {
            Some(Setting::DepthRecovery)
        } else if !fine(self.margin) {
            Some(Setting::Margin)
        } else {
            None
        };
        problem.map_or(Ok(()), |setting| Err(Error::InvalidSetting { setting }))
    }
}

/// The workspace of [`time_step`] for up to `NP` candidate points.
#[derive(Clone, Debug)]
pub struct TimeSteppingData<S: Scalar, const NV: usize, const NC: usize, const NP: usize> {
    /// The constraint workspace (`NC ≥ 3 NP` rows): `J_c`, `M⁻¹ J_cᵀ` and
    /// the Delassus matrix of the last step's contacts.
    pub constraint: ConstraintData<S, NV, NC>,
    /// Each candidate point's impulse over the last step (N s, world axes,
    /// zero when it was not in contact); divided by the step it is the
    /// mean contact force.
    pub impulses: [Vec3<S>; NP],
    /// Each candidate point's gap before the last step (m; negative below
    /// the ground).
    pub gaps: [S; NP],
    /// Whether each point was among the last step's contacts.
    pub in_contact: [bool; NP],
    /// The largest change of an impulse entry in the last sweep (N s): how
    /// far from converged the solver stopped.
    pub last_change: S,
}

impl<S: Scalar, const NV: usize, const NC: usize, const NP: usize> TimeSteppingData<S, NV, NC, NP> {
    /// A zeroed workspace (usable in `const`).
    #[must_use]
    pub const fn new() -> Self {
        Self {
            constraint: ConstraintData::new(),
            impulses: [Vec3::ZERO; NP],
            gaps: [S::ZERO; NP],
            in_contact: [false; NP],
            last_change: S::ZERO,
        }
    }
}

impl<S: Scalar, const NV: usize, const NC: usize, const NP: usize> Default
    for TimeSteppingData<S, NV, NC, NP>
{
    fn default() -> Self {
        Self::new()
    }
}

/// Advances `state` by `dt` (s) under joint forces `tau` (N m, N) and the
/// implicit joint damping `damping` (`D`'s diagonal, N m s/rad, N s/m),
/// with the origins of `points` held out of the ground plane `z = 0` by
/// rigid contact with Coulomb friction (see the [module](self)). The
/// points' last impulses in `sdata` warm-start the solver: keep one
/// `sdata` per simulation.
///
/// On error the state is unchanged (`sdata` holds the failed attempt's
/// gaps and contacts).
///
/// # Errors
/// [`Error::TooManyConstraints`] when `NC < 3 NP`,
/// [`Error::InvalidSetting`] for bad settings (see [`TimeSteppingSettings`];
/// [`Setting::JointDamping`] for a negative or non-finite damping entry),
/// [`Error::FrameBodyOutOfRange`] for a point on a missing body,
/// [`Error::NonFinite`] for a non-finite time, step, state or torque, or
/// a point whose placement is not finite (`Quantity::Contact`, the
/// point's index),
/// [`Error::OutOfRange`] (`Quantity::Time`, index 1) for a step that is
/// not positive, and those of the algorithms it runs.
#[allow(clippy::too_many_arguments)]
pub fn time_step<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NC: usize,
    const NP: usize,
>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    sdata: &mut TimeSteppingData<S, NV, NC, NP>,
    state: &mut State<S, NQ, NV>,
    tau: &[S; NV],
    damping: &[S; NV],
    points: &[Frame<S, Spatial>; NP],
    settings: &TimeSteppingSettings<S>,
    dt: S,
) -> Result<()> {
    if 3 * NP > NC {
        return Err(Error::TooManyConstraints {
            rows: 3 * NP,
            capacity: NC,
        });
    }
    settings.validate()?;
    if let Some(dof) = damping
        .iter()
        .position(|d| !(d.is_finite() && d.to_f64() >= 0.0))
    {
        return Err(Error::InvalidSetting {
            setting: Setting::JointDamping { dof },
        });
    }
    check_time(state.t, dt)?;
    if dt.to_f64() <= 0.0 {
        return Err(Error::OutOfRange {
            quantity: Quantity::Time,
            index: 1,
        });
    }
    state.check_finite()?;
    check_finite(tau, Quantity::Torque)?;
    let (q, v) = (&state.q, &state.v);

    // The bias forces and the mass matrix first: they leave the joints'
    // transforms, from which the poses are composed without forming them
    // again.
    let bias = bias_and_mass(model, data, q, v, None)?;
    pose_pass(model, data);

    // The candidates within the margin become point contacts (their anchor
    // is not used: the gap term replaces Baumgarte's).
    let mut contacts = [Contact::point(Frame::new(0, Transform::IDENTITY), Vec3::ZERO); NP];
    let mut index = [0; NP];
    let mut active = 0;
    for (p, point) in points.iter().enumerate() {
        // A point whose placement is not finite is refused, naming it,
        // rather than read as a point above the ground.
        let gap = frame_placement(data, point)
            .map_err(|error| match error {
                Error::NonFinite { .. } => Error::NonFinite {
                    quantity: Quantity::Contact,
                    index: p,
                },
                other => other,
            })?
            .trans
            .z;
        sdata.gaps[p] = gap;
        sdata.in_contact[p] = gap.to_f64() <= settings.margin.to_f64();
        if sdata.in_contact[p] {
            contacts[active] = Contact::point(*point, Vec3::ZERO);
            index[active] = p;
            active += 1;
        } else {
            sdata.impulses[p] = Vec3::ZERO;
        }
    }
    let contacts = &contacts[..active];
    let rows = 3 * active;

    // J_c, M̃⁻¹ J_cᵀ and G; v_free = v + dt M̃⁻¹ (τ − b − D v).
    let added: [S; NV] = core::array::from_fn(|k| dt * damping[k]);
    form_delassus(
        model,
        data,
        &mut sdata.constraint,
        q,
        contacts,
        S::ZERO,
        Some(&added),
        Poses::FromJointTransformsAndMass,
    )?;
    let mut v_free: [S; NV] = core::array::from_fn(|k| tau[k] - bias[k] - damping[k] * v[k]);
    ltdl_solve(model, data, &mut v_free)?;
    for (vf, vk) in v_free.iter_mut().zip(v) {
        *vf = *vk + dt * *vf;
    }

    // The contact velocities at Λ = 0, with the gap term on the normals.
    let cdata = &mut sdata.constraint;
    let mut free = [S::ZERO; NC];
    for (r, b) in free[..rows].iter_mut().enumerate() {
        *b = dot(&cdata.jc[r], &v_free);
    }
    for (c, &p) in index[..active].iter().enumerate() {
        // `index` holds points of this step (`get`: no panic path).
        let Some(&gap) = sdata.gaps.get(p) else {
            continue;
        };
        let closing = if gap.to_f64() > 0.0 {
            gap
        } else {
            settings.depth_recovery * gap
        };
        free[3 * c + 2] += closing / dt;
        let warm = sdata.impulses.get(p).map_or([S::ZERO; 3], |i| i.to_array());
        cdata.lambda[3 * c..3 * c + 3].copy_from_slice(&warm);
    }
    sdata.last_change =
        projected_gauss_seidel(&cdata.delassus, &free, &mut cdata.lambda, active, settings);

    // v⁺ = v_free + M⁻¹ J_cᵀ Λ; q⁺ = q ⊕ dt v⁺.
    add_response(model, data, cdata, &v_free);
    check_result(&cdata.lambda[..rows], Quantity::Contact)?;
    check_result(&cdata.ddq, Quantity::Velocity)?;
    for (c, &p) in index[..active].iter().enumerate() {
        let l = &cdata.lambda[3 * c..3 * c + 3];
        if let Some(impulse) = sdata.impulses.get_mut(p) {
            *impulse = Vec3::new(l[0], l[1], l[2]);
        }
    }
    let v_next = cdata.ddq;
    let mut q_next = model.integrate(q, &v_next, dt)?;
    model.normalize(&mut q_next)?;
    let next = State::new(q_next, v_next);
    next.check_finite()?;
    let t = state.t + dt;
    *state = State { t, ..next };
    Ok(())
}

/// Projected Gauss–Seidel on `u = G Λ + b` over `contacts` blocks of three
/// rows (tangent x, tangent y, normal z): each sweep sets each contact's
/// normal impulse so that its normal velocity vanishes, projected on
/// `Λ_z ≥ 0`, then its tangential impulse so that its slip vanishes,
/// projected on the disc `‖Λ_xy‖ ≤ μ Λ_z`. Returns the largest change of
/// an impulse entry in the last sweep.
fn projected_gauss_seidel<S: Scalar, const NC: usize>(
    g: &[[S; NC]; NC],
    b: &[S; NC],
    lambda: &mut [S; NC],
    contacts: usize,
    settings: &TimeSteppingSettings<S>,
) -> S {
    let rows = 3 * contacts;
    let velocity = |lambda: &[S; NC], r: usize| {
        g[r][..rows]
            .iter()
            .zip(&lambda[..rows])
            .fold(b[r], |acc, (gij, lj)| acc + *gij * *lj)
    };
    let mut change = S::ZERO;
    for _ in 0..settings.sweeps {
        change = S::ZERO;
        for c in 0..contacts {
            let (x, y, z) = (3 * c, 3 * c + 1, 3 * c + 2);
            let before = [lambda[x], lambda[y], lambda[z]];
            // A diagonal entry is a point's inverse apparent mass: positive
            // unless the point cannot move at all, when any impulse works.
            let step_length = |g: S| {
                if g.to_f64() > 0.0 {
                    S::ONE / g
                } else {
                    S::ZERO
                }
            };
            let step = |r: usize, u: S| step_length(g[r][r]) * u;
            lambda[z] = (lambda[z] - step(z, velocity(lambda, z))).max(S::ZERO);
            // Both tangential slips at the same impulses, and one step
            // length for both: the projection on the disc then keeps the
            // impulse opposite to the slip, as maximal dissipation asks.
            // (A step per axis, or the 2×2 block's inverse, skews it and
            // leaves internal forces that eat the cone.)
            let (ux, uy) = (velocity(lambda, x), velocity(lambda, y));
            let r = step_length(g[x][x].max(g[y][y]));
            let tx = lambda[x] - r * ux;
            let ty = lambda[y] - r * uy;
            let limit = settings.friction * lambda[z];
            let norm = (tx * tx + ty * ty).sqrt();
            let scale = if norm.to_f64() > limit.to_f64() {
                limit / norm
            } else {
                S::ONE
            };
            lambda[x] = tx * scale;
            lambda[y] = ty * scale;
            for (after, was) in [lambda[x], lambda[y], lambda[z]].iter().zip(before) {
                change = change.max((*after - was).abs());
            }
        }
    }
    change
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One point of unit inverse mass on each axis, falling at 1 m/s onto
    /// the ground, pushed sideways at 2 m/s with μ = 0.5: the normal
    /// impulse stops it, the tangential one reaches the cone's edge and
    /// opposes the slip.
    #[test]
    fn a_sliding_point_stops_falling_and_meets_the_cone() {
        let mut g = [[0.0_f64; 3]; 3];
        for (r, row) in g.iter_mut().enumerate() {
            row[r] = 1.0;
        }
        let b = [2.0, 0.0, -1.0];
        let mut lambda = [0.0; 3];
        let settings = TimeSteppingSettings::with_friction(0.5);
        let change = projected_gauss_seidel(&g, &b, &mut lambda, 1, &settings);
        assert!((lambda[2] - 1.0).abs() < 1e-15, "{lambda:?}");
        assert!((lambda[0] + 0.5).abs() < 1e-15, "{lambda:?}");
        assert_eq!(lambda[1], 0.0);
        assert_eq!(change, 0.0);
    }
}
