//! Jacobians: every joint's motion-subspace columns in the world, in one
//! pass, and the Jacobian of any frame in each [`ReferenceFrame`]
//! (Pinocchio's `computeJointJacobians`, `getFrameJacobian`,
//! `computeJointJacobiansTimeVariation`).
//!
//! Column k of the joint Jacobian is `ᵒX_i Sₖ`, joint i's k-th motion
//! subspace column in the world (Featherstone §4.4, the world-frame form of
//! `J = [... ⁱX_j S_j ...]`). The Jacobian of a frame on body b has the
//! columns of b's supporting joints only; the others are zero. Its time
//! derivative in the world is `ᵒJ̇ₖ = ᵒvᵢ × ᵒJₖ`, `ᵒvᵢ` body i's velocity in
//! the world (the columns move with their bodies).
//!
//! Results are columns of motion vectors (rodyn's order, angular first):
//! `[G::Motion<S>; NV]`. [`to_linear_first`] turns a 3-D one into the 6×NV
//! array, linear rows first, that Pinocchio returns.
//!
//! ```
//! use rodyn::prelude::*;
//! use rodyn::algorithm::frames::{frame_velocity, ReferenceFrame};
//! use rodyn::algorithm::jacobian::{frame_jacobian, joint_jacobians, to_linear_first, JacobianData};
//! use rodyn::algorithm::kinematics::forward_kinematics_velocity;
//! use rodyn::Frame;
//!
//! // A two-link arm about z, links 1 m; a tool 0.5 m beyond the second joint.
//! const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(0.5, 0.0, 0.0));
//! const ARM: Model<f64, 2, 2, 2> = Model::new(
//!     [None, Some(0)],
//!     [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
//!     [Transform::IDENTITY, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))],
//!     [LINK, LINK],
//!     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
//! );
//! let tool = Frame::new(1, Transform::from_translation(Vec3::new(0.5, 0.0, 0.0)));
//! let (mut data, mut jac) = (Data::new(), JacobianData::new());
//! let (q, v) = ([0.3, -0.6], [1.0, 2.0]);
//! joint_jacobians(&ARM, &mut data, &mut jac, &q)?;
//! let mut columns = [Motion::ZERO; 2];
//! frame_jacobian(&ARM, &data, &jac, &tool, ReferenceFrame::LocalWorldAligned, &mut columns)?;
//! let j: [[f64; 2]; 6] = to_linear_first(&columns); // rows: vx vy vz wx wy wz
//! // The tool's velocity is J v.
//! forward_kinematics_velocity(&ARM, &mut data, &q, &v)?;
//! let velocity = frame_velocity(&data, &tool, ReferenceFrame::LocalWorldAligned)?;
//! let vx = j[0][0] * v[0] + j[0][1] * v[1];
//! assert!((vx - velocity.lin.x).abs() < 1e-12);
//! # Ok::<(), rodyn::Error>(())
//! ```

use super::common::{pose_step, poses, JointSinCos};
use super::frames::{
    express_world_motion, frame_placement, frame_velocity, zero_motion, FrameSpace, ReferenceFrame,
};
use super::kinematics::forward_kinematics_velocity;
use crate::data::Data;
use crate::error::{Error, Quantity, Result};
use crate::frame::Frame;
use crate::model::{check_finite, Model};
use crate::space::{MotionVector, RigidTransform, Space, VectorOps};
use crate::spatial::{Motion, Spatial};
use crate::tuning::TURNED_POSES;
use crate::Scalar;

/// The joint Jacobians' workspace: NV columns in the world, and their time
/// derivatives. Its own type so that a firmware without Jacobians pays no
/// RAM for them.
#[derive(Clone, Debug)]
pub struct JacobianData<S: Scalar, const NV: usize, G: Space = Spatial> {
    /// `ᵒJₖ = ᵒX_i Sₖ` for every coordinate k of body i: world axes, at the
    /// world's origin (rad/s and m/s per unit rate).
    pub j: [G::Motion<S>; NV],
    /// `ᵒJ̇ₖ = ᵒvᵢ × ᵒJₖ`, same frame (per second).
    pub dj: [G::Motion<S>; NV],
}

impl<S: Scalar, const NV: usize, G: Space> JacobianData<S, NV, G> {
    /// Zero columns; `const`, so it can initialise a `static`.
    #[must_use]
    pub const fn new() -> Self {
        Self {
            j: [<G::Motion<S> as VectorOps<S>>::ZERO; NV],
            dj: [<G::Motion<S> as VectorOps<S>>::ZERO; NV],
        }
    }
}

impl<S: Scalar, const NV: usize, G: Space> Default for JacobianData<S, NV, G> {
    fn default() -> Self {
        Self::new()
    }
}

