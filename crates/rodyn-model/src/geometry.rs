//! The few pieces of 3-D geometry the compiler needs, in `f64`: rotations
//! from roll-pitch-yaw, rigid poses, and rigid-body inertias that can be
//! moved between frames and summed (fixed joints merge their child link into
//! the parent body).
//!
//! Conventions are rodyn's and Pinocchio's: a [`Pose`] `aMb` holds the
//! rotation of frame b in frame a and the origin of b in a; a point in b maps
//! to `rot * p + trans` in a.

/// A 3-vector.
pub type Vec3 = [f64; 3];
/// A 3x3 matrix, row-major.
pub type Mat3 = [[f64; 3]; 3];

/// The identity matrix.
pub const IDENTITY: Mat3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// `a * b`.
#[must_use]
pub fn mat_mul(a: &Mat3, b: &Mat3) -> Mat3 {
    let mut c = [[0.0; 3]; 3];
    for (i, row) in c.iter_mut().enumerate() {
        for (j, cij) in row.iter_mut().enumerate() {
            *cij = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    c
}

/// `aᵀ`.
#[must_use]
pub fn transpose(a: &Mat3) -> Mat3 {
    let mut t = [[0.0; 3]; 3];
    for (i, row) in a.iter().enumerate() {
        for (j, aij) in row.iter().enumerate() {
            t[j][i] = *aij;
        }
    }
    t
}

/// `a * v`.
#[must_use]
pub fn mat_vec(a: &Mat3, v: &Vec3) -> Vec3 {
    [0, 1, 2].map(|i| a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2])
}

/// `a + b`.
#[must_use]
pub fn add(a: &Vec3, b: &Vec3) -> Vec3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a - b`.
#[must_use]
pub fn sub(a: &Vec3, b: &Vec3) -> Vec3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `s * a`.
#[must_use]
pub fn scale(a: &Vec3, s: f64) -> Vec3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// Euclidean norm.
#[must_use]
pub fn norm(a: &Vec3) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

/// The rotation of URDF's `rpy` attribute: `R = Rz(yaw) Ry(pitch) Rx(roll)`
/// (fixed-axis roll about x, then pitch about y, then yaw about z), as
/// urdfdom and Pinocchio compute it.
#[must_use]
pub fn rotation_from_rpy(rpy: &Vec3) -> Mat3 {
    let (sr, cr) = rpy[0].sin_cos();
    let (sp, cp) = rpy[1].sin_cos();
    let (sy, cy) = rpy[2].sin_cos();
    [
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ]
}

/// How close (absolute) an entry must be to 0 or ±1 for
/// [`snap_signed_permutation`] to round it when a file asks for it
/// ([`ModelDescription::round_quarter_turns`](crate::ModelDescription::round_quarter_turns)):
/// above the 4.9e-12 of π/2 written to 12 digits (`1.57079632679`, as the
/// UR descriptions write it) and far below any deliberate rotation. The
/// rounding moves the model: on Talos, ABA by up to 2.8e-9 relative.
pub const SNAP_TOLERANCE: f64 = 1e-10;

/// The default: only the rounding that evaluating an exact quarter turn
/// leaves (`cos(π/2)` is 6.1e-17 in f64), so the compiled model keeps the
/// file's rotation to the last bit but a few.
pub const EXACT_TOLERANCE: f64 = 4.0 * f64::EPSILON;

/// `m` with its entries rounded to exactly 0 or ±1 when every entry is within
/// `tolerance` ([`EXACT_TOLERANCE`] or, on request, [`SNAP_TOLERANCE`]) of
/// one of them and the result is a rotation (a signed permutation: one ±1
/// per row and column, determinant +1); otherwise `None`.
///
/// A URDF `rpy` of 0 or ±π/2 gives such a rotation up to 6e-17 entries where
/// zeros belong, or up to 5e-12 when π/2 is written to 12 digits; exact
/// entries keep the generated source readable and the products with them
/// exact, and let the algorithms take the quarter turn into their frames.
/// [`snap_deviation`] says how far the entries moved.
#[must_use]
pub fn snap_signed_permutation(m: &Mat3, tolerance: f64) -> Option<Mat3> {
    let mut out = [[0.0; 3]; 3];
    for (row, out_row) in m.iter().zip(&mut out) {
        for (v, o) in row.iter().zip(out_row.iter_mut()) {
            let snapped = v.round();
            if (v - snapped).abs() > tolerance || snapped.abs() > 1.0 {
                return None;
            }
            // `round` keeps the sign of a tiny negative: write a clean zero.
            *o = if snapped == 0.0 { 0.0 } else { snapped };
        }
    }
    let one_per_line = (0..3).all(|k| {
        let row: f64 = out[k].iter().map(|v| v.abs()).sum();
        let col: f64 = out.iter().map(|r| r[k].abs()).sum();
        row == 1.0 && col == 1.0
    });
    let det = out[0][0] * (out[1][1] * out[2][2] - out[1][2] * out[2][1])
        - out[0][1] * (out[1][0] * out[2][2] - out[1][2] * out[2][0])
        + out[0][2] * (out[1][0] * out[2][1] - out[1][1] * out[2][0]);
    (one_per_line && det == 1.0).then_some(out)
}

/// The largest change of an entry of `m` that [`snap_signed_permutation`]
/// makes at `tolerance`; `None` where it does not snap.
#[must_use]
pub fn snap_deviation(m: &Mat3, tolerance: f64) -> Option<f64> {
    let snapped = snap_signed_permutation(m, tolerance)?;
    Some(
        m.iter()
            .flatten()
            .zip(snapped.iter().flatten())
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max),
    )
}

/// A rigid pose `aMb` (rotation, then translation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    /// Orientation of b's axes in a.
    pub rot: Mat3,
    /// Origin of b in a (m).
    pub trans: Vec3,
}

impl Pose {
    /// The identity pose.
    pub const IDENTITY: Self = Self {
        rot: IDENTITY,
        trans: [0.0; 3],
    };

    /// From a translation and URDF roll-pitch-yaw angles (rad).
    #[must_use]
    pub fn from_xyz_rpy(xyz: &Vec3, rpy: &Vec3) -> Self {
        Self {
            rot: rotation_from_rpy(rpy),
            trans: *xyz,
        }
    }

    /// `aMc = aMb * bMc`.
    #[must_use]
    pub fn compose(&self, b_m_c: &Self) -> Self {
        Self {
            rot: mat_mul(&self.rot, &b_m_c.rot),
            trans: add(&mat_vec(&self.rot, &b_m_c.trans), &self.trans),
        }
    }

    /// A point given in b, seen from a.
    #[must_use]
    pub fn act_point(&self, p: &Vec3) -> Vec3 {
        add(&mat_vec(&self.rot, p), &self.trans)
    }

    /// `true` when the rotation is exactly the identity.
    #[must_use]
    pub fn has_identity_rotation(&self) -> bool {
        self.rot == IDENTITY
    }
}

/// Mass (kg), centre of mass (m) and rotational inertia about the centre of
/// mass (kg m²), all in one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidInertia {
    /// Mass.
    pub mass: f64,
    /// Centre of mass.
    pub com: Vec3,
    /// Rotational inertia about the centre of mass, symmetric.
    pub inertia: Mat3,
}

impl RigidInertia {
    /// No mass.
    pub const ZERO: Self = Self {
        mass: 0.0,
        com: [0.0; 3],
        inertia: [[0.0; 3]; 3],
    };

    /// The same body expressed in frame a, given `aMb` (it was expressed in b).
    #[must_use]
    pub fn expressed_in(&self, a_m_b: &Pose) -> Self {
        let r = &a_m_b.rot;
        Self {
            mass: self.mass,
            com: a_m_b.act_point(&self.com),
            inertia: mat_mul(&mat_mul(r, &self.inertia), &transpose(r)),
        }
    }

    /// Two bodies rigidly joined, both expressed in the same frame: masses add,
    /// the centre of mass is the weighted mean, and each rotational inertia
    /// moves to the new centre by the parallel-axis theorem.
    #[must_use]
    pub fn combined(&self, other: &Self) -> Self {
        let mass = self.mass + other.mass;
        if mass <= 0.0 {
            return Self::ZERO;
        }
        let com = scale(
            &add(&scale(&self.com, self.mass), &scale(&other.com, other.mass)),
            1.0 / mass,
        );
        let mut inertia = [[0.0; 3]; 3];
        for part in [self, other] {
            let d = sub(&part.com, &com);
            let d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            for (i, row) in inertia.iter_mut().enumerate() {
                for (j, x) in row.iter_mut().enumerate() {
                    let delta = if i == j { 1.0 } else { 0.0 };
                    *x += part.inertia[i][j] + part.mass * (d2 * delta - d[i] * d[j]);
                }
            }
        }
        Self { mass, com, inertia }
    }
}

/// Eigenvalues of a symmetric 3x3 matrix, ascending (cyclic Jacobi sweeps;
/// exact enough for the physical checks, which use a relative tolerance).
#[must_use]
pub fn symmetric_eigenvalues(m: &Mat3) -> Vec3 {
    let mut a = *m;
    for _ in 0..50 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        if off <= 1e-300 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            // The rotation in the (p, q) plane that zeroes a[p][q].
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let t = if theta == 0.0 { 1.0 } else { t };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            let mut j = IDENTITY;
            j[p][p] = c;
            j[q][q] = c;
            j[p][q] = s;
            j[q][p] = -s;
            a = mat_mul(&mat_mul(&transpose(&j), &a), &j);
        }
    }
    let mut e = [a[0][0], a[1][1], a[2][2]];
    e.sort_by(f64::total_cmp);
    e
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rpy_matches_the_product_of_elementary_rotations() {
        let rpy = [0.3, -0.7, 1.1];
        let rx = rotation_from_rpy(&[rpy[0], 0.0, 0.0]);
        let ry = rotation_from_rpy(&[0.0, rpy[1], 0.0]);
        let rz = rotation_from_rpy(&[0.0, 0.0, rpy[2]]);
        let expected = mat_mul(&rz, &mat_mul(&ry, &rx));
        let r = rotation_from_rpy(&rpy);
        for i in 0..3 {
            for j in 0..3 {
                assert!((r[i][j] - expected[i][j]).abs() < 1e-15);
            }
        }
        // Rz(pi/2) maps x to y.
        let rz90 = rotation_from_rpy(&[0.0, 0.0, core::f64::consts::FRAC_PI_2]);
        let y = mat_vec(&rz90, &[1.0, 0.0, 0.0]);
        assert!((y[1] - 1.0).abs() < 1e-15 && y[0].abs() < 1e-15);
    }

    #[test]
    // π/2 as URDF files write it, on purpose.
    #[allow(clippy::approx_constant)]
    fn quarter_turns_snap_to_exact_signed_permutations_and_nothing_else_does() {
        let half_pi = core::f64::consts::FRAC_PI_2;
        let quarter = rotation_from_rpy(&[half_pi, 0.0, -half_pi]);
        assert!(quarter
            .iter()
            .flatten()
            .any(|v| *v != 0.0 && v.abs() < 1e-15));
        let snapped = snap_signed_permutation(&quarter, EXACT_TOLERANCE).expect("a quarter turn");
        assert!(snapped
            .iter()
            .flatten()
            .all(|v| [0.0, 1.0, -1.0].contains(v)));
        for (a, b) in snapped.iter().flatten().zip(quarter.iter().flatten()) {
            assert!((a - b).abs() < 1e-15);
        }
        // π/2 to 12 digits, as the UR descriptions write it: kept as
        // written by default; rounded on request, and the change said; to
        // 10 digits (1.8e-9 off): kept either way.
        let ur = rotation_from_rpy(&[0.0, 1.57079632679, 0.0]);
        assert_eq!(snap_deviation(&ur, EXACT_TOLERANCE), None);
        let moved = snap_deviation(&ur, SNAP_TOLERANCE).expect("a quarter turn to 12 digits");
        assert!(moved > 4.8e-12 && moved < 5.0e-12, "{moved}");
        assert_eq!(
            snap_deviation(&rotation_from_rpy(&[0.0, 1.570796327, 0.0]), SNAP_TOLERANCE),
            None
        );
        // A small deliberate rotation is kept as it is.
        assert_eq!(
            snap_signed_permutation(&rotation_from_rpy(&[1e-9, 0.0, 0.0]), SNAP_TOLERANCE),
            None
        );
        // A reflection is not a rotation.
        let mirror = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]];
        assert_eq!(snap_signed_permutation(&mirror, SNAP_TOLERANCE), None);
    }

    #[test]
    fn eigenvalues_of_a_rotated_diagonal_matrix() {
        let r = rotation_from_rpy(&[0.4, 0.2, -0.9]);
        let d = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 5.0]];
        let m = mat_mul(&mat_mul(&r, &d), &transpose(&r));
        let e = symmetric_eigenvalues(&m);
        for (got, want) in e.iter().zip([1.0, 2.0, 5.0]) {
            assert!((got - want).abs() < 1e-12, "{e:?}");
        }
    }

    #[test]
    fn combining_two_point_masses_gives_the_dumbbell_inertia() {
        let a = RigidInertia {
            mass: 1.0,
            com: [1.0, 0.0, 0.0],
            inertia: [[0.0; 3]; 3],
        };
        let b = RigidInertia {
            com: [-1.0, 0.0, 0.0],
            ..a
        };
        let c = a.combined(&b);
        assert_eq!(c.mass, 2.0);
        assert_eq!(c.com, [0.0; 3]);
        // Two 1 kg masses 1 m from the centre: 2 kg m² about y and z, 0 about x.
        assert_eq!(c.inertia[0][0], 0.0);
        assert_eq!(c.inertia[1][1], 2.0);
        assert_eq!(c.inertia[2][2], 2.0);
    }
}
