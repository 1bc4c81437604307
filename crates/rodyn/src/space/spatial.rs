//! 3-D space's algebra: the spatial algebra's types ([`crate::spatial`])
//! behind the traits the algorithms are written against. The algebra
//! itself imports nothing above the scalar; its place among the traits is
//! set here. [`Spatial`](crate::spatial::Spatial) as a whole
//! [`Geometry`](super::Geometry), which names the 3-D joints, is set with
//! the joints (`joint/spatial_geometry.rs`).

use super::{
    ArticulatedInertia, BodyInertia, ForceVector, MotionVector, RigidTransform, VectorOps,
};
use crate::spatial::articulated::{cross_matrix, outer, rotate_mat};
use crate::spatial::{ArticulatedInertia6, Force, Inertia, Mat3, Motion, Sym3, Transform, Vec3};
use crate::Scalar;

impl<S: Scalar> VectorOps<S> for Motion<S> {
    const ZERO: Self = Self::new(Vec3::ZERO, Vec3::ZERO);
    #[inline]
    fn is_finite(&self) -> bool {
        // One test of the sum (a NaN or infinity makes it non-finite);
        // the entries one by one only when it fails, since finite entries
        // can overflow it.
        let (a, l) = (&self.ang, &self.lin);
        ((a.x + a.y) + (a.z + l.x) + (l.y + l.z)).is_finite()
            || crate::scalar::entries_finite(&[a.x, a.y, a.z, l.x, l.y, l.z])
    }
    #[inline]
    fn component(&self, k: usize) -> S {
        if k < 3 {
            self.ang.get(k)
        } else {
            self.lin.get(k - 3)
        }
    }
}

impl<S: Scalar> MotionVector<S> for Motion<S> {
    type Force = Force<S>;
    #[inline]
    fn cross_motion(&self, m: &Self) -> Self {
        Self::new(
            self.ang.cross(&m.ang),
            self.ang.cross(&m.lin) + self.lin.cross(&m.ang),
        )
    }
    #[inline]
    fn cross_force(&self, f: &Force<S>) -> Force<S> {
        Force::new(
            self.ang.cross(&f.ang) + self.lin.cross(&f.lin),
            self.ang.cross(&f.lin),
        )
    }
    #[inline]
    fn dot(&self, f: &Force<S>) -> S {
        self.ang.dot(&f.ang) + self.lin.dot(&f.lin)
    }
}

impl<S: Scalar> VectorOps<S> for Force<S> {
    const ZERO: Self = Self::new(Vec3::ZERO, Vec3::ZERO);
    #[inline]
    fn is_finite(&self) -> bool {
        // One test of the sum (a NaN or infinity makes it non-finite);
        // the entries one by one only when it fails, since finite entries
        // can overflow it.
        let (a, l) = (&self.ang, &self.lin);
        ((a.x + a.y) + (a.z + l.x) + (l.y + l.z)).is_finite()
            || crate::scalar::entries_finite(&[a.x, a.y, a.z, l.x, l.y, l.z])
    }
    #[inline]
    fn component(&self, k: usize) -> S {
        if k < 3 {
            self.ang.get(k)
        } else {
            self.lin.get(k - 3)
        }
    }
}

impl<S: Scalar> ForceVector<S> for Force<S> {}

impl<S: Scalar> RigidTransform<S> for Transform<S> {
    type Motion = Motion<S>;
    type Force = Force<S>;
    type Point = Vec3<S>;
    const IDENTITY: Self = Transform::IDENTITY;

