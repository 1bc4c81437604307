//! The planar joints' motion: [`PlanarJoint`] (defined with the planar
//! algebra, `rodyn::planar`) as a [`JointModel`] of the plane.

use super::{first, set_first, ConfigurationError, JointModel};
use crate::planar::{
    ArticulatedInertia3, Planar, PlanarForce, PlanarJoint, PlanarMotion, PlanarTransform, Vec2,
};
use crate::space::MotionVector;
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
            Self::Floating => {
                let [x, y, w] = *qd.first_chunk::<3>().unwrap_or(&[S::ZERO; 3]);
                PlanarMotion::new(w, Vec2::new(x, y))
            }
        }
    }
    // The one-coordinate joints touch only the components they move, as
    // the 3-D joints do.
    #[inline(always)]
    fn add_motion(&self, m: &PlanarMotion<S>, qd: &[S]) -> PlanarMotion<S> {
        match self {
            Self::Revolute => PlanarMotion::new(m.ang + first(qd), m.lin),
            Self::Prismatic(a) => PlanarMotion::new(m.ang, m.lin + *a * first(qd)),
            Self::Fixed => *m,
            Self::Floating => *m + self.motion(qd),
        }
    }
    #[inline(always)]
    fn cross_motion(&self, v: &PlanarMotion<S>, qd: &[S]) -> PlanarMotion<S> {
        match self {
            // v × (ω, 0) = (0, -ω × v_lin) in the plane.
            Self::Revolute => {
                let w = first(qd);
                PlanarMotion::new(S::ZERO, Vec2::new(v.lin.y * w, -(v.lin.x * w)))
            }
            Self::Fixed => PlanarMotion::new(S::ZERO, Vec2::ZERO),
            Self::Prismatic(_) | Self::Floating => v.cross_motion(&self.motion(qd)),
        }
    }
    // One branch on the kind for both: the floating arm, without a panic
    // path since it reads through `first_chunk`, compiled twice per body
    // pushed the velocity passes of small models past the size at which
    // the compiler unrolls them (the performance notebook, "Panic paths").
    #[inline(always)]
    fn velocity_and_bias(
        &self,
        m: &PlanarMotion<S>,
        qd: &[S],
    ) -> (PlanarMotion<S>, PlanarMotion<S>) {
        match self {
            Self::Revolute => {
                let w = first(qd);
                let c = Vec2::new(m.lin.y * w, -(m.lin.x * w));
                (
                    PlanarMotion::new(m.ang + w, m.lin),
                    PlanarMotion::new(S::ZERO, c),
                )
            }
            Self::Fixed => (*m, PlanarMotion::new(S::ZERO, Vec2::ZERO)),
            _ => {
                let s = self.motion(qd);
                let v = *m + s;
                (v, v.cross_motion(&s))
            }
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn written_out_motions_match_the_general_forms() {
        let joints = [
            PlanarJoint::Revolute,
            PlanarJoint::Prismatic(Vec2::new(0.6, -0.8)),
            PlanarJoint::Fixed,
            PlanarJoint::Floating,
        ];
        let m = PlanarMotion::new(0.3_f64, Vec2::new(-1.2, 0.7));
        let rates = [0.9, -0.4, 2.5];
        for joint in joints {
            // Full-length and short slices (a short one reads as zeros).
            for qd in [&rates[..], &rates[..1], &[]] {
                let s = joint.motion(qd);
                let v = m + s;
                let c = v.cross_motion(&s);
                let close = |a: PlanarMotion<f64>, b: PlanarMotion<f64>| {
                    (a.ang - b.ang).abs() < 1e-15 && (a.lin - b.lin).norm_squared() < 1e-30
                };
                assert!(close(joint.add_motion(&m, qd), v), "{joint:?} {qd:?}");
                assert!(close(joint.cross_motion(&v, qd), c), "{joint:?} {qd:?}");
                let (v_i, c_i) = joint.velocity_and_bias(&m, qd);
                assert!(close(v_i, v) && close(c_i, c), "{joint:?} {qd:?}");
            }
        }
        assert_eq!(
            PlanarJoint::Floating.motion(&rates),
            PlanarMotion::new(2.5, Vec2::new(0.9, -0.4))
        );
    }
}
