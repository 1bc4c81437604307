//! The composite-rigid-body algorithm for the mass matrix (Featherstone Table 6.2).
//!
//! | file            | what it is                                                        |
//! |-----------------|-------------------------------------------------------------------|
//! | [`textbook`]    | the book's algorithm as written, the oracle the tests hold the rest to |
//! | `mod.rs`        | the public entries, the choice of pass ([`CrbaPass`]), the steps   |
//! | `plan.rs`       | [`CrbaPlan`]: the turned frames, computed once per model          |
//! | `src/space/turned_frame.rs` | [`TurnedFrame`]: a body's frame turned by the quarter turns above it |
//! | `src/space/crba.rs` | [`CrbaSpace`]: the hooks CRBA needs from a geometry (beside [`Space`], which requires them) |
//! | `spatial.rs`, `planar.rs` | [`CrbaSpace`] for 3-D space and the plane               |
//! | `step.rs`       | [`TransformStep`]: a joint transform prepared to move many columns |
//! | `fused_body.rs` | one body's whole step fused: a joint about its own axis, a free-flying root |
//! | `local.rs`      | the default backward pass, in each body's (turned) frame          |
//! | `root_frame.rs` | the backward pass for long `f64` chains, in the root frame        |
//! | `triangle.rs`   | the mirror above the diagonal and the zeros between limbs         |
//!
//! The tuned passes compute what [`textbook::crba`] computes: the backward
//! pass from the leaves to the root, at body i its composite inertia `Iᶜᵢ`,
//! its columns `F = Iᶜᵢ Sₖ`, the entries `M[d][k] = Sₖᵀ F_d` against every
//! coordinate d of its subtree, then the subtree's columns and `Iᶜᵢ` moved to
//! the parent through `ˡⁱXᵢ`. They differ from the book in three ways, each
//! for speed and none for the result:
//! - a subtree's columns move up together, one step per body
//!   ([`CrbaSpace::step_forces`]); a revolute joint about a coordinate axis
//!   whose placement does not rotate (or turns about the same axis) moves
//!   them by mixing two components ([`CrbaSpace::joint_step`]), and the geometry
//!   may fuse a whole body's step ([`CrbaSpace::crba_axis_body`],
//!   [`CrbaSpace::crba_free_root`]);
//! - with a [`CrbaPlan`] ([`crba_planned`]), bodies behind quarter-turn
//!   placements (a URDF arm's) are expressed in frames turned by the
//!   quarter turns above them ([`TurnedFrame`]), where their joints turn
//!   about coordinate axes again; `ic` is left in those frames. Without
//!   one ([`crba`]) every body keeps its own frame;
//! - with the bodies numbered depth first (URDF order), a body's subtree
//!   holds a contiguous range of coordinates, so a column's rows are one
//!   slice; any other tree takes the same steps with a test of support
//!   per coordinate.
//!
//! Which backward pass runs is [`CrbaPass`], chosen by the caller of
//! [`crba_with`] or [`crba_planned_with`] or, for [`crba`] and
//! [`crba_planned`], by [`CrbaPass::default_for`]. Whether the
//! passes write the upper triangle and the zeros as they go or in separate
//! loops afterwards is the build's tuning profile
//! (`ENTRIES_IN_PASS`); `M` is the same either way.

mod fused_body;
mod local;
mod plan;
mod planar;
mod root_frame;
mod spatial;
mod step;
pub mod textbook;
mod triangle;

use crate::algorithm::common::{
    backward_force_pass_with, body_transform_with, check_state, forward_body, joint_configuration,
    JointSinCos, ANGLES_FIRST,
};
use crate::data::Data;
use crate::error::{Quantity, Result};
use crate::model::{check_result, Model};
pub use crate::space::crba::CrbaSpace;
pub use crate::space::turned_frame::{TurnedAxis, TurnedFrame};
use crate::space::{Space, VectorOps};
use crate::topology::Topology;
use crate::Scalar;
use local::backward_body;
pub use plan::CrbaPlan;
use plan::{BodyFrames, Unturned};
use root_frame::about_root;
pub use step::TransformStep;
use triangle::{clear_lower, mirror_lower};

// Whether the local backward pass writes `M`'s zeros and, for `crba`, its
// entries above the diagonal itself (the root-frame pass, for `crba`, the
// entries above the diagonal), instead of separate clear and mirror loops
// afterwards: a choice of the tuning profile.
use crate::tuning::ENTRIES_IN_PASS;

/// The backward pass that forms `M`. Both give the same matrix (to
/// rounding); they differ in cost and in `f32` accuracy.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CrbaPass {
    /// Columns kept in each body's (turned) frame and moved up one joint
    /// per body (`local.rs`). O(n·depth) column moves; every lever arm a
    /// link long, so `f32` keeps its accuracy. The default.
    Local,
    /// Columns and subspace columns moved once into the tree's root frame,
    /// each entry a dot product there (`root_frame.rs`). It repays its two
    /// general transforms per body only on long chains, and its entries are
    /// differences of terms that grow with the distance from the root:
    /// meant for `f64` (in `f32` long chains lose digits).
    RootFrame,
}

