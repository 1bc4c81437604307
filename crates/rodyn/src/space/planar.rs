//! The plane as a [`Geometry`]: the planar algebra's types
//! ([`crate::planar`]) behind the traits the algorithms are written
//! against.

use super::{
    ArticulatedInertia, BodyInertia, ForceVector, Geometry, MotionVector, RigidTransform, VectorOps,
};
use crate::error::ModelProblem;
use crate::planar::articulated::{force_vec, motion_vec};
use crate::planar::{
    ArticulatedInertia3, Planar, PlanarForce, PlanarInertia, PlanarJoint, PlanarMotion,
    PlanarTransform, Vec2,
};
use crate::spatial::{Mat3, Sym3};
use crate::Scalar;

impl Geometry for Planar {
    const DIM: usize = 3;
    type Motion<S: Scalar> = PlanarMotion<S>;
    type Force<S: Scalar> = PlanarForce<S>;
    type Point<S: Scalar> = Vec2<S>;
    type Transform<S: Scalar> = PlanarTransform<S>;
    type Inertia<S: Scalar> = PlanarInertia<S>;
    type Articulated<S: Scalar> = ArticulatedInertia3<S>;
    type Joint<S: Scalar> = PlanarJoint<S>;

    fn default_joint<S: Scalar>() -> PlanarJoint<S> {
        PlanarJoint::Fixed
    }
    fn cast_joint<S: Scalar, T: Scalar>(j: &PlanarJoint<S>) -> Option<PlanarJoint<T>> {
        Some(j.cast())
    }
    fn point_is_finite<S: Scalar>(p: &Vec2<S>) -> bool {
        p.is_finite()
    }
    fn cast_transform<S: Scalar, T: Scalar>(x: &PlanarTransform<S>) -> PlanarTransform<T> {
        x.cast()
    }
    fn cast_inertia<S: Scalar, T: Scalar>(i: &PlanarInertia<S>) -> PlanarInertia<T> {
        i.cast()
    }
    fn cast_motion<S: Scalar, T: Scalar>(m: &PlanarMotion<S>) -> PlanarMotion<T> {
        PlanarMotion::new(T::from_f64(m.ang.to_f64()), m.lin.cast())
    }
    fn validate_inertia<S: Scalar>(i: &PlanarInertia<S>) -> Result<(), ModelProblem> {
        i.validate().map_err(ModelProblem::from)
    }
    fn validate_transform<S: Scalar>(x: &PlanarTransform<S>) -> Result<(), ModelProblem> {
        x.validate().map_err(ModelProblem::from)
    }
    fn validate_joint<S: Scalar>(j: &PlanarJoint<S>) -> Result<(), ModelProblem> {
        match j {
            PlanarJoint::Prismatic(a)
                if (a.norm_squared().to_f64() - 1.0).abs() > 1e3 * S::EPSILON =>
            {
                Err(ModelProblem::AxisNotUnit)
            }
            _ => Ok(()),
        }
    }
}

impl<S: Scalar> VectorOps<S> for PlanarMotion<S> {
    const ZERO: Self = Self::new(S::ZERO, Vec2::ZERO);
    #[inline]
    fn is_finite(&self) -> bool {
        self.ang.is_finite() && self.lin.is_finite()
    }
    #[inline]
    fn component(&self, k: usize) -> S {
        match k {
            0 => self.ang,
            1 => self.lin.x,
            _ => self.lin.y,
        }
    }
}

impl<S: Scalar> MotionVector<S> for PlanarMotion<S> {
    type Force = crate::planar::PlanarForce<S>;
    #[inline]
    fn cross_motion(&self, m: &Self) -> Self {
        // ω × ω_m vanishes in the plane; ω × v_m + v × ω_m remains.
        Self::new(
            S::ZERO,
            m.lin.perp_scaled(self.ang) - self.lin.perp_scaled(m.ang),
        )
    }
    #[inline]
    fn cross_force(&self, f: &crate::planar::PlanarForce<S>) -> crate::planar::PlanarForce<S> {
        crate::planar::PlanarForce::new(self.lin.cross(&f.lin), f.lin.perp_scaled(self.ang))
    }
    #[inline]
    fn dot(&self, f: &crate::planar::PlanarForce<S>) -> S {
        self.ang * f.ang + self.lin.dot(&f.lin)
    }
}

impl<S: Scalar> VectorOps<S> for PlanarForce<S> {
    const ZERO: Self = Self::new(S::ZERO, Vec2::ZERO);
    #[inline]
    fn is_finite(&self) -> bool {
        self.ang.is_finite() && self.lin.is_finite()
    }
    #[inline]
    fn component(&self, k: usize) -> S {
        match k {
            0 => self.ang,
            1 => self.lin.x,
            _ => self.lin.y,
        }
    }
}

impl<S: Scalar> ForceVector<S> for PlanarForce<S> {}

impl<S: Scalar> RigidTransform<S> for PlanarTransform<S> {
    type Motion = PlanarMotion<S>;
    type Force = PlanarForce<S>;
    type Point = Vec2<S>;
    const IDENTITY: Self = Self::from_cos_sin(S::ONE, S::ZERO, Vec2::ZERO);

