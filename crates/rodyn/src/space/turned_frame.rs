//! Body frames turned so that quarter-turn placements vanish from CRBA.
//!
//! A URDF arm's joint `i` typically turns about `z` behind a placement that
//! is a quarter turn `Pᵢ` about another axis, so its transform `ˡⁱXᵢ`
//! rotates about no coordinate axis and CRBA moves every column and
//! inertia through a full 3x3 rotation. Expressing body i in its frame
//! turned by `Qᵢ = Q_λ Pᵢ` (the product of the quarter turns above it)
//! instead turns the step into a rotation about the coordinate axis
//! `Qᵢ e_K`, by the joint angle alone, followed by the translation
//! `Q_λ p`:
//!
//! `Q_λ (Pᵢ R_K(q)) Qᵢᵀ = Qᵢ R_K(q) Qᵢᵀ`.
//!
//! The mass matrix does not depend on the frames (each entry is
//! `Sⱼᵀ Fᵢ`, and both factors turn together), so CRBA only has to turn each
//! body's inertia once (a reordering of its entries with sign flips, exact)
//! and read each joint's subspace column on its turned axis.
//!
//! Defined with the geometry traits, whose CRBA hooks take it; users name
//! it `rodyn::algorithm::crba::TurnedFrame`.

use crate::spatial::{AxisPermutation, Mat3};
use crate::Scalar;

/// How CRBA expresses one body: its frame turned by [`Self::turn`]
/// (`Qᵢ`), and its joint's axis in that frame when the joint's step is a
/// rotation about a coordinate axis by the joint angle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TurnedFrame {
    placement: Option<AxisPermutation>,
    turn: AxisPermutation,
    parent_turn: AxisPermutation,
    axis: Option<TurnedAxis>,
}

/// A revolute joint's coordinate axis `K` and its image in the turned frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TurnedAxis {
    /// `K`: the joint's axis in its own frame (0, 1, 2 for x, y, z).
    pub joint: usize,
    /// The coordinate axis `Qᵢ e_K` lies along.
    pub turned: usize,
    /// `Qᵢ e_K` is minus that axis: the turned joint turns by `-q`.
    pub reversed: bool,
    /// Where `cos q` and `± sin q` sit in the rotation `Pᵢ R_K(q)` of the
    /// joint transform: rows, column, and signs (sine's with `reversed`).
    cos_row: usize,
    sin_row: usize,
    column: usize,
    cos_negative: bool,
    sin_negative: bool,
}

impl TurnedAxis {
    /// `(cos q, sin q)` for the turned joint (`sin q` negated when
    /// [`Self::reversed`]), read from the rotation `Pᵢ R_K(q)` of its
    /// transform between the bodies' own frames: two entries of `Pᵢᵀ` times
    /// it, with no sine or cosine to evaluate.
    #[inline(always)]
    #[must_use]
    pub fn cos_sin_in<S: Scalar>(&self, rot: &Mat3<S>) -> (S, S) {
        let signed = |x: S, negative: bool| if negative { -x } else { x };
        let m = &rot.m;
        (
            signed(m[self.cos_row % 3][self.column % 3], self.cos_negative),
            signed(m[self.sin_row % 3][self.column % 3], self.sin_negative),
        )
    }
}

impl TurnedFrame {
    /// A body expressed in its own frame, as every body of a model whose
    /// placements are not known to be quarter turns.
    pub const UNTURNED: Self = Self {
        placement: None,
        turn: AxisPermutation::IDENTITY,
        parent_turn: AxisPermutation::IDENTITY,
        axis: None,
    };

    /// The frames of a tree, parents before children: `placements[i]` is
    /// placement i's rotation when it is exactly an [`AxisPermutation`],
    /// `axes[i]` joint i's coordinate axis when it is revolute about one.
    /// A body takes a turned frame when it has a parent, such a placement
    /// and such a joint; any other body keeps its own frame (and its step
    /// turns by its parent's `Q_λ` in full).
    #[must_use]
    pub const fn tree<const NB: usize>(
        parents: &[Option<usize>; NB],
        placements: &[Option<AxisPermutation>; NB],
        axes: &[Option<usize>; NB],
    ) -> [Self; NB] {
        let mut frames = [Self::UNTURNED; NB];
        let mut i = 0;
        while i < NB {
            frames[i].placement = placements[i];
            if let Some(p) = parents[i] {
                let parent_turn = frames[p].turn;
                frames[i].parent_turn = parent_turn;
                if let (Some(placement), Some(k)) = (placements[i], axes[i]) {
                    let turn = parent_turn.compose(&placement);
                    let (turned, reversed) = turn.image_of_axis(k);
                    // R_K(q) = Pᵀ (P R_K(q)): cos q at (a, a), sin q at
                    // (b, a), with (a, b) the plane axes after K; entry
                    // (r, c) of Pᵀ M is ±M[row][c].
                    let (a, b) = ((k + 1) % 3, (k + 2) % 3);
                    let back = placement.transpose();
                    let (cos_row, cos_negative) = back.row(a);
                    let (sin_row, sin_negative) = back.row(b);
                    frames[i].turn = turn;
                    frames[i].axis = Some(TurnedAxis {
                        joint: k,
                        turned,
                        reversed,
                        cos_row,
                        sin_row,
                        column: a,
                        cos_negative,
                        sin_negative: sin_negative != reversed,
                    });
                }
            }
            i += 1;
        }
        frames
    }

    /// The placement's rotation, when it is an [`AxisPermutation`].
    #[must_use]
    pub const fn placement(&self) -> Option<AxisPermutation> {
        self.placement
    }
    /// `Qᵢ`: coordinates in the turned frame are `Qᵢ` times those in the
    /// body's own frame.
    #[must_use]
    pub const fn turn(&self) -> AxisPermutation {
        self.turn
    }
    /// `Q_λ`, the parent's turn (the identity at a root).
    #[must_use]
    pub const fn parent_turn(&self) -> AxisPermutation {
        self.parent_turn
    }
    /// The joint's axis in the turned frame, when its step is a rotation
    /// about that coordinate axis by the joint angle.
    #[must_use]
    pub const fn axis(&self) -> Option<TurnedAxis> {
        self.axis
    }
}