impl CrbaPass {
    /// Mean number of moving ancestors a coordinate's column walks past
    /// above which [`CrbaPass::RootFrame`] is the default (a chain of about
    /// 50 links; an arm or a legged robot never reaches it).
    pub const ROOT_FRAME_MIN_DEPTH: usize = 25;

    /// The pass [`crba`] takes: [`CrbaPass::RootFrame`] in a scalar of
    /// `f64` precision on trees whose mean support depth
    /// ([`TopologyTables::mean_support_depth`](crate::topology::TopologyTables::mean_support_depth)) is at least
    /// [`ROOT_FRAME_MIN_DEPTH`](Self::ROOT_FRAME_MIN_DEPTH), else
    /// [`CrbaPass::Local`]. The condition on `NV` follows from the depth
    /// and is known at compile time, so a smaller model's code carries no
    /// root-frame pass.
    #[inline(always)]
    pub fn default_for<S: Scalar, const NB: usize, const NV: usize>(t: &Topology<NB, NV>) -> Self {
        let depth = Self::ROOT_FRAME_MIN_DEPTH;
        if NV > 2 * depth && S::EPSILON < 1.0e-10 && t.mean_support_depth >= depth {
            Self::RootFrame
        } else {
            Self::Local
        }
    }
}

/// The joint-space mass matrix `M(q)` (symmetric, NV x NV), by the pass
/// [`CrbaPass::default_for`] chooses, every body in its own frame.
/// [`crba_planned`] gives the same matrix faster on models whose
/// placements are quarter turns (a URDF arm's).
///
/// Inputs: `q` (NQ). Returns `data.mass_matrix` with both triangles filled.
/// Leaves valid: `mass_matrix`, and `ic`, each body's composite inertia
/// (its own and its subtree's) in its own frame.
/// Reads and writes nothing else of `data`.
///
/// # Errors
/// An invalid configuration.
///
/// # Example
///
/// ```
/// use rodyn::algorithm::crba::crba;
/// # use rodyn::prelude::*;
/// // A 2 kg point mass 0.5 m from a pivot about z: M = m l².
/// const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
///     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
///     [Inertia::point_mass(2.0, Vec3::new(0.5, 0.0, 0.0))],
///     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// );
/// let mut data = Data::new();
/// let m = crba(&PENDULUM, &mut data, &[0.7])?;
/// assert!((m[0][0] - 0.5).abs() < 1e-15);
/// # Ok::<(), rodyn::Error>(())
/// ```
pub fn crba<'d, S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
) -> Result<&'d [[S; NV]; NV]> {
    let pass = CrbaPass::default_for::<S, NB, NV>(model.topology());
    mass_matrix(model, &Unturned(model), data, q, pass)
}

/// [`crba`] by the backward pass `pass`; same inputs, results and errors.
#[inline]
pub fn crba_with<'d, S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    pass: CrbaPass,
) -> Result<&'d [[S; NV]; NV]> {
    mass_matrix(model, &Unturned(model), data, q, pass)
}

/// [`crba`] in the frames of `plan`, which must be `model`'s
/// ([`CrbaPlan::is_for`], checked in debug builds): the same matrix, with
/// each joint behind quarter-turn placements stepped about a coordinate
/// axis. Leaves valid what [`crba`] leaves, `ic` in the plan's turned
/// frames ([`TurnedFrame::turn`](crate::algorithm::crba::TurnedFrame::turn) of
/// [`CrbaPlan::frame`]; the body's own frame at a root).
///
/// # Errors
/// As [`crba`].
#[inline]
pub fn crba_planned<'d, S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    plan: &CrbaPlan<S, NB, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
) -> Result<&'d [[S; NV]; NV]> {
    debug_assert!(plan.is_for(model), "a CRBA plan made for another model");
    let pass = CrbaPass::default_for::<S, NB, NV>(model.topology());
    if G::TURNS_FRAMES {
        mass_matrix(model, plan, data, q, pass)
    } else {
        mass_matrix(model, &Unturned(model), data, q, pass)
    }
}

/// [`crba_planned`] by the backward pass `pass`.
///
/// # Errors
/// As [`crba`].
#[inline]
pub fn crba_planned_with<
    'd,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    plan: &CrbaPlan<S, NB, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    pass: CrbaPass,
) -> Result<&'d [[S; NV]; NV]> {
    debug_assert!(plan.is_for(model), "a CRBA plan made for another model");
    if G::TURNS_FRAMES {
        mass_matrix(model, plan, data, q, pass)
    } else {
        mass_matrix(model, &Unturned(model), data, q, pass)
    }
}

