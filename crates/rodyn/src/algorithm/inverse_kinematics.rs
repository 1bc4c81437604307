//! Inverse kinematics: damped least squares (Levenberg-Marquardt) steps
//! that bring a [`Frame`] to a target pose, with a fixed iteration budget
//! so that a control loop knows its worst-case cost.
//!
//! The error of frame f against target t is `e = log(ᶠMₜ)`, the twist
//! that carries f onto t in one unit of time, in f's axes: its angular
//! part `log₃(Rfᵀ Rt)` (rad), its linear part `Rfᵀ (pt − pf)` (m). With
//! f's Jacobian in its own axes `J` ([`ReferenceFrame::Local`]), one step
//! is `Δq = Jᵀ (J Jᵀ + λ² I)⁻¹ e` (Wampler 1986; Nakamura & Hanafusa
//! 1986), integrated on the configuration manifold. `J` stands in for the
//! exact derivative of `e` (which also holds the log's Jacobian); the two
//! agree at the solution, so the steps still converge to it. The damping
//! `λ` keeps the step bounded near singular configurations and for
//! unreachable targets, where the iteration then settles at the closest
//! reachable pose and reports [`Error::NotConverged`].
//!
//! Damped least squares is a local method: from a start in another basin
//! (the elbow on the wrong side, the arm stretched straight, a singular
//! wrist) it stalls short of a reachable target. [`solve_with_fallback`]
//! then falls back to joint space: it restarts from a configuration the
//! caller names (a home posture, the last solution of a control loop) for
//! what is left of the same budget, so the worst case stays one budget.

use super::dense::{cholesky_in_place, cholesky_solve_unchecked};
use super::frame_chain::{chain_jacobian, FrameChain};
use super::frames::ReferenceFrame;
use crate::data::Data;
use crate::error::{Error, ModelProblem, Quantity, Result, Setting};
use crate::frame::Frame;
use crate::model::Model;
use crate::space::VectorOps;
/// The rotation vector of a rotation (moved to [`crate::spatial`], where
/// the frame contacts' `log6` uses it too; kept here for existing paths).
pub use crate::spatial::log3;
use crate::spatial::{Motion, Spatial, Transform, Vec3};
use crate::Scalar;

/// Settings of [`solve`].
///
/// `#[non_exhaustive]`: a later setting is not a breaking change. Build it
/// with [`IkSettings::new`] and the `with_…` methods.
///
/// ```
/// use rodyn::algorithm::inverse_kinematics::IkSettings;
///
/// let settings = IkSettings::<f64>::new().with_tolerance(1e-9).with_max_iterations(200);
/// assert_eq!((settings.tolerance, settings.max_iterations), (1e-9, 200));
/// assert_eq!(settings.damping, IkSettings::<f64>::new().damping);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct IkSettings<S> {
    /// The damping `λ` (in the units of `e`: rad and m), > 0.
    pub damping: S,
    /// Convergence: the largest component of `e` (rad, m) at most this.
    pub tolerance: S,
    /// The iteration budget (each iteration: one Jacobian and one 6×6 solve).
    pub max_iterations: usize,
    /// [`solve_with_fallback`]: a start counts as stalled when a window of
    /// this many steps leaves the error's largest component above 99 % of
    /// its value when the window began.
    pub stall_iterations: usize,
}

impl<S: Scalar> IkSettings<S> {
    /// λ = 1e-3, tolerance 1e-6 (f64) or 1e-4 (f32), 100 iterations, a
    /// start stalled after 10 iterations without progress.
    #[must_use]
    pub fn new() -> Self {
        Self {
            damping: S::from_f64(1e-3),
            tolerance: S::from_f64(if S::EPSILON < 1e-10 { 1e-6 } else { 1e-4 }),
            max_iterations: 100,
            stall_iterations: 10,
        }
    }

    /// These settings with damping `λ` (> 0).
    ///
    /// ```
    /// use rodyn::algorithm::inverse_kinematics::IkSettings;
    ///
    /// assert_eq!(IkSettings::new().with_damping(1e-2).damping, 1e-2);
    /// ```
    #[must_use]
    pub const fn with_damping(mut self, damping: S) -> Self {
        self.damping = damping;
        self
    }

