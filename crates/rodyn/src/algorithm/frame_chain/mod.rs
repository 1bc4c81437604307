//! One frame's kinematics straight from the configuration, along its own
//! chain: its placement `ᵒMf`, its Jacobian in each [`ReferenceFrame`]
//! and, given `v`, its velocity and `J̇ v` (Pinocchio's
//! `computeFrameJacobian`, and `getFrameJacobianTimeVariation` times `v`),
//! and the same for a set of frames (a quadruped's feet) that share the
//! joints above them.
//!
//! A frame on body b moves with the joints of b's support path only, the
//! bodies from the root to b ([`SupportPath`], Featherstone's κ⁻¹ path;
//! the model's topology gives it). These functions walk that path and
//! nothing else: on a branched robot (a leg of a quadruped, an arm of a
//! humanoid) they skip every other limb, which
//! [`joint_jacobians`](super::jacobian::joint_jacobians) followed by
//! [`frame_jacobian`](super::jacobian::frame_jacobian) would form.
//!
//! Along the path (Featherstone §3.4 and §4.4):
//!
//! * the poses `ᵒMᵢ = ᵒM_λ ˡⁱMᵢ`, then the frame's `ᵒMf = ᵒM_b ᵇMf`;
//! * the world columns `ᵒJₖ = ᵒXᵢ Sₖ` of each body's joint, moved into the
//!   reference frame: unchanged in [`World`](ReferenceFrame::World) (axes
//!   and origin of the world), by `ᶠX_o` in [`Local`](ReferenceFrame::Local)
//!   (the frame's axes at its origin), by the translation to the frame's
//!   origin in [`LocalWorldAligned`](ReferenceFrame::LocalWorldAligned)
//!   (the world's axes at the frame's origin). Columns of joints off the
//!   path are zero.
//! * with `v`: each body's velocity `vᵢ = ⁱX_λ v_λ + Sᵢ q̇ᵢ` and its
//!   acceleration at `q̈ = 0`, `aᵢ = ⁱX_λ a_λ + vᵢ × Sᵢ q̇ᵢ`, in its own
//!   frame. At `q̈ = 0` the acceleration is `J̇ v`: the frame's spatial
//!   acceleration in [`World`](ReferenceFrame::World) and
//!   [`Local`](ReferenceFrame::Local), and in
//!   [`LocalWorldAligned`](ReferenceFrame::LocalWorldAligned) the classical
//!   one, `a + (0, ω × ṗ)` (the origin's acceleration `p̈` and `ω̇`), since
//!   there the reference frame itself moves with the origin's velocity `ṗ`.
//!
//! The results are those of `joint_jacobians` + `frame_jacobian` (and of
//! `frame_jacobian_time_variation` times `v`) to rounding; the tests hold
//! them to 1e-14 in `f64`. [`plain`] has the same functions in the book's
//! form, one column at a time, for reading and for the tests; the
//! functions here form the path's angles' sines and cosines two at a time
//! (on hosts, where their dependent chains then overlap; a path through
//! every body, on hosts, takes the order of
//! [`joint_jacobians`](super::jacobian::joint_jacobians)' poses), carry the
//! parent's pose in registers, read a revolute column off the pose's
//! rotation, and move the columns with one loop per reference frame (in
//! LOCAL_WORLD_ALIGNED a shift without the identity rotation,
//! [`FrameSpace::shift_motion`]).
//!
//! A [`FrameChain`] is a frame with its support path. Found once (it is
//! `const`, so a frame known when compiling, like the frame constants of
//! a model compiled by `rodyn-model`, keeps its path in a constant), it
//! spares each call the walk up the parents.
//!
//! ```
//! use rodyn::algorithm::frame_chain::{frame_jacobian_from_q, FrameChain, chain_jacobian};
//! use rodyn::algorithm::frames::ReferenceFrame;
//! use rodyn::prelude::*;
//! use rodyn::Frame;
//!
//! // A two-link arm about z, links 1 m; a tool 1 m beyond the second joint.
//! const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(0.5, 0.0, 0.0));
//! const ARM: Model<f64, 2, 2, 2> = Model::new(
//!     [None, Some(0)],
//!     [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
//!     [Transform::IDENTITY, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))],
//!     [LINK, LINK],
//!     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
//! );
//! const TOOL: Frame<f64> = Frame::new(1, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0)));
//! let (q1, q2) = (0.3, -0.6);
//! let mut j = [Motion::ZERO; 2];
//! let o_m_tool = frame_jacobian_from_q(&ARM, &[q1, q2], &TOOL, ReferenceFrame::LocalWorldAligned, &mut j)?;
//! // The tip at (cos q1 + cos(q1 + q2), sin q1 + sin(q1 + q2)); the
//! // second joint moves it by (-sin(q1 + q2), cos(q1 + q2)) per rad.
//! assert!((o_m_tool.trans.x - (q1.cos() + (q1 + q2).cos())).abs() < 1e-12);
//! assert!((j[1].lin.x + (q1 + q2).sin()).abs() < 1e-12);
//! // The same with the path found when compiling.
//! const TOOL_CHAIN: FrameChain<f64, 2> = FrameChain::new(&ARM, TOOL).unwrap();
//! let mut again = [Motion::ZERO; 2];
//! chain_jacobian(&ARM, &[q1, q2], &TOOL_CHAIN, ReferenceFrame::LocalWorldAligned, &mut again)?;
//! assert_eq!(again, j);
//! # Ok::<(), rodyn::Error>(())
//! ```