/// The entries' common body: checks `q`, forms `M` by `pass` with the
/// bodies in `frames`, mirrors it and checks its diagonal.
#[inline]
fn mass_matrix<
    'd,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
    F: BodyFrames<S, NB, G>,
>(
    model: &Model<S, NB, NQ, NV, G>,
    frames: &F,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    pass: CrbaPass,
) -> Result<&'d [[S; NV]; NV]> {
    check_state(model, q, None)?;
    let upper_written = if ENTRIES_IN_PASS {
        mass_matrix_pass::<S, NB, NQ, NV, G, F, true>(model, frames, data, Some(q), pass)
    } else {
        mass_matrix_pass::<S, NB, NQ, NV, G, F, false>(model, frames, data, Some(q), pass);
        false
    };
    if !upper_written {
        mirror_lower(&mut data.mass_matrix);
    }
    // The diagonal holds every body's composite inertia: an overflow
    // anywhere in a subtree reaches it.
    let diagonal: [S; NV] = core::array::from_fn(|k| data.mass_matrix[k][k]);
    check_result(&diagonal, Quantity::MassMatrix)?;
    Ok(&data.mass_matrix)
}

/// [`crba`] without the check of `q` and without mirroring: leaves `M`'s
/// lower triangle (diagonal included) in `data.mass_matrix`; the entries
/// above the diagonal are not written. With `q` `None` it takes the joint
/// transforms from `data.li_m_i`, which must hold them for the
/// configuration (as RNEA leaves them) instead of computing them again.
#[inline(always)]
pub(crate) fn crba_lower<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: Option<&[S; NQ]>,
) {
    crba_lower_in(model, &Unturned(model), data, q);
}

/// [`crba_lower`] in the frames of `plan`.
#[inline(always)]
pub(crate) fn crba_lower_planned<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    plan: &CrbaPlan<S, NB, G>,
    data: &mut Data<S, NB, NV, G>,
    q: Option<&[S; NQ]>,
) {
    if G::TURNS_FRAMES {
        crba_lower_in(model, plan, data, q);
    } else {
        crba_lower_in(model, &Unturned(model), data, q);
    }
}

/// [`crba_lower`] with the bodies in `frames`.
#[inline(always)]
fn crba_lower_in<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
    F: BodyFrames<S, NB, G>,
>(
    model: &Model<S, NB, NQ, NV, G>,
    frames: &F,
    data: &mut Data<S, NB, NV, G>,
    q: Option<&[S; NQ]>,
) {
    let pass = CrbaPass::default_for::<S, NB, NV>(model.topology());
    mass_matrix_pass::<S, NB, NQ, NV, G, F, false>(model, frames, data, q, pass);
}

/// [`crba_lower`], which with `UPPER` writes the entries above the
/// diagonal too where it can: the root-frame pass, and the local pass on a
/// tree whose subtrees hold contiguous coordinates; each meets each entry
/// once while it is in a register. Returns whether it did.
#[inline]
fn mass_matrix_pass<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
    F: BodyFrames<S, NB, G>,
    const UPPER: bool,
>(
    model: &Model<S, NB, NQ, NV, G>,
    frames: &F,
    data: &mut Data<S, NB, NV, G>,
    q: Option<&[S; NQ]>,
    pass: CrbaPass,
) -> bool {
    let t = model.topology();
    for (i, ic) in data.ic.iter_mut().enumerate() {
        *ic = *frames.inertia(i);
    }
    let upper_written = if pass == CrbaPass::RootFrame {
        clear_lower(t, &mut data.mass_matrix, UPPER);
        // Its steps are formed in a pass of their own already.
        about_root::<S, NB, NQ, NV, G, UPPER>(model, frames, data, |li_m_i, i| {
            joint_step(model, frames, li_m_i, q, None, i)
        });
        UPPER
    } else {
        // Other trees take `clear_lower` (and `crba` the mirror afterwards).
        if !(ENTRIES_IN_PASS && t.subtrees_contiguous) {
            clear_lower(t, &mut data.mass_matrix, false);
        }
        let angles = q
            .filter(|_| ANGLES_FIRST)
            .map(|q| step_sin_cos(model, frames, q));
        let mut columns = [G::Force::<S>::ZERO; NV];
        for i in (0..NB).rev() {
            let sin_cos = angles.as_ref().map(|a| a.get(i));
            let step = joint_step(model, frames, &data.li_m_i, q, sin_cos, i);
            backward_body(
                model,
                frames.frame(i),
                data,
                i,
                step.as_ref(),
                &mut columns,
                UPPER,
            );
        }
        UPPER && ENTRIES_IN_PASS && t.subtrees_contiguous
    };
    add_armature(model, data);
    upper_written
}