/// All joint Jacobians at configuration `q` (NQ): `jac.j` (NV world
/// columns). Runs [`forward_kinematics`](super::kinematics::forward_kinematics); leaves valid `data.li_m_i`,
/// `data.o_m_i` and `jac.j`; `jac.dj` is stale.
///
/// # Errors
/// As [`forward_kinematics`](super::kinematics::forward_kinematics).
pub fn joint_jacobians<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    jac: &mut JacobianData<S, NV, G>,
    q: &[S; NQ],
) -> Result<()> {
    model.check_configuration(q)?;
    let t = model.topology();
    if TURNED_POSES {
        // Out of order, the centroidal map's poses (the joint transforms
        // first, then the chain with the quarter-turn products), then the
        // columns from the stored poses.
        poses(model, data, q);
        for i in 0..NB {
            let joint = model.joint(i);
            let (iv, nv) = t.velocity_range(i);
            for (k, column) in jac.j[iv..iv + nv].iter_mut().enumerate() {
                *column = G::act_subspace_column(&data.o_m_i[i], joint, k);
            }
        }
        return Ok(());
    }
    let sin_cos = JointSinCos::at(model, q);
    let mut o_m_i = <G::Transform<S> as RigidTransform<S>>::IDENTITY;
    for i in 0..NB {
        o_m_i = pose_step(model, data, i, q, sin_cos.formed(), Some(&o_m_i));
        let joint = model.joint(i);
        let (iv, nv) = t.velocity_range(i);
        for (k, column) in jac.j[iv..iv + nv].iter_mut().enumerate() {
            *column = G::act_subspace_column(&o_m_i, joint, k);
        }
    }
    Ok(())
}

/// [`joint_jacobians`] from the joint transforms already in `data.li_m_i`
/// (left by RNEA or ABA at the same configuration): the world poses by
/// composition only, without forming the joints' transforms again, and
/// the columns of the bodies in `columns_of` only (the others stale).
/// Leaves valid `data.o_m_i` and those columns of `jac.j`.
pub(crate) fn joint_jacobians_from_transforms<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    jac: &mut JacobianData<S, NV, G>,
    columns_of: &[bool; NB],
) {
    let t = model.topology();
    for i in 0..NB {
        let o_m_i = match t.parent(i) {
            Some(p) => G::then_joint(&data.o_m_i[p], &data.li_m_i[i], model.joint(i)),
            None => data.li_m_i[i],
        };
        data.o_m_i[i] = o_m_i;
        if !columns_of[i] {
            continue;
        }
        let joint = model.joint(i);
        let (iv, nv) = t.velocity_range(i);
        for (k, column) in jac.j[iv..iv + nv].iter_mut().enumerate() {
            *column = G::act_subspace_column(&o_m_i, joint, k);
        }
    }
}

/// All joint Jacobians and their time derivatives at `(q, v)`: `jac.j` and
/// `jac.dj` (world columns). Runs
/// [`forward_kinematics_velocity`]; leaves valid `data.li_m_i`,
/// `data.o_m_i`, `data.v`, `data.c`, `jac.j`, `jac.dj`.
///
/// # Errors
/// As [`forward_kinematics_velocity`].
pub fn joint_jacobians_time_variation<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    jac: &mut JacobianData<S, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
) -> Result<()> {
    forward_kinematics_velocity(model, data, q, v)?;
    columns_pass(model, data, jac);
    let t = model.topology();
    for i in 0..NB {
        let o_v = data.o_m_i[i].act_motion(&data.v[i]);
        for k in t.velocity_coordinates(i) {
            jac.dj[k] = o_v.cross_motion(&jac.j[k]);
        }
    }
    Ok(())
}

/// `ᵒJₖ = ᵒX_i Sₖ` from the poses in `data.o_m_i`.
fn columns_pass<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: FrameSpace>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    jac: &mut JacobianData<S, NV, G>,
) {
    let t = model.topology();
    for i in 0..NB {
        let joint = model.joint(i);
        let (iv, nv) = t.velocity_range(i);
        for (k, column) in jac.j[iv..iv + nv].iter_mut().enumerate() {
            *column = G::act_subspace_column(&data.o_m_i[i], joint, k);
        }
    }
}

/// Calls `f(k)` for every velocity coordinate k of the bodies that support
/// `body` (itself included), leaf to root.
#[inline]
fn for_each_supporting_coordinate<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    body: usize,
    mut f: impl FnMut(usize),
) {
    let t = model.topology();
    let mut b = Some(body);
    // Parents come before children, so the walk ends within NB steps.
    while let Some(i) = b {
        // `body` is the caller's; the parents are in range.
        if i >= NB {
            break;
        }
        for k in t.velocity_coordinates(i) {
            f(k);
        }
        b = t.parent(i);
    }
}