pub mod plain;
pub(crate) mod union;

use super::common::{joint_configuration, joint_rates, ANGLES_FIRST};
use super::frames::{zero_motion, FrameSpace, ReferenceFrame};
use crate::data::Data;
use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::joint::JointModel;
use crate::model::Model;
use crate::space::{MotionVector, RigidTransform, Space, VectorOps};
use crate::spatial::Spatial;
use crate::topology::SupportPath;
use crate::tuning::TURNED_POSES;
use crate::Scalar;

/// A frame and the support path of its body (see the [module](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameChain<S: Scalar, const NB: usize, G: Space = Spatial> {
    frame: Frame<S, G>,
    path: SupportPath<NB>,
}

impl<S: Scalar, const NB: usize, G: Space> FrameChain<S, NB, G> {
    /// `frame` with its body's support path in `model`; `None` when the
    /// body is not one of the model's. `const`: a frame known when
    /// compiling keeps its path in a constant. The chain belongs to this
    /// model: with another one's, the results are meaningless (never out
    /// of bounds).
    #[must_use]
    pub const fn new<const NQ: usize, const NV: usize>(
        model: &Model<S, NB, NQ, NV, G>,
        frame: Frame<S, G>,
    ) -> Option<Self> {
        match model.topology().support_path(frame.body) {
            Some(path) => Some(Self { frame, path }),
            None => None,
        }
    }

    /// [`Self::new`], with an error that names the body.
    ///
    /// # Errors
    /// [`Error::FrameBodyOutOfRange`] when `frame.body` is not below `NB`.
    pub fn try_new<const NQ: usize, const NV: usize>(
        model: &Model<S, NB, NQ, NV, G>,
        frame: &Frame<S, G>,
    ) -> Result<Self> {
        Self::new(model, *frame).ok_or(Error::FrameBodyOutOfRange { body: frame.body })
    }

    /// The frame.
    #[must_use]
    pub const fn frame(&self) -> &Frame<S, G> {
        &self.frame
    }

    /// Its body's support path, root first.
    #[must_use]
    pub const fn path(&self) -> &SupportPath<NB> {
        &self.path
    }
}

/// A frame's placement and motion at `(q, v)`, in the reference frame
/// asked for, beside its Jacobian ([`chain_kinematics`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameMotion<S: Scalar, G: Space = Spatial> {
    /// `ᵒMf`, world from frame.
    pub placement: G::Transform<S>,
    /// `J v`: the frame's spatial velocity (rad/s, m/s).
    pub velocity: G::Motion<S>,
    /// `J̇ v`: its acceleration at zero joint accelerations (rad/s²,
    /// m/s²; the classical acceleration in
    /// [`LocalWorldAligned`](ReferenceFrame::LocalWorldAligned), see the
    /// [module](self)).
    pub dj_v: G::Motion<S>,
}

/// The Jacobian of `frame` at `q` in `reference` into `jacobian` (NV
/// columns, zero off the frame's path; as
/// [`frame_jacobian`](super::jacobian::frame_jacobian) after
/// [`joint_jacobians`](super::jacobian::joint_jacobians)), walking only
/// the joints that move the frame; returns the frame's placement `ᵒMf`.
/// [`chain_jacobian`] with the path found on each call.
///
/// # Errors
/// [`Error::FrameBodyOutOfRange`] when `frame.body` is not below `NB`;
/// otherwise as [`Model::check_configuration`].
pub fn frame_jacobian_from_q<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
    frame: &Frame<S, G>,
    reference: ReferenceFrame,
    jacobian: &mut [G::Motion<S>; NV],
) -> Result<G::Transform<S>> {
    chain_jacobian(
        model,
        q,
        &FrameChain::try_new(model, frame)?,
        reference,
        jacobian,
    )
}