/// The sines and cosines of each body's [`CrbaSpace::step_angle`].
#[inline(always)]
fn step_sin_cos<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
    F: BodyFrames<S, NB, G>,
>(
    model: &Model<S, NB, NQ, NV, G>,
    frames: &F,
    q: &[S; NQ],
) -> JointSinCos<S, NB> {
    JointSinCos::from_angles(|i| {
        let q = joint_configuration(model, i, q);
        G::step_angle(frames.frame(i), model.joint(i), q)
    })
}

/// Body i's step from its turned frame to its parent's, from `q` or, with
/// `q` `None`, from the joint transforms `li_m_i`; `None` at a root, whose
/// transform moves nothing. `sin_cos`: body i's entry of
/// [`step_sin_cos`], when formed.
#[inline(always)]
fn joint_step<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
    F: BodyFrames<S, NB, G>,
>(
    model: &Model<S, NB, NQ, NV, G>,
    frames: &F,
    li_m_i: &[G::Transform<S>; NB],
    q: Option<&[S; NQ]>,
    sin_cos: Option<(S, S)>,
    i: usize,
) -> Option<G::Step<S>> {
    let frame = frames.frame(i);
    model.parent(i).map(|_| match q {
        Some(q) => G::turned_joint_step(
            frame,
            model.joint(i),
            frames.placement(i),
            joint_configuration(model, i, q),
            sin_cos,
        ),
        None => G::turned_step(frame, &li_m_i[i], frames.placement(i)),
    })
}

/// Bias forces and `M`'s lower triangle in one pass over the bodies, for
/// [`Crba`](crate::algorithm::forward_dynamics::Crba): RNEA's forward pass
/// (`a = 0`), then its backward pass with CRBA's step for each body beside
/// its own, which reuse its joint transforms. Leaves `h` in `data.tau` and
/// what [`nonlinear_effects`](crate::algorithm::rnea::nonlinear_effects)
/// and [`crba_lower`] leave; checks nothing.
#[inline(always)]
pub(crate) fn bias_and_mass_lower<
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
) {
    bias_and_mass_lower_in(model, &Unturned(model), data, q, v, f_ext);
}

/// [`bias_and_mass_lower`] in the frames of `plan`.
#[inline(always)]
pub(crate) fn bias_and_mass_lower_planned<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    plan: &CrbaPlan<S, NB, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    f_ext: Option<&[G::Force<S>; NB]>,
) {
    if G::TURNS_FRAMES {
        bias_and_mass_lower_in(model, plan, data, q, v, f_ext);
    } else {
        bias_and_mass_lower_in(model, &Unturned(model), data, q, v, f_ext);
    }
}

/// [`bias_and_mass_lower`] with the bodies in `frames`.
#[inline]
fn bias_and_mass_lower_in<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
    F: BodyFrames<S, NB, G>,
>(
    model: &Model<S, NB, NQ, NV, G>,
    frames: &F,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    f_ext: Option<&[G::Force<S>; NB]>,
) {
    let t = model.topology();
    let minus_g = -*model.gravity();
    let sin_cos = JointSinCos::at(model, q);
    for i in 0..NB {
        let li_m_i = body_transform_with(model, i, q, sin_cos.formed());
        data.ic[i] = *frames.inertia(i);
        forward_body(model, data, i, li_m_i, v, None, f_ext, &minus_g);
    }
    if CrbaPass::default_for::<S, NB, NV>(t) == CrbaPass::RootFrame {
        clear_lower(t, &mut data.mass_matrix, false);
        backward_force_pass_with(model, data, None, |_, _| {});
        about_root::<S, NB, NQ, NV, G, false>(model, frames, data, |li_m_i, i| {
            joint_step(model, frames, li_m_i, None, None, i)
        });
    } else {
        if !(ENTRIES_IN_PASS && t.subtrees_contiguous) {
            clear_lower(t, &mut data.mass_matrix, false);
        }
        let mut columns = [G::Force::<S>::ZERO; NV];
        backward_force_pass_with(model, data, None, |data, i| {
            let step = joint_step(model, frames, &data.li_m_i, None, None, i);
            backward_body(
                model,
                frames.frame(i),
                data,
                i,
                step.as_ref(),
                &mut columns,
                false,
            );
        });
    }
    add_armature(model, data);
}