    #[inline]
    fn compose(&self, o: &Self) -> Self {
        Self::from_cos_sin(
            self.cos * o.cos - self.sin * o.sin,
            self.sin * o.cos + self.cos * o.sin,
            self.rotate(&o.trans) + self.trans,
        )
    }
    #[inline]
    fn inverse(&self) -> Self {
        Self::from_cos_sin(self.cos, -self.sin, -self.rotate_inv(&self.trans))
    }
    #[inline]
    fn act_motion(&self, m: &PlanarMotion<S>) -> PlanarMotion<S> {
        PlanarMotion::new(m.ang, self.rotate(&m.lin) - self.trans.perp_scaled(m.ang))
    }
    #[inline]
    fn act_inv_motion(&self, m: &PlanarMotion<S>) -> PlanarMotion<S> {
        PlanarMotion::new(
            m.ang,
            self.rotate_inv(&(m.lin + self.trans.perp_scaled(m.ang))),
        )
    }
    #[inline]
    fn act_force(&self, f: &PlanarForce<S>) -> PlanarForce<S> {
        let lin = self.rotate(&f.lin);
        PlanarForce::new(f.ang + self.trans.cross(&lin), lin)
    }
    #[inline]
    fn act_inv_force(&self, f: &PlanarForce<S>) -> PlanarForce<S> {
        PlanarForce::new(f.ang - self.trans.cross(&f.lin), self.rotate_inv(&f.lin))
    }
    #[inline]
    fn act_point(&self, p: &Vec2<S>) -> Vec2<S> {
        self.rotate(p) + self.trans
    }
    #[inline]
    fn translation(&self) -> Vec2<S> {
        self.trans
    }
    fn is_finite(&self) -> bool {
        PlanarTransform::is_finite(self)
    }
}

impl<S: Scalar> BodyInertia<S> for PlanarInertia<S> {
    type Motion = PlanarMotion<S>;
    type Force = PlanarForce<S>;
    type Transform = PlanarTransform<S>;
    const ZERO: Self = Self::new(S::ZERO, Vec2::ZERO, S::ZERO);

    #[inline]
    fn mass(&self) -> S {
        self.mass
    }
    #[inline]
    fn com(&self) -> Vec2<S> {
        self.com
    }
    #[inline]
    fn mul_motion(&self, v: &PlanarMotion<S>) -> PlanarForce<S> {
        // Velocity of the centre of mass is v + ω ẑ × c.
        let lin = (v.lin + self.com.perp_scaled(v.ang)) * self.mass;
        PlanarForce::new(self.izz * v.ang + self.com.cross(&lin), lin)
    }
    #[inline]
    fn act(&self, x: &PlanarTransform<S>) -> Self {
        Self::new(self.mass, x.act_point(&self.com), self.izz)
    }
    fn combine(&self, o: &Self) -> Self {
        let mass = self.mass + o.mass;
        let inv = S::ONE / mass.max(S::from_f64(S::EPSILON));
        let com = (self.com * self.mass + o.com * o.mass) * inv;
        let d = self.com - o.com;
        let izz = self.izz + o.izz + self.mass * o.mass * inv * d.norm_squared();
        Self::new(mass, com, izz)
    }
    #[inline]
    fn potential_energy(&self, gravity: &PlanarMotion<S>) -> S {
        -(self.mass * gravity.lin.dot(&self.com))
    }
    fn is_finite(&self) -> bool {
        PlanarInertia::is_finite(self)
    }
}

impl<S: Scalar> ArticulatedInertia<S> for ArticulatedInertia3<S> {
    type Motion = PlanarMotion<S>;
    type Force = PlanarForce<S>;
    type Transform = PlanarTransform<S>;
    type Inertia = PlanarInertia<S>;
    const ZERO: Self = Self { m: Sym3::ZERO };

    fn from_rigid(i: &PlanarInertia<S>) -> Self {
        let (m, cx, cy) = (i.mass, i.com.x, i.com.y);
        Self {
            m: Sym3::new(
                i.izz + m * (cx * cx + cy * cy),
                -(m * cy),
                m * cx,
                m,
                S::ZERO,
                m,
            ),
        }
    }
    #[inline]
    fn mul_motion(&self, m: &PlanarMotion<S>) -> PlanarForce<S> {
        let f = self.m.mul_vec(&motion_vec(m));
        PlanarForce::new(f.x, crate::planar::Vec2::new(f.y, f.z))
    }
    #[inline]
    fn add_assign(&mut self, o: &Self) {
        self.m += o.m;
    }
    #[inline]
    fn sub_outer(&mut self, a: &PlanarForce<S>, s: S) {
        self.m -= Sym3::outer(&force_vec(a), s);
    }
    #[inline]
    fn sub_outer_sym(&mut self, a: &PlanarForce<S>, b: &PlanarForce<S>, s: S) {
        self.m -= Sym3::outer_sym(&force_vec(a), &force_vec(b), s);
    }
    fn act(&self, x: &PlanarTransform<S>) -> Self {
        // Force transform = (motion transform a→b)ᵀ: result Tᵀ M T with
        // T = ᵇX_a = [1 0; Rᵀ(-p_y, p_x) Rᵀ].
        let (c, s) = (x.cos, x.sin);
        let (px, py) = (x.trans.x, x.trans.y);
        let t10 = c * (-py) + s * px;
        let t20 = -s * (-py) + c * px;
        let t = Mat3::from_rows([[S::ONE, S::ZERO, S::ZERO], [t10, c, s], [t20, -s, c]]);
        Self {
            m: self.m.rotate(&t.transpose()),
        }
    }
    #[inline]
    fn trace(&self) -> S {
        self.m.trace()
    }
}
