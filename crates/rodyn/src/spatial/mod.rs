//! Featherstone's 6-D spatial algebra for models in 3-D space.
//!
//! One concept per file: [`Motion`], [`Force`], [`Transform`], [`Inertia`],
//! [`ArticulatedInertia6`], [`AxisPermutation`], and the 3-D building
//! blocks [`Vec3`], [`Mat3`], [`Sym3`]. [`Spatial`] ties them together as
//! a [`Geometry`].

mod articulated;
pub(crate) mod axis_permutation;
mod force;
mod inertia;
mod log;
mod mat3;
mod motion;
mod parameter_problem;
mod sym3;
mod transform;
mod vec3;

pub use articulated::ArticulatedInertia6;
pub use axis_permutation::AxisPermutation;
pub use force::Force;
pub use inertia::Inertia;
pub use log::{log3, log6};
pub use mat3::Mat3;
pub use motion::Motion;
pub use parameter_problem::ParameterProblem;
pub use sym3::Sym3;
pub use transform::Transform;
pub use vec3::Vec3;

use crate::error::ModelProblem;
use crate::joint::Joint;
use crate::space::{Geometry, RigidTransform};
use crate::Scalar;

/// Full 3-D space: 6-D motion and force vectors.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Spatial;

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
        use crate::joint::JointModel;
        // A revolute joint about a coordinate axis behind a placement
        // without rotation (or one about the same axis) turns two of its
        // parent's columns by the angle whose cosine and sine are entries
        // of `x`'s rotation: the product with `x` would only add exact
        // zeros besides. `x` itself says whether it has that form, so that
        // kinematics needs no per-model plan.
        let rot = match joint.revolute_axis_index() {
            Some(0) if turns_about::<S, 0>(&x.rot) => {
                parent
                    .rot
                    .mul_axis_rotation(0, x.rot.m[2][1], x.rot.m[1][1])
            }
            Some(1) if turns_about::<S, 1>(&x.rot) => {
                parent
                    .rot
                    .mul_axis_rotation(1, x.rot.m[0][2], x.rot.m[2][2])
            }
            Some(2) if turns_about::<S, 2>(&x.rot) => {
                parent
                    .rot
                    .mul_axis_rotation(2, x.rot.m[1][0], x.rot.m[0][0])
            }
            _ => return parent.compose(x),
        };
        Transform::new(rot, parent.act_point(&x.trans))
    }
}

/// `true` when `rot` is exactly a rotation about coordinate axis `K`: its
/// row and column K are `e_K`, and its plane block is `[[c, -s], [s, c]]`
/// entry for entry. The column first: behind a quarter turn about
/// another axis it fails at once.
#[inline(always)]
fn turns_about<S: Scalar, const K: usize>(rot: &Mat3<S>) -> bool {
    let (a, b) = ((K + 1) % 3, (K + 2) % 3);
    let m = &rot.m;
    m[K][K] == S::ONE
        && m[a][K] == S::ZERO
        && m[b][K] == S::ZERO
        && m[K][a] == S::ZERO
        && m[K][b] == S::ZERO
        && m[b][b] == m[a][a]
        && m[a][b] == -m[b][a]
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use crate::joint::{Axis, Joint};
    use crate::space::{Geometry, RigidTransform};
    use crate::spatial::{AxisPermutation, Mat3, Spatial, Transform, Vec3};

    /// `Spatial::then_joint` gives the composition `parent x`, bit for bit,
    /// behind every kind of placement (the identity, a quarter turn, a
    /// general rotation, one about z) for joints about each coordinate
    /// axis and others.
    #[test]
    fn then_joint_is_the_composition() {
        let parent = Transform::new(
            Mat3::from_axis_angle(&Vec3::new(0.36, -0.48, 0.8), 0.9),
            Vec3::new(0.4, -1.3, 0.7),
        );
        let quarter = AxisPermutation::from_rows([[1, 0, 0], [0, 0, -1], [0, 1, 0]]);
        let joints = [
            Joint::revolute(Axis::X),
            Joint::revolute(Axis::Y),
            Joint::revolute(Axis::Z),
            Joint::revolute(Axis::Unit(Vec3::new(0.0, 0.6, 0.8))),
            Joint::prismatic(Axis::Y),
        ];
        let rotations = [
            Mat3::IDENTITY,
            quarter.matrix(),
            Mat3::from_axis_angle(&Vec3::new(0.6, 0.0, 0.8), 0.4),
            Mat3::from_axis_index(2, 0.3f64.sin(), 0.3f64.cos()),
        ];
        for rot in rotations {
            for joint in &joints {
                use crate::joint::JointModel;
                let placement = Transform::new(rot, Vec3::new(0.1, -0.25, 0.3));
                for q in [0.0, 0.7, -2.9] {
                    let x = joint.placed_transform(&placement, &[q]);
                    assert_eq!(
                        Spatial::then_joint(&parent, &x, joint),
                        parent.compose(&x),
                        "{rot:?} {joint:?} {q}"
                    );
                }
            }
        }
    }
}
