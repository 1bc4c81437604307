//! CRBA's hooks in the plane: a plane transform is its own prepared step,
//! and a plane has no frames to turn.

use super::{CrbaSpace, TurnedFrame};
use crate::planar::{Planar, PlanarForce, PlanarInertia, PlanarJoint, PlanarTransform};
use crate::space::RigidTransform;
use crate::Scalar;

impl CrbaSpace for Planar {
    // A plane rotation is already two products per vector: nothing to prepare.
    type Step<S: Scalar> = PlanarTransform<S>;
    #[inline(always)]
    fn step<S: Scalar>(x: &PlanarTransform<S>) -> PlanarTransform<S> {
        *x
    }
    #[inline(always)]
    fn joint_step<S: Scalar>(
        j: &PlanarJoint<S>,
        placement: &PlanarTransform<S>,
        q: &[S],
    ) -> PlanarTransform<S> {
        use crate::joint::JointModel;
        j.placed_transform(placement, q)
    }
    /// A revolute joint: its angle.
    #[inline(always)]
    fn step_angle<S: Scalar>(_frame: &TurnedFrame, j: &PlanarJoint<S>, q: &[S]) -> Option<S> {
        matches!(j, PlanarJoint::Revolute).then(|| q[0])
    }
    // Only the out-of-order profile forms the angles first
    // (`crate::tuning::ANGLES_FIRST`); on the Cortex-M4 the extra call site
    // of `compose` cost the muscle robot's forward dynamics instructions
    // through other inlining (see the performance notebook, "Sine and
    // cosine").
    #[cfg(rodyn_tuning = "out_of_order")]
    #[inline(always)]
    fn turned_joint_step<S: Scalar>(
        _frame: &TurnedFrame,
        j: &PlanarJoint<S>,
        placement: &PlanarTransform<S>,
        q: &[S],
        sin_cos: Option<(S, S)>,
    ) -> PlanarTransform<S> {
        match (j, sin_cos) {
            (PlanarJoint::Revolute, Some((sin, cos))) => {
                let rotation = PlanarTransform::from_cos_sin(cos, sin, crate::planar::Vec2::ZERO);
                placement.compose(&rotation)
            }
            _ => Self::joint_step(j, placement, q),
        }
    }
    #[inline(always)]
    fn then_step<S: Scalar>(
        x: &PlanarTransform<S>,
        step: &PlanarTransform<S>,
    ) -> PlanarTransform<S> {
        x.compose(step)
    }
    #[inline(always)]
    fn step_forces<S: Scalar>(x: &PlanarTransform<S>, forces: &mut [PlanarForce<S>]) {
        for f in forces {
            *f = x.act_force(f);
        }
    }
    #[inline(always)]
    fn add_stepped_inertia<S: Scalar>(
        acc: &mut PlanarInertia<S>,
        x: &PlanarTransform<S>,
        i: &PlanarInertia<S>,
    ) {
        // As `PlanarInertia::combine` with `x.act(i)`: its centre of mass
        // moved, `izz` unchanged by a rotation about z.
        let com_i = x.act_point(&i.com);
        let mass = acc.mass + i.mass;
        let inv = S::ONE / mass.max(S::from_f64(S::EPSILON));
        let d = acc.com - com_i;
        acc.izz = acc.izz + i.izz + acc.mass * i.mass * inv * d.norm_squared();
        acc.com = (acc.com * acc.mass + com_i * i.mass) * inv;
        acc.mass = mass;
    }
    #[inline(always)]
    fn inertia_column<S: Scalar>(
        i: &PlanarInertia<S>,
        j: &PlanarJoint<S>,
        k: usize,
    ) -> PlanarForce<S> {
        use crate::joint::JointModel;
        use crate::space::BodyInertia;
        i.mul_motion(&j.subspace_column(k))
    }
}
