//! CRBA's plan: what its tuned passes derive from one model once.
//!
//! Why it exists: a URDF arm's placements are mostly quarter turns, and
//! behind them a joint about a coordinate axis turns about no coordinate
//! axis of its parent's frame. Expressing each body in its frame turned by
//! the quarter turns above it ([`TurnedFrame`]) makes those steps
//! rotations about coordinate axes again, at the price of turning each
//! body's inertia and placement once. Those turned copies are per-model
//! precomputation that belongs to CRBA, not to the [`Model`], so they
//! live here, in a value the caller keeps beside the model (a `const`
//! from the model compiler, or built once at start-up) and hands to the
//! planned entries ([`crba_planned`](super::crba_planned),
//! [`Crba::forward_dynamics_planned`](crate::algorithm::forward_dynamics::Crba::forward_dynamics_planned)).
//! Without a plan the same passes run with every frame unturned: the same
//! results, slower on models with quarter-turn placements.
//!
//! **The rule:** a plan is made for one model's placements, inertias and
//! joints. After [`Model::set_placement`] or [`Model::set_inertia`], build
//! the plan again ([`CrbaPlan::new`]); a stale plan gives a wrong mass
//! matrix. The planned entries check [`CrbaPlan::is_for`] with
//! `debug_assert!`, so tests and debug builds catch a stale plan; release
//! builds do not pay for the check. The plan is an explicit argument, not
//! a cache in [`Data`](crate::Data): a workspace may serve several models
//! of one size, and a cache keyed on the model could not tell them apart.

use super::TurnedFrame;
use crate::joint::{Axis, Joint, JointModel};
use crate::model::Model;
use crate::space::Space;
use crate::spatial::axis_permutation::{
    turn_inertia_f32, turn_inertia_f64, turn_transform_f32, turn_transform_f64,
};
use crate::spatial::{AxisPermutation, Spatial};
use crate::Scalar;

/// CRBA's plan for a model of `NB` bodies in geometry `G`: each body's
/// turned frame, and its inertia and placement in the turned frames
/// (see the module documentation for when to build it again).
#[derive(Clone, Copy, Debug)]
pub struct CrbaPlan<S: Scalar, const NB: usize, G: Space = Spatial> {
    /// The frame each body is expressed in.
    frames: [TurnedFrame; NB],
    /// Each body's inertia in its turned frame.
    inertias: [G::Inertia<S>; NB],
    /// Each placement seen from its parent's turned frame: `Q_λ` then the
    /// placement.
    placements: [G::Transform<S>; NB],
}

impl<S: Scalar, const NB: usize, G: Space> CrbaPlan<S, NB, G> {
    /// The plan that turns no frame: what the plan-less entries run with
    /// (usable in `const`, for any scalar and geometry).
    #[must_use]
    pub const fn unturned<const NQ: usize, const NV: usize>(
        model: &Model<S, NB, NQ, NV, G>,
    ) -> Self {
        Self {
            frames: [TurnedFrame::UNTURNED; NB],
            inertias: *model.inertias(),
            placements: *model.placements(),
        }
    }

    /// The plan of `model`, its placements' quarter turns recognised at
    /// run time (exact entries only; only 3-D placements have them).
    #[must_use]
    pub fn new<const NQ: usize, const NV: usize>(model: &Model<S, NB, NQ, NV, G>) -> Self {
        let turns: [Option<AxisPermutation>; NB] =
            core::array::from_fn(|i| G::axis_permutation(model.placement(i)));
        let axes: [Option<usize>; NB] =
            core::array::from_fn(|i| model.joint(i).revolute_axis_index());
        let frames = TurnedFrame::tree(&model.topology().parents, &turns, &axes);
        Self {
            frames,
            inertias: core::array::from_fn(|i| {
                G::turn_inertia(&frames[i].turn(), model.inertia(i))
            }),
            placements: core::array::from_fn(|i| {
                G::turn_transform(&frames[i].parent_turn(), model.placement(i))
            }),
        }
    }

