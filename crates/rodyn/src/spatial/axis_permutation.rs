//! Rotations that carry coordinate axes onto coordinate axes.
//!
//! URDF arms place most joints with quarter turns (`rpy="-1.5708 0 0"`):
//! the rotation's matrix has one entry ±1 in each row and column. Such a
//! rotation moves a vector by reordering its components and flipping
//! signs, exactly in any scalar, and two of them compose by integer
//! arithmetic, so a `const` CRBA plan can carry them (see
//! [`CrbaPlan::from_turns`](crate::algorithm::crba::CrbaPlan::from_turns)).

use super::{Inertia, Mat3, Sym3, Transform, Vec3};
use crate::Scalar;

/// One of the 24 rotations that map each coordinate axis onto a
/// coordinate axis, possibly reversed (products of quarter turns about
/// coordinate axes). Row `r` of its matrix holds `±1` in column
/// `axes[r]`, so `(P v)ᵣ = ±v[axes[r]]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct AxisPermutation {
    /// The column of row r's nonzero entry.
    axes: [u8; 3],
    /// Bit r set: row r's entry is −1.
    negative: u8,
}

impl AxisPermutation {
    /// No rotation.
    pub const IDENTITY: Self = Self {
        axes: [0, 1, 2],
        negative: 0,
    };

    /// The rotation with these matrix rows (entries 0, 1 or −1).
    ///
    /// # Panics
    /// When the rows are not a rotation that permutes the axes (a
    /// reflection included); in a `const` this is a compile error.
    #[must_use]
    pub const fn from_rows(rows: [[i8; 3]; 3]) -> Self {
        match Self::try_from_rows(rows) {
            Some(p) => p,
            None => panic!("not a rotation that carries coordinate axes onto coordinate axes"),
        }
    }

    /// [`Self::from_rows`] without the panic: `None` when the rows are not
    /// such a rotation.
    #[must_use]
    pub const fn try_from_rows(rows: [[i8; 3]; 3]) -> Option<Self> {
        let mut axes = [0u8; 3];
        let mut negative = 0u8;
        let mut used = [false; 3];
        let mut r = 0;
        while r < 3 {
            let mut found = false;
            let mut c = 0;
            while c < 3 {
                match rows[r][c] {
                    0 => {}
                    1 | -1 if !found && !used[c] => {
                        found = true;
                        used[c] = true;
                        axes[r] = c as u8;
                        if rows[r][c] < 0 {
                            negative |= 1 << r;
                        }
                    }
                    _ => return None,
                }
                c += 1;
            }
            if !found {
                return None;
            }
            r += 1;
        }
        let p = Self { axes, negative };
        if p.is_proper() {
            Some(p)
        } else {
            None
        }
    }

    /// `Some` when `rot` is exactly such a rotation (entries exactly 0 and
    /// ±1, as a model compiler writes quarter turns).
    #[must_use]
    pub fn from_matrix<S: Scalar>(rot: &Mat3<S>) -> Option<Self> {
        let mut rows = [[0i8; 3]; 3];
        for (row, m_row) in rows.iter_mut().zip(&rot.m) {
            for (entry, &m) in row.iter_mut().zip(m_row) {
                *entry = if m == S::ZERO {
                    0
                } else if m == S::ONE {
                    1
                } else if m == -S::ONE {
                    -1
                } else {
                    return None;
                };
            }
        }
        Self::try_from_rows(rows)
    }

    /// A determinant of +1: the parity of the permutation times the signs.
    const fn is_proper(&self) -> bool {
        let [a, b, c] = self.axes;
        // Even permutations are the cyclic shifts of (0, 1, 2).
        let even = (b == (a + 1) % 3) && (c == (b + 1) % 3);
        let flips = self.negative.count_ones() % 2 == 1;
        even != flips
    }

    /// Whether this is the identity.
    #[must_use]
    pub const fn is_identity(&self) -> bool {
        self.negative == 0 && self.axes[0] == 0 && self.axes[1] == 1 && self.axes[2] == 2
    }

    /// Row `r`'s sign: whether its entry is −1.
    #[inline]
    const fn flips(&self, r: usize) -> bool {
        self.negative & (1 << r) != 0
    }

    /// `self · other`: `other` first, then `self`.
    #[must_use]
    pub const fn compose(&self, other: &Self) -> Self {
        // (A B v)ᵣ = ±(B v)[a_r] = ±±v[b[a_r]].
        let mut axes = [0u8; 3];
        let mut negative = 0u8;
        let mut r = 0;
        while r < 3 {
            let a = self.axes[r] as usize;
            axes[r] = other.axes[a];
            if self.flips(r) != other.flips(a) {
                negative |= 1 << r;
            }
            r += 1;
        }
        Self { axes, negative }
    }

    /// The inverse rotation.
    #[must_use]
    pub const fn transpose(&self) -> Self {
        // Row r's entry at column a_r becomes row a_r's entry at column r.
        let mut axes = [0u8; 3];
        let mut negative = 0u8;
        let mut r = 0;
        while r < 3 {
            let a = self.axes[r] as usize;
            axes[a] = r as u8;
            if self.flips(r) {
                negative |= 1 << a;
            }
            r += 1;
        }
        Self { axes, negative }
    }

