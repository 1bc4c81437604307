//! The hooks CRBA needs from a geometry beyond its algebra
//! ([`Geometry`]): a joint transform prepared to act on many columns
//! ([`CrbaSpace::Step`]), the fused steps of one body, and the turned
//! frames ([`TurnedFrame`]). Implemented for [`Spatial`] and [`Planar`]
//! beside CRBA (`algorithm/crba/spatial.rs`, `planar.rs`); the defaults
//! ignore the turned frames, for geometries without quarter turns. The
//! trait is defined here, below the algorithms, because [`Space`](super::Space)
//! requires it; users name it `rodyn::algorithm::crba::CrbaSpace`.
//!
//! [`Spatial`]: crate::spatial::Spatial
//! [`Planar`]: crate::planar::Planar

use super::joint_model::JointModel;
use super::turned_frame::TurnedFrame;
use super::{Geometry, RigidTransform};
use crate::spatial::AxisPermutation;
use crate::Scalar;

/// CRBA's hooks in a geometry (see the module documentation).
pub trait CrbaSpace: Geometry {
    /// Whether the geometry has fused CRBA steps ([`Self::crba_axis_body`],
    /// [`Self::crba_free_root`]): without them CRBA does not look for
    /// them, and carries no code for the test.
    const FUSES_CRBA_STEPS: bool = false;
    /// Whether CRBA can turn this geometry's body frames (whether its
    /// placements can be quarter turns, [`Self::axis_permutation`]):
    /// without, a CRBA plan holds nothing the model does not, and the
    /// planned entries read the model instead.
    const TURNS_FRAMES: bool = false;

    // CRBA's backward pass: each joint transform moves every column of
    // its body's subtree and the body's composite inertia into the
    // parent's frame.