/// [`frame_jacobian_from_q`] for a frame whose path is known
/// ([`FrameChain`]).
///
/// # Errors
/// As [`Model::check_configuration`].
pub fn chain_jacobian<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
    chain: &FrameChain<S, NB, G>,
    reference: ReferenceFrame,
    jacobian: &mut [G::Motion<S>; NV],
) -> Result<G::Transform<S>> {
    model.check_configuration(q)?;
    let o_m_b = world_columns_along(model, q, &chain.path, jacobian);
    let o_m_f = checked_placement(o_m_b.compose(&chain.frame.placement), &chain.frame)?;
    express_path_columns(model, &chain.path, &o_m_f, reference, jacobian);
    Ok(o_m_f)
}

/// `ᵒMf` when it is finite. One test of the pose covers a NaN or infinite
/// frame placement (a [`Frame`] is plain data, checked by nothing when it
/// was made), as [`frame_placement`](super::frames::frame_placement) does.
fn checked_placement<S: Scalar, G: Space>(
    o_m_f: G::Transform<S>,
    frame: &Frame<S, G>,
) -> Result<G::Transform<S>> {
    if o_m_f.is_finite() {
        Ok(o_m_f)
    } else {
        Err(super::frames::frame_error(frame))
    }
}

/// The Jacobian of `frame` at `q` in `reference` (as
/// [`frame_jacobian_from_q`]) and, at `(q, v)`, its velocity `J v` and
/// `J̇ v` in the same reference frame (the latter as
/// [`frame_jacobian_time_variation`](super::jacobian::frame_jacobian_time_variation)
/// times `v`), walking only the joints that move the frame.
///
/// # Errors
/// [`Error::FrameBodyOutOfRange`] when `frame.body` is not below `NB`;
/// otherwise as [`Model::check_configuration`], or
/// [`Error::NonFinite`] for a non-finite `v`.
pub fn frame_kinematics_from_q<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    frame: &Frame<S, G>,
    reference: ReferenceFrame,
    jacobian: &mut [G::Motion<S>; NV],
) -> Result<FrameMotion<S, G>> {
    chain_kinematics(
        model,
        q,
        v,
        &FrameChain::try_new(model, frame)?,
        reference,
        jacobian,
    )
}

/// [`frame_kinematics_from_q`] for a frame whose path is known.
///
/// # Errors
/// As [`Model::check_configuration`], or [`Error::NonFinite`] for a
/// non-finite `v`.
pub fn chain_kinematics<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    chain: &FrameChain<S, NB, G>,
    reference: ReferenceFrame,
    jacobian: &mut [G::Motion<S>; NV],
) -> Result<FrameMotion<S, G>> {
    super::common::check_state(model, q, Some(v))?;
    let o_m_b = world_columns_along(model, q, &chain.path, jacobian);
    // The body's velocity and acceleration at q̈ = 0, in its own frame:
    // the velocity pass along the path, from the joint transforms again
    // (cheaper than keeping them: a path's transforms are a few, each
    // formed from a sine and a cosine).
    let (mut v_b, mut a_b) = (zero_motion::<S, G>(), zero_motion::<S, G>());
    for i in chain.path.iter() {
        let li_m_i = super::common::body_transform(model, i, q);
        let (v_i, c_i) = model
            .joint(i)
            .velocity_and_bias(&li_m_i.act_inv_motion(&v_b), joint_rates(model, i, v));
        a_b = li_m_i.act_inv_motion(&a_b) + c_i;
        v_b = v_i;
    }
    let placement = &chain.frame.placement;
    let o_m_f = checked_placement(o_m_b.compose(placement), &chain.frame)?;
    let (v_f, a_f) = (
        placement.act_inv_motion(&v_b),
        placement.act_inv_motion(&a_b),
    );
    let (velocity, dj_v) = match reference {
        ReferenceFrame::Local => (v_f, a_f),
        ReferenceFrame::World => (o_m_f.act_motion(&v_f), o_m_f.act_motion(&a_f)),
        ReferenceFrame::LocalWorldAligned => {
            // The frame's axes turned to the world's, origin kept.
            let turn = G::translation_only(&o_m_f).inverse().compose(&o_m_f);
            let (velocity, a) = (turn.act_motion(&v_f), turn.act_motion(&a_f));
            // (ω, ṗ) × (0, ṗ) = (0, ω × ṗ).
            (
                velocity,
                a + velocity.cross_motion(&G::linear_part(&velocity)),
            )
        }
    };
    // One test of the sum: a velocity near the square root of the largest
    // float overflows `J̇ v` (the velocity's products) though q, v and the
    // pose are finite.
    if !(velocity + dj_v).is_finite() {
        return Err(super::frames::frame_error(&chain.frame));
    }
    express_path_columns(model, &chain.path, &o_m_f, reference, jacobian);
    Ok(FrameMotion {
        placement: o_m_f,
        velocity,
        dj_v,
    })
}

