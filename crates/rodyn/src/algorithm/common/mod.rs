//! What several algorithms share: input checks, each body's slice of `q`
//! and `v`, its transform `ˡⁱMᵢ` (from sines and cosines formed first on
//! hosts), the velocity and pose passes, and the supporting coordinate
//! ranges of the mass matrix, and the Newton-Euler body steps
//! ([`newton_euler`]). An algorithm imports these from here, never from
//! another algorithm's file, so that each algorithm file holds only its
//! own passes.

mod newton_euler;

pub(crate) use newton_euler::{backward_force_pass_with, forward_body};

use crate::data::Data;
use crate::error::{Quantity, Result};
use crate::joint::JointModel;
use crate::model::{check_finite, Model};
use crate::space::{RigidTransform, Space, VectorOps};
use crate::topology::Topology;
use crate::tuning::TURNED_POSES;
use crate::Scalar;

/// Checks that external forces are finite.
pub(crate) fn check_external<S: Scalar, F: VectorOps<S>>(f_ext: Option<&[F]>) -> Result<()> {
    if let Some(f) = f_ext {
        if let Some(index) = f.iter().position(|f| !f.is_finite()) {
            return Err(crate::Error::NonFinite {
                quantity: Quantity::ExternalForce,
                index,
            });
        }
    }
    Ok(())
}

/// Joint transform and placement of body `i`: `ˡⁱMᵢ = placement · jMi(q)`.
///
/// Inlined into each algorithm: with the firmware at opt-level 3 that saves
/// the Panda instructions on every body (its bounds checks fold into the
/// algorithm's loop) for some of the pendulum's flash. (At opt-level "s"
/// one shared out-of-line copy is the better trade.) Figures: the
/// performance notebook, "Cortex-M4 rounds".
#[inline]
pub(crate) fn body_transform<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    i: usize,
    q: &[S; NQ],
) -> G::Transform<S> {
    model
        .joint(i)
        .placed_transform(model.placement(i), joint_configuration(model, i, q))
}

// Whether the passes over the bodies form the sines and cosines of all the
// joint angles before the bodies' work ([`JointSinCos`]): out of order,
// where each pair's long chain of dependent operations overlaps the
// next pair's; in order, which would only pay for storing them. A choice
// of the tuning profile.
pub(crate) use crate::tuning::ANGLES_FIRST;

/// The sine and cosine of each body's joint angle
/// ([`JointModel::angle`]; a zero angle's for a joint without one), formed
/// in one pass ([`Scalar::sin_cos_array`]).
pub(crate) struct JointSinCos<S, const NB: usize> {
    sin: [S; NB],
    cos: [S; NB],
}

impl<S: Scalar, const NB: usize> JointSinCos<S, NB> {
    /// At configuration `q`; zeros, never read, where [`ANGLES_FIRST`] is
    /// false (see [`formed`](Self::formed)).
    ///
    /// Not an `Option<Self>`: moving the arrays into the option's payload
    /// is a copy the compiler keeps (a call of `memcpy` once they are
    /// large), while the unread zeros of the in-order profile are removed.
    #[inline(always)]
    pub(crate) fn at<const NQ: usize, const NV: usize, G: Space>(
        model: &Model<S, NB, NQ, NV, G>,
        q: &[S; NQ],
    ) -> Self {
        if ANGLES_FIRST {
            Self::from_angles(|i| model.joint(i).angle(joint_configuration(model, i, q)))
        } else {
            Self {
                sin: [S::ZERO; NB],
                cos: [S::ZERO; NB],
            }
        }
    }

    /// `self` where [`ANGLES_FIRST`] formed it, `None` where it did not.
    #[inline(always)]
    pub(crate) fn formed(&self) -> Option<&Self> {
        ANGLES_FIRST.then_some(self)
    }

