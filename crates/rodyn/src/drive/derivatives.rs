//! Analytic derivatives of the drives' generalised forces with respect to
//! the state, `∂Q/∂q` and `∂Q/∂v`, and forward dynamics with drives
//! differentiated through them.
//!
//! A path element pulls with a tension `T(L, L̇, w)` along a path of length
//! `L(q)`; its generalised force is `Q = −T ∇L` (the path's moment arms
//! `∇L = ∂L/∂q`, and `L̇ = ∇L · v`). Hence
//!
//! ```text
//! ∂Q/∂q = −∇L (T_L ∇Lᵀ + T_L̇ (vᵀ ∇²L)) − T ∇²L
//! ∂Q/∂v = −T_L̇ ∇L ∇Lᵀ
//! ```
//!
//! with the tension's partials `T_L`, `T_L̇` from each element and the
//! path's gradient and Hessian from [`Path::length_derivatives`]. A point p
//! on body b moves with `J_pc = ᵒS_c` at p for every coordinate c that
//! supports b; turning coordinate r moves p by `J_pr` and, when r is at or
//! above c's joint, turns `ᵒS_c` by `ᵒS_r × ᵒS_c`. Derivatives with respect
//! to `q` are in the tangent space, as in
//! [`algorithm::derivatives`](crate::algorithm::derivatives).

use crate::algorithm::derivatives::{aba_derivatives, DerivativeData, DerivativeSpace};
use crate::algorithm::jacobian::{joint_jacobians_time_variation, JacobianData};
use crate::data::Data;
use crate::drive::path::{body_out_of_range, non_finite_path};
use crate::drive::{ForceElement, Path, PointGeometry, MIN_SEGMENT_LENGTH};
use crate::error::{Quantity, Result};
use crate::model::{check_finite, check_result, Model};
use crate::space::{MotionVector, RigidTransform, Space};
use crate::topology::Topology;
use crate::Scalar;

/// The generalised force of a set of drives and its derivatives with
/// respect to the state (row-major, rows and columns in `v`'s order).
#[derive(Clone, Debug)]
pub struct DriveDerivatives<S: Scalar, const NV: usize> {
    /// The generalised force `Q` (N m or N).
    pub tau: [S; NV],
    /// `∂Q/∂q` (tangent space).
    pub dtau_dq: [[S; NV]; NV],
    /// `∂Q/∂v`.
    pub dtau_dv: [[S; NV]; NV],
}

impl<S: Scalar, const NV: usize> DriveDerivatives<S, NV> {
    /// All zero; `const`, so it can initialise a `static`.
    #[must_use]
    pub const fn new() -> Self {
        Self {
            tau: [S::ZERO; NV],
            dtau_dq: [[S::ZERO; NV]; NV],
            dtau_dv: [[S::ZERO; NV]; NV],
        }
    }
    /// Resets every entry to zero.
    pub fn clear(&mut self) {
        *self = Self::new();
    }
}

impl<S: Scalar, const NV: usize> Default for DriveDerivatives<S, NV> {
    fn default() -> Self {
        Self::new()
    }
}

/// What an element's derivatives read: body poses (`data.o_m_i`), the
/// joint Jacobian's world columns `ᵒS_c`, the tree, and the velocity.
#[derive(Clone, Copy, Debug)]
pub struct DriveDerivativeState<'a, S: Scalar, G: Space, const NB: usize, const NV: usize> {
    /// Kinematics at the state (reads `o_m_i`).
    pub data: &'a Data<S, NB, NV, G>,
    /// `ᵒS_c`, one world column per velocity coordinate.
    pub columns: &'a [G::Motion<S>; NV],
    /// The model's tree.
    pub topology: &'a Topology<NB, NV>,
    /// Joint velocity.
    pub v: &'a [S; NV],
}

/// A path's length, its rate and their derivatives at one state.
#[derive(Clone, Debug)]
pub struct PathDerivatives<S: Scalar, const NV: usize> {
    /// `L` (m).
    pub length: S,
    /// `L̇ = ∇L · v` (m/s).
    pub lengthening_velocity: S,
    /// `∇L = ∂L/∂q`, the negated moment arms (m per rad, or m/m).
    pub gradient: [S; NV],
    /// `∇²L`: `hessian[r][c] = ∂(∇L_r)/∂q_c` (tangent space). Symmetric
    /// but for the blocks of joints whose coordinates do not commute (a
    /// free-flyer's: its increments are body-frame twists).
    pub hessian: [[S; NV]; NV],
}