    /// These settings with the convergence tolerance on `e`'s largest
    /// component (rad, m).
    ///
    /// ```
    /// use rodyn::algorithm::inverse_kinematics::IkSettings;
    ///
    /// assert_eq!(IkSettings::new().with_tolerance(1e-8).tolerance, 1e-8);
    /// ```
    #[must_use]
    pub const fn with_tolerance(mut self, tolerance: S) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// These settings with an iteration budget of `max_iterations`.
    ///
    /// ```
    /// use rodyn::algorithm::inverse_kinematics::IkSettings;
    ///
    /// assert_eq!(IkSettings::<f32>::new().with_max_iterations(20).max_iterations, 20);
    /// ```
    #[must_use]
    pub const fn with_max_iterations(mut self, max_iterations: usize) -> Self {
        self.max_iterations = max_iterations;
        self
    }

    /// These settings with [`solve_with_fallback`]'s stall window of
    /// `stall_iterations` steps.
    ///
    /// ```
    /// use rodyn::algorithm::inverse_kinematics::IkSettings;
    ///
    /// assert_eq!(IkSettings::<f64>::new().with_stall_iterations(5).stall_iterations, 5);
    /// ```
    #[must_use]
    pub const fn with_stall_iterations(mut self, stall_iterations: usize) -> Self {
        self.stall_iterations = stall_iterations;
        self
    }
}

impl<S: Scalar> Default for IkSettings<S> {
    fn default() -> Self {
        Self::new()
    }
}

/// The pose error `e = log(ᶠMₜ)` of a frame at `o_m_f` against `target`
/// (both world from frame): rad and m, in the frame's axes.
///
/// # Errors
/// [`Error::InvalidPose`] naming the target (`Quantity::Target`) or the
/// frame's pose (`Quantity::WorldPose`, index 0) when it is not a rigid
/// motion (a non-finite entry, a rotation that is not orthonormal or is a
/// reflection); [`Error::NonFiniteResult`] (`Quantity::Target`) when the
/// translations' difference overflows.
pub fn pose_error<S: Scalar>(o_m_f: &Transform<S>, target: &Transform<S>) -> Result<Motion<S>> {
    target.validate().map_err(|problem| Error::InvalidPose {
        quantity: Quantity::Target,
        index: 0,
        problem: ModelProblem::from(problem),
    })?;
    o_m_f.validate().map_err(|problem| Error::InvalidPose {
        quantity: Quantity::WorldPose,
        index: 0,
        problem: ModelProblem::from(problem),
    })?;
    let e = pose_error_unchecked(o_m_f, target);
    if !e.is_finite() {
        return Err(Error::NonFiniteResult {
            quantity: Quantity::Target,
            index: 0,
        });
    }
    Ok(e)
}

/// [`pose_error`] without its checks, for [`step`], which checks the frame
/// and target once up front.
fn pose_error_unchecked<S: Scalar>(o_m_f: &Transform<S>, target: &Transform<S>) -> Motion<S> {
    let rot = o_m_f.rot.tr_mul_mat(&target.rot);
    let lin = o_m_f.rot.tr_mul_vec(&(target.trans - o_m_f.trans));
    Motion::new(log3(&rot), lin)
}

/// The workspace of [`solve`]: the frame's Jacobian. Its own type so that
/// models without inverse kinematics pay nothing for it.
#[derive(Clone, Debug)]
pub struct IkData<S: Scalar, const NV: usize> {
    /// The frame's Jacobian in its own axes at the last iteration.
    pub frame_jacobian: [Motion<S>; NV],
}

impl<S: Scalar, const NV: usize> IkData<S, NV> {
    /// A zeroed workspace; `const`, so it can initialise a `static`.
    #[must_use]
    pub const fn new() -> Self {
        Self {
            frame_jacobian: [Motion::new(Vec3::ZERO, Vec3::ZERO); NV],
        }
    }
}

impl<S: Scalar, const NV: usize> Default for IkData<S, NV> {
    fn default() -> Self {
        Self::new()
    }
}