    /// `true` when the plan fits `model` as it is now: every declared
    /// quarter turn is the placement's rotation, every turned axis the
    /// joint's, and the turned inertias and placements are the model's.
    /// O(NB) comparisons; the planned entries `debug_assert!` it.
    #[must_use]
    pub fn is_for<const NQ: usize, const NV: usize>(
        &self,
        model: &Model<S, NB, NQ, NV, G>,
    ) -> bool {
        (0..NB).all(|i| {
            let frame = &self.frames[i];
            let parent_turn = model
                .parent(i)
                .map_or(AxisPermutation::IDENTITY, |p| self.frames[p].turn());
            frame
                .placement()
                .is_none_or(|p| G::axis_permutation(model.placement(i)) == Some(p))
                && frame
                    .axis()
                    .is_none_or(|a| model.joint(i).revolute_axis_index() == Some(a.joint))
                && frame.parent_turn() == parent_turn
                && self.inertias[i] == G::turn_inertia(&frame.turn(), model.inertia(i))
                && self.placements[i] == G::turn_transform(&parent_turn, model.placement(i))
        })
    }

    /// The frame CRBA expresses body `i` in.
    #[must_use]
    pub const fn frame(&self, i: usize) -> &TurnedFrame {
        &self.frames[i]
    }
    /// Body `i`'s inertia in its turned frame.
    #[must_use]
    pub const fn inertia(&self, i: usize) -> &G::Inertia<S> {
        &self.inertias[i]
    }
    /// Joint `i`'s placement seen from its parent's turned frame.
    #[must_use]
    pub const fn placement(&self, i: usize) -> &G::Transform<S> {
        &self.placements[i]
    }
}

/// [`CrbaPlan::from_turns`] for one floating-point type: turning the
/// inertias negates entries, which a `const fn` can do on `f32` and `f64`
/// but not through the [`Scalar`] trait.
macro_rules! plan_from_turns_for {
    ($S:ty, $turn_inertia:ident, $turn_transform:ident) => {
        impl<const NB: usize> CrbaPlan<$S, NB, Spatial> {
            /// The plan of `model` with its quarter-turn placements
            /// declared (usable in `const`; what `rodyn-model` emits):
            /// `turns[i]`, when `Some`, is placement i's rotation, exactly.
            /// The same plan as [`CrbaPlan::new`] finds for the turns it
            /// declares.
            ///
            /// # Panics
            /// When a declared turn is not its placement's rotation, entry
            /// for entry; in a `const` this is a compile error.
            ///
            /// ```
            /// use rodyn::algorithm::crba::{crba, crba_planned, CrbaPlan};
            /// use rodyn::{Data, Model, joint::{Axis, Joint}, spatial::*};
            /// // A two-link arm whose second placement is a quarter turn about x.
            /// const QUARTER_X: AxisPermutation =
            ///     AxisPermutation::from_rows([[1, 0, 0], [0, 0, -1], [0, 1, 0]]);
            /// const ARM: Model<f64, 2, 2, 2> = Model::new(
            ///     [None, Some(0)],
            ///     [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
            ///     [Transform::IDENTITY, Transform::new(QUARTER_X.matrix(), Vec3::new(0.0, 0.0, 0.3))],
            ///     [Inertia::point_mass(1.0, Vec3::new(0.0, 0.0, 0.2)); 2],
            ///     Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
            /// );
            /// // The scalar named: the constructor exists for `f32` and `f64`.
            /// const PLAN: CrbaPlan<f64, 2> =
            ///     CrbaPlan::<f64, 2>::from_turns(&ARM, [None, Some(QUARTER_X)]);
            /// // Joint 2 turns about z, which its frame turned by the quarter turn
            /// // about x carries onto minus y.
            /// let axis = PLAN.frame(1).axis().unwrap();
            /// assert_eq!((axis.turned, axis.reversed), (1, true));
            /// assert!(PLAN.is_for(&ARM));
            /// // The same mass matrix as without the plan.
            /// let q = [0.3, -0.8];
            /// let planned = *crba_planned(&ARM, &PLAN, &mut Data::new(), &q)?;
            /// let plain = *crba(&ARM, &mut Data::new(), &q)?;
            /// assert!((planned[1][0] - plain[1][0]).abs() < 1e-15);
            /// # Ok::<(), rodyn::Error>(())
            /// ```
            #[must_use]
            pub const fn from_turns<const NQ: usize, const NV: usize>(
                model: &Model<$S, NB, NQ, NV, Spatial>,
                turns: [Option<AxisPermutation>; NB],
            ) -> Self {
                let mut axes = [None; NB];
                let mut i = 0;
                while i < NB {
                    if let Some(turn) = turns[i] {
                        let (declared, rot) = (turn.matrix::<$S>(), &model.placement(i).rot);
                        let mut r = 0;
                        while r < 9 {
                            let (a, b) = (declared.m[r / 3][r % 3], rot.m[r / 3][r % 3]);
                            assert!(
                                a == b,
                                "a declared quarter turn is not its placement's rotation"
                            );
                            r += 1;
                        }
                    }
                    if let Joint::Revolute(j) = model.joint(i) {
                        axes[i] = match j.axis {
                            Axis::X => Some(0),
                            Axis::Y => Some(1),
                            Axis::Z => Some(2),
                            Axis::Unit(_) => None,
                        };
                    }
                    i += 1;
                }
                let frames = TurnedFrame::tree(&model.topology().tables().parents, &turns, &axes);
                let mut plan = Self::unturned(model);
                plan.frames = frames;
                let mut i = 0;
                while i < NB {
                    plan.inertias[i] = $turn_inertia(&frames[i].turn(), model.inertia(i));
                    plan.placements[i] =
                        $turn_transform(&frames[i].parent_turn(), model.placement(i));
                    i += 1;
                }
                plan
            }
        }
    };
}

