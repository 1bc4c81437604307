//! Articulated-body inertia (Featherstone §7.2): a symmetric 6x6 matrix.
//!
//! Stored as three 3x3 blocks so that `f = I^A m` reads
//! `n = A ω + B v`, `f = Bᵀ ω + C v`, with `A` and `C` symmetric.

use super::{Force, Inertia, Mat3, Motion, Sym3, Transform, Vec3};
use crate::space::ArticulatedInertia;
use crate::Scalar;

/// A symmetric 6x6 articulated-body inertia in block form.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArticulatedInertia6<S> {
    /// Angular-angular block (kg m²).
    pub a: Sym3<S>,
    /// Angular-linear block (kg m).
    pub b: Mat3<S>,
    /// Linear-linear block (kg).
    pub c: Sym3<S>,
}

/// `[p×]` as a matrix.
fn cross_matrix<S: Scalar>(p: &Vec3<S>) -> Mat3<S> {
    let z = S::ZERO;
    Mat3::from_rows([[z, -p.z, p.y], [p.z, z, -p.x], [-p.y, p.x, z]])
}

/// The outer product `s a bᵀ`.
fn outer<S: Scalar>(a: &Vec3<S>, b: &Vec3<S>, s: S) -> Mat3<S> {
    let a = a.scale(s);
    Mat3::from_rows([
        [a.x * b.x, a.x * b.y, a.x * b.z],
        [a.y * b.x, a.y * b.y, a.y * b.z],
        [a.z * b.x, a.z * b.y, a.z * b.z],
    ])
}

impl<S: Scalar> ArticulatedInertia6<S> {
    /// Entry (i, j) of the 6x6 matrix, angular rows and columns first.
    #[must_use]
    pub fn get(&self, i: usize, j: usize) -> S {
        match (i < 3, j < 3) {
            (true, true) => self.a.get(i, j),
            (true, false) => self.b.m[i][j - 3],
            (false, true) => self.b.m[j][i - 3],
            (false, false) => self.c.get(i - 3, j - 3),
        }
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

    fn from_rigid(i: &Inertia<S>) -> Self {
        Self {
            a: i.rot_inertia_at_origin(),
            b: cross_matrix(&i.com.scale(i.mass)),
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
        // Rotate every block into a, then shift the reference point by
        // p = x.trans, with P = [p×] (so Pᵀ = -P):
        // B_a = B' + P C',  A_a = A' - B'P - (B'P)ᵀ - P C' P,  C_a = C'.
        let r = &x.rot;
        let p = &x.trans;
        let a = self.a.rotate(r);
        let b = r.mul_mat(&self.b).mul_mat_tr(r);
        let c = self.c.rotate(r);
        let pc = Mat3::cross_mul(p, &c.to_mat3());
        let bp = b.mul_cross(p);
        // P C' P is symmetric: row i is (P C')_i × p, and only its upper
        // triangle is formed.
        let (r0, r1, r2) = (pc.row(0).cross(p), pc.row(1).cross(p), pc.row(2).cross(p));
        let pcp = Sym3::new(r0.x, r0.y, r0.z, r1.y, r1.z, r2.z);
        Self {
            a: a - bp.sym_sum() - pcp,
            b: b + pc,
            c,
        }
    }
    #[inline]
    fn trace(&self) -> S {
        self.a.trace() + self.c.trace()
    }
}