/// One damped least-squares step: the error at `q` (returned, as
/// [`pose_error`]) and `q` moved by `Δq = Jᵀ (J Jᵀ + λ² I)⁻¹ e` on the
/// configuration manifold ([`Model::integrate`]). The frame's pose and
/// Jacobian come from [`chain_jacobian`], along the joints that move the
/// frame only; leaves valid `ws.frame_jacobian` (at the `q` before the
/// step). `data` is neither read nor written (the signature of the
/// iterations that call it, which keep it for their callers).
///
/// # Errors
/// As [`chain_jacobian`];
/// [`Error::FrameBodyOutOfRange`]; when the step is not finite, the
/// error that names why ([`check_problem`]'s for the frame, the target
/// and the damping, otherwise [`Error::NonFiniteResult`] for the
/// configuration); those of [`Model::integrate`] when the moved `q` is
/// not (`q` is then left as it was).
pub fn step<S: Scalar, const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    _data: &mut Data<S, NB, NV, Spatial>,
    ws: &mut IkData<S, NV>,
    frame: &Frame<S>,
    target: &Transform<S>,
    damping: S,
    q: &mut [S; NQ],
) -> Result<Motion<S>> {
    let chain = FrameChain::try_new(model, frame)?;
    let o_m_f = chain_jacobian(
        model,
        q,
        &chain,
        ReferenceFrame::Local,
        &mut ws.frame_jacobian,
    )?;
    let e = pose_error_unchecked(&o_m_f, target);
    let j = &ws.frame_jacobian;
    // A = J Jᵀ + λ² I (6×6, symmetric positive definite for λ > 0).
    let mut a = [[S::ZERO; 6]; 6];
    for k in 0..NV {
        let c = column(&j[k]);
        for r in 0..6 {
            for s in 0..=r {
                a[r][s] += c[r] * c[s];
            }
        }
    }
    for r in 0..6 {
        a[r][r] += damping * damping;
    }
    let y = cholesky_solve_6(&mut a, &column(&e));
    let dq: [S; NV] = core::array::from_fn(|k| {
        let c = column(&j[k]);
        (0..6).fold(S::ZERO, |acc, r| acc + c[r] * y[r])
    });
    if !dq.iter().all(|x| x.is_finite()) {
        return Err(bad_step(frame, target, damping, &dq));
    }
    *q = model.integrate(q, &dq, S::ONE)?;
    Ok(e)
}

/// Moves `q` until `frame` reaches `target` (world from frame) within
/// `settings.tolerance`, in at most `settings.max_iterations` steps
/// ([`step`]). Returns the number of steps taken; `q` is then the
/// configuration whose error was within tolerance. Leaves valid what
/// [`step`] does.
///
/// # Errors
/// Those of [`check_problem`] before any step (a bad frame, target,
/// damping or tolerance); [`Error::NotConverged`] with the last error's
/// largest component when the budget runs out (an unreachable target, or
/// a start too far away), `q` then holding the last iterate; and those of
/// [`step`].
pub fn solve<S: Scalar, const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    ws: &mut IkData<S, NV>,
    frame: &Frame<S>,
    target: &Transform<S>,
    settings: &IkSettings<S>,
    q: &mut [S; NQ],
) -> Result<usize> {
    check_problem::<S, NB>(frame, target, settings)?;
    let problem = Problem {
        model,
        frame,
        target,
        settings,
    };
    match problem.iterate(data, ws, q, settings.max_iterations, None)? {
        Outcome::Converged(iterations) => Ok(iterations),
        Outcome::Stopped { residual, .. } => Err(Error::NotConverged {
            iterations: settings.max_iterations,
            residual: residual.to_f64(),
        }),
    }
}

