//! Featherstone's 6-D spatial algebra for models in 3-D space.
//!
//! One concept per file: [`Motion`], [`Force`], [`Transform`], [`Inertia`],
//! [`ArticulatedInertia6`], and the 3-D building blocks [`Vec3`], [`Mat3`],
//! [`Sym3`]. [`Spatial`] ties them together as a [`Space`].

mod articulated;
mod force;
mod inertia;
mod mat3;
mod motion;
mod sym3;
mod transform;
mod vec3;

pub use articulated::ArticulatedInertia6;
pub use force::Force;
pub use inertia::Inertia;
pub use mat3::Mat3;
pub use motion::Motion;
pub use sym3::Sym3;
pub use transform::Transform;
pub use vec3::Vec3;

use crate::error::ModelProblem;
use crate::joint::Joint;
use crate::space::Space;
use crate::Scalar;

/// Full 3-D space: 6-D motion and force vectors.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Spatial;

impl Space for Spatial {
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
        crate::model::validate_inertia_3d(i)
    }
    fn validate_transform<S: Scalar>(x: &Transform<S>) -> Result<(), ModelProblem> {
        crate::model::validate_transform_3d(x)
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
    fn rotate_transform<S: Scalar>(x: &Transform<S>, y: &Transform<S>) -> Transform<S> {
        Transform::new(x.rot.mul_mat(&y.rot), x.rot.mul_vec(&y.trans))
    }
    #[inline(always)]
    fn rotate_inertia<S: Scalar>(i: &Inertia<S>, x: &Transform<S>) -> Inertia<S> {
        // `R I Rᵀ`: T = R I (27 products), then the upper triangle of T Rᵀ.
        let r = &x.rot.m;
        let c = &i.rot_inertia;
        let t = |row: &[S; 3]| {
            [
                row[0] * c.xx + row[1] * c.xy + row[2] * c.xz,
                row[0] * c.xy + row[1] * c.yy + row[2] * c.yz,
                row[0] * c.xz + row[1] * c.yz + row[2] * c.zz,
            ]
        };
        let (t0, t1, t2) = (t(&r[0]), t(&r[1]), t(&r[2]));
        let dot = |a: &[S; 3], b: &[S; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let rot_inertia = Sym3::new(
            dot(&t0, &r[0]),
            dot(&t0, &r[1]),
            dot(&t0, &r[2]),
            dot(&t1, &r[1]),
            dot(&t1, &r[2]),
            dot(&t2, &r[2]),
        );
        Inertia::new(i.mass, x.rot.mul_vec(&i.com), rot_inertia)
    }
    #[inline(always)]
    fn rotate_subspace_column<S: Scalar>(j: &Joint<S>, k: usize, x: &Transform<S>) -> Motion<S> {
        let r = &x.rot;
        // A coordinate axis picks one column of the rotation.
        let axis = |a: &crate::joint::Axis<S>| match a.index() {
            Some(c) => r.column(c),
            None => r.mul_vec(&a.vector()),
        };
        match j {
            Joint::Revolute(rj) => Motion::new(axis(&rj.axis), Vec3::ZERO),
            Joint::Prismatic(pj) => Motion::new(Vec3::ZERO, axis(&pj.axis)),
            Joint::Fixed => Motion::new(Vec3::ZERO, Vec3::ZERO),
            Joint::FreeFlyer(_) if k < 3 => Motion::new(Vec3::ZERO, r.column(k)),
            Joint::FreeFlyer(_) => Motion::new(r.column(k - 3), Vec3::ZERO),
            Joint::Custom(_) => {
                use crate::joint::JointModel;
                let s = j.subspace_column(k);
                Motion::new(r.mul_vec(&s.ang), r.mul_vec(&s.lin))
            }
        }
    }
    #[inline(always)]
    fn translate_force<S: Scalar>(f: &Force<S>, t: &Vec3<S>) -> Force<S> {
        Force::new(f.ang + t.cross(&f.lin), f.lin)
    }
    #[inline(always)]
    fn add_translated_inertia<S: Scalar>(acc: &mut Inertia<S>, i: &Inertia<S>, x: &Transform<S>) {
        // As `Inertia::combine`, with `i`'s centre of mass moved by `t`.
        let com_i = i.com + x.trans;
        let mass = acc.mass + i.mass;
        // A massless pair keeps a zero inertia rather than dividing by zero.
        let inv = S::ONE / mass.max(S::from_f64(S::EPSILON));
        let d = acc.com - com_i;
        let reduced = acc.mass * i.mass * inv;
        acc.com = (acc.com * acc.mass + com_i * i.mass) * inv;
        acc.rot_inertia = acc.rot_inertia + i.rot_inertia + Sym3::parallel_axis(&d).scale(reduced);
        acc.mass = mass;
    }
}