/// Rotor (armature) inertias, on the diagonal only.
#[inline]
fn add_armature<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
) {
    for (k, armature) in model.armature().iter().enumerate() {
        data.mass_matrix[k][k] += *armature;
    }
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::{
        bias_and_mass_lower, bias_and_mass_lower_planned, crba, crba_lower, crba_lower_planned,
        crba_planned, CrbaPass, CrbaPlan,
    };
    use crate::algorithm::common::body_transform;
    use crate::joint::{Axis, Joint};
    use crate::spatial::{AxisPermutation, Inertia, Mat3, Motion, Spatial, Sym3, Transform, Vec3};
    use crate::{Data, Model};

    const QUARTER_X: AxisPermutation =
        AxisPermutation::from_rows([[1, 0, 0], [0, 0, -1], [0, 1, 0]]);
    const QUARTER_Y: AxisPermutation =
        AxisPermutation::from_rows([[0, 0, 1], [0, 1, 0], [-1, 0, 0]]);
    const HALF_Z_THEN_X: AxisPermutation =
        AxisPermutation::from_rows([[-1, 0, 0], [0, 0, 1], [0, 1, 0]]);
    const CYCLE: AxisPermutation = AxisPermutation::from_rows([[0, 1, 0], [0, 0, 1], [1, 0, 0]]);

    /// A branched tree with joints about every coordinate axis behind
    /// quarter turns (reversing axes too), a tilted placement under a
    /// turned parent, a prismatic joint and a general axis.
    fn model() -> Model<f64, 7, 7, 7, Spatial> {
        let turned =
            |p: AxisPermutation, t: [f64; 3]| Transform::new(p.matrix(), Vec3::from_array(t));
        let tilted = Mat3::from_axis_angle(&Vec3::new(0.6, 0.0, 0.8), 0.4);
        let inertia = |k: f64| {
            Inertia::new(
                1.0 + k,
                Vec3::new(0.1 * k, -0.05, 0.02 * k),
                Sym3::new(0.3, 0.01 * k, -0.02, 0.4, 0.03, 0.5 + 0.1 * k),
            )
        };
        Model::new(
            [None, Some(0), Some(1), Some(2), Some(1), Some(4), Some(5)],
            [
                Joint::revolute(Axis::Z),
                Joint::revolute(Axis::Z),
                Joint::revolute(Axis::X),
                Joint::revolute(Axis::Y),
                Joint::revolute(Axis::Y),
                Joint::prismatic(Axis::X),
                Joint::revolute(Axis::Unit(Vec3::new(0.0, 0.6, 0.8))),
            ],
            [
                turned(QUARTER_Y, [0.0, 0.0, 0.3]),
                turned(QUARTER_X, [0.1, -0.2, 0.0]),
                turned(HALF_Z_THEN_X, [0.0, 0.3, 0.05]),
                turned(CYCLE, [0.2, 0.0, -0.1]),
                Transform::new(tilted, Vec3::new(0.0, 0.1, 0.2)),
                turned(QUARTER_X, [0.05, 0.0, 0.1]),
                turned(CYCLE, [0.0, 0.0, 0.15]),
            ],
            core::array::from_fn(|k| inertia(k as f64)),
            Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
        )
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-13 * (1.0 + a.abs().max(b.abs()))
    }

    #[test]
    fn turned_frames_give_the_unturned_mass_matrix_on_every_path() {
        let plain = model();
        let declared = CrbaPlan::<f64, 7>::from_turns(
            &plain,
            [
                Some(QUARTER_Y),
                Some(QUARTER_X),
                Some(HALF_Z_THEN_X),
                Some(CYCLE),
                None,
                Some(QUARTER_X),
                Some(CYCLE),
            ],
        );
        let recognised = CrbaPlan::new(&plain);
        assert_eq!(declared.frame(3), recognised.frame(3));
        assert!(declared.is_for(&plain) && recognised.is_for(&plain));
        assert!(CrbaPlan::unturned(&plain).is_for(&plain));
        // Bodies 1-3 turn; 4 (tilted), 5 (prismatic) and 6 (general axis) keep their frames.
        for (i, turned) in [
            (1, true),
            (2, true),
            (3, true),
            (4, false),
            (5, false),
            (6, false),
        ] {
            assert_eq!(recognised.frame(i).axis().is_some(), turned, "body {i}");
        }
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut random = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 6.0 - 3.0
        };
        let mut reference = Data::new();
        let mut data = Data::new();
        for _ in 0..crate::test_points(20, 3) {
            let q: [f64; 7] = core::array::from_fn(|_| random());
            let v: [f64; 7] = core::array::from_fn(|_| random());
            let expected = *crba(&plain, &mut reference, &q).unwrap();
            let model = &plain;
            for plan in [&declared, &recognised] {
                let lower = |m: &[[f64; 7]; 7], what: &str| {
                    for r in 0..7 {
                        for c in 0..=r {
                            let (a, b) = (m[r][c], expected[r][c]);
                            assert!(close(a, b), "{what}: M[{r}][{c}] {a} against {b}");
                        }
                    }
                };
                lower(crba_planned(model, plan, &mut data, &q).unwrap(), "crba");
                // From the joint transforms RNEA leaves (the Cortex-M's path).
                for i in 0..7 {
                    data.li_m_i[i] = body_transform(model, i, &q);
                }
                crba_lower_planned(model, plan, &mut data, None);
                lower(&data.mass_matrix, "from transforms");
                bias_and_mass_lower_planned(model, plan, &mut data, &q, &v, None);
                lower(&data.mass_matrix, "fused with the bias forces");
            }
        }
    }

    /// A 52-link chain, long enough in `f64` for the root-frame pass.
    fn long_chain() -> Model<f64, 52, 52, 52, Spatial> {
        long_tree(
            core::array::from_fn(|i| i.checked_sub(1)),
            Joint::revolute(Axis::X),
        )
    }

    /// A tree on `parents`, body 0 on `root`, the others on
    /// single-coordinate joints: about every axis behind quarter turns,
    /// tilted placements, a prismatic joint and a general axis.
    fn long_tree<const NB: usize, const NQ: usize, const NV: usize>(
        parents: [Option<usize>; NB],
        root: Joint<f64>,
    ) -> Model<f64, NB, NQ, NV, Spatial> {
        let turns = [QUARTER_X, QUARTER_Y, HALF_Z_THEN_X, CYCLE];
        let tilted = Mat3::from_axis_angle(&Vec3::new(0.6, 0.0, 0.8), 0.4);
        Model::new(
            parents,
            core::array::from_fn(|i| match i % 7 {
                _ if i == 0 => root,
                3 => Joint::prismatic(Axis::Y),
                5 => Joint::revolute(Axis::Unit(Vec3::new(0.0, 0.6, 0.8))),
                k => Joint::revolute([Axis::X, Axis::Y, Axis::Z][k % 3]),
            }),
            core::array::from_fn(|i| {
                let rot = match i % 5 {
                    4 => tilted,
                    0 => Mat3::IDENTITY,
                    k => turns[(i + k) % 4].matrix(),
                };
                let k = i as f64;
                Transform::new(rot, Vec3::new(0.1 + 0.01 * k, -0.02 * (k % 3.0), 0.05))
            }),
            core::array::from_fn(|i| {
                let k = (i % 4) as f64;
                Inertia::new(
                    0.5 + k,
                    Vec3::new(0.05 * k, -0.02, 0.01 * k),
                    Sym3::new(0.03, 0.001 * k, -0.002, 0.04, 0.003, 0.05 + 0.01 * k),
                )
            }),
            Motion::new(Vec3::ZERO, Vec3::ZERO),
        )
    }

    #[test]
    // A minute and more under Miri, whose run the two long trees below
    // (the same pass, with turned placements too) keep to minutes.
    #[cfg_attr(miri, ignore)]
    fn the_root_frame_pass_gives_rneas_columns_with_and_without_turns() {
        let model = long_chain();
        assert!(CrbaPass::default_for::<f64, 52, 52>(model.topology()) == CrbaPass::RootFrame);
        let plan = CrbaPlan::new(&model);
        let turned_bodies = (0..52).filter(|&i| plan.frame(i).axis().is_some()).count();
        assert!(turned_bodies >= 8, "{turned_bodies} turned bodies");
        let q: [f64; 52] = core::array::from_fn(|k| (0.7 * k as f64).sin() * 1.5);
        assert_rneas_columns(&model, &q);
    }

    #[test]
    fn the_root_frame_pass_fills_the_zeros_between_branches() {
        // A 40-link trunk; a 10-link branch from its tip and another from
        // its 31st link, whose coordinates and the first's share zeros.
        let parents = core::array::from_fn(|i| match i {
            0 => None,
            50 => Some(30),
            i => Some(i - 1),
        });
        let model = long_tree::<60, 60, 60>(parents, Joint::revolute(Axis::X));
        assert!(CrbaPass::default_for::<f64, 60, 60>(model.topology()) == CrbaPass::RootFrame);
        let q: [f64; 60] = core::array::from_fn(|k| (0.9 * k as f64).cos() * 1.2);
        assert_rneas_columns(&model, &q);
        let m = *crba(&model, &mut Data::new(), &q).unwrap();
        assert_eq!((m[55][45], m[45][55]), (0.0, 0.0));
    }

    #[test]
    fn the_root_frame_pass_takes_a_free_flying_root() {
        // A 60-link chain on a free flyer: the root's six coordinates form
        // a block whose entries below its diagonal are dot products too.
        let parents = core::array::from_fn(|i: usize| i.checked_sub(1));
        let model = long_tree::<61, 67, 66>(parents, Joint::free_flyer());
        assert!(CrbaPass::default_for::<f64, 61, 66>(model.topology()) == CrbaPass::RootFrame);
        let norm = (0.01f64 + 0.04 + 0.09 + 0.86).sqrt();
        let q: [f64; 67] = core::array::from_fn(|k| match k {
            0..3 => 0.3 * k as f64 - 0.2,
            3..7 => [0.1, -0.2, 0.3, 0.86f64.sqrt()][k - 3] / norm,
            k => (0.9 * k as f64).cos() * 1.2,
        });
        assert_rneas_columns(&model, &q);
    }

    /// Holds `M` from [`crba`], from the joint transforms and fused with
    /// the bias forces to RNEA's columns (column k is the torque for the
    /// unit acceleration of coordinate k, without velocities), to 1e-12,
    /// without a plan and with the model's recognised turns.
    /// The model has no gravity.
    fn assert_rneas_columns<const NB: usize, const NQ: usize, const NV: usize>(
        model: &Model<f64, NB, NQ, NV, Spatial>,
        q: &[f64; NQ],
    ) {
        assert_rneas_columns_in(model, None, q);
        assert_rneas_columns_in(model, Some(&CrbaPlan::new(model)), q);
    }

    /// [`assert_rneas_columns`] with `plan`, or without one.
    fn assert_rneas_columns_in<const NB: usize, const NQ: usize, const NV: usize>(
        model: &Model<f64, NB, NQ, NV, Spatial>,
        plan: Option<&CrbaPlan<f64, NB>>,
        q: &[f64; NQ],
    ) {
        use crate::algorithm::rnea::rnea;
        let v = [0.0; NV];
        let mut data = Data::new();
        let mut expected = [[0.0; NV]; NV];
        // Every column; under Miri every tenth (the free flyer's first
        // among them), each RNEA call being a whole pass over the tree.
        let stride = crate::test_points(1, 10);
        for k in (0..NV).step_by(stride) {
            let mut a = [0.0; NV];
            a[k] = 1.0;
            let tau = *rnea(model, &mut data, q, &v, &a, None).unwrap();
            for r in 0..NV {
                expected[r][k] = tau[r];
            }
        }
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + a.abs().max(b.abs()));
        // Every entry written, the zeros of unrelated limbs included.
        data.mass_matrix = [[f64::NAN; NV]; NV];
        let m = match plan {
            Some(plan) => *crba_planned(model, plan, &mut data, q).unwrap(),
            None => *crba(model, &mut data, q).unwrap(),
        };
        for i in 0..NB {
            data.li_m_i[i] = body_transform(model, i, q);
        }
        data.mass_matrix = [[f64::NAN; NV]; NV];
        match plan {
            Some(plan) => crba_lower_planned(model, plan, &mut data, None),
            None => crba_lower(model, &mut data, None),
        }
        let from_transforms = data.mass_matrix;
        data.mass_matrix = [[f64::NAN; NV]; NV];
        match plan {
            Some(plan) => bias_and_mass_lower_planned(model, plan, &mut data, q, &v, None),
            None => bias_and_mass_lower(model, &mut data, q, &v, None),
        }
        for r in 0..NV {
            for c in (0..NV).step_by(stride) {
                let e = expected[r][c];
                assert!(
                    close(m[r][c], e),
                    "crba: M[{r}][{c}] {} against {e}",
                    m[r][c]
                );
                if c > r {
                    continue;
                }
                for (what, got) in [
                    ("from transforms", from_transforms[r][c]),
                    ("fused", data.mass_matrix[r][c]),
                ] {
                    assert!(close(got, e), "{what}: M[{r}][{c}] {got} against {e}");
                }
            }
        }
    }

    /// A free-flying base with two limbs (`parents`): joints about every
    /// axis behind quarter turns, behind placements that turn about the
    /// joint's own axis or not at all, a prismatic joint and a general
    /// axis; no gravity.
    fn floating_tree(parents: [Option<usize>; 8]) -> Model<f64, 8, 14, 13, Spatial> {
        let turned =
            |p: AxisPermutation, t: [f64; 3]| Transform::new(p.matrix(), Vec3::from_array(t));
        let (s, c) = 0.3f64.sin_cos();
        Model::new(
            parents,
            [
                Joint::free_flyer(),
                Joint::revolute(Axis::X),
                Joint::revolute(Axis::Z),
                Joint::revolute(Axis::Y),
                Joint::revolute(Axis::Z),
                Joint::revolute(Axis::Y),
                Joint::prismatic(Axis::X),
                Joint::revolute(Axis::Unit(Vec3::new(0.0, 0.6, 0.8))),
            ],
            [
                Transform::IDENTITY,
                turned(QUARTER_Y, [0.1, 0.2, 0.0]),
                turned(QUARTER_X, [0.0, 0.0, 0.3]),
                turned(HALF_Z_THEN_X, [0.05, 0.3, 0.0]),
                Transform::new(Mat3::from_axis_index(2, s, c), Vec3::new(-0.1, 0.2, 0.0)),
                Transform::new(Mat3::IDENTITY, Vec3::new(0.0, 0.25, 0.1)),
                turned(CYCLE, [0.2, 0.0, -0.1]),
                Transform::new(Mat3::IDENTITY, Vec3::new(0.0, 0.1, 0.15)),
            ],
            core::array::from_fn(|i| {
                let k = i as f64;
                Inertia::new(
                    0.7 + k,
                    Vec3::new(0.04 * k, -0.03, 0.02 * k),
                    Sym3::new(0.3, 0.01 * k, -0.02, 0.4, 0.03, 0.5 + 0.1 * k),
                )
            }),
            Motion::new(Vec3::ZERO, Vec3::ZERO),
        )
    }

    #[test]
    fn a_floating_tree_gives_rneas_columns_in_either_body_order() {
        // Limbs {1, 2, 3} and {4, 5, 6, 7} (5 branching), each subtree's
        // coordinates contiguous; then the same joints with the limbs'
        // bodies interleaved, which the pass walks with a test of support.
        let contiguous = floating_tree([
            None,
            Some(0),
            Some(1),
            Some(2),
            Some(0),
            Some(4),
            Some(5),
            Some(5),
        ]);
        assert!(contiguous.topology().subtrees_contiguous);
        let interleaved = floating_tree([
            None,
            Some(0),
            Some(1),
            Some(2),
            Some(0),
            Some(4),
            Some(5),
            Some(3),
        ]);
        assert!(!interleaved.topology().subtrees_contiguous);
        for model in [&contiguous, &interleaved] {
            let plan = CrbaPlan::new(model);
            let turned = (1..8).filter(|&i| plan.frame(i).axis().is_some()).count();
            assert!(turned >= 3, "{turned} turned bodies");
        }
        let mut q: [f64; 14] = core::array::from_fn(|k| (0.9 * k as f64 + 0.4).sin() * 1.3);
        let norm = q[3..7].iter().map(|x| x * x).sum::<f64>().sqrt();
        q[3..7].iter_mut().for_each(|x| *x /= norm);
        assert_rneas_columns(&contiguous, &q);
        assert_rneas_columns(&interleaved, &q);
    }

    /// Every entry above the diagonal is its mirror's, at every parity of
    /// the size (the host's copy goes by 2 x 2 blocks).
    fn assert_mirrors<const N: usize>() {
        let mut m = [[f64::NAN; N]; N];
        for (r, row) in m.iter_mut().enumerate() {
            for (c, e) in row.iter_mut().enumerate().take(r + 1) {
                *e = (10 * r + c) as f64;
            }
        }
        super::triangle::mirror_lower(&mut m);
        for r in 0..N {
            for c in 0..N {
                let e = (10 * r.max(c) + r.min(c)) as f64;
                assert_eq!(m[r][c], e, "N = {N}: M[{r}][{c}]");
            }
        }
    }

    #[test]
    fn the_mirror_fills_the_upper_triangle_at_every_size() {
        assert_mirrors::<1>();
        assert_mirrors::<2>();
        assert_mirrors::<3>();
        assert_mirrors::<4>();
        assert_mirrors::<5>();
        assert_mirrors::<8>();
        assert_mirrors::<13>();
    }

    #[test]
    fn a_plan_goes_stale_when_the_model_changes() {
        let mut model = model();
        let plan = CrbaPlan::new(&model);
        assert!(plan.is_for(&model));
        let tilted = Transform::new(
            Mat3::from_axis_angle(&Vec3::new(1.0, 0.0, 0.0), 0.3),
            Vec3::new(0.1, -0.2, 0.0),
        );
        model.set_placement(1, tilted).unwrap();
        assert!(!plan.is_for(&model));
        let replanned = CrbaPlan::new(&model);
        assert!(replanned.frame(1).axis().is_none());
        // Its child's frame no longer includes the parent's turn.
        assert_eq!(replanned.frame(2).parent_turn(), AxisPermutation::IDENTITY);
        let q = [0.3, -1.1, 0.7, 2.0, -0.4, 0.1, 0.9];
        let (mut a, mut b) = (Data::new(), Data::new());
        let expected = *crba(&model, &mut a, &q).unwrap();
        let got = *crba_planned(&model, &replanned, &mut b, &q).unwrap();
        for r in 0..7 {
            for c in 0..7 {
                assert!(close(got[r][c], expected[r][c]), "M[{r}][{c}]");
            }
        }
        // A new inertia: the plan's turned copy no longer matches.
        let inertia = Inertia::new(2.5, Vec3::new(0.0, 0.1, 0.0), Sym3::diagonal(0.2, 0.3, 0.4));
        model.set_inertia(2, inertia).unwrap();
        assert!(!replanned.is_for(&model));
        let replanned = CrbaPlan::new(&model);
        assert_eq!(
            *replanned.inertia(2),
            replanned.frame(2).turn().apply_inertia(&inertia)
        );
    }
}