/// The Jacobian of `frame` in `reference` into `out` (NV columns): column k
/// maps coordinate k's rate to the frame's spatial velocity in `reference`
/// (see [`ReferenceFrame`]), so that `Σₖ out[k] vₖ` is
/// [`frame_velocity`]. Columns of joints
/// that do not support the frame's body are zero. A body's Jacobian is that
/// of a frame with the identity placement.
///
/// Reads `jac.j` and `data.o_m_i`, valid after [`joint_jacobians`] (or
/// [`joint_jacobians_time_variation`]); changes neither.
///
/// # Errors
/// [`Error::FrameBodyOutOfRange`] when
/// `frame.body` is not below `NB`; those of
/// [`frame_placement`] for a frame whose
/// placement is not finite.
pub fn frame_jacobian<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    jac: &JacobianData<S, NV, G>,
    frame: &Frame<S, G>,
    reference: ReferenceFrame,
    out: &mut [G::Motion<S>; NV],
) -> Result<()> {
    let o_m_f = frame_placement(data, frame)?;
    *out = [zero_motion::<S, G>(); NV];
    for_each_supporting_coordinate(model, frame.body, |k| {
        out[k] = express_world_motion::<S, G>(&o_m_f, &jac.j[k], reference);
    });
    Ok(())
}

/// The time derivative of [`frame_jacobian`]'s result in `reference`
/// (Pinocchio's `getFrameJacobianTimeVariation`), into `out` (NV columns,
/// per second), zero for joints that do not support the frame. In the
/// world it is `ᵒJ̇ₖ`; moved to a frame whose transform `ᶠX_o` changes as
/// `−(v_f ×) ᶠX_o` (`v_f` that frame's own velocity: the frame's spatial
/// velocity in [`Local`](ReferenceFrame::Local), the translation `(0, ṗ)`
/// in [`LocalWorldAligned`](ReferenceFrame::LocalWorldAligned)) it is
/// `ᶠX_o ᵒJ̇ₖ − v_f × ᶠJₖ`. For task-space control, the product `J̇ v` of
/// a frame's classical Jacobian is
/// [`frame_classical_acceleration`](super::frames::frame_classical_acceleration)
/// at zero joint acceleration.
///
/// Reads `jac.j`, `jac.dj`, `data.o_m_i` and `data.v`, valid after
/// [`joint_jacobians_time_variation`].
///
/// # Errors
/// [`Error::FrameBodyOutOfRange`] when
/// `frame.body` is not below `NB`; those of
/// [`frame_placement`] for a frame whose
/// placement is not finite.
pub fn frame_jacobian_time_variation<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    jac: &JacobianData<S, NV, G>,
    frame: &Frame<S, G>,
    reference: ReferenceFrame,
    out: &mut [G::Motion<S>; NV],
) -> Result<()> {
    let o_m_f = frame_placement(data, frame)?;
    let v_f = match reference {
        ReferenceFrame::World => zero_motion::<S, G>(),
        ReferenceFrame::Local => frame_velocity(data, frame, reference)?,
        ReferenceFrame::LocalWorldAligned => {
            G::linear_part(&frame_velocity(data, frame, reference)?)
        }
    };
    *out = [zero_motion::<S, G>(); NV];
    for_each_supporting_coordinate(model, frame.body, |k| {
        let dj = express_world_motion::<S, G>(&o_m_f, &jac.dj[k], reference);
        let j = express_world_motion::<S, G>(&o_m_f, &jac.j[k], reference);
        out[k] = dj - v_f.cross_motion(&j);
    });
    Ok(())
}

/// A 3-D Jacobian's columns as the 6×NV array Pinocchio returns: rows 0-2
/// linear, rows 3-5 angular.
///
/// A reordering without arithmetic: finite columns give finite entries
/// (whatever their size, 1e300 or subnormal), so it has nothing to report.
#[must_use]
pub fn to_linear_first<S: Scalar, const NV: usize>(columns: &[Motion<S>; NV]) -> [[S; NV]; 6] {
    let mut m = [[S::ZERO; NV]; 6];
    for (k, c) in columns.iter().enumerate() {
        let l = c.to_linear_first();
        for r in 0..6 {
            m[r][k] = l[r];
        }
    }
    m
}

/// `Σₖ columns[k] v[k]`: a Jacobian times joint rates (or, with `dj`, `J̇ v`).
///
/// # Errors
/// [`Error::NonFinite`] naming the first non-finite rate
/// (`Quantity::Velocity`) or column (`Quantity::Jacobian`);
/// [`Error::NonFiniteResult`] (`Quantity::Jacobian`) when finite inputs
/// overflow. One finiteness test of the product when all is well.
pub fn mul_rates<S: Scalar, const NV: usize, G: Space>(
    columns: &[G::Motion<S>; NV],
    v: &[S; NV],
) -> Result<G::Motion<S>> {
    let mut acc = zero_motion::<S, G>();
    for k in 0..NV {
        acc += columns[k] * v[k];
    }
    if !acc.is_finite() {
        check_finite(v, Quantity::Velocity)?;
        if let Some(k) = columns.iter().position(|c| !c.is_finite()) {
            return Err(Error::NonFinite {
                quantity: Quantity::Jacobian,
                index: k,
            });
        }
        return Err(Error::NonFiniteResult {
            quantity: Quantity::Jacobian,
            index: 0,
        });
    }
    Ok(acc)
}
