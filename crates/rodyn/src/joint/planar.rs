//! The planar joints' motion: [`PlanarJoint`] (defined with the planar
//! algebra, `rodyn::planar`) as a [`JointModel`] of the plane.

use super::{first, set_first, ConfigurationError, JointModel};
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
            // The entries from the front, without a panic path (as the 3-D
            // joints read them: see `first`).
            Self::Revolute => PlanarTransform::from_angle(first(q), Vec2::ZERO),
            Self::Prismatic(a) => PlanarTransform::from_translation(*a * first(q)),
            Self::Fixed => PlanarTransform::from_translation(Vec2::ZERO),
            Self::Floating => match q.first_chunk() {
                Some(&[x, y, th]) => PlanarTransform::from_angle(th, Vec2::new(x, y)),
                None => PlanarTransform::from_translation(Vec2::ZERO),
            },
        }
    }
    #[inline(always)]
    fn angle(&self, q: &[S]) -> Option<S> {
        matches!(self, Self::Revolute).then(|| first(q))
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
    // Always inlined: with `first`'s fallbacks `#[inline]` alone left it
    // out of line in places (the muscle robot's forward dynamics +2 %).
    #[inline(always)]
    fn motion(&self, qd: &[S]) -> PlanarMotion<S> {
        match self {
            Self::Revolute => PlanarMotion::new(first(qd), Vec2::ZERO),
            Self::Prismatic(a) => PlanarMotion::new(S::ZERO, *a * first(qd)),
            Self::Fixed => PlanarMotion::new(S::ZERO, Vec2::ZERO),
            // Indexed: every non-panicking read tried here (`first_chunk`,
            // entry by entry, a cold fallback, out of line) cost the muscle
            // robot's forward dynamics (no floating joint) 7 % more
            // instructions on the Cortex-M4; the performance notebook,
            // "Panic paths".
            Self::Floating => PlanarMotion::new(qd[2], Vec2::new(qd[0], qd[1])),
        }
    }
    #[inline]
    fn subspace_column(&self, k: usize) -> PlanarMotion<S> {
        match self {
            Self::Floating => {
                let mut e = [S::ZERO; 3];
                if let Some(e_k) = e.get_mut(k) {
                    *e_k = S::ONE;
                }
                self.motion(&e)
            }
            _ => self.motion(&[S::ONE]),
        }
    }
    #[inline]
    fn project_force(&self, f: &PlanarForce<S>, out: &mut [S]) {
        match self {
            Self::Revolute => set_first(out, f.ang),
            Self::Prismatic(a) => set_first(out, a.dot(&f.lin)),
            Self::Fixed => {}
            Self::Floating => {
                if let Some(out) = out.first_chunk_mut() {
                    *out = [f.lin.x, f.lin.y, f.ang];
                }
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
            Self::Revolute => {
                if let Some(u) = u.first_mut() {
                    *u = col(0);
                }
            }
            Self::Prismatic(a) => {
                if let Some(u) = u.first_mut() {
                    *u = col(1) * a.x + col(2) * a.y;
                }
            }
            Self::Fixed => {}
            Self::Floating => {
                if let Some(u) = u.first_chunk_mut() {
                    *u = [col(1), col(2), col(0)];
                }
            }
        }
    }
    fn neutral(&self, q: &mut [S]) {
        if let Some(q) = q.get_mut(..self.const_nq()) {
            q.fill(S::ZERO);
        }
    }
    fn integrate(&self, q: &[S], v: &[S], dt: S, out: &mut [S]) {
        match self {
            Self::Revolute | Self::Prismatic(_) => set_first(out, first(q) + first(v) * dt),
            Self::Fixed => {}
            Self::Floating => {
                let (Some(&[x, y, angle]), Some(&[vx, vy, w]), Some(out)) =
                    (q.first_chunk(), v.first_chunk(), out.first_chunk_mut())
                else {
                    return;
                };
                // Exponential map of SE(2): the body-frame displacement of a
                // constant twist, rotated into the parent.
                let th = w * dt;
                let (s, c) = th.sin_cos();
                let small = th.abs() < S::from_f64(1e-6);
                let (a, b) = if small {
                    (S::ONE - th * th / S::from_f64(6.0), th * S::from_f64(0.5))
                } else {
                    (s / th, (S::ONE - c) / th)
                };
                let (vx, vy) = (vx * dt, vy * dt);
                let local = Vec2::new(a * vx - b * vy, b * vx + a * vy);
                let here = PlanarTransform::from_angle(angle, Vec2::new(x, y));
                let p = here.act_point_public(&local);
                *out = [p.x, p.y, angle + th];
            }
        }
    }
    fn configuration_rate(&self, q: &[S], v: &[S], q_dot: &mut [S]) {
        match self {
            Self::Revolute | Self::Prismatic(_) => set_first(q_dot, first(v)),
            Self::Fixed => {}
            Self::Floating => {
                let (Some(&[_, _, angle]), Some(&[vx, vy, w]), Some(q_dot)) =
                    (q.first_chunk(), v.first_chunk(), q_dot.first_chunk_mut())
                else {
                    return;
                };
                // [x y θ] with [vx vy ω] in the body frame.
                let (s, c) = angle.sin_cos();
                *q_dot = [c * vx - s * vy, s * vx + c * vy, w];
            }
        }
    }
    fn check_configuration(&self, q: &[S]) -> Result<(), ConfigurationError> {
        // A short slice is checked as far as it goes (see `first`).
        let q = q.get(..self.const_nq()).unwrap_or(q);
        if q.iter().all(|x| x.is_finite()) {
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