    /// Of `angle(i)` for each body i, a zero angle's where it is `None`.
    #[inline(always)]
    pub(crate) fn from_angles(angle: impl Fn(usize) -> Option<S>) -> Self {
        let angle = core::array::from_fn(|i| angle(i).unwrap_or(S::ZERO));
        let (sin, cos) = S::sin_cos_array(&angle);
        Self { sin, cos }
    }

    /// Body i's `(sin, cos)`.
    #[inline(always)]
    pub(crate) fn get(&self, i: usize) -> (S, S) {
        (self.sin[i], self.cos[i])
    }
}

/// [`body_transform`], from the sines and cosines in `sin_cos` when given.
#[inline(always)]
pub(crate) fn body_transform_with<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    i: usize,
    q: &[S; NQ],
    sin_cos: Option<&JointSinCos<S, NB>>,
) -> G::Transform<S> {
    match sin_cos {
        // `ANGLES_FIRST` again so that the Cortex-M4's build drops the arm
        // before inlining (it cost its planar forward dynamics instructions;
        // the performance notebook, "Sine and cosine").
        Some(t) if ANGLES_FIRST => model.joint(i).placed_transform_from_sin_cos(
            model.placement(i),
            joint_configuration(model, i, q),
            t.get(i),
        ),
        _ => body_transform(model, i, q),
    }
}

/// Body `i`'s joint configuration: `q` from its first coordinate on (the
/// joints read their `nq` entries from the front, see [`JointModel`]).
///
/// [`JointModel`]: crate::joint::JointModel
#[inline(always)]
pub(crate) fn joint_configuration<
    'q,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    i: usize,
    q: &'q [S; NQ],
) -> &'q [S] {
    // The start is in range (`Model::configuration_range`); the joints
    // check their length (`first_chunk`), so no end is cut here.
    let (iq, _) = model.configuration_range(i);
    &q[iq..]
}

/// Body `i`'s joint rates: `v` (which holds every joint's rates, or
/// accelerations) from its first coordinate on, as [`joint_configuration`].
#[inline(always)]
pub(crate) fn joint_rates<
    'v,
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    i: usize,
    v: &'v [S; NV],
) -> &'v [S] {
    let (iv, _) = model.topology().velocity_range(i);
    &v[iv..]
}

/// Checks `q` (finite, unit quaternions) and `v` (finite).
pub(crate) fn check_state<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
    v: Option<&[S; NV]>,
) -> Result<()> {
    model.check_configuration(q)?;
    if let Some(v) = v {
        check_finite(v, Quantity::Velocity)?;
    }
    Ok(())
}

/// The forward pass shared by the dynamics algorithms: `ˡⁱMᵢ`,
/// `vᵢ = ⁱX_λ v_λ + v_J` and `cᵢ = vᵢ × v_J`. Inputs must already be checked.
///
/// It leaves the world poses `ᵒMᵢ` alone: RNEA and ABA work in body frames
/// and never read them, and composing them costs a 3x3 product per body
/// (a visible share of RNEA on the Cortex-M4; the performance notebook,
/// "Cortex-M4 rounds"). Callers that need poses run
/// [`forward_kinematics`](super::kinematics::forward_kinematics) or
/// [`forward_kinematics_velocity`](super::kinematics::forward_kinematics_velocity).
#[inline]
pub(crate) fn velocity_pass<
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
) {
    for i in 0..NB {
        let (li_m_i, v_i, c_i) = body_velocity(model, data, i, q, v);
        data.c[i] = c_i;
        data.v[i] = v_i;
        data.li_m_i[i] = li_m_i;
    }
}

