//! Planar articulated-body inertia: a symmetric 3x3 matrix over `(ω, vx, vy)`.

use super::{PlanarForce, PlanarInertia, PlanarMotion, PlanarTransform};
use crate::space::ArticulatedInertia;
use crate::spatial::{Mat3, Sym3, Vec3};
use crate::Scalar;

/// A symmetric 3x3 articulated-body inertia; index 0 is angular, 1 and 2 linear.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArticulatedInertia3<S> {
    /// The matrix.
    pub m: Sym3<S>,
}

fn motion_vec<S: Scalar>(m: &PlanarMotion<S>) -> Vec3<S> {
    Vec3::new(m.ang, m.lin.x, m.lin.y)
}
fn force_vec<S: Scalar>(f: &PlanarForce<S>) -> Vec3<S> {
    Vec3::new(f.ang, f.lin.x, f.lin.y)
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
        PlanarForce::new(f.x, super::Vec2::new(f.y, f.z))
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
