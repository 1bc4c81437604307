//! CRBA's hooks in 3-D space: the prepared joint steps ([`TransformStep`]),
//! the fused steps of a body about its own axis and of a free-flying root
//! (`fused_body.rs`), and the turned frames.

use super::fused_body;
use super::step::TransformStep;
use super::{CrbaSpace, TurnedAxis, TurnedFrame};
use crate::joint::Joint;
use crate::spatial::{AxisPermutation, Force, Inertia, Motion, Spatial, Sym3, Transform, Vec3};
use crate::Scalar;

impl CrbaSpace for Spatial {
    const FUSES_CRBA_STEPS: bool = true;
    const TURNS_FRAMES: bool = true;
    type Step<S: Scalar> = TransformStep<S>;
    #[inline(always)]
    fn step<S: Scalar>(x: &Transform<S>) -> TransformStep<S> {
        TransformStep::new(x)
    }
    #[inline(always)]
    fn joint_step<S: Scalar>(j: &Joint<S>, placement: &Transform<S>, q: &[S]) -> TransformStep<S> {
        use crate::joint::JointModel;
        // A revolute joint about a coordinate axis of a placement that
        // leaves that axis alone (no rotation, or a turn about the same
        // axis): the step turns by the sum of the two angles. With any
        // other placement the transform turns about a coordinate axis at
        // isolated angles at most, so it takes the general step without
        // `TransformStep::new`'s search.
        let mut about_other_axes = false;
        if let Joint::Revolute(r) = j {
            if let Some(axis) = r.axis.index() {
                match TransformStep::turn_about(&placement.rot, axis) {
                    Some((cos_p, sin_p)) => {
                        let (sin, cos) = crate::joint::first(q).sin_cos();
                        // Exact when the placement does not rotate.
                        return TransformStep::Axis {
                            axis,
                            cos: cos_p * cos - sin_p * sin,
                            sin: sin_p * cos + cos_p * sin,
                            trans: placement.trans,
                        };
                    }
                    None => about_other_axes = true,
                }
            }
        }
        // One call site for the transform: a second one (an early return
        // above) made the Cortex-M4's CRBA stack frame larger (see the
        // performance notebook, "CRBA").
        let x = j.placed_transform(placement, q);
        if about_other_axes {
            TransformStep::General(x)
        } else {
            TransformStep::new(&x)
        }
    }
    #[inline(always)]
    fn then_step<S: Scalar>(x: &Transform<S>, step: &TransformStep<S>) -> Transform<S> {
        step.after(x)
    }
    #[inline(always)]
    fn step_forces<S: Scalar>(step: &TransformStep<S>, forces: &mut [Force<S>]) {
        step.act_forces(forces);
    }
    #[inline(always)]
    fn add_stepped_inertia<S: Scalar>(
        acc: &mut Inertia<S>,
        step: &TransformStep<S>,
        i: &Inertia<S>,
    ) {
        add_shifted_inertia(acc, &step.rotate_inertia(i), &step.translation());
    }
    #[inline(always)]
    fn crba_axis_body<S: Scalar, const NV: usize>(
        step: &TransformStep<S>,
        axis: (usize, bool),
        ic: &Inertia<S>,
        parent_ic: &mut Inertia<S>,
        columns: &mut [Force<S>],
        rows: &mut [[S; NV]],
        iv: usize,
        upper: bool,
    ) -> bool {
        fused_body::axis_body(step, axis, ic, parent_ic, columns, rows, iv, upper)
    }
    #[inline(always)]
    fn crba_free_root<S: Scalar, const NV: usize>(
        joint: &Joint<S>,
        ic: &Inertia<S>,
        columns: &[Force<S>],
        rows: &mut [[S; NV]],
        iv: usize,
        upper: bool,
    ) -> bool {
        let free = matches!(joint, Joint::FreeFlyer(_));
        if free {
            fused_body::free_flyer_root(ic, columns, rows, iv, upper);
        }
        free
    }
    #[inline(always)]
    fn inertia_column<S: Scalar>(i: &Inertia<S>, j: &Joint<S>, k: usize) -> Force<S> {
        use crate::joint::JointModel;
        use crate::space::BodyInertia;
        match j.revolute_axis_index() {
            Some(0) => revolute_inertia_column::<S, 0>(i),
            Some(1) => revolute_inertia_column::<S, 1>(i),
            Some(_) => revolute_inertia_column::<S, 2>(i),
            None => match j {
                // Linear columns first, then angular ones.
                Joint::FreeFlyer(_) => match k {
                    0 => linear_inertia_column::<S, 0>(i),
                    1 => linear_inertia_column::<S, 1>(i),
                    2 => linear_inertia_column::<S, 2>(i),
                    3 => revolute_inertia_column::<S, 0>(i),
                    4 => revolute_inertia_column::<S, 1>(i),
                    _ => revolute_inertia_column::<S, 2>(i),
                },
                _ => i.mul_motion(&j.subspace_column(k)),
            },
        }
    }