/// [`solve`] from `q`, falling back to joint space when that start stalls
/// (a window of `settings.stall_iterations` steps leaves the error's
/// largest component above 99 % of its value when the window began): the
/// iteration restarts from `fallback` (a home posture, or the last
/// solution of a control loop) with the steps left of
/// `settings.max_iterations`. Returns the steps taken from both starts;
/// `q` is then the configuration within tolerance. The worst case is one
/// budget of [`step`]s, as for [`solve`].
///
/// # Errors
/// Those of [`check_problem`] before any step;
/// [`Error::NotConverged`] when neither start converges within the budget,
/// with the steps taken and the smaller of the two final residuals, `q`
/// then holding that iterate; and those of [`step`].
#[allow(clippy::too_many_arguments)]
pub fn solve_with_fallback<S: Scalar, const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    ws: &mut IkData<S, NV>,
    frame: &Frame<S>,
    target: &Transform<S>,
    settings: &IkSettings<S>,
    fallback: &[S; NQ],
    q: &mut [S; NQ],
) -> Result<usize> {
    check_problem::<S, NB>(frame, target, settings)?;
    let problem = Problem {
        model,
        frame,
        target,
        settings,
    };
    let budget = settings.max_iterations;
    let (used, first_residual) =
        match problem.iterate(data, ws, q, budget, Some(settings.stall_iterations))? {
            Outcome::Converged(iterations) => return Ok(iterations),
            Outcome::Stopped {
                iterations,
                residual,
            } => (iterations, residual),
        };
    let mut restart = *fallback;
    match problem.iterate(data, ws, &mut restart, budget - used, None)? {
        Outcome::Converged(iterations) => {
            *q = restart;
            Ok(used + iterations)
        }
        Outcome::Stopped { residual, .. } => {
            if residual < first_residual {
                *q = restart;
            }
            Err(Error::NotConverged {
                iterations: budget,
                residual: residual.min(first_residual).to_f64(),
            })
        }
    }
}

/// A window of steps makes progress when it ends with the error below
/// this fraction of what it was when the window began.
const STALL_PROGRESS: f64 = 0.99;

/// What one start of the iteration came to.
/// The residuals stay in `S` until an error reports one: an `f32` solve
/// does no double-precision arithmetic.
enum Outcome<S> {
    /// Within tolerance after this many steps.
    Converged(usize),
    /// Out of budget, or stalled: steps taken and the last error's largest
    /// component.
    Stopped { iterations: usize, residual: S },
}

/// The fixed inputs of an inverse-kinematics solve.
struct Problem<'a, S: Scalar, const NB: usize, const NQ: usize, const NV: usize> {
    model: &'a Model<S, NB, NQ, NV, Spatial>,
    frame: &'a Frame<S>,
    target: &'a Transform<S>,
    settings: &'a IkSettings<S>,
}

impl<S: Scalar, const NB: usize, const NQ: usize, const NV: usize> Problem<'_, S, NB, NQ, NV> {
    /// Damped least-squares steps from `q`, at most `budget` of them, and,
    /// with `stall = Some(n)`, stopping at the end of a window of `n` steps
    /// that brought the error no lower than 99 % of its value when the
    /// window began. On
    /// convergence `q` is the configuration within tolerance, otherwise
    /// the last iterate.
    fn iterate(
        &self,
        data: &mut Data<S, NB, NV, Spatial>,
        ws: &mut IkData<S, NV>,
        q: &mut [S; NQ],
        budget: usize,
        stall: Option<usize>,
    ) -> Result<Outcome<S>> {
        let mut residual = S::from_f64(f64::INFINITY);
        // The error when the current window of `stall` steps began.
        let mut window_start = residual;
        for iteration in 0..budget {
            let before = *q;
            let e = step(
                self.model,
                data,
                ws,
                self.frame,
                self.target,
                self.settings.damping,
                q,
            )?;
            let size = largest_component(&e);
            residual = size;
            if size <= self.settings.tolerance {
                *q = before;
                return Ok(Outcome::Converged(iteration));
            }
            // Compared window by window, not step by step: near a singular
            // configuration a step can throw the error up before the next
            // ones bring it down.
            if stall.is_some_and(|n| n > 0 && iteration % n == 0) {
                if iteration > 0 && residual >= S::from_f64(STALL_PROGRESS) * window_start {
                    return Ok(Outcome::Stopped {
                        iterations: iteration + 1,
                        residual,
                    });
                }
                window_start = residual;
            }
        }
        Ok(Outcome::Stopped {
            iterations: budget,
            residual,
        })
    }
}