    /// A joint transform `ˡⁱXᵢ` prepared to act many times.
    type Step<S: Scalar>: Copy;
    /// Prepares `x` ([`Self::Step`]).
    fn step<S: Scalar>(x: &Self::Transform<S>) -> Self::Step<S>;
    /// The step of joint `j` at `q` behind `placement`: `step(&j
    /// .placed_transform(placement, q))`, without forming the transform
    /// where the step does not need it.
    fn joint_step<S: Scalar>(
        j: &Self::Joint<S>,
        placement: &Self::Transform<S>,
        q: &[S],
    ) -> Self::Step<S>;
    /// `x.act_force(f)` through a prepared step, for every force of `forces`.
    fn step_forces<S: Scalar>(step: &Self::Step<S>, forces: &mut [Self::Force<S>]);
    /// CRBA's whole step at a body with one coordinate, fused, when its
    /// joint turns about coordinate axis `axis.0` of the columns' frame
    /// (the opposite way when `axis.1`) and `step` turns about that same
    /// axis: the body's column `Iᶜ S` into `columns[0]`; for each column
    /// `F_d` of `columns` (the body's subtree, its own first) the entry
    /// `rows[d][iv] = Sᵀ F_d` (with `upper`, also `rows[0][iv + d]`, its
    /// mirror above the diagonal) and `F_d` moved through the step; then
    /// `ic` moved and added to `parent_ic`. Returns `false`, having done
    /// nothing, where it does not apply (the default: always).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn crba_axis_body<S: Scalar, const NV: usize>(
        _step: &Self::Step<S>,
        _axis: (usize, bool),
        _ic: &Self::Inertia<S>,
        _parent_ic: &mut Self::Inertia<S>,
        _columns: &mut [Self::Force<S>],
        _rows: &mut [[S; NV]],
        _iv: usize,
        _upper: bool,
    ) -> bool {
        false
    }
    /// CRBA's step at a root body whose joint's motion subspace is the
    /// identity (a free flyer, linear coordinates first), fused: its own
    /// block of `M`, the composite inertia `ic` itself, into the lower
    /// triangle of `rows[..6]`, and its entries against the rest of its
    /// subtree, `rows[6 + d][iv..iv + 6]` = `columns[d]` reordered; with
    /// `upper`, their mirrors above the diagonal too. Nothing moves from a
    /// root. Returns `false`, having done nothing, for any other joint (the
    /// default: always).
    #[inline(always)]
    fn crba_free_root<S: Scalar, const NV: usize>(
        _joint: &Self::Joint<S>,
        _ic: &Self::Inertia<S>,
        _columns: &[Self::Force<S>],
        _rows: &mut [[S; NV]],
        _iv: usize,
        _upper: bool,
    ) -> bool {
        false
    }
    /// `acc` plus `i` moved through the step (`x.act(i)`): the composite of
    /// a parent and its child, in the parent's frame.
    fn add_stepped_inertia<S: Scalar>(
        acc: &mut Self::Inertia<S>,
        step: &Self::Step<S>,
        i: &Self::Inertia<S>,
    );
    /// `x` followed by the step: the transform `x ˡⁱXᵢ`, as from a root
    /// frame to body i's when `x` is from the root frame to its parent's.
    fn then_step<S: Scalar>(x: &Self::Transform<S>, step: &Self::Step<S>) -> Self::Transform<S>;
    /// `i Sₖ`: the inertia times column k of joint `j`'s motion subspace,
    /// both in the joint's body frame.
    fn inertia_column<S: Scalar>(
        i: &Self::Inertia<S>,
        j: &Self::Joint<S>,
        k: usize,
    ) -> Self::Force<S>;

    // Turned frames ([`TurnedFrame`]): CRBA may express a body in its
    // frame turned by the quarter turns of the placements above it. Only
    // 3-D placements are recognised as quarter turns; the defaults, for
    // geometries without them, ignore the frames.

    /// `Some` when placement `x`'s rotation is exactly an
    /// [`AxisPermutation`].
    fn axis_permutation<S: Scalar>(_x: &Self::Transform<S>) -> Option<AxisPermutation> {
        None
    }
    /// The angle of body i's joint whose sine and cosine
    /// [`Self::turned_joint_step`] takes when given them (`None`: it takes
    /// none), so that a caller can form many at once
    /// ([`Scalar::sin_cos_array`]).
    #[inline(always)]
    fn step_angle<S: Scalar>(_frame: &TurnedFrame, _j: &Self::Joint<S>, _q: &[S]) -> Option<S> {
        None
    }
    /// [`Self::joint_step`] from body i's turned frame to its parent's,
    /// given its placement seen from the parent's turned frame
    /// ([`CrbaPlan::placement`](crate::algorithm::crba::CrbaPlan::placement)).
    /// `sin_cos`, when the caller has formed it, is the sine and cosine of
    /// [`Self::step_angle`].
    #[inline(always)]
    fn turned_joint_step<S: Scalar>(
        _frame: &TurnedFrame,
        j: &Self::Joint<S>,
        turned_placement: &Self::Transform<S>,
        q: &[S],
        _sin_cos: Option<(S, S)>,
    ) -> Self::Step<S> {
        Self::joint_step(j, turned_placement, q)
    }
    /// [`Self::step`] from body i's turned frame to its parent's, given
    /// `x = ˡⁱXᵢ` between their own frames (as RNEA leaves it) and the
    /// placement seen from the parent's turned frame.
    #[inline(always)]
    fn turned_step<S: Scalar>(
        _frame: &TurnedFrame,
        x: &Self::Transform<S>,
        _turned_placement: &Self::Transform<S>,
    ) -> Self::Step<S> {
        Self::step(x)
    }
    /// `i` expressed in the frame turned by `turn` (`turn` applied to its
    /// centre of mass, `turn I turnᵀ` to its rotational inertia).
    #[inline(always)]
    fn turn_inertia<S: Scalar>(_turn: &AxisPermutation, i: &Self::Inertia<S>) -> Self::Inertia<S> {
        *i
    }
    /// `turn` then `x` (`x` seen from the frame turned by `turn`).
    #[inline(always)]
    fn turn_transform<S: Scalar>(
        _turn: &AxisPermutation,
        x: &Self::Transform<S>,
    ) -> Self::Transform<S> {
        *x
    }
    /// `x Sₖ`: column k of joint `j`'s motion subspace, in body i's
    /// turned frame, moved by `x` (as into a root frame).
    #[inline(always)]
    fn act_turned_subspace_column<S: Scalar>(
        x: &Self::Transform<S>,
        _frame: &TurnedFrame,
        j: &Self::Joint<S>,
        k: usize,
    ) -> Self::Motion<S> {
        x.act_motion(&j.subspace_column(k))
    }
    /// [`Self::inertia_column`] in body i's turned frame.
    #[inline(always)]
    fn turned_inertia_column<S: Scalar>(
        _frame: &TurnedFrame,
        i: &Self::Inertia<S>,
        j: &Self::Joint<S>,
        k: usize,
    ) -> Self::Force<S> {
        Self::inertia_column(i, j, k)
    }
}