/// The Jacobians of several frames at `q` in `reference`, one into each
/// of `jacobians` (as [`chain_jacobian`] for each), forming the joints
/// their paths share (a floating base, a trunk) once; returns the frames'
/// placements. Leaves in `data.o_m_i` the poses of the bodies on the
/// paths (the others untouched).
///
/// # Errors
/// As [`Model::check_configuration`].
pub fn chains_jacobians<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const N: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    chains: &[FrameChain<S, NB, G>; N],
    reference: ReferenceFrame,
    jacobians: &mut [[G::Motion<S>; NV]; N],
) -> Result<[G::Transform<S>; N]> {
    model.check_configuration(q)?;
    let Some((last, others)) = jacobians.split_last_mut() else {
        // No frames.
        return Ok(core::array::from_fn(|_| {
            <G::Transform<S> as RigidTransform<S>>::IDENTITY
        }));
    };
    // Every world column of the paths' union, once, into the last
    // Jacobian (the coordinates of different bodies do not overlap).
    let on_paths = union::bodies_on_paths(chains);
    union::union_world_columns(model, data, q, &on_paths, last);
    let t = model.topology();
    let placements: [G::Transform<S>; N] = core::array::from_fn(|f| {
        let chain = &chains[f];
        data.o_m_i[chain.path.body()].compose(&chain.frame.placement)
    });
    for (o_m_f, chain) in placements.iter().zip(chains) {
        checked_placement(*o_m_f, &chain.frame)?;
    }
    // Each other frame's columns moved out of the shared world columns.
    for ((chain, out), o_m_f) in chains.iter().zip(others.iter_mut()).zip(&placements) {
        *out = [zero_motion::<S, G>(); NV];
        for i in chain.path.iter() {
            let range = t.velocity_coordinates(i);
            express_columns::<S, G>(o_m_f, reference, &last[range.clone()], &mut out[range]);
        }
    }
    // The last frame's in place, and the coordinates off its path zeroed.
    if let (Some(chain), Some(o_m_f)) = (chains.last(), placements.last()) {
        let mut on_last = [false; NB];
        for i in chain.path.iter() {
            on_last[i] = true;
        }
        for i in 0..NB {
            let range = t.velocity_coordinates(i);
            if on_last[i] {
                move_columns::<S, G>(o_m_f, reference, &mut last[range]);
            } else {
                last[range].fill(zero_motion::<S, G>());
            }
        }
    }
    Ok(placements)
}

