//! Articulated-body inertia (Featherstone §7.2): a symmetric 6x6 matrix.
//!
//! Stored as three 3x3 blocks so that `f = I^A m` reads
//! `n = A ω + B v`, `f = Bᵀ ω + C v`, with `A` and `C` symmetric.

use super::mat3::dot3;
use super::{Force, Mat3, Motion, Sym3, Transform, Vec3};
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
pub(crate) fn cross_matrix<S: Scalar>(p: &Vec3<S>) -> Mat3<S> {
    let z = S::ZERO;
    Mat3::from_rows([[z, -p.z, p.y], [p.z, z, -p.x], [-p.y, p.x, z]])
}

/// The outer product `s a bᵀ`.
pub(crate) fn outer<S: Scalar>(a: &Vec3<S>, b: &Vec3<S>, s: S) -> Mat3<S> {
    let a = a.scale(s);
    Mat3::from_rows([
        [a.x * b.x, a.x * b.y, a.x * b.z],
        [a.y * b.x, a.y * b.y, a.y * b.z],
        [a.z * b.x, a.z * b.y, a.z * b.z],
    ])
}

/// `u × v` on arrays.
#[inline(always)]
fn cross<S: Scalar>(u: &[S; 3], v: &Vec3<S>) -> [S; 3] {
    [
        u[1] * v.z - u[2] * v.y,
        u[2] * v.x - u[0] * v.z,
        u[0] * v.y - u[1] * v.x,
    ]
}

/// `R B Rᵀ` for a general `B` (54 products).
#[inline(always)]
pub(crate) fn rotate_mat<S: Scalar>(b: &[[S; 3]; 3], r: &[[S; 3]; 3]) -> [[S; 3]; 3] {
    // Column j of B Rᵀ is B r_j.
    let t = [
        [dot3(&b[0], &r[0]), dot3(&b[1], &r[0]), dot3(&b[2], &r[0])],
        [dot3(&b[0], &r[1]), dot3(&b[1], &r[1]), dot3(&b[2], &r[1])],
        [dot3(&b[0], &r[2]), dot3(&b[1], &r[2]), dot3(&b[2], &r[2])],
    ];
    [
        [dot3(&r[0], &t[0]), dot3(&r[0], &t[1]), dot3(&r[0], &t[2])],
        [dot3(&r[1], &t[0]), dot3(&r[1], &t[1]), dot3(&r[1], &t[2])],
        [dot3(&r[2], &t[0]), dot3(&r[2], &t[1]), dot3(&r[2], &t[2])],
    ]
}