    /// Row `r`'s nonzero entry: its column, and whether it is −1.
    #[must_use]
    pub const fn row(&self, r: usize) -> (usize, bool) {
        (self.axes[r] as usize, self.flips(r))
    }

    /// `P e_k` as `(axis, reversed)`: the coordinate axis that axis `k`
    /// becomes, and whether it points the other way.
    #[must_use]
    pub const fn image_of_axis(&self, k: usize) -> (usize, bool) {
        let mut r = 0;
        while r < 2 && self.axes[r] as usize != k {
            r += 1;
        }
        (r, self.flips(r))
    }

    /// The matrix, exact in any scalar.
    #[must_use]
    pub const fn matrix<S: Scalar>(&self) -> Mat3<S> {
        let mut m = [[S::ZERO; 3]; 3];
        let mut r = 0;
        while r < 3 {
            m[r][self.axes[r] as usize] = if self.flips(r) { S::NEG_ONE } else { S::ONE };
            r += 1;
        }
        Mat3::from_rows(m)
    }

    /// `±x` for row `r`.
    #[inline(always)]
    fn sign<S: Scalar>(&self, r: usize, x: S) -> S {
        if self.flips(r) {
            -x
        } else {
            x
        }
    }

    /// `P v`.
    #[inline(always)]
    #[must_use]
    pub fn apply<S: Scalar>(&self, v: &Vec3<S>) -> Vec3<S> {
        let v = v.to_array();
        let [a, b, c] = self.axes.map(|a| usize::from(a) % 3);
        Vec3::new(self.sign(0, v[a]), self.sign(1, v[b]), self.sign(2, v[c]))
    }

    /// `P S Pᵀ`: entry `(r, c)` is `±S[a_r][a_c]`.
    #[inline(always)]
    #[must_use]
    pub fn apply_sym<S: Scalar>(&self, s: &Sym3<S>) -> Sym3<S> {
        let rows = s.rows();
        let [a, b, c] = self.axes.map(|a| usize::from(a) % 3);
        // Off the diagonal the two rows' signs multiply.
        let off = |r: usize, k: usize, x: S| {
            if self.flips(r) != self.flips(k) {
                -x
            } else {
                x
            }
        };
        Sym3::new(
            rows[a][a],
            off(0, 1, rows[a][b]),
            off(0, 2, rows[a][c]),
            rows[b][b],
            off(1, 2, rows[b][c]),
            rows[c][c],
        )
    }

    /// The inertia in the turned frame: `(m, P c, P I_c Pᵀ)`.
    #[inline(always)]
    #[must_use]
    pub fn apply_inertia<S: Scalar>(&self, i: &Inertia<S>) -> Inertia<S> {
        Inertia::new(i.mass, self.apply(&i.com), self.apply_sym(&i.rot_inertia))
    }

    /// `P X`: the transform `x` followed by this rotation (its rows
    /// reordered and signed).
    #[inline(always)]
    #[must_use]
    pub fn then_transform<S: Scalar>(&self, x: &Transform<S>) -> Transform<S> {
        let rows = x.rot.m;
        let row = |r: usize| {
            let src = rows[usize::from(self.axes[r]) % 3];
            src.map(|e| self.sign(r, e))
        };
        Transform::new(
            Mat3::from_rows([row(0), row(1), row(2)]),
            self.apply(&x.trans),
        )
    }
}

/// `const` versions of [`AxisPermutation::apply_inertia`] and
/// [`AxisPermutation::then_transform`] for one floating-point type (a
/// `const fn` can negate an `f32` or `f64`, not a generic [`Scalar`]).
macro_rules! const_turns_for {
    ($S:ty, $turn_vec:ident, $turn_inertia:ident, $turn_transform:ident) => {
        const fn $turn_vec(p: &AxisPermutation, v: &Vec3<$S>) -> Vec3<$S> {
            let v = [v.x, v.y, v.z];
            let mut out = [0.0; 3];
            let mut r = 0;
            while r < 3 {
                let x = v[p.axes[r] as usize];
                out[r] = if p.flips(r) { -x } else { x };
                r += 1;
            }
            Vec3::new(out[0], out[1], out[2])
        }

        /// `(m, P c, P I_c Pᵀ)`.
        pub(crate) const fn $turn_inertia(p: &AxisPermutation, i: &Inertia<$S>) -> Inertia<$S> {
            let s = &i.rot_inertia;
            let rows = [[s.xx, s.xy, s.xz], [s.xy, s.yy, s.yz], [s.xz, s.yz, s.zz]];
            let mut out = [[0.0; 3]; 3];
            let mut r = 0;
            while r < 3 {
                let mut c = 0;
                while c < 3 {
                    let x = rows[p.axes[r] as usize][p.axes[c] as usize];
                    out[r][c] = if p.flips(r) != p.flips(c) { -x } else { x };
                    c += 1;
                }
                r += 1;
            }
            Inertia::new(
                i.mass,
                $turn_vec(p, &i.com),
                Sym3::new(
                    out[0][0], out[0][1], out[0][2], out[1][1], out[1][2], out[2][2],
                ),
            )
        }

        /// `P X`.
        pub(crate) const fn $turn_transform(
            p: &AxisPermutation,
            x: &Transform<$S>,
        ) -> Transform<$S> {
            let mut rows = [[0.0; 3]; 3];
            let mut r = 0;
            while r < 3 {
                let src = x.rot.m[p.axes[r] as usize];
                let mut c = 0;
                while c < 3 {
                    rows[r][c] = if p.flips(r) { -src[c] } else { src[c] };
                    c += 1;
                }
                r += 1;
            }
            Transform::new(Mat3::from_rows(rows), $turn_vec(p, &x.trans))
        }
    };
}

