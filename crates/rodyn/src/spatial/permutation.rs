//! Signed permutations: the rotations of the ±90° placements of URDF robots.
//!
//! A joint placement written with `rpy` angles of 0 or ±π/2 (most arms,
//! e.g. the Panda's `rpy="-1.5708 0 0"`) has a rotation `E` whose entries
//! are 0 or ±1: a permutation of the axes with signs. Applying such an `E`
//! moves and negates entries and multiplies nothing. The model records which
//! placements are one ([`PlacementRotation`]), so that a transform can apply
//! `E` and the joint's own rotation separately. The algorithms do not use it
//! yet: applied through run-time column indices, as here, the moves cost
//! more on the Cortex-M4 than the multiply-accumulates they replace
//! (`docs/sections/performance.md`).
//!
//! Row `r` of `E` holds its only non-zero entry, `±1`, in column `col[r]`:
//! `(E v)_r = ±v_col[r]`.

use super::{Mat3, Sym3, Vec3};
use crate::Scalar;

/// A rotation matrix whose entries are 0 or ±1 (a signed permutation with
/// determinant +1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SignedPermutation {
    /// Column of the non-zero entry of each row.
    col: [u8; 3],
    /// Whether that entry is -1.
    neg: [bool; 3],
}

/// `x` or `-x`: applying a ±1 entry without a multiplication.
#[inline]
fn signed<S: Scalar>(x: S, neg: bool) -> S {
    if neg {
        -x
    } else {
        x
    }
}

impl SignedPermutation {
    /// The identity.
    pub const IDENTITY: Self = Self::new([0, 1, 2], [false, false, false]);

    /// The rotation with entry `(r, col[r]) = if neg[r] { -1 } else { 1 }`.
    ///
    /// # Panics
    /// When `col` is not a permutation of `0, 1, 2` or the matrix is a
    /// reflection (determinant -1); in a `const` this is a compile error.
    #[must_use]
    pub const fn new(col: [u8; 3], neg: [bool; 3]) -> Self {
        assert!(
            col[0] < 3 && col[1] < 3 && col[2] < 3,
            "a signed permutation's columns are 0, 1 and 2"
        );
        assert!(
            col[0] != col[1] && col[0] != col[2] && col[1] != col[2],
            "a signed permutation uses each column once"
        );
        // The determinant: the permutation's parity times the signs.
        let odd_permutation =
            col[0] == 0 && col[1] == 2 || col[0] == 1 && col[1] == 0 || col[0] == 2 && col[1] == 1;
        let negatives = neg[0] as u8 + neg[1] as u8 + neg[2] as u8;
        assert!(
            (negatives % 2 == 1) == odd_permutation,
            "a signed permutation must be a rotation (determinant +1)"
        );
        Self { col, neg }
    }

    /// The signed permutation equal to `m`, if every entry of `m` is exactly
    /// 0 or ±1 and `m` is a rotation; otherwise `None`.
    ///
    /// Exact equality is required: the fast paths ignore the stored matrix
    /// and apply the permutation, so both must be the same matrix. The model
    /// compiler rounds entries within 1e-12 of 0 or ±1 before writing them.
    #[must_use]
    pub fn from_mat3<S: Scalar>(m: &Mat3<S>) -> Option<Self> {
        let mut col = [0u8; 3];
        let mut neg = [false; 3];
        for (r, row) in m.m.iter().enumerate() {
            let mut found = false;
            for (c, value) in row.iter().enumerate() {
                let v = value.to_f64();
                if v == 0.0 {
                    continue;
                }
                if found || v.abs() != 1.0 {
                    return None;
                }
                found = true;
                col[r] = c as u8;
                neg[r] = v < 0.0;
            }
            if !found {
                return None;
            }
        }
        let distinct = col[0] != col[1] && col[0] != col[2] && col[1] != col[2];
        let e = Self { col, neg };
        // A reflection is not a placement (validation rejects it anyway).
        (distinct && e.determinant_is_positive()).then_some(e)
    }

    const fn determinant_is_positive(&self) -> bool {
        let c = &self.col;
        let odd = c[0] == 0 && c[1] == 2 || c[0] == 1 && c[1] == 0 || c[0] == 2 && c[1] == 1;
        let negatives = self.neg[0] as u8 + self.neg[1] as u8 + self.neg[2] as u8;
        (negatives % 2 == 1) == odd
    }

    /// Column of row `r`'s non-zero entry.
    #[inline]
    #[must_use]
    pub const fn column_of_row(&self, r: usize) -> usize {
        self.col[r] as usize
    }
    /// Whether row `r`'s non-zero entry is -1.
    #[inline]
    #[must_use]
    pub const fn is_negative(&self, r: usize) -> bool {
        self.neg[r]
    }

    /// The matrix.
    #[must_use]
    pub fn to_mat3<S: Scalar>(&self) -> Mat3<S> {
        let mut m = Mat3::ZERO;
        for r in 0..3 {
            m.m[r][self.col[r] as usize] = signed(S::ONE, self.neg[r]);
        }
        m
    }