impl<S: Scalar, G: PointGeometry, const K: usize> Path<S, G, K> {
    /// The path's length, rate, gradient and Hessian at `state`. Segments
    /// shorter than [`MIN_SEGMENT_LENGTH`] are skipped, as by
    /// [`kinematics`](Self::kinematics).
    ///
    /// # Errors
    /// [`Error::InvalidDrive`](crate::Error::InvalidDrive) when an endpoint names a body out of range;
    /// as [`kinematics`](Self::kinematics) for a point that is not finite
    /// or a length that overflows.
    pub fn length_derivatives<const NB: usize, const NV: usize>(
        &self,
        state: &DriveDerivativeState<'_, S, G, NB, NV>,
    ) -> Result<PathDerivatives<S, NV>> {
        self.check(NB)?;
        let t = state.topology;
        // World positions, and J_pc for the coordinates that move each point.
        let zero = G::point_zero::<S>();
        let mut points = [zero; K];
        let mut jacobians = [[zero; NV]; K];
        let mut moved_by = [[false; NV]; K];
        for (k, endpoint) in self.points.iter().enumerate() {
            let Some(b) = endpoint.body else {
                points[k] = endpoint.position;
                continue;
            };
            let Some(pose) = state.data.o_m_i.get(b) else {
                return Err(body_out_of_range(b));
            };
            points[k] = pose.act_point(&endpoint.position);
            for c in 0..NV {
                if t.supports(t.body_of_v[c], b) {
                    moved_by[k][c] = true;
                    jacobians[k][c] = G::point_velocity(&state.columns[c], &points[k]);
                }
            }
        }
        // `∂J_pc/∂q_r` for point k (column c along direction r): the point
        // moves (ω_c × J_pr), and S_c turns when r is at or above c's joint.
        let point_hessian = |k: usize, c: usize, r: usize| -> G::Point<S> {
            if !(moved_by[k][c] && moved_by[k][r]) {
                return zero;
            }
            let s_c = &state.columns[c];
            let moved = G::point_sub(
                &G::point_velocity(s_c, &jacobians[k][r]),
                &G::point_velocity(s_c, &zero),
            );
            if t.supports(t.body_of_v[r], t.body_of_v[c]) {
                let turned = state.columns[r].cross_motion(s_c);
                G::point_add(&moved, &G::point_velocity(&turned, &points[k]))
            } else {
                moved
            }
        };
        let mut out = PathDerivatives {
            length: S::ZERO,
            lengthening_velocity: S::ZERO,
            gradient: [S::ZERO; NV],
            hessian: [[S::ZERO; NV]; NV],
        };
        let min_length = S::from_f64(MIN_SEGMENT_LENGTH);
        for k in 0..K - 1 {
            let d = G::point_sub(&points[k + 1], &points[k]);
            let l_squared = G::point_dot(&d, &d);
            if l_squared <= min_length * min_length {
                continue;
            }
            let l = l_squared.sqrt();
            let e = G::point_scale(&d, S::ONE / l);
            out.length += l;
            // D_c = J_(k+1)c − J_kc, and its projection on the segment.
            let diff: [G::Point<S>; NV] =
                core::array::from_fn(|c| G::point_sub(&jacobians[k + 1][c], &jacobians[k][c]));
            let along: [S; NV] = core::array::from_fn(|c| G::point_dot(&e, &diff[c]));
            for c in 0..NV {
                out.gradient[c] += along[c];
                for r in 0..NV {
                    // ∂e/∂q_r = (D_r − e (e · D_r)) / l.
                    let turn = (G::point_dot(&diff[r], &diff[c]) - along[r] * along[c]) / l;
                    let bend = G::point_dot(
                        &e,
                        &G::point_sub(&point_hessian(k + 1, r, c), &point_hessian(k, r, c)),
                    );
                    out.hessian[r][c] += turn + bend;
                }
            }
        }
        for (g, v) in out.gradient.iter().zip(state.v) {
            out.lengthening_velocity += *g * *v;
        }
        if !(out.length + out.lengthening_velocity).is_finite() {
            return Err(non_finite_path::<S, G>(points.into_iter()));
        }
        Ok(out)
    }
}