plan_from_turns_for!(f32, turn_inertia_f32, turn_transform_f32);
plan_from_turns_for!(f64, turn_inertia_f64, turn_transform_f64);

/// Where CRBA's passes read each body's frame, inertia and placement: a
/// [`CrbaPlan`], or the model itself with every frame unturned
/// ([`Unturned`]), whose constant frame lets the compiler drop the turned
/// branches from the plan-less code.
pub(super) trait BodyFrames<S: Scalar, const NB: usize, G: Space> {
    /// Body `i`'s frame.
    fn frame(&self, i: usize) -> &TurnedFrame;
    /// Body `i`'s inertia in its frame.
    fn inertia(&self, i: usize) -> &G::Inertia<S>;
    /// Placement `i` seen from its parent's frame.
    fn placement(&self, i: usize) -> &G::Transform<S>;
}

impl<S: Scalar, const NB: usize, G: Space> BodyFrames<S, NB, G> for CrbaPlan<S, NB, G> {
    #[inline(always)]
    fn frame(&self, i: usize) -> &TurnedFrame {
        &self.frames[i]
    }
    #[inline(always)]
    fn inertia(&self, i: usize) -> &G::Inertia<S> {
        &self.inertias[i]
    }
    #[inline(always)]
    fn placement(&self, i: usize) -> &G::Transform<S> {
        &self.placements[i]
    }
}

/// A model read with every body in its own frame: the plan-less entries.
pub(super) struct Unturned<
    'm,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(pub(super) &'m Model<S, NB, NQ, NV, G>);

impl<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space> BodyFrames<S, NB, G>
    for Unturned<'_, S, NB, NQ, NV, G>
{
    #[inline(always)]
    fn frame(&self, _i: usize) -> &TurnedFrame {
        &TurnedFrame::UNTURNED
    }
    #[inline(always)]
    fn inertia(&self, i: usize) -> &G::Inertia<S> {
        self.0.inertia(i)
    }
    #[inline(always)]
    fn placement(&self, i: usize) -> &G::Transform<S> {
        self.0.placement(i)
    }
}