const_turns_for!(f32, turn_vec_f32, turn_inertia_f32, turn_transform_f32);
const_turns_for!(f64, turn_vec_f64, turn_inertia_f64, turn_transform_f64);

impl Default for AxisPermutation {
    fn default() -> Self {
        Self::IDENTITY
    }
}

/// All 24 rotations that carry coordinate axes onto coordinate axes, from
/// every sign pattern of every permutation (for tests here and elsewhere).
#[cfg(all(test, feature = "std"))]
pub(crate) fn all_for_tests() -> std::vec::Vec<AxisPermutation> {
    let perms = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    let mut out = std::vec::Vec::new();
    for p in perms {
        for signs in 0..8 {
            let mut rows = [[0i8; 3]; 3];
            for r in 0..3 {
                rows[r][p[r]] = if signs & (1 << r) != 0 { -1 } else { 1 };
            }
            out.extend(AxisPermutation::try_from_rows(rows));
        }
    }
    assert_eq!(out.len(), 24);
    out
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::AxisPermutation;
    use crate::spatial::{Inertia, Mat3, Sym3, Transform, Vec3};

    fn all() -> Vec<AxisPermutation> {
        super::all_for_tests()
    }

    fn close(a: &Mat3<f64>, b: &Mat3<f64>) -> bool {
        (0..3).all(|r| (0..3).all(|c| (a.m[r][c] - b.m[r][c]).abs() < 1e-15))
    }

    #[test]
    fn there_are_24_and_each_is_a_rotation() {
        let all = all();
        assert_eq!(all.len(), 24);
        for p in &all {
            let m = p.matrix::<f64>();
            assert!(close(&m.mul_mat(&m.transpose()), &Mat3::IDENTITY));
            let m = m.m;
            let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
            assert_eq!(det, 1.0);
            let m = p.matrix::<f64>();
            assert_eq!(AxisPermutation::from_matrix(&m), Some(*p));
        }
        // A reflection and a non-permutation are refused.
        assert_eq!(
            AxisPermutation::try_from_rows([[-1, 0, 0], [0, 1, 0], [0, 0, 1]]),
            None
        );
        assert_eq!(
            AxisPermutation::try_from_rows([[1, 1, 0], [0, 1, 0], [0, 0, 1]]),
            None
        );
        let almost = Mat3::from_rows([[1.0, 0.0, 0.0], [0.0, 6e-17, -1.0], [0.0, 1.0, 6e-17]]);
        assert_eq!(AxisPermutation::from_matrix(&almost), None);
    }

    #[test]
    fn compose_transpose_and_actions_agree_with_the_matrices() {
        let v = Vec3::new(0.3, -1.2, 0.7);
        let s = Sym3::new(0.3, 0.01, -0.02, 0.4, 0.03, 0.5);
        let x = Transform::new(Mat3::from_axis_angle(&Vec3::new(0.6, 0.0, 0.8), 0.4), v);
        for a in all() {
            let ma = a.matrix::<f64>();
            assert!(close(&a.transpose().matrix(), &ma.transpose()));
            assert_eq!(a.apply(&v), ma.mul_vec(&v));
            assert_eq!(
                a.apply_sym(&s).to_mat3(),
                ma.mul_mat(&s.to_mat3()).mul_mat(&ma.transpose())
            );
            let i = Inertia::new(2.0, v, s);
            assert_eq!(a.apply_inertia(&i).com, ma.mul_vec(&v));
            let turned = a.then_transform(&x);
            assert!(close(&turned.rot, &ma.mul_mat(&x.rot)));
            assert_eq!(turned.trans, ma.mul_vec(&x.trans));
            for k in 0..3 {
                let (axis, reversed) = a.image_of_axis(k);
                let image = ma.mul_vec(&Vec3::unit(k));
                let sign = if reversed { -1.0 } else { 1.0 };
                assert_eq!(image, Vec3::unit(axis) * sign);
            }
            for b in all() {
                assert!(close(&a.compose(&b).matrix(), &ma.mul_mat(&b.matrix())));
            }
        }
        assert!(AxisPermutation::IDENTITY.is_identity());
    }
}