impl<S: Scalar> ArticulatedInertia6<S> {
    /// `self += ᵃX_b* o ᵇX_a` with the rotated `B` and `A` blocks supplied
    /// by `rotated_b` and `rotated_a`.
    ///
    /// Rotate every block into a, then shift the reference point by
    /// p = x.trans, with P = [p×] (so Pᵀ = -P):
    /// B_a = B' + P C',  A_a = A' - B'P - (B'P)ᵀ - P C' P,  C_a = C'.
    /// Written out on scalars: the intermediates stay in registers and
    /// nothing is copied through memory. Block by block, each added to
    /// `self` as soon as it is complete, so that few intermediates are alive
    /// at once (fewer spills); hence the rotations come as closures.
    #[inline(always)]
    pub(crate) fn add_rotated_shifted(
        &mut self,
        o: &Self,
        x: &Transform<S>,
        rotated_b: impl FnOnce() -> [[S; 3]; 3],
        rotated_a: impl FnOnce() -> Sym3<S>,
    ) {
        let p = &x.trans;
        let c = o.c.rotate(&x.rot);
        self.c += c;
        // P C': column j of C' crossed by p, (p × c_j).
        let cm = c.rows();
        let pc = [
            [
                p.y * cm[2][0] - p.z * cm[1][0],
                p.y * cm[2][1] - p.z * cm[1][1],
                p.y * cm[2][2] - p.z * cm[1][2],
            ],
            [
                p.z * cm[0][0] - p.x * cm[2][0],
                p.z * cm[0][1] - p.x * cm[2][1],
                p.z * cm[0][2] - p.x * cm[2][2],
            ],
            [
                p.x * cm[1][0] - p.y * cm[0][0],
                p.x * cm[1][1] - p.y * cm[0][1],
                p.x * cm[1][2] - p.y * cm[0][2],
            ],
        ];
        // P C' P is symmetric: row i is (P C')_i × p; its upper triangle.
        let pcp0 = cross(&pc[0], p);
        let pcp1y = pc[1][2] * p.x - pc[1][0] * p.z;
        let pcp1z = pc[1][0] * p.y - pc[1][1] * p.x;
        let pcp2z = pc[2][0] * p.y - pc[2][1] * p.x;
        self.a.xx -= pcp0[0];
        self.a.xy -= pcp0[1];
        self.a.xz -= pcp0[2];
        self.a.yy -= pcp1y;
        self.a.yz -= pcp1z;
        self.a.zz -= pcp2z;
        let b = rotated_b();
        for ((row, b), pc) in self.b.m.iter_mut().zip(&b).zip(&pc) {
            row[0] += b[0] + pc[0];
            row[1] += b[1] + pc[1];
            row[2] += b[2] + pc[2];
        }
        // B'P: row i is b_i × p.
        let bp = [cross(&b[0], p), cross(&b[1], p), cross(&b[2], p)];
        self.a.xx -= bp[0][0] + bp[0][0];
        self.a.xy -= bp[0][1] + bp[1][0];
        self.a.xz -= bp[0][2] + bp[2][0];
        self.a.yy -= bp[1][1] + bp[1][1];
        self.a.yz -= bp[1][2] + bp[2][1];
        self.a.zz -= bp[2][2] + bp[2][2];
        self.a += rotated_a();
    }

    /// [`add_act`](ArticulatedInertia::add_act) for an `o` whose angular
    /// row and column K (the axis normal to the plane of I and J) and whose
    /// `B` row K are zero: only rows I and J of `A` and `B` are read.
    // Out of line in the in-order profile (the Cortex-M4's 32 registers
    // hold the kernel's intermediates; inlined, ABA took more instructions
    // on the Panda), inlined out of order (x86-64's 16 registers spill less
    // when the kernel is scheduled with its caller: fewer instructions in
    // ABA). Figures: the performance notebook, "ABA"; the profile:
    // `crate::tuning`.
    #[cfg_attr(rodyn_tuning = "in_order", inline(never))]
    #[cfg_attr(rodyn_tuning = "out_of_order", inline)]
    pub(crate) fn add_act_plane<const I: usize, const J: usize>(
        &mut self,
        o: &Self,
        x: &Transform<S>,
    ) {
        let r = &x.rot.m;
        // B' = Σₘ R eₘ (R bₘ)ᵀ over the rows m = I, J of B.
        let rotated_b = || {
            let (b_i, b_j) = (&o.b.m[I], &o.b.m[J]);
            let rb_i = [dot3(&r[0], b_i), dot3(&r[1], b_i), dot3(&r[2], b_i)];
            let rb_j = [dot3(&r[0], b_j), dot3(&r[1], b_j), dot3(&r[2], b_j)];
            let row = |p: usize| {
                [
                    r[p][I] * rb_i[0] + r[p][J] * rb_j[0],
                    r[p][I] * rb_i[1] + r[p][J] * rb_j[1],
                    r[p][I] * rb_i[2] + r[p][J] * rb_j[2],
                ]
            };
            [row(0), row(1), row(2)]
        };
        // A' = Σₘₙ aₘₙ R eₘ (R eₙ)ᵀ over m, n = I, J.
        let rotated_a = || {
            let a = o.a.rows();
            let (a_ii, a_ij, a_jj) = (a[I][I], a[I][J], a[J][J]);
            let u = |p: usize| a_ii * r[p][I] + a_ij * r[p][J];
            let w = |p: usize| a_ij * r[p][I] + a_jj * r[p][J];
            let (u0, u1, u2) = (u(0), u(1), u(2));
            let (w0, w1, w2) = (w(0), w(1), w(2));
            Sym3::new(
                u0 * r[0][I] + w0 * r[0][J],
                u0 * r[1][I] + w0 * r[1][J],
                u0 * r[2][I] + w0 * r[2][J],
                u1 * r[1][I] + w1 * r[1][J],
                u1 * r[2][I] + w1 * r[2][J],
                u2 * r[2][I] + w2 * r[2][J],
            )
        };
        self.add_rotated_shifted(o, x, rotated_b, rotated_a);
    }

