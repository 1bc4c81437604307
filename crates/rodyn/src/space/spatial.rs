//! 3-D space as a [`Geometry`]: the spatial algebra's types
//! ([`crate::spatial`]) behind the traits the algorithms are written
//! against. The algebra itself imports nothing above the scalar; its place
//! among the traits, the joints and the model's errors is set here.

use super::{
    ArticulatedInertia, BodyInertia, ForceVector, Geometry, MotionVector, RigidTransform, VectorOps,
};
use crate::error::ModelProblem;
use crate::joint::Joint;
use crate::spatial::articulated::{cross_matrix, outer, rotate_mat};
use crate::spatial::{
    ArticulatedInertia6, Force, Inertia, Mat3, Motion, Spatial, Sym3, Transform, Vec3,
};
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