/// Body `i`'s transform `ˡⁱMᵢ` and velocity `vᵢ = ⁱX_λ v_λ + S q̇ᵢ`, given
/// its parent's velocity in `data.v` (the step every root-to-leaves pass
/// starts a body with).
#[inline(always)]
pub(crate) fn body_velocity<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    i: usize,
    q: &[S; NQ],
    v: &[S; NV],
) -> (G::Transform<S>, G::Motion<S>, G::Motion<S>) {
    let li_m_i = body_transform(model, i, q);
    // Parents precede children (`Topology::try_new`), so `p < i < NB`.
    let v_parent = match model.parent(i).and_then(|p| data.v.get(p)) {
        Some(v_p) => li_m_i.act_inv_motion(v_p),
        None => G::Motion::<S>::ZERO,
    };
    let (v_i, c_i) = model
        .joint(i)
        .velocity_and_bias(&v_parent, joint_rates(model, i, v));
    (li_m_i, v_i, c_i)
}

/// `ᵒMᵢ = ᵒM_λ ˡⁱMᵢ` from the parent transforms already in `data.li_m_i`.
#[inline]
pub(crate) fn pose_pass<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
) {
    for i in 0..NB {
        data.o_m_i[i] = match model.parent(i) {
            Some(p) => {
                // A valid topology's parent is a body (`p < i`); one that
                // is not stops the pass.
                let Some(o_m_p) = data.o_m_i.get(p) else {
                    return;
                };
                G::then_joint(o_m_p, &data.li_m_i[i], model.joint(i))
            }
            None => data.li_m_i[i],
        };
    }
}

/// Body poses at `q` (as [`forward_kinematics`](super::kinematics::forward_kinematics): `data.li_m_i`,
/// `data.o_m_i`), the joint angles' sines and cosines formed first on
/// hosts: the centroidal map's and, out of order, the joint Jacobians'.
/// `q` must already be checked.
#[inline]
pub(crate) fn poses<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
) {
    let sin_cos = JointSinCos::at(model, q);
    let mut previous = <G::Transform<S> as RigidTransform<S>>::IDENTITY;
    if TURNED_POSES {
        // Out of order, the joint transforms first, in a loop of their
        // own, so that the chain's products have the registers to
        // themselves (formed beside them, each transform and the parent's
        // pose spilled each other, and the quarter-turn products of
        // `then_turned_joint` saved nothing); each then read by reference,
        // so that a product loads only the entries it uses.
        for i in 0..NB {
            data.li_m_i[i] = body_transform_with(model, i, q, sin_cos.formed());
        }
        for i in 0..NB {
            let li_m_i = &data.li_m_i[i];
            previous = match chain_parent(model, &data.o_m_i, i, previous) {
                Some(o_m_p) => G::then_turned_joint(&o_m_p, li_m_i, model.joint(i)),
                None => *li_m_i,
            };
            data.o_m_i[i] = previous;
        }
        return;
    }
    for i in 0..NB {
        let li_m_i = body_transform_with(model, i, q, sin_cos.formed());
        previous = match chain_parent(model, &data.o_m_i, i, previous) {
            Some(o_m_p) => G::then_joint(&o_m_p, &li_m_i, model.joint(i)),
            None => li_m_i,
        };
        data.li_m_i[i] = li_m_i;
        data.o_m_i[i] = previous;
    }
}

/// Body i's parent's pose for [`poses`]: `previous` (body i - 1's) when
/// that is the parent, else the stored one.
///
/// [`pose_step`]'s choice of the parent's pose, made on values: a
/// reference to either the previous pose or a stored one made the previous
/// pose go through the stack behind a general placement. (`pose_step`,
/// whose callers read the pose beside other work, keeps the reference.)
#[inline(always)]
fn chain_parent<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    o_m_i: &[G::Transform<S>; NB],
    i: usize,
    previous: G::Transform<S>,
) -> Option<G::Transform<S>> {
    match model.parent(i) {
        Some(p) if p + 1 == i => Some(previous),
        Some(p) => o_m_i.get(p).copied(),
        None => None,
    }
}

