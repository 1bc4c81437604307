//! The planar joints' motion: [`PlanarJoint`] (defined with the planar
//! algebra, `rodyn::planar`) as a [`JointModel`] of the plane.

use super::{ConfigurationError, JointModel};
use crate::planar::{
    ArticulatedInertia3, Planar, PlanarForce, PlanarJoint, PlanarMotion, PlanarTransform, Vec2,
};
use crate::Scalar;

impl<S: Scalar> JointModel<S, Planar> for PlanarJoint<S> {
    #[inline]
    fn nq(&self) -> usize {
        self.const_nq()
    }
    #[inline]
    fn nv(&self) -> usize {
        self.const_nv()
    }
    #[inline]
    fn transform(&self, q: &[S]) -> PlanarTransform<S> {
        match self {
            Self::Revolute => PlanarTransform::from_angle(q[0], Vec2::ZERO),
            Self::Prismatic(a) => PlanarTransform::from_translation(*a * q[0]),
            Self::Fixed => PlanarTransform::from_translation(Vec2::ZERO),
            Self::Floating => PlanarTransform::from_angle(q[2], Vec2::new(q[0], q[1])),
        }
    }
    #[inline(always)]
    fn angle(&self, q: &[S]) -> Option<S> {
        matches!(self, Self::Revolute).then(|| q[0])
    }
    #[inline(always)]
    fn placed_transform_from_sin_cos(
        &self,
        placement: &PlanarTransform<S>,
        q: &[S],
        (sin, cos): (S, S),
    ) -> PlanarTransform<S> {
        match self {
            Self::Revolute => crate::space::RigidTransform::compose(
                placement,
                &PlanarTransform::from_cos_sin(cos, sin, Vec2::ZERO),
            ),
            _ => self.placed_transform(placement, q),
        }
    }
    #[inline]
    fn motion(&self, qd: &[S]) -> PlanarMotion<S> {
        match self {
            Self::Revolute => PlanarMotion::new(qd[0], Vec2::ZERO),
            Self::Prismatic(a) => PlanarMotion::new(S::ZERO, *a * qd[0]),
            Self::Fixed => PlanarMotion::new(S::ZERO, Vec2::ZERO),
            Self::Floating => PlanarMotion::new(qd[2], Vec2::new(qd[0], qd[1])),
        }
    }
    #[inline]
    fn subspace_column(&self, k: usize) -> PlanarMotion<S> {
        match self {
            Self::Floating => {
                let mut e = [S::ZERO; 3];
                e[k] = S::ONE;
                self.motion(&e)
            }
            _ => self.motion(&[S::ONE]),
        }
    }
    #[inline]
    fn project_force(&self, f: &PlanarForce<S>, out: &mut [S]) {
        match self {
            Self::Revolute => out[0] = f.ang,
            Self::Prismatic(a) => out[0] = a.dot(&f.lin),
            Self::Fixed => {}
            Self::Floating => {
                out[0] = f.lin.x;
                out[1] = f.lin.y;
                out[2] = f.ang;
            }
        }
    }
    #[inline]
    fn articulated_columns(&self, ia: &ArticulatedInertia3<S>, u: &mut [PlanarForce<S>]) {
        let col = |k: usize| {
            let c = ia.m.column(k);
            PlanarForce::new(c.x, Vec2::new(c.y, c.z))
        };
        match self {
            Self::Revolute => u[0] = col(0),
            Self::Prismatic(a) => u[0] = col(1) * a.x + col(2) * a.y,
            Self::Fixed => {}
            Self::Floating => {
                u[0] = col(1);
                u[1] = col(2);
                u[2] = col(0);
            }
        }
    }
    fn neutral(&self, q: &mut [S]) {
        q[..self.const_nq()].fill(S::ZERO);
    }
    fn integrate(&self, q: &[S], v: &[S], dt: S, out: &mut [S]) {
        match self {
            Self::Revolute | Self::Prismatic(_) => out[0] = q[0] + v[0] * dt,
            Self::Fixed => {}
            Self::Floating => {
                // Exponential map of SE(2): the body-frame displacement of a
                // constant twist, rotated into the parent.
                let th = v[2] * dt;
                let (s, c) = th.sin_cos();
                let small = th.abs() < S::from_f64(1e-6);
                let (a, b) = if small {
                    (S::ONE - th * th / S::from_f64(6.0), th * S::from_f64(0.5))
                } else {
                    (s / th, (S::ONE - c) / th)
                };
                let (vx, vy) = (v[0] * dt, v[1] * dt);
                let local = Vec2::new(a * vx - b * vy, b * vx + a * vy);
                let here = PlanarTransform::from_angle(q[2], Vec2::new(q[0], q[1]));
                let p = here.act_point_public(&local);
                out[0] = p.x;
                out[1] = p.y;
                out[2] = q[2] + th;
            }
        }
    }
    fn configuration_rate(&self, q: &[S], v: &[S], q_dot: &mut [S]) {
        match self {
            Self::Revolute | Self::Prismatic(_) => q_dot[0] = v[0],
            Self::Fixed => {}
            Self::Floating => {
                // [x y θ] with [vx vy ω] in the body frame.
                let (s, c) = q[2].sin_cos();
                q_dot[0] = c * v[0] - s * v[1];
                q_dot[1] = s * v[0] + c * v[1];
                q_dot[2] = v[2];
            }
        }
    }
    fn check_configuration(&self, q: &[S]) -> Result<(), ConfigurationError> {
        if q[..self.const_nq()].iter().all(|x| x.is_finite()) {
            Ok(())
        } else {
            Err(ConfigurationError::NonFinite)
        }
    }
    /// Every planar joint accepts any finite `q` (angles, not quaternions).
    #[inline]
    fn constrains_configuration(&self) -> bool {
        false
    }
    fn normalize(&self, _q: &mut [S]) {}
}

impl<S: Scalar> PlanarTransform<S> {
    fn act_point_public(&self, p: &Vec2<S>) -> Vec2<S> {
        self.rotate(p) + self.trans
    }
}
