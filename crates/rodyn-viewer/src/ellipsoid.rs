//! A body's inertia drawn as the solid ellipsoid of uniform density with
//! the same mass and rotational inertia about the centre of mass.
//!
//! A uniform ellipsoid of semi-axes a, b, c has I_x = m (b² + c²) / 5 and
//! cyclically, so a² = 5 (I_y + I_z − I_x) / (2m) over the principal
//! moments. The principal axes come from Jacobi rotations.

/// Semi-axes (m) along the columns of `axes`, in the body frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ellipsoid {
    /// Semi-axis lengths, m.
    pub radii: [f64; 3],
    /// Rotation whose columns are the principal axes (determinant +1).
    pub axes: [[f64; 3]; 3],
}

/// The equivalent ellipsoid of mass `mass` (kg) and rotational inertia
/// `inertia` about the centre of mass (kg m²); `None` for a massless body
/// or a tensor that is not finite. A tensor that breaks the triangle
/// inequality gives a zero semi-axis where the formula turns negative.
#[must_use]
pub fn inertia_ellipsoid(mass: f64, inertia: &[[f64; 3]; 3]) -> Option<Ellipsoid> {
    let massive = mass > 0.0 && mass.is_finite();
    if !massive || !inertia.iter().flatten().all(|v| v.is_finite()) {
        return None;
    }
    let (moments, axes) = symmetric_eigen(inertia);
    let radii = core::array::from_fn(|k| {
        let others = moments[(k + 1) % 3] + moments[(k + 2) % 3];
        (2.5 * (others - moments[k]) / mass).max(0.0).sqrt()
    });
    Some(Ellipsoid { radii, axes })
}

/// Eigenvalues and eigenvectors (columns of a rotation) of a symmetric
/// 3 × 3 matrix by cyclic Jacobi rotations (Golub & Van Loan, §8.5).
fn symmetric_eigen(m: &[[f64; 3]; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let mut a = *m;
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let scale = a.iter().flatten().map(|x| x.abs()).fold(0.0, f64::max);
    for _sweep in 0..50 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        if off <= 1e-15 * scale {
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
            for row in &mut a {
                let (akp, akq) = (row[p], row[q]);
                row[p] = c * akp - s * akq;
                row[q] = s * akp + c * akq;
            }
            let (row_p, row_q) = (a[p], a[q]);
            a[p] = core::array::from_fn(|k| c * row_p[k] - s * row_q[k]);
            a[q] = core::array::from_fn(|k| s * row_p[k] + c * row_q[k]);
            for row in &mut v {
                let (vp, vq) = (row[p], row[q]);
                row[p] = c * vp - s * vq;
                row[q] = s * vp + c * vq;
            }
        }
    }
    // Keep a right-handed frame for the page's rotation.
    let det = v[0][0] * (v[1][1] * v[2][2] - v[1][2] * v[2][1])
        - v[0][1] * (v[1][0] * v[2][2] - v[1][2] * v[2][0])
        + v[0][2] * (v[1][0] * v[2][1] - v[1][1] * v[2][0]);
    if det < 0.0 {
        for row in &mut v {
            row[2] = -row[2];
        }
    }
    ([a[0][0], a[1][1], a[2][2]], v)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A uniform ellipsoid's own tensor gives its semi-axes back, turned.
    #[test]
    fn a_uniform_ellipsoid_gives_its_semi_axes_back() {
        let (m, a, b, c) = (2.0, 0.3, 0.2, 0.1);
        let diag = [
            m * (b * b + c * c) / 5.0,
            m * (a * a + c * c) / 5.0,
            m * (a * a + b * b) / 5.0,
        ];
        // Turned by 0.7 rad about z: R diag Rᵀ.
        let (s, co) = 0.7f64.sin_cos();
        let r = [[co, -s, 0.0], [s, co, 0.0], [0.0, 0.0, 1.0]];
        let mut i = [[0.0; 3]; 3];
        for p in 0..3 {
            for q in 0..3 {
                i[p][q] = (0..3).map(|k| r[p][k] * diag[k] * r[q][k]).sum();
            }
        }
        let e = inertia_ellipsoid(m, &i).unwrap();
        let mut radii = e.radii;
        radii.sort_by(f64::total_cmp);
        for (got, want) in radii.iter().zip([c, b, a]) {
            assert!((got - want).abs() < 1e-12, "{radii:?}");
        }
        // The longest semi-axis lies along R's first column.
        let k = (0..3)
            .max_by(|&x, &y| e.radii[x].total_cmp(&e.radii[y]))
            .unwrap();
        let along = (0..3).map(|row| e.axes[row][k] * r[row][0]).sum::<f64>();
        assert!((along.abs() - 1.0).abs() < 1e-12, "{along}");
    }

    #[test]
    fn a_massless_body_has_no_ellipsoid() {
        assert_eq!(inertia_ellipsoid(0.0, &[[0.0; 3]; 3]), None);
        assert_eq!(inertia_ellipsoid(1.0, &[[f64::NAN; 3]; 3]), None);
    }
}