    /// [`project_mul_motion`](ArticulatedInertia::project_mul_motion) for a
    /// revolute joint about axis K, normal to the plane of I and J, without
    /// armature: `u = (A eₖ, Bᵀ eₖ)`, and the projection leaves the angular
    /// row and column K of `A` and the row K of `B` zero (set exactly), so
    /// only the other 15 entries are updated and enter the product.
    #[inline(always)]
    pub(crate) fn project_plane<const I: usize, const J: usize>(
        &mut self,
        u: &Force<S>,
        d_inv: S,
        m: &Motion<S>,
    ) -> Force<S> {
        let k = 3 - I - J;
        let (ua, ul) = (u.ang.to_array(), u.lin.to_array());
        let (w, v) = (m.ang.to_array(), m.lin.to_array());
        let (sa_i, sa_j) = (ua[I] * d_inv, ua[J] * d_inv);
        // A: the I-J block; row and column K zero.
        let a_ii = self.a.get(I, I) - sa_i * ua[I];
        let a_ij = self.a.get(I, J) - sa_i * ua[J];
        let a_jj = self.a.get(J, J) - sa_j * ua[J];
        *self.a.get_mut(I, I) = a_ii;
        *self.a.get_mut(I, J) = a_ij;
        *self.a.get_mut(J, J) = a_jj;
        *self.a.get_mut(k, k) = S::ZERO;
        *self.a.get_mut(k, I) = S::ZERO;
        *self.a.get_mut(k, J) = S::ZERO;
        // B: rows I and J; row K zero. Written out: at opt-level "s" a
        // three-step loop is not unrolled.
        let b = &mut self.b.m;
        b[I] = [
            b[I][0] - sa_i * ul[0],
            b[I][1] - sa_i * ul[1],
            b[I][2] - sa_i * ul[2],
        ];
        b[J] = [
            b[J][0] - sa_j * ul[0],
            b[J][1] - sa_j * ul[1],
            b[J][2] - sa_j * ul[2],
        ];
        b[k] = [S::ZERO; 3];
        // C: every entry.
        let sl = [ul[0] * d_inv, ul[1] * d_inv, ul[2] * d_inv];
        let c = &mut self.c;
        c.xx -= sl[0] * ul[0];
        c.xy -= sl[0] * ul[1];
        c.xz -= sl[0] * ul[2];
        c.yy -= sl[1] * ul[1];
        c.yz -= sl[1] * ul[2];
        c.zz -= sl[2] * ul[2];
        // The product, skipping the zero row and column.
        let bv = |r: usize| b[r][0] * v[0] + b[r][1] * v[1] + b[r][2] * v[2];
        let mut ang = [S::ZERO; 3];
        ang[I] = a_ii * w[I] + a_ij * w[J] + bv(I);
        ang[J] = a_ij * w[I] + a_jj * w[J] + bv(J);
        let cm = c.rows();
        let lin = |q: usize| b[I][q] * w[I] + b[J][q] * w[J] + dot3(&cm[q], &v);
        Force::new(Vec3::from_array(ang), Vec3::new(lin(0), lin(1), lin(2)))
    }

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