    #[inline]
    fn compose(&self, o: &Self) -> Self {
        Self::new(
            self.rot.mul_mat(&o.rot),
            self.rot.mul_vec(&o.trans) + self.trans,
        )
    }
    #[inline]
    fn inverse(&self) -> Self {
        Self::new(self.rot.transpose(), -self.rot.tr_mul_vec(&self.trans))
    }
    #[inline]
    fn act_motion(&self, m: &Motion<S>) -> Motion<S> {
        let ang = self.rot.mul_vec(&m.ang);
        let lin = self.rot.mul_vec(&m.lin) + self.trans.cross(&ang);
        Motion::new(ang, lin)
    }
    #[inline]
    fn act_inv_motion(&self, m: &Motion<S>) -> Motion<S> {
        let ang = self.rot.tr_mul_vec(&m.ang);
        let lin = self.rot.tr_mul_vec(&(m.lin - self.trans.cross(&m.ang)));
        Motion::new(ang, lin)
    }
    #[inline]
    fn act_force(&self, f: &Force<S>) -> Force<S> {
        let lin = self.rot.mul_vec(&f.lin);
        let ang = self.rot.mul_vec(&f.ang) + self.trans.cross(&lin);
        Force::new(ang, lin)
    }
    #[inline]
    fn act_inv_force(&self, f: &Force<S>) -> Force<S> {
        let lin = self.rot.tr_mul_vec(&f.lin);
        let ang = self.rot.tr_mul_vec(&(f.ang - self.trans.cross(&f.lin)));
        Force::new(ang, lin)
    }
    #[inline]
    fn act_point(&self, p: &Vec3<S>) -> Vec3<S> {
        self.rot.mul_vec(p) + self.trans
    }
    #[inline]
    fn translation(&self) -> Vec3<S> {
        self.trans
    }
    fn is_finite(&self) -> bool {
        Transform::is_finite(self)
    }
}

impl<S: Scalar> BodyInertia<S> for Inertia<S> {
    type Motion = Motion<S>;
    type Force = Force<S>;
    type Transform = Transform<S>;
    const ZERO: Self = Self::new(S::ZERO, Vec3::ZERO, Sym3::ZERO);

    #[inline]
    fn mass(&self) -> S {
        self.mass
    }
    #[inline]
    fn com(&self) -> Vec3<S> {
        self.com
    }
    #[inline]
    fn mul_motion(&self, v: &Motion<S>) -> Force<S> {
        // Momentum of the centre of mass, then its moment about the origin.
        let lin = (v.lin - self.com.cross(&v.ang)) * self.mass;
        let ang = self.rot_inertia.mul_vec(&v.ang) + self.com.cross(&lin);
        Force::new(ang, lin)
    }
    #[inline]
    fn net_force(&self, v: &Motion<S>, a: &Motion<S>) -> Force<S> {
        // Newton and Euler at the centre of mass, then the moment carried to
        // the origin: 51 products instead of the 66 of I a + v ×* I v.
        // The COM's classical acceleration is a_lin + α × c + ω × (v_lin + ω × c).
        let (omega, alpha) = (&v.ang, &a.ang);
        let v_com = v.lin + omega.cross(&self.com);
        let lin = (a.lin + alpha.cross(&self.com) + omega.cross(&v_com)) * self.mass;
        let spin = self.rot_inertia.mul_vec(omega);
        let ang = self.rot_inertia.mul_vec(alpha) + omega.cross(&spin) + self.com.cross(&lin);
        Force::new(ang, lin)
    }
    #[inline]
    fn velocity_product_force(&self, v: &Motion<S>) -> Force<S> {
        let omega = &v.ang;
        let v_com = v.lin + omega.cross(&self.com);
        let lin = omega.cross(&v_com) * self.mass;
        let spin = self.rot_inertia.mul_vec(omega);
        Force::new(omega.cross(&spin) + self.com.cross(&lin), lin)
    }
    #[inline(always)]
    fn act(&self, x: &Transform<S>) -> Self {
        Self::new(
            self.mass,
            x.act_point(&self.com),
            self.rot_inertia.rotate(&x.rot),
        )
    }
    #[inline(always)]
    fn combine(&self, o: &Self) -> Self {
        let mass = self.mass + o.mass;
        // A massless pair keeps a zero inertia rather than dividing by zero.
        let eps = S::from_f64(S::EPSILON);
        let inv = S::ONE / mass.max(eps);
        let com = (self.com * self.mass + o.com * o.mass) * inv;
        let d = self.com - o.com;
        let reduced = self.mass * o.mass * inv;
        let rot_inertia = self.rot_inertia + o.rot_inertia + Sym3::parallel_axis(&d).scale(reduced);
        Self::new(mass, com, rot_inertia)
    }
    #[inline]
    fn potential_energy(&self, gravity: &Motion<S>) -> S {
        -(self.mass * gravity.lin.dot(&self.com))
    }
    fn is_finite(&self) -> bool {
        Inertia::is_finite(self)
    }
}