/// The world columns `ᵒXᵢ Sₖ` of the bodies on `path` into `jacobian`
/// (the others zero), and the pose of the path's last body.
///
/// Out of order ([`ANGLES_FIRST`]) the path goes two bodies at a time,
/// their angles' sines and cosines formed together: each is a long chain
/// of dependent operations, which the other's overlaps (alone, the pose
/// products beside it do not cover it); a path through every body takes
/// the joint Jacobians' order instead ([`TURNED_POSES`]). In order, one
/// body after another.
#[inline(always)]
fn world_columns_along<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
    path: &SupportPath<NB>,
    jacobian: &mut [G::Motion<S>; NV],
) -> G::Transform<S> {
    *jacobian = [zero_motion::<S, G>(); NV];
    let t = model.topology();
    let mut o_m_i = <G::Transform<S> as RigidTransform<S>>::IDENTITY;
    if TURNED_POSES && path.len() == NB {
        // A path through every body (a serial chain; parents come first,
        // so it is 0, 1, …, NB − 1): the all-joints path's order, every
        // joint transform first and then the poses with the quarter-turn
        // products, which out of order have the registers to themselves.
        let sin_cos = super::common::JointSinCos::at(model, q);
        let mut li_m_i = [<G::Transform<S> as RigidTransform<S>>::IDENTITY; NB];
        for (i, x) in li_m_i.iter_mut().enumerate() {
            *x = super::common::body_transform_with(model, i, q, sin_cos.formed());
        }
        for (i, x) in li_m_i.iter().enumerate() {
            o_m_i = if i == 0 {
                *x
            } else {
                G::then_turned_joint(&o_m_i, x, model.joint(i))
            };
            let joint = model.joint(i);
            let (iv, nv) = t.velocity_range(i);
            for (c, column) in jacobian[iv..iv + nv].iter_mut().enumerate() {
                *column = G::act_subspace_column(&o_m_i, joint, c);
            }
        }
        return o_m_i;
    }
    let mut step = |k: usize, i: usize, li_m_i: &G::Transform<S>, o_m_i: &mut G::Transform<S>| {
        // The path's first body hangs on the world.
        *o_m_i = if k == 0 {
            *li_m_i
        } else {
            G::then_joint(o_m_i, li_m_i, model.joint(i))
        };
        let joint = model.joint(i);
        let (iv, nv) = t.velocity_range(i);
        for (c, column) in jacobian[iv..iv + nv].iter_mut().enumerate() {
            *column = G::act_subspace_column(o_m_i, joint, c);
        }
    };
    if ANGLES_FIRST {
        let angle = |b: Option<usize>| {
            b.and_then(|i| model.joint(i).angle(joint_configuration(model, i, q)))
                .unwrap_or(S::ZERO)
        };
        for k in (0..path.len()).step_by(2) {
            let pair = [path.get(k), path.get(k + 1)];
            let (sin, cos) = S::sin_cos_array(&pair.map(angle));
            for (c, body) in pair.into_iter().enumerate() {
                let Some(i) = body else { break };
                let li_m_i = model.joint(i).placed_transform_from_sin_cos(
                    model.placement(i),
                    joint_configuration(model, i, q),
                    (sin[c], cos[c]),
                );
                step(k + c, i, &li_m_i, &mut o_m_i);
            }
        }
        return o_m_i;
    }
    for (k, i) in path.iter().enumerate() {
        let li_m_i = super::common::body_transform(model, i, q);
        step(k, i, &li_m_i, &mut o_m_i);
    }
    o_m_i
}

/// The world columns of `path`'s bodies in `jacobian`, moved in place
/// into `reference` at the frame whose pose is `o_m_f`.
#[inline(always)]
fn express_path_columns<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    path: &SupportPath<NB>,
    o_m_f: &G::Transform<S>,
    reference: ReferenceFrame,
    jacobian: &mut [G::Motion<S>; NV],
) {
    if reference == ReferenceFrame::World {
        return;
    }
    let t = model.topology();
    for i in path.iter() {
        move_columns::<S, G>(o_m_f, reference, &mut jacobian[t.velocity_coordinates(i)]);
    }
}

/// World columns moved in place into `reference` at the frame `o_m_f`.
#[inline(always)]
fn move_columns<S: Scalar, G: FrameSpace>(
    o_m_f: &G::Transform<S>,
    reference: ReferenceFrame,
    columns: &mut [G::Motion<S>],
) {
    match reference {
        ReferenceFrame::World => {}
        ReferenceFrame::Local => columns
            .iter_mut()
            .for_each(|c| *c = o_m_f.act_inv_motion(c)),
        ReferenceFrame::LocalWorldAligned => {
            let p = o_m_f.translation();
            columns.iter_mut().for_each(|c| *c = G::shift_motion(c, &p));
        }
    }
}

/// World columns `from` moved into `reference` at the frame `o_m_f`, into
/// `to` (the shorter's length).
#[inline(always)]
fn express_columns<S: Scalar, G: FrameSpace>(
    o_m_f: &G::Transform<S>,
    reference: ReferenceFrame,
    from: &[G::Motion<S>],
    to: &mut [G::Motion<S>],
) {
    let pairs = to.iter_mut().zip(from);
    match reference {
        ReferenceFrame::World => pairs.for_each(|(t, f)| *t = *f),
        ReferenceFrame::Local => pairs.for_each(|(t, f)| *t = o_m_f.act_inv_motion(f)),
        ReferenceFrame::LocalWorldAligned => {
            let p = o_m_f.translation();
            pairs.for_each(|(t, f)| *t = G::shift_motion(f, &p));
        }
    }
}