/// Adds a path element's `Q = −T ∇L` and its derivatives to `out`, from
/// the tension `T` and its partials `T_L` (`tension_dl`) and `T_L̇`
/// (`tension_dv`).
pub(crate) fn add_tension_derivatives<S: Scalar, const NV: usize>(
    path: &PathDerivatives<S, NV>,
    v: &[S; NV],
    (tension, tension_dl, tension_dv): (S, S, S),
    out: &mut DriveDerivatives<S, NV>,
) {
    let g = &path.gradient;
    // ∂L̇/∂q_c = Σ_r ∂(∇L_r)/∂q_c v_r.
    let rate_dq: [S; NV] =
        core::array::from_fn(|c| (0..NV).fold(S::ZERO, |sum, r| sum + path.hessian[r][c] * v[r]));
    for r in 0..NV {
        out.tau[r] -= tension * g[r];
        for c in 0..NV {
            out.dtau_dq[r][c] -=
                g[r] * (tension_dl * g[c] + tension_dv * rate_dq[c]) + tension * path.hessian[r][c];
            out.dtau_dv[r][c] -= tension_dv * g[r] * g[c];
        }
    }
}

/// The drives' generalised force `Q(q, v, w)` and its derivatives
/// `∂Q/∂q`, `∂Q/∂v`, into `out`. Runs
/// [`joint_jacobians_time_variation`]; leaves valid what it leaves.
///
/// # Errors
/// Non-finite `w`, errors of the kinematics and of the elements (an
/// element without state derivatives reports
/// [`DriveProblem::NotDifferentiable`](crate::error::DriveProblem::NotDifferentiable)),
/// and non-finite results.
#[allow(clippy::too_many_arguments)]
pub fn drive_force_derivatives<S, G, E, const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    jac: &mut JacobianData<S, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    elements: &E,
    w: &[S],
    out: &mut DriveDerivatives<S, NV>,
) -> Result<()>
where
    S: Scalar,
    G: PointGeometry + DerivativeSpace,
    E: ForceElement<S, G, NB, NV> + ?Sized,
{
    check_finite(w, Quantity::DriveInput)?;
    joint_jacobians_time_variation(model, data, jac, q, v)?;
    out.clear();
    let state = DriveDerivativeState {
        data,
        columns: &jac.j,
        topology: model.topology(),
        v,
    };
    elements.add_state_derivatives(&state, w, out)?;
    check_result(&out.tau, Quantity::Torque)?;
    check_result(out.dtau_dq.as_flattened(), Quantity::Derivative)?;
    check_result(out.dtau_dv.as_flattened(), Quantity::Derivative)
}

/// Forward dynamics with drives and their total derivatives:
/// `q̈ = FD(q, v, τ + Q(q, v, w))` in `data.ddq`, `dq̈/dq` in
/// `deriv.ddq_dq`, `dq̈/dv` in `deriv.ddq_dv` (each `∂FD/∂x + M⁻¹ ∂Q/∂x`),
/// `M⁻¹` in `deriv.minv`, and the drives' `Q` and derivatives in `drive`.
/// (`∂q̈/∂w` is the sensitivity of [`crate::sensitivity`].)
///
/// # Errors
/// As [`drive_force_derivatives`] and [`aba_derivatives`].
#[allow(clippy::too_many_arguments)]
pub fn aba_derivatives_with_drives<S, G, E, const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    deriv: &mut DerivativeData<S, NB, NV, G>,
    jac: &mut JacobianData<S, NV, G>,
    drive: &mut DriveDerivatives<S, NV>,
    q: &[S; NQ],
    v: &[S; NV],
    tau: &[S; NV],
    elements: &E,
    w: &[S],
) -> Result<()>
where
    S: Scalar,
    G: PointGeometry + DerivativeSpace,
    E: ForceElement<S, G, NB, NV> + ?Sized,
{
    drive_force_derivatives(model, data, jac, q, v, elements, w, drive)?;
    let total: [S; NV] = core::array::from_fn(|k| tau[k] + drive.tau[k]);
    aba_derivatives(model, data, deriv, q, v, &total, None)?;
    for r in 0..NV {
        for c in 0..NV {
            let (mut dq, mut dv) = (S::ZERO, S::ZERO);
            for k in 0..NV {
                dq += deriv.minv[r][k] * drive.dtau_dq[k][c];
                dv += deriv.minv[r][k] * drive.dtau_dv[k][c];
            }
            deriv.ddq_dq[r][c] += dq;
            deriv.ddq_dv[r][c] += dv;
        }
    }
    check_result(deriv.ddq_dq.as_flattened(), Quantity::Derivative)?;
    check_result(deriv.ddq_dv.as_flattened(), Quantity::Derivative)
}
