//! approx's comparisons for rodyn's value types (feature `approx`).
//!
//! Two values are close when every entry is, by the scalar's own
//! comparison with the same tolerances: a `Transform`'s nine rotation and
//! three translation entries, an `Inertia`'s mass, centre of mass and six
//! tensor entries.
//!
//! ```
//! use approx::assert_relative_eq;
//! use rodyn::prelude::*;
//!
//! let a = Motion::new(Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.1, 0.2, 0.3));
//! let b = a * (1.0 + 1e-14);
//! assert_relative_eq!(a, b, max_relative = 1e-12);
//! assert!(approx::abs_diff_ne!(a, a * 2.0));
//! ```

use ::approx::{AbsDiffEq, RelativeEq, UlpsEq};

use crate::spatial::{Force, Inertia, Mat3, Motion, Sym3, Transform, Vec3};
use crate::Scalar;

/// A value as the list of its scalar entries, in a fixed order.
trait Entries<S> {
    /// The entries' array.
    type Array: AsRef<[S]>;
    /// Every entry, in a fixed order.
    fn entries(&self) -> Self::Array;
}

impl<S: Scalar> Entries<S> for Vec3<S> {
    type Array = [S; 3];
    fn entries(&self) -> [S; 3] {
        self.to_array()
    }
}

impl<S: Scalar> Entries<S> for Mat3<S> {
    type Array = [S; 9];
    fn entries(&self) -> [S; 9] {
        let m = &self.m;
        [
            m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2],
        ]
    }
}

impl<S: Scalar> Entries<S> for Sym3<S> {
    type Array = [S; 6];
    fn entries(&self) -> [S; 6] {
        [self.xx, self.xy, self.xz, self.yy, self.yz, self.zz]
    }
}

impl<S: Scalar> Entries<S> for Motion<S> {
    type Array = [S; 6];
    fn entries(&self) -> [S; 6] {
        self.to_linear_first()
    }
}

impl<S: Scalar> Entries<S> for Force<S> {
    type Array = [S; 6];
    fn entries(&self) -> [S; 6] {
        self.to_linear_first()
    }
}

impl<S: Scalar> Entries<S> for Transform<S> {
    type Array = [S; 12];
    fn entries(&self) -> [S; 12] {
        let (r, t) = (self.rot.entries(), &self.trans);
        [
            r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8], t.x, t.y, t.z,
        ]
    }
}

impl<S: Scalar> Entries<S> for Inertia<S> {
    type Array = [S; 10];
    fn entries(&self) -> [S; 10] {
        let (c, i) = (&self.com, self.rot_inertia.entries());
        [self.mass, c.x, c.y, c.z, i[0], i[1], i[2], i[3], i[4], i[5]]
    }
}

/// `AbsDiffEq`, `RelativeEq` and `UlpsEq` for `$ty<S>`, entry by entry.
macro_rules! approx_by_entries {
    ($($ty:ident),*) => {$(
        impl<S: Scalar + AbsDiffEq> AbsDiffEq for $ty<S>
        where
            S::Epsilon: Copy,
        {
            type Epsilon = S::Epsilon;
            fn default_epsilon() -> S::Epsilon {
                S::default_epsilon()
            }
            fn abs_diff_eq(&self, other: &Self, epsilon: S::Epsilon) -> bool {
                let (a, b) = (self.entries(), other.entries());
                a.as_ref().iter().zip(b.as_ref()).all(|(x, y)| x.abs_diff_eq(y, epsilon))
            }
        }

        impl<S: Scalar + RelativeEq> RelativeEq for $ty<S>
        where
            S::Epsilon: Copy,
        {
            fn default_max_relative() -> S::Epsilon {
                S::default_max_relative()
            }
            fn relative_eq(&self, other: &Self, epsilon: S::Epsilon, max_relative: S::Epsilon) -> bool {
                let (a, b) = (self.entries(), other.entries());
                a.as_ref()
                    .iter()
                    .zip(b.as_ref())
                    .all(|(x, y)| x.relative_eq(y, epsilon, max_relative))
            }
        }

        impl<S: Scalar + UlpsEq> UlpsEq for $ty<S>
        where
            S::Epsilon: Copy,
        {
            fn default_max_ulps() -> u32 {
                S::default_max_ulps()
            }
            fn ulps_eq(&self, other: &Self, epsilon: S::Epsilon, max_ulps: u32) -> bool {
                let (a, b) = (self.entries(), other.entries());
                a.as_ref().iter().zip(b.as_ref()).all(|(x, y)| x.ulps_eq(y, epsilon, max_ulps))
            }
        }
    )*};
}

approx_by_entries!(Vec3, Mat3, Sym3, Motion, Force, Transform, Inertia);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_entry_off_by_more_than_the_tolerance_makes_values_differ() {
        let t = Transform::new(
            Mat3::from_axis_angle(&Vec3::new(0.0, 0.0, 1.0), 0.3),
            Vec3::new(1.0, 2.0, 3.0),
        );
        let mut moved = t;
        moved.trans.z += 1e-6;
        assert!(t.abs_diff_eq(&moved, 1e-5));
        assert!(!t.abs_diff_eq(&moved, 1e-7));
        assert!(t.relative_eq(&moved, 0.0, 1e-6));
        assert!(!t.relative_eq(&moved, 0.0, 1e-8));
        assert!(t.ulps_eq(&t, 0.0, 0));
        assert!(!t.ulps_eq(&moved, 0.0, 4));
        let inertia = Inertia::point_mass(2.0_f32, Vec3::new(0.1, 0.0, 0.0));
        let heavier = Inertia::point_mass(2.0 + 1e-3, Vec3::new(0.1, 0.0, 0.0));
        assert!(inertia.abs_diff_eq(&heavier, 2e-3));
        assert!(!inertia.abs_diff_eq(&heavier, 1e-4));
    }
}