/// Checks what an inverse-kinematics solve is given, so that it never
/// iterates on a target or frame that is not a pose, nor compares with a
/// tolerance that no error can meet (or every error meets):
///
/// * `frame`: on a body below `NB`, its placement a rigid motion;
/// * `target`: a rigid motion (finite, its rotation orthonormal within
///   1e3 ε with determinant +1, as a model's placements);
/// * `settings.damping` and `settings.tolerance`: finite and positive.
///
/// # Errors
/// [`Error::FrameBodyOutOfRange`]; [`Error::InvalidPose`] naming the frame
/// (`Quantity::FramePlacement`, its body) or the target
/// (`Quantity::Target`) and what is wrong with it;
/// [`Error::InvalidSetting`] naming the damping or the tolerance.
pub fn check_problem<S: Scalar, const NB: usize>(
    frame: &Frame<S>,
    target: &Transform<S>,
    settings: &IkSettings<S>,
) -> Result<()> {
    if frame.body >= NB {
        return Err(Error::FrameBodyOutOfRange { body: frame.body });
    }
    frame
        .placement
        .validate()
        .map_err(|problem| Error::InvalidPose {
            quantity: Quantity::FramePlacement,
            index: frame.body,
            problem: ModelProblem::from(problem),
        })?;
    target.validate().map_err(|problem| Error::InvalidPose {
        quantity: Quantity::Target,
        index: 0,
        problem: ModelProblem::from(problem),
    })?;
    let positive = |x: S| x.is_finite() && x > S::ZERO;
    if !positive(settings.damping) {
        return Err(Error::InvalidSetting {
            setting: Setting::IkDamping,
        });
    }
    if !positive(settings.tolerance) {
        return Err(Error::InvalidSetting {
            setting: Setting::IkTolerance,
        });
    }
    Ok(())
}

/// Why a step came out non-finite: a bad input [`check_problem`] names,
/// otherwise an overflow of the step (entry `k` of `Δq`).
#[cold]
fn bad_step<S: Scalar, const NV: usize>(
    frame: &Frame<S>,
    target: &Transform<S>,
    damping: S,
    dq: &[S; NV],
) -> Error {
    let settings = IkSettings {
        damping,
        tolerance: S::ONE,
        ..IkSettings::new()
    };
    // The body was in range: `frame_jacobian` read it.
    match check_problem::<S, { usize::MAX }>(frame, target, &settings) {
        Err(error) => error,
        Ok(()) => Error::NonFiniteResult {
            quantity: Quantity::Velocity,
            index: dq.iter().position(|x| !x.is_finite()).unwrap_or(0),
        },
    }
}

/// The largest component of a pose error (rad or m); NaN when a component
/// is NaN (`max` would drop it), so that no comparison with the tolerance
/// can pass.
fn largest_component<S: Scalar>(e: &Motion<S>) -> S {
    column(e).iter().fold(S::ZERO, |m, x| {
        if x.is_finite() && m.is_finite() {
            m.max(x.abs())
        } else {
            S::from_f64(f64::NAN)
        }
    })
}

/// A motion's six components, angular first.
#[inline]
fn column<S: Scalar>(m: &Motion<S>) -> [S; 6] {
    [m.ang.x, m.ang.y, m.ang.z, m.lin.x, m.lin.y, m.lin.z]
}

/// Solves `A y = b` for a symmetric positive definite 6×6 `A` given by its
/// lower triangle, which it overwrites with its Cholesky factor. A
/// non-positive pivot (rounding with a tiny damping) makes the step
/// non-finite, which the caller reports.
fn cholesky_solve_6<S: Scalar>(a: &mut [[S; 6]; 6], b: &[S; 6]) -> [S; 6] {
    let mut y = *b;
    match cholesky_in_place(a, 6, 0.0) {
        Ok(()) => cholesky_solve_unchecked(a, 6, &mut y),
        Err(_) => y = [S::from_f64(f64::NAN); 6],
    }
    y
}
