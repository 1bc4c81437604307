//! 3-D space as a [`Geometry`]: the spatial algebra's types with the
//! closed set of 3-D joints, [`Joint`]. The algebra's traits on those types
//! are in `space/spatial.rs`; this impl, which names the joints, stands
//! with them, a layer above.

use super::Joint;
use crate::error::ModelProblem;
use crate::space::{Geometry, RigidTransform};
use crate::spatial::{ArticulatedInertia6, Force, Inertia, Mat3, Motion, Spatial, Transform, Vec3};
use crate::Scalar;

impl Geometry for Spatial {
    const DIM: usize = 6;
    type Motion<S: Scalar> = Motion<S>;
    type Force<S: Scalar> = Force<S>;
    type Point<S: Scalar> = Vec3<S>;
    type Transform<S: Scalar> = Transform<S>;
    type Inertia<S: Scalar> = Inertia<S>;
    type Articulated<S: Scalar> = ArticulatedInertia6<S>;
    type Joint<S: Scalar> = Joint<S>;

    fn default_joint<S: Scalar>() -> Joint<S> {
        Joint::Fixed
    }
    fn cast_joint<S: Scalar, T: Scalar>(j: &Joint<S>) -> Option<Joint<T>> {
        j.cast()
    }
    fn point_is_finite<S: Scalar>(p: &Vec3<S>) -> bool {
        p.is_finite()
    }
    fn cast_transform<S: Scalar, T: Scalar>(x: &Transform<S>) -> Transform<T> {
        x.cast()
    }
    fn cast_inertia<S: Scalar, T: Scalar>(i: &Inertia<S>) -> Inertia<T> {
        i.cast()
    }
    fn cast_motion<S: Scalar, T: Scalar>(m: &Motion<S>) -> Motion<T> {
        Motion::new(m.ang.cast(), m.lin.cast())
    }
    fn validate_inertia<S: Scalar>(i: &Inertia<S>) -> Result<(), ModelProblem> {
        i.validate().map_err(ModelProblem::from)
    }
    fn validate_transform<S: Scalar>(x: &Transform<S>) -> Result<(), ModelProblem> {
        x.validate().map_err(ModelProblem::from)
    }
    fn validate_joint<S: Scalar>(j: &Joint<S>) -> Result<(), ModelProblem> {
        let axis = match j {
            Joint::Revolute(r) => r.axis,
            Joint::Prismatic(p) => p.axis,
            _ => return Ok(()),
        };
        let n = axis.vector().norm_squared().to_f64();
        if (n - 1.0).abs() > 1e3 * S::EPSILON {
            Err(ModelProblem::AxisNotUnit)
        } else {
            Ok(())
        }
    }
    #[inline(always)]
    fn then_joint<S: Scalar>(
        parent: &Transform<S>,
        x: &Transform<S>,
        joint: &Joint<S>,
    ) -> Transform<S> {
        joint_step::<S, false>(parent, x, joint)
    }
    #[inline(always)]
    fn then_turned_joint<S: Scalar>(
        parent: &Transform<S>,
        x: &Transform<S>,
        joint: &Joint<S>,
    ) -> Transform<S> {
        joint_step::<S, true>(parent, x, joint)
    }
}

/// `parent x` for [`Geometry::then_joint`] (`TURNS` false) and
/// [`Geometry::then_turned_joint`] (`TURNS` true).
///
/// A revolute joint about a coordinate axis behind a placement without
/// rotation (or one about the same axis) leaves that axis alone: only two
/// of its parent's columns mix, through the plane block of `x`'s rotation;
/// the product with `x` would only add exact zeros besides. With `TURNS`,
/// behind a quarter turn that carries the joint's axis onto another
/// coordinate axis, the product likewise skips the zeros of `x`. `x`
/// itself says whether it has such a form, so that kinematics needs no
/// per-model plan.
#[inline(always)]
fn joint_step<S: Scalar, const TURNS: bool>(
    parent: &Transform<S>,
    x: &Transform<S>,
    joint: &Joint<S>,
) -> Transform<S> {
    use crate::joint::JointModel;
    let (p, r) = (&parent.rot, &x.rot);
    let rot = match joint.revolute_axis_index() {
        Some(0) if keeps_axis::<S, 0>(r) => p.mul_plane_block::<1, 2>(r),
        Some(0) if TURNS && carries_axis::<S, 0, 2>(r) => p.mul_carried_axis::<0, 2>(r),
        Some(0) if TURNS && carries_axis::<S, 0, 1>(r) => p.mul_carried_axis::<0, 1>(r),
        Some(1) if keeps_axis::<S, 1>(r) => p.mul_plane_block::<2, 0>(r),
        Some(1) if TURNS && carries_axis::<S, 1, 0>(r) => p.mul_carried_axis::<1, 0>(r),
        Some(1) if TURNS && carries_axis::<S, 1, 2>(r) => p.mul_carried_axis::<1, 2>(r),
        Some(2) if keeps_axis::<S, 2>(r) => p.mul_plane_block::<0, 1>(r),
        Some(2) if TURNS && carries_axis::<S, 2, 1>(r) => p.mul_carried_axis::<2, 1>(r),
        Some(2) if TURNS && carries_axis::<S, 2, 0>(r) => p.mul_carried_axis::<2, 0>(r),
        _ => return parent.compose(x),
    };
    Transform::new(rot, parent.act_point(&x.trans))
}