/// Body i's `ˡⁱMᵢ` and `ᵒMᵢ` into `data`, its parent's pose already there;
/// returns `ᵒMᵢ`. `previous`, when given, is body i - 1's pose (anything
/// at body 0), read instead of `data` when it is the parent: a chain's step then
/// starts from registers rather than from the pose just stored, which the
/// processor may not forward to loads laid out otherwise than the stores.
#[inline(always)]
pub(crate) fn pose_step<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    i: usize,
    q: &[S; NQ],
    sin_cos: Option<&JointSinCos<S, NB>>,
    previous: Option<&G::Transform<S>>,
) -> G::Transform<S> {
    let li_m_i = body_transform_with(model, i, q, sin_cos);
    let parent = model.parent(i).and_then(|p| match previous {
        Some(x) if p + 1 == i => Some(x),
        _ => data.o_m_i.get(p),
    });
    let o_m_i = match parent {
        Some(o_m_p) => G::then_joint(o_m_p, &li_m_i, model.joint(i)),
        None => li_m_i,
    };
    data.li_m_i[i] = li_m_i;
    data.o_m_i[i] = o_m_i;
    o_m_i
}

/// The ranges of coordinates that support coordinate `k` (`k` included),
/// from `k` towards the root: `(first, last)` pairs, each one unbroken
/// stretch of the λ chain (see [`TopologyTables::chain_start_v`]).
///
/// [`TopologyTables::chain_start_v`]: crate::topology::TopologyTables::chain_start_v
#[inline]
pub(crate) fn supporting_ranges<const NB: usize, const NV: usize>(
    topology: &Topology<NB, NV>,
    k: Option<usize>,
) -> impl Iterator<Item = (usize, usize)> + '_ {
    let mut last = k;
    core::iter::from_fn(move || {
        let end = last?;
        // `end` is a coordinate (`Topology::lambda` is below its argument,
        // which the caller takes in range); a test the optimiser removes
        // where it knows that.
        if end >= NV {
            return None;
        }
        let first = topology.chain_start(end);
        last = topology.lambda(first);
        Some((first, end))
    })
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::{
        body_transform, body_transform_with, joint_configuration, JointSinCos, ANGLES_FIRST,
    };
    use crate::joint::{Axis, Joint, JointModel};
    use crate::planar::{PlanarInertia, PlanarJoint, PlanarMotion, PlanarTransform, Vec2};
    use crate::space::Space;
    use crate::spatial::{Inertia, Mat3, Motion, Sym3, Transform, Vec3};
    use crate::Model;

    /// The sines and cosines formed first, as the passes form them in the
    /// out-of-order profile (`JointSinCos::at`), whatever the profile.
    fn formed_first<const NB: usize, const NQ: usize, const NV: usize, G: Space>(
        model: &Model<f64, NB, NQ, NV, G>,
        q: &[f64; NQ],
    ) -> JointSinCos<f64, NB> {
        let sin_cos = JointSinCos::at(model, q);
        assert_eq!(sin_cos.formed().is_some(), ANGLES_FIRST);
        if ANGLES_FIRST {
            sin_cos
        } else {
            JointSinCos::from_angles(|i| model.joint(i).angle(joint_configuration(model, i, q)))
        }
    }

    /// Body i's transform from `sin_cos`, as [`body_transform_with`] forms
    /// it in the out-of-order profile.
    fn from_sin_cos<const NB: usize, const NQ: usize, const NV: usize, G: Space>(
        model: &Model<f64, NB, NQ, NV, G>,
        i: usize,
        q: &[f64; NQ],
        sin_cos: &JointSinCos<f64, NB>,
    ) -> G::Transform<f64> {
        if ANGLES_FIRST {
            body_transform_with(model, i, q, Some(sin_cos))
        } else {
            model.joint(i).placed_transform_from_sin_cos(
                model.placement(i),
                joint_configuration(model, i, q),
                sin_cos.get(i),
            )
        }
    }

    /// The transforms from the sines and cosines formed first are those
    /// formed body by body, bit for bit, for every joint type. In both
    /// tuning profiles: the in-order one does not form them first
    /// (`JointSinCos::at` gives `None`), but the kernels are the same.
    #[test]
    fn transforms_from_the_angles_formed_first_are_the_same() {
        let tilted = Mat3::from_axis_angle(&Vec3::new(0.6, 0.0, 0.8), 0.4);
        let spatial: Model<f64, 5, 11, 10, _> = Model::new(
            [None, Some(0), Some(1), Some(2), Some(3)],
            [
                Joint::free_flyer(),
                Joint::revolute(Axis::Y),
                Joint::revolute(Axis::Unit(Vec3::new(0.0, 0.6, 0.8))),
                Joint::prismatic(Axis::X),
                Joint::revolute(Axis::Z),
            ],
            [Transform::new(tilted, Vec3::new(0.1, -0.2, 0.3)); 5],
            [Inertia::new(1.0, Vec3::new(0.1, 0.0, 0.0), Sym3::diagonal(0.1, 0.2, 0.3)); 5],
            Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
        );
        let mut q = [0.7, -0.3, 0.2, 0.0, 0.6, 0.0, 0.8, 2.9, -7.4, 0.35, 1.0e6];
        q[3..7].copy_from_slice(&[0.0, 0.6, 0.0, 0.8]);
        let sin_cos = formed_first(&spatial, &q);
        for i in 0..5 {
            let (a, b) = (
                from_sin_cos(&spatial, i, &q, &sin_cos),
                body_transform(&spatial, i, &q),
            );
            assert_eq!(a, b, "body {i}");
        }
        let planar: Model<f64, 3, 3, 3, _> = Model::new_planar(
            [None, Some(0), Some(1)],
            [
                PlanarJoint::Revolute,
                PlanarJoint::Prismatic(Vec2::new(0.6, 0.8)),
                PlanarJoint::Revolute,
            ],
            [PlanarTransform::from_angle(0.3, Vec2::new(0.5, 0.1)); 3],
            [PlanarInertia::new(1.0, Vec2::new(0.2, 0.0), 0.1); 3],
            PlanarMotion::new(0.0, Vec2::new(0.0, -9.81)),
        );
        let q = [-2.2, 0.4, 4.1];
        let sin_cos = formed_first(&planar, &q);
        for i in 0..3 {
            let (a, b) = (
                from_sin_cos(&planar, i, &q, &sin_cos),
                body_transform(&planar, i, &q),
            );
            assert_eq!(a, b, "planar body {i}");
        }
    }

    /// The poses of the centroidal map (`poses`) are the book's
    /// `ᵒMᵢ = ᵒM_λ ˡⁱMᵢ`, bit for bit, for a tree whose placements are
    /// quarter turns about each axis, half turns, the identity and a
    /// general rotation, behind every kind of joint, in `f64` and `f32`.
    #[test]
    fn poses_are_the_composition() {
        use crate::spatial::AxisPermutation;
        let turn = |rows| AxisPermutation::from_rows(rows).matrix::<f64>();
        let placements = [
            Transform::from_translation(Vec3::new(0.0, 0.0, 0.3)),
            Transform::new(turn([[1, 0, 0], [0, 0, 1], [0, -1, 0]]), Vec3::ZERO),
            Transform::new(
                turn([[1, 0, 0], [0, 0, -1], [0, 1, 0]]),
                Vec3::new(0.0, -0.3, 0.0),
            ),
            Transform::new(
                turn([[0, 0, 1], [0, 1, 0], [-1, 0, 0]]),
                Vec3::new(0.1, 0.0, 0.0),
            ),
            Transform::new(
                turn([[0, -1, 0], [1, 0, 0], [0, 0, 1]]),
                Vec3::new(0.0, 0.2, 0.1),
            ),
            Transform::new(
                turn([[-1, 0, 0], [0, -1, 0], [0, 0, 1]]),
                Vec3::new(0.2, 0.0, 0.0),
            ),
            Transform::new(
                turn([[0, 1, 0], [0, 0, 1], [1, 0, 0]]),
                Vec3::new(0.0, 0.0, -0.2),
            ),
            Transform::new(
                Mat3::from_axis_angle(&Vec3::new(0.6, 0.0, 0.8), 0.4),
                Vec3::new(0.1, -0.2, 0.3),
            ),
            Transform::new(
                turn([[1, 0, 0], [0, -1, 0], [0, 0, -1]]),
                Vec3::new(0.0, 0.1, 0.0),
            ),
        ];
        let model: Model<f64, 9, 14, 13, _> = Model::new(
            [
                None,
                Some(0),
                Some(1),
                Some(2),
                Some(1),
                Some(4),
                Some(5),
                Some(0),
                Some(7),
            ],
            [
                Joint::free_flyer(),
                Joint::revolute(Axis::Z),
                Joint::revolute(Axis::Z),
                Joint::revolute(Axis::Y),
                Joint::revolute(Axis::X),
                Joint::prismatic(Axis::Z),
                Joint::revolute(Axis::Unit(Vec3::new(0.0, 0.6, 0.8))),
                Joint::revolute(Axis::X),
                Joint::Fixed,
            ],
            placements,
            [Inertia::new(1.0, Vec3::new(0.1, 0.0, 0.0), Sym3::diagonal(0.1, 0.2, 0.3)); 9],
            Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
        );
        let mut state = 3u64;
        for _ in 0..crate::test_points(50, 2) {
            let mut q = [0.0; 14];
            for v in &mut q {
                state = state
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                *v = ((state >> 11) as f64 / (1u64 << 53) as f64) * 8.0 - 4.0;
            }
            let n = q[3..7].iter().map(|v| v * v).sum::<f64>().sqrt();
            q[3..7].iter_mut().for_each(|v| *v /= n);
            check_poses(&model, &q);
            check_poses(&model.cast::<f32>().unwrap(), &q.map(|v| v as f32));
        }
    }

    /// `poses` against the composition of the joint transforms.
    fn check_poses<S: crate::Scalar, const NB: usize, const NQ: usize, const NV: usize>(
        model: &Model<S, NB, NQ, NV>,
        q: &[S; NQ],
    ) {
        use crate::space::RigidTransform;
        let mut data = crate::Data::new();
        super::poses(model, &mut data, q);
        let mut book = [Transform::IDENTITY; NB];
        for i in 0..NB {
            let x = body_transform(model, i, q);
            book[i] = model.parent(i).map_or(x, |p| book[p].compose(&x));
            assert_eq!(data.li_m_i[i], x, "body {i}");
            assert_eq!(data.o_m_i[i], book[i], "body {i}");
        }
    }

    /// A free flyer behind a placement without rotation (the usual
    /// floating base) takes a shortcut past the composition; its transform
    /// is still the composition's, bit for bit, with and without an offset,
    /// and a turned placement still composes.
    #[test]
    fn free_flyer_behind_an_unturned_placement_is_the_composition() {
        use crate::space::RigidTransform;
        let joint: Joint<f64> = Joint::free_flyer();
        let q = [0.7, -0.3, 0.2, 0.0, 0.6, 0.0, 0.8];
        let turned = Mat3::from_axis_angle(&Vec3::new(0.6, 0.0, 0.8), 0.4);
        for placement in [
            Transform::IDENTITY,
            Transform::from_translation(Vec3::new(0.1, -2.5, 0.03)),
            Transform::new(turned, Vec3::new(0.1, -2.5, 0.03)),
        ] {
            let expected = placement.compose(
                &JointModel::<f64, crate::spatial::Spatial>::transform(&joint, &q),
            );
            assert_eq!(joint.placed_transform(&placement, &q), expected);
        }
    }
}