    fn axis_permutation<S: Scalar>(x: &Transform<S>) -> Option<AxisPermutation> {
        AxisPermutation::from_matrix(&x.rot)
    }
    /// A joint whose frame turns about a coordinate axis: its angle.
    #[inline(always)]
    fn step_angle<S: Scalar>(frame: &TurnedFrame, _j: &Joint<S>, q: &[S]) -> Option<S> {
        frame.axis().map(|_| q[0])
    }
    #[inline(always)]
    fn turned_joint_step<S: Scalar>(
        frame: &TurnedFrame,
        j: &Joint<S>,
        turned_placement: &Transform<S>,
        q: &[S],
        sin_cos: Option<(S, S)>,
    ) -> TransformStep<S> {
        match frame.axis() {
            // The placement's turn is in the frames: the joint angle alone.
            Some(a) => {
                let (sin, cos) = sin_cos.unwrap_or_else(|| crate::joint::first(q).sin_cos());
                TransformStep::Axis {
                    axis: a.turned,
                    cos,
                    sin: if a.reversed { -sin } else { sin },
                    trans: turned_placement.trans,
                }
            }
            // The body keeps its own frame: `Q_λ X_P X_J(q)`.
            None => Self::joint_step(j, turned_placement, q),
        }
    }
    #[inline(always)]
    fn turned_step<S: Scalar>(
        frame: &TurnedFrame,
        x: &Transform<S>,
        turned_placement: &Transform<S>,
    ) -> TransformStep<S> {
        if let Some(a) = frame.axis() {
            let (cos, sin) = a.cos_sin_in(&x.rot);
            return TransformStep::Axis {
                axis: a.turned,
                cos,
                sin,
                trans: turned_placement.trans,
            };
        }
        let parent = frame.parent_turn();
        if parent.is_identity() {
            Self::step(x)
        } else {
            TransformStep::General(parent.then_transform(x))
        }
    }
    #[inline(always)]
    fn turn_transform<S: Scalar>(turn: &AxisPermutation, x: &Transform<S>) -> Transform<S> {
        if turn.is_identity() {
            *x
        } else {
            turn.then_transform(x)
        }
    }
    #[inline(always)]
    fn turn_inertia<S: Scalar>(turn: &AxisPermutation, i: &Inertia<S>) -> Inertia<S> {
        if turn.is_identity() {
            *i
        } else {
            turn.apply_inertia(i)
        }
    }
    #[inline(always)]
    fn act_turned_subspace_column<S: Scalar>(
        x: &Transform<S>,
        frame: &TurnedFrame,
        j: &Joint<S>,
        k: usize,
    ) -> Motion<S> {
        use crate::joint::JointModel;
        use crate::space::RigidTransform;
        match frame.axis() {
            // `x [±e_K; 0]`: a column of the rotation, and its moment.
            Some(a) => {
                let column = x.rot.column(a.turned);
                let ang = if a.reversed { -column } else { column };
                Motion::new(ang, x.trans.cross(&ang))
            }
            None => x.act_motion(&j.subspace_column(k)),
        }
    }
    #[inline(always)]
    fn turned_inertia_column<S: Scalar>(
        frame: &TurnedFrame,
        i: &Inertia<S>,
        j: &Joint<S>,
        k: usize,
    ) -> Force<S> {
        match frame.axis() {
            Some(a) => turned_revolute_column(i, a),
            None => Self::inertia_column(i, j, k),
        }
    }
}

/// `I [e_K; 0]` for the turned axis `a`, negated when it is reversed.
#[inline(always)]
fn turned_revolute_column<S: Scalar>(i: &Inertia<S>, a: TurnedAxis) -> Force<S> {
    let column = match a.turned {
        0 => revolute_inertia_column::<S, 0>(i),
        1 => revolute_inertia_column::<S, 1>(i),
        _ => revolute_inertia_column::<S, 2>(i),
    };
    if a.reversed {
        -column
    } else {
        column
    }
}

/// `I [0; e_K]`: the momentum `m e_K` of a translation along axis K, and
/// its moment `c × m e_K` about the origin.
#[inline(always)]
fn linear_inertia_column<S: Scalar, const K: usize>(i: &Inertia<S>) -> Force<S> {
    let lin = Vec3::unit(K) * i.mass;
    Force::new(i.com.cross(&lin), lin)
}

/// `I [e_K; 0]`: the centre of mass's momentum `m e_K × c`, and its moment
/// about the origin.
#[inline(always)]
pub(super) fn revolute_inertia_column<S: Scalar, const K: usize>(i: &Inertia<S>) -> Force<S> {
    let c = &i.com;
    let axis_cross_com = match K {
        0 => Vec3::new(S::ZERO, -c.z, c.y),
        1 => Vec3::new(c.z, S::ZERO, -c.x),
        _ => Vec3::new(-c.y, c.x, S::ZERO),
    };
    let lin = axis_cross_com * i.mass;
    Force::new(i.rot_inertia.column(K) + c.cross(&lin), lin)
}

/// `acc` plus `i` with its centre of mass moved by `t`: as
/// `Inertia::combine`, without building the moved inertia.
#[inline(always)]
pub(super) fn add_shifted_inertia<S: Scalar>(acc: &mut Inertia<S>, i: &Inertia<S>, t: &Vec3<S>) {
    let com_i = i.com + *t;
    let mass = acc.mass + i.mass;
    // A massless pair keeps a zero inertia rather than dividing by zero.
    let inv = S::ONE / mass.max(S::from_f64(S::EPSILON));
    let d = acc.com - com_i;
    let reduced = acc.mass * i.mass * inv;
    acc.com = (acc.com * acc.mass + com_i * i.mass) * inv;
    acc.rot_inertia = acc.rot_inertia + i.rot_inertia + Sym3::parallel_axis(&d).scale(reduced);
    acc.mass = mass;
}
