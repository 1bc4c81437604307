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

use super::dense::{cholesky_in_place, cholesky_solve};
use super::frames::{frame_placement, ReferenceFrame};
use super::jacobian::{frame_jacobian, joint_jacobians, JacobianData};
use crate::data::Data;
use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::model::Model;
/// The rotation vector of a rotation (moved to [`crate::spatial`], where
/// the frame contacts' `log6` uses it too; kept here for existing paths).
pub use crate::spatial::log3;
use crate::spatial::{Motion, Spatial, Transform, Vec3};
use crate::Scalar;

/// Settings of [`solve`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IkSettings<S> {
    /// The damping `λ` (in the units of `e`: rad and m), > 0.
    pub damping: S,
    /// Convergence: the largest component of `e` (rad, m) at most this.
    pub tolerance: S,
    /// The iteration budget (each iteration: one Jacobian and one 6×6 solve).
    pub max_iterations: usize,
}

impl<S: Scalar> IkSettings<S> {
    /// λ = 1e-3, tolerance 1e-6 (f64) or 1e-4 (f32), 100 iterations.
    #[must_use]
    pub fn new() -> Self {
        Self {
            damping: S::from_f64(1e-3),
            tolerance: S::from_f64(if S::EPSILON < 1e-10 { 1e-6 } else { 1e-4 }),
            max_iterations: 100,
        }
    }
}

impl<S: Scalar> Default for IkSettings<S> {
    fn default() -> Self {
        Self::new()
    }
}

/// The pose error `e = log(ᶠMₜ)` of a frame at `o_m_f` against `target`
/// (both world from frame): rad and m, in the frame's axes.
#[must_use]
pub fn pose_error<S: Scalar>(o_m_f: &Transform<S>, target: &Transform<S>) -> Motion<S> {
    let rot = o_m_f.rot.tr_mul_mat(&target.rot);
    let lin = o_m_f.rot.tr_mul_vec(&(target.trans - o_m_f.trans));
    Motion::new(log3(&rot), lin)
}

/// The workspace of [`solve`]: the Jacobians. Its own type so that models
/// without inverse kinematics pay nothing for it.
#[derive(Clone, Debug)]
pub struct IkData<S: Scalar, const NV: usize> {
    /// Joint Jacobians of the last iteration.
    pub jac: JacobianData<S, NV>,
    /// The frame's Jacobian in its own axes at the last iteration.
    pub frame_jacobian: [Motion<S>; NV],
}

impl<S: Scalar, const NV: usize> IkData<S, NV> {
    /// A zeroed workspace; `const`, so it can initialise a `static`.
    #[must_use]
    pub const fn new() -> Self {
        Self {
            jac: JacobianData::new(),
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
/// configuration manifold ([`Model::integrate`]). Runs [`joint_jacobians`]; leaves valid `data.li_m_i`,
/// `data.o_m_i` (at the `q` before the step), `ws.jac.j`,
/// `ws.frame_jacobian`.
///
/// # Errors
/// As [`joint_jacobians`];
/// [`Error::FrameBodyOutOfRange`]; [`Error::NotConverged`] (with zero
/// iterations) when the step is not finite; those of [`Model::integrate`]
/// when the moved `q` is not (`q` is then left as it was).
pub fn step<S: Scalar, const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    ws: &mut IkData<S, NV>,
    frame: &Frame<S>,
    target: &Transform<S>,
    damping: S,
    q: &mut [S; NQ],
) -> Result<Motion<S>> {
    joint_jacobians(model, data, &mut ws.jac, q)?;
    let o_m_f = frame_placement(data, frame)?;
    let e = pose_error(&o_m_f, target);
    frame_jacobian(
        model,
        data,
        &ws.jac,
        frame,
        ReferenceFrame::Local,
        &mut ws.frame_jacobian,
    )?;
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
        return Err(Error::NotConverged {
            iterations: 0,
            residual: f64::INFINITY,
        });
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
/// [`Error::NotConverged`] with the last error's largest component when
/// the budget runs out (an unreachable target, or a start too far away),
/// `q` then holding the last iterate; and those of [`step`].
pub fn solve<S: Scalar, const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    ws: &mut IkData<S, NV>,
    frame: &Frame<S>,
    target: &Transform<S>,
    settings: &IkSettings<S>,
    q: &mut [S; NQ],
) -> Result<usize> {
    let mut residual = f64::INFINITY;
    for iteration in 0..settings.max_iterations {
        let before = *q;
        let e = step(model, data, ws, frame, target, settings.damping, q)?;
        let size = column(&e).iter().fold(S::ZERO, |m, x| m.max(x.abs()));
        residual = size.to_f64();
        if size <= settings.tolerance {
            *q = before;
            return Ok(iteration);
        }
    }
    Err(Error::NotConverged {
        iterations: settings.max_iterations,
        residual,
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
        Ok(()) => cholesky_solve(a, 6, &mut y),
        Err(_) => y = [S::from_f64(f64::NAN); 6],
    }
    y
}