/// `true` when `rot` leaves coordinate axis `K` exactly where it is: its
/// row and column K are `e_K` (a rotation about K, the identity
/// included).
#[inline(always)]
fn keeps_axis<S: Scalar, const K: usize>(rot: &Mat3<S>) -> bool {
    let (a, b) = ((K + 1) % 3, (K + 2) % 3);
    let m = &rot.m;
    m[K][K] == S::ONE && S::all_zero([m[a][K], m[b][K], m[K][a], m[K][b]])
}

/// `true` when `rot` carries coordinate axis `K` onto axis `U` with no
/// other entry in row U or column K (a quarter turn that takes K to ±U,
/// then a rotation about K).
#[inline(always)]
fn carries_axis<S: Scalar, const K: usize, const U: usize>(rot: &Mat3<S>) -> bool {
    let (i, j) = ((K + 1) % 3, (K + 2) % 3);
    let (a, b) = ((U + 1) % 3, (U + 2) % 3);
    let m = &rot.m;
    S::all_zero([m[a][K], m[b][K], m[U][i], m[U][j]])
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use crate::joint::{Axis, Joint};
    use crate::space::{Geometry, RigidTransform};
    use crate::spatial::{AxisPermutation, Mat3, Spatial, Transform, Vec3};

    /// The 24 rotations that carry coordinate axes onto coordinate axes.
    fn quarter_turns() -> Vec<AxisPermutation> {
        crate::spatial::axis_permutation::all_for_tests()
    }

    /// A pseudo-random number in [-1, 1) (a fixed sequence).
    fn next(state: &mut u64) -> f64 {
        *state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((*state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }

    /// `Spatial::then_joint` and `then_turned_joint` give the composition
    /// `parent x`, bit for bit, behind every kind of placement (the
    /// identity, each of the 24 quarter and half turns, general rotations,
    /// rotations about a coordinate axis) for every kind of joint, at
    /// random parents and joint positions, in `f64` and `f32`.
    #[test]
    fn then_joint_is_the_composition() {
        let joints = [
            Joint::revolute(Axis::X),
            Joint::revolute(Axis::Y),
            Joint::revolute(Axis::Z),
            Joint::revolute(Axis::Unit(Vec3::new(0.0, 0.6, 0.8))),
            Joint::prismatic(Axis::Y),
            Joint::prismatic(Axis::Unit(Vec3::new(0.6, 0.0, 0.8))),
            Joint::Fixed,
            Joint::free_flyer(),
        ];
        let mut rotations: Vec<Mat3<f64>> = quarter_turns().iter().map(|p| p.matrix()).collect();
        rotations.extend([
            Mat3::from_axis_angle(&Vec3::new(0.6, 0.0, 0.8), 0.4),
            Mat3::from_axis_index(2, 0.3f64.sin(), 0.3f64.cos()),
            Mat3::from_axis_angle(&Vec3::new(0.0, 0.0, 1.0), -1.1),
            Mat3::from_axis_angle(&Vec3::new(1.0, 0.0, 0.0), 0.8),
        ]);
        let mut state = 7;
        for rot in rotations {
            for joint in &joints {
                for _ in 0..crate::test_points(20, 1) {
                    let mut r = || next(&mut state);
                    let axis = Vec3::new(r(), r(), r() + 1.5);
                    let parent = Transform::new(
                        Mat3::from_axis_angle(&axis.scale(1.0 / axis.norm()), 3.0 * r()),
                        Vec3::new(r(), r(), r()),
                    );
                    let placement = Transform::new(rot, Vec3::new(r(), 0.0, r()));
                    let (w, x, y) = (r(), r(), r());
                    let n = (w * w + x * x + y * y + 0.25).sqrt();
                    let q = [4.0 * r(), r(), r(), x / n, y / n, 0.5 / n, w / n];
                    check(joint, &parent, &placement, &q);
                    let joint32 = joint.cast::<f32>().unwrap();
                    let q32 = q.map(|v| v as f32);
                    check(&joint32, &parent.cast(), &placement.cast(), &q32);
                }
            }
        }
    }

    /// Both steps against the composition at one state.
    fn check<S: crate::Scalar>(
        joint: &Joint<S>,
        parent: &Transform<S>,
        placement: &Transform<S>,
        q: &[S],
    ) {
        use crate::joint::JointModel;
        let x = joint.placed_transform(placement, q);
        let book = parent.compose(&x);
        assert_eq!(
            Spatial::then_joint(parent, &x, joint),
            book,
            "{placement:?} {joint:?}"
        );
        assert_eq!(
            Spatial::then_turned_joint(parent, &x, joint),
            book,
            "{placement:?} {joint:?}"
        );
    }
}