    /// `E v`.
    #[inline]
    #[must_use]
    pub fn mul_vec<S: Scalar>(&self, v: &Vec3<S>) -> Vec3<S> {
        let v = v.to_array();
        Vec3::from_array(core::array::from_fn(|r| {
            signed(v[self.col[r] as usize], self.neg[r])
        }))
    }

    /// `Eᵀ v`.
    #[inline]
    #[must_use]
    pub fn tr_mul_vec<S: Scalar>(&self, v: &Vec3<S>) -> Vec3<S> {
        let v = v.to_array();
        let mut out = [S::ZERO; 3];
        for r in 0..3 {
            out[self.col[r] as usize] = signed(v[r], self.neg[r]);
        }
        Vec3::from_array(out)
    }

    /// `E M Eᵀ`: entry `(a, b)` is `±M[col a][col b]`.
    #[must_use]
    pub fn conjugate<S: Scalar>(&self, m: &Mat3<S>) -> Mat3<S> {
        let mut out = Mat3::ZERO;
        for a in 0..3 {
            let row = &m.m[self.col[a] as usize];
            for b in 0..3 {
                out.m[a][b] = signed(row[self.col[b] as usize], self.neg[a] != self.neg[b]);
            }
        }
        out
    }

    /// `E S Eᵀ` for a symmetric `S` (six entries moved, some negated).
    #[must_use]
    pub fn conjugate_sym<S: Scalar>(&self, s: &Sym3<S>) -> Sym3<S> {
        let (c, n) = (&self.col, &self.neg);
        let e = |a: usize, b: usize| signed(s.get(c[a] as usize, c[b] as usize), n[a] != n[b]);
        Sym3::new(e(0, 0), e(0, 1), e(0, 2), e(1, 1), e(1, 2), e(2, 2))
    }
}

/// What is known about the rotation of a joint's placement, found once when
/// the model is built ([`Model::with_placement_rotations`](crate::Model::with_placement_rotations),
/// [`Model::with_classified_placements`](crate::Model::with_classified_placements)).
///
/// It is meant to let the algorithms that carry inertias, forces and motions
/// across a joint apply the placement's rotation `E` and the joint's own
/// rotation separately, where that is cheaper than the full product
/// `E Rⱼ(q)`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PlacementRotation {
    /// Any rotation: the general 3x3 products.
    #[default]
    General,
    /// Exactly this signed permutation (identity included).
    SignedPermutation(SignedPermutation),
}

impl PlacementRotation {
    /// The class of rotation `m`.
    #[must_use]
    pub fn classify<S: Scalar>(m: &Mat3<S>) -> Self {
        match SignedPermutation::from_mat3(m) {
            Some(e) => Self::SignedPermutation(e),
            None => Self::General,
        }
    }
    /// `true` when `m` is the rotation this class claims (always for
    /// [`General`](Self::General)).
    #[must_use]
    pub fn matches<S: Scalar>(&self, m: &Mat3<S>) -> bool {
        match self {
            Self::General => true,
            Self::SignedPermutation(e) => SignedPermutation::from_mat3(m) == Some(*e),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn panda_placement_is_recognised_and_applied_exactly() {
        // rpy = (-π/2, 0, 0) with its entries rounded.
        let m = Mat3::<f64>::from_rows([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]]);
        let e = SignedPermutation::from_mat3(&m).expect("a signed permutation");
        assert_eq!(e.to_mat3::<f64>(), m);
        let v = Vec3::new(0.3, -1.7, 2.9);
        assert_eq!(e.mul_vec(&v), m.mul_vec(&v));
        assert_eq!(e.tr_mul_vec(&v), m.tr_mul_vec(&v));
        let g = Mat3::from_rows([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0], [7.0, 8.0, 9.0]]);
        assert_eq!(e.conjugate(&g), m.mul_mat(&g).mul_mat_tr(&m));
        let s = Sym3::new(1.0, 0.2, 0.3, 2.0, 0.5, 3.0);
        assert_eq!(e.conjugate_sym(&s), s.rotate(&m));
    }

    #[test]
    fn near_permutations_and_reflections_are_general() {
        let near = Mat3::<f64>::from_rows([
            [1.0, 0.0, 0.0],
            [0.0, 6.123e-17, 1.0],
            [0.0, -1.0, 6.123e-17],
        ]);
        assert_eq!(
            PlacementRotation::classify(&near),
            PlacementRotation::General
        );
        let reflection =
            Mat3::<f64>::from_rows([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]);
        assert_eq!(SignedPermutation::from_mat3(&reflection), None);
        assert_eq!(
            PlacementRotation::classify(&Mat3::<f32>::IDENTITY),
            PlacementRotation::SignedPermutation(SignedPermutation::IDENTITY)
        );
    }
}