impl<S: Scalar> ArticulatedInertia<S> for ArticulatedInertia6<S> {
    type Motion = Motion<S>;
    type Force = Force<S>;
    type Transform = Transform<S>;
    type Inertia = Inertia<S>;
    const ZERO: Self = Self {
        a: Sym3::ZERO,
        b: Mat3::ZERO,
        c: Sym3::ZERO,
    };

    #[inline]
    fn from_rigid(i: &Inertia<S>) -> Self {
        // A = I_c + m ([c]ₓ[c]ₓᵀ), formed from h = m c: 9 products, not 15.
        let (c, h) = (&i.com, i.com.scale(i.mass));
        let r = &i.rot_inertia;
        let a = Sym3::new(
            r.xx + (h.y * c.y + h.z * c.z),
            r.xy - h.x * c.y,
            r.xz - h.x * c.z,
            r.yy + (h.x * c.x + h.z * c.z),
            r.yz - h.y * c.z,
            r.zz + (h.x * c.x + h.y * c.y),
        );
        Self {
            a,
            b: cross_matrix(&h),
            c: Sym3::identity_scaled(i.mass),
        }
    }
    #[inline]
    fn mul_motion(&self, m: &Motion<S>) -> Force<S> {
        Force::new(
            self.a.mul_vec(&m.ang) + self.b.mul_vec(&m.lin),
            self.b.tr_mul_vec(&m.ang) + self.c.mul_vec(&m.lin),
        )
    }
    #[inline]
    fn add_assign(&mut self, o: &Self) {
        self.a += o.a;
        self.b = self.b + o.b;
        self.c += o.c;
    }
    #[inline]
    fn sub_outer(&mut self, u: &Force<S>, s: S) {
        self.a -= Sym3::outer(&u.ang, s);
        self.b = self.b - outer(&u.ang, &u.lin, s);
        self.c -= Sym3::outer(&u.lin, s);
    }
    fn sub_outer_sym(&mut self, u: &Force<S>, w: &Force<S>, s: S) {
        self.a -= Sym3::outer_sym(&u.ang, &w.ang, s);
        self.b = self.b - outer(&u.ang, &w.lin, s) - outer(&w.ang, &u.lin, s);
        self.c -= Sym3::outer_sym(&u.lin, &w.lin, s);
    }
    fn act(&self, x: &Transform<S>) -> Self {
        let mut out = Self::ZERO;
        out.add_act(self, x);
        out
    }
    #[inline]
    fn add_act(&mut self, o: &Self, x: &Transform<S>) {
        let r = &x.rot.m;
        self.add_rotated_shifted(o, x, || rotate_mat(&o.b.m, r), || o.a.rotate(&x.rot));
    }
    #[inline(always)]
    fn project_mul_motion(
        &mut self,
        u: &Force<S>,
        d_inv: S,
        m: &Motion<S>,
        revolute_axis: Option<usize>,
    ) -> Force<S> {
        match revolute_axis {
            Some(0) => self.project_plane::<1, 2>(u, d_inv, m),
            Some(1) => self.project_plane::<2, 0>(u, d_inv, m),
            Some(2) => self.project_plane::<0, 1>(u, d_inv, m),
            _ => {
                self.sub_outer(u, d_inv);
                self.mul_motion(m)
            }
        }
    }
    #[inline(always)]
    fn add_act_projected(&mut self, o: &Self, x: &Transform<S>, revolute_axis: Option<usize>) {
        // Iᵃ S = 0 for the joint just projected out: about coordinate axis
        // k, the angular row and column k of A and the row k of B vanish
        // (exactly, in exact arithmetic; here they hold rounding residue,
        // which is dropped). Rotating what remains costs 60 products
        // instead of 99.
        match revolute_axis {
            Some(0) => self.add_act_plane::<1, 2>(o, x),
            Some(1) => self.add_act_plane::<2, 0>(o, x),
            Some(2) => self.add_act_plane::<0, 1>(o, x),
            _ => self.add_act(o, x),
        }
    }
    #[inline]
    fn trace(&self) -> S {
        self.a.trace() + self.c.trace()
    }
}
