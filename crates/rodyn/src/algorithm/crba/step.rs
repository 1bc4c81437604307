//! A joint transform prepared to move many forces and one inertia into the
//! parent's frame, as CRBA's backward pass does at each body.
//!
//! Many joints turn about a coordinate axis of a placement that does not
//! rotate, or turns about the same axis (every joint of a Solo12 leg or of
//! a chain, and of the UR5); their transform then mixes two components of
//! each vector: 4 products where a general rotation takes 9, and 12
//! instead of 45 for an inertia.

use crate::space::RigidTransform;
use crate::spatial::{Force, Inertia, Mat3, Sym3, Transform, Vec3};
use crate::Scalar;

/// `ˡⁱXᵢ`, ready to act on forces and inertias.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TransformStep<S> {
    /// A rotation by `(cos, sin)` about coordinate axis `axis`, then the
    /// translation `trans`.
    Axis {
        /// 0, 1 or 2 for x, y, z.
        axis: usize,
        /// Cosine of the angle.
        cos: S,
        /// Sine of the angle.
        sin: S,
        /// The child's origin in the parent's frame.
        trans: Vec3<S>,
    },
    /// Any other transform.
    General(Transform<S>),
}

impl<S: Scalar> TransformStep<S> {
    /// Recognises a rotation about a coordinate axis by its exact zeros and
    /// its unit entry (a joint about a coordinate axis composed with a
    /// placement that does not rotate has them exactly).
    #[inline(always)]
    #[must_use]
    pub fn new(x: &Transform<S>) -> Self {
        for axis in 0..3 {
            if let Some((cos, sin)) = Self::turn_about(&x.rot, axis) {
                return Self::Axis {
                    axis,
                    cos,
                    sin,
                    trans: x.trans,
                };
            }
        }
        Self::General(*x)
    }

    /// `Some((cos, sin))` when `rot` turns about coordinate axis `axis`
    /// only: its row and column `axis` are exactly those of the identity.
    #[inline(always)]
    #[must_use]
    pub fn turn_about(rot: &Mat3<S>, axis: usize) -> Option<(S, S)> {
        // Constant indices for each axis: no index arithmetic at run time.
        match axis {
            0 => turn_about_axis::<S, 0>(rot),
            1 => turn_about_axis::<S, 1>(rot),
            _ => turn_about_axis::<S, 2>(rot),
        }
    }

    /// The translation: the child's origin in the parent's frame.
    #[inline]
    #[must_use]
    pub fn translation(&self) -> Vec3<S> {
        match self {
            Self::Axis { trans, .. } => *trans,
            Self::General(x) => x.trans,
        }
    }

    /// `x` followed by this step, as one transform: for a rotation about
    /// axis K, two columns of `x`'s rotation mix (12 products where a
    /// general product of rotations takes 27).
    #[inline(always)]
    #[must_use]
    pub fn after(&self, x: &Transform<S>) -> Transform<S> {
        match *self {
            Self::Axis {
                axis,
                cos,
                sin,
                trans,
            } => {
                let rot = match axis {
                    0 => turn_columns_about::<S, 0>(&x.rot, cos, sin),
                    1 => turn_columns_about::<S, 1>(&x.rot, cos, sin),
                    _ => turn_columns_about::<S, 2>(&x.rot, cos, sin),
                };
                Transform::new(rot, x.rot.mul_vec(&trans) + x.trans)
            }
            Self::General(g) => x.compose(&g),
        }
    }

    /// `X* f` for every force of `forces`: forces in the child's frame
    /// expressed in the parent's.
    #[inline(always)]
    pub fn act_forces(&self, forces: &mut [Force<S>]) {
        match *self {
            Self::Axis {
                axis,
                cos,
                sin,
                trans,
            } => match axis {
                0 => act_forces_about::<S, 0>(cos, sin, &trans, forces),
                1 => act_forces_about::<S, 1>(cos, sin, &trans, forces),
                _ => act_forces_about::<S, 2>(cos, sin, &trans, forces),
            },
            Self::General(x) => {
                for f in forces {
                    *f = x.act_force(f);
                }
            }
        }
    }
}

impl<S: Scalar> TransformStep<S> {
    /// The inertia's rotation alone: `(m, R c, R Ī Rᵀ)`. (The translation
    /// is applied where it is added to the parent's.)
    #[inline(always)]
    #[must_use]
    pub fn rotate_inertia(&self, i: &Inertia<S>) -> Inertia<S> {
        match *self {
            Self::Axis { axis, cos, sin, .. } => match axis {
                0 => rotate_inertia_about::<S, 0>(cos, sin, i),
                1 => rotate_inertia_about::<S, 1>(cos, sin, i),
                _ => rotate_inertia_about::<S, 2>(cos, sin, i),
            },
            Self::General(x) => {
                Inertia::new(i.mass, x.rot.mul_vec(&i.com), i.rot_inertia.rotate(&x.rot))
            }
        }
    }
}

/// [`TransformStep::turn_about`] for axis `K`.
#[inline(always)]
fn turn_about_axis<S: Scalar, const K: usize>(rot: &Mat3<S>) -> Option<(S, S)> {
    let m = &rot.m;
    let (zero, one) = (S::ZERO, S::ONE);
    let (a, b) = ((K + 1) % 3, (K + 2) % 3);
    let about_axis =
        m[K][K] == one && m[K][a] == zero && m[K][b] == zero && m[a][K] == zero && m[b][K] == zero;
    about_axis.then(|| (m[a][a], m[b][a]))
}

/// `m R` for a rotation `R` by `(c, s)` about axis `K`: each row of `m`
/// turns as a plane vector in its components `(K + 1, K + 2) mod 3`.
#[inline(always)]
fn turn_columns_about<S: Scalar, const K: usize>(m: &Mat3<S>, c: S, s: S) -> Mat3<S> {
    let (a, b) = ((K + 1) % 3, (K + 2) % 3);
    let mut out = *m;
    for (row, turned) in m.m.iter().zip(out.m.iter_mut()) {
        turned[a] = c * row[a] + s * row[b];
        turned[b] = c * row[b] - s * row[a];
    }
    out
}

/// `X* f` over `forces` for a rotation by `(c, s)` about axis `K`.
#[inline(always)]
fn act_forces_about<S: Scalar, const K: usize>(
    c: S,
    s: S,
    trans: &Vec3<S>,
    forces: &mut [Force<S>],
) {
    for f in forces {
        let lin = rotate_about::<S, K>(c, s, &f.lin);
        let ang = rotate_about::<S, K>(c, s, &f.ang) + trans.cross(&lin);
        *f = Force::new(ang, lin);
    }
}

/// `(m, R c, R Ī Rᵀ)` for a rotation by `(c, s)` about axis `K`.
#[inline(always)]
pub(super) fn rotate_inertia_about<S: Scalar, const K: usize>(
    c: S,
    s: S,
    i: &Inertia<S>,
) -> Inertia<S> {
    Inertia::new(
        i.mass,
        rotate_about::<S, K>(c, s, &i.com),
        rotate_sym_about::<S, K>(c, s, &i.rot_inertia),
    )
}

/// `R v` for a rotation by `(c, s)` about axis `K`: the components
/// `(a, b) = (K + 1, K + 2) mod 3` turn as a plane vector.
#[inline(always)]
pub(super) fn rotate_about<S: Scalar, const K: usize>(c: S, s: S, v: &Vec3<S>) -> Vec3<S> {
    match K {
        0 => Vec3::new(v.x, c * v.y - s * v.z, s * v.y + c * v.z),
        1 => Vec3::new(s * v.z + c * v.x, v.y, c * v.z - s * v.x),
        _ => Vec3::new(c * v.x - s * v.y, s * v.x + c * v.y, v.z),
    }
}

/// `R I Rᵀ` for a rotation by `(c, s)` about axis `K`: the plane block
/// `(aa, ab, bb)` turns by a 2-D congruence (its trace kept exactly), the
/// pair `(ak, bk)` as a plane vector, and `kk` stays.
#[inline(always)]
fn rotate_sym_about<S: Scalar, const K: usize>(c: S, s: S, i: &Sym3<S>) -> Sym3<S> {
    let (a, b) = ((K + 1) % 3, (K + 2) % 3);
    let (aa, ab, bb) = (i.get(a, a), i.get(a, b), i.get(b, b));
    let (ak, bk) = (i.get(a, K), i.get(b, K));
    // First row of R I over the plane, then its products with R's rows.
    let (u, w) = (c * aa - s * ab, c * ab - s * bb);
    let aa_new = u * c - w * s;
    let ab_new = u * s + w * c;
    let mut out = *i;
    *out.get_mut(a, a) = aa_new;
    *out.get_mut(a, b) = ab_new;
    *out.get_mut(b, b) = (aa + bb) - aa_new;
    *out.get_mut(a, K) = c * ak - s * bk;
    *out.get_mut(b, K) = s * ak + c * bk;
    out
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::TransformStep;
    use crate::space::{BodyInertia, RigidTransform};
    use crate::spatial::{Force, Inertia, Mat3, Sym3, Transform, Vec3};

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-14 * (1.0 + a.abs().max(b.abs()))
    }

    #[test]
    fn agrees_with_the_general_transform_about_each_axis_and_otherwise() {
        let f = Force::new(Vec3::new(0.3, -1.2, 0.7), Vec3::new(2.0, 0.5, -0.4));
        let inertia = Inertia::new(
            1.7,
            Vec3::new(0.1, -0.2, 0.05),
            Sym3::new(0.3, 0.01, -0.02, 0.4, 0.03, 0.5),
        );
        let trans = Vec3::new(0.2, -0.1, 0.3);
        let (s, c) = 0.83f64.sin_cos();
        let tilted = Mat3::from_axis_sin_cos(&Vec3::new(0.6, 0.0, 0.8), s, c);
        // A URDF arm's placement, a quarter turn about x, takes the general path.
        let quarter_x = Mat3::from_rows([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]);
        let transforms = [
            Transform::new(Mat3::from_axis_index(0, s, c), trans),
            Transform::new(Mat3::from_axis_index(1, s, c), trans),
            Transform::new(Mat3::from_axis_index(2, s, c), trans),
            Transform::new(tilted, trans),
            Transform::new(quarter_x.mul_mat(&Mat3::from_axis_index(2, s, c)), trans),
        ];
        for (k, x) in transforms.iter().enumerate() {
            let step = TransformStep::new(x);
            match step {
                TransformStep::Axis { axis, .. } => assert_eq!(axis, k),
                TransformStep::General(_) => assert!(k >= 3),
            }
            let mut fast = [f];
            step.act_forces(&mut fast);
            let (fast, slow) = (fast[0], x.act_force(&f));
            for j in 0..6 {
                use crate::space::VectorOps;
                assert!(
                    close(fast.component(j), slow.component(j)),
                    "force, axis {k}"
                );
            }
            let fast = step.rotate_inertia(&inertia);
            let slow = inertia.act(&Transform::new(x.rot, Vec3::ZERO));
            assert!(close(fast.mass, slow.mass));
            for j in 0..3 {
                assert!(close(fast.com.get(j), slow.com.get(j)), "com, axis {k}");
                for l in 0..3 {
                    let (a, b) = (fast.rot_inertia.get(j, l), slow.rot_inertia.get(j, l));
                    assert!(close(a, b), "inertia ({j}, {l}), axis {k}: {a} against {b}");
                }
            }
            assert_eq!(step.translation(), trans);
        }
    }

    #[test]
    fn a_joint_step_agrees_with_its_placed_transform() {
        use crate::algorithm::crba::CrbaSpace;
        use crate::joint::{Axis, Joint, JointModel};
        use crate::space::VectorOps;
        use crate::spatial::Spatial;
        let f = Force::new(Vec3::new(0.3, -1.2, 0.7), Vec3::new(2.0, 0.5, -0.4));
        let trans = Vec3::new(0.2, -0.1, 0.3);
        let quarter_x = Mat3::from_rows([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]);
        let (s, c) = 0.4f64.sin_cos();
        // No rotation and a turn about the joint's axis take the axis
        // step; a quarter turn about another axis (a URDF arm's) does not.
        let placements = [
            (Mat3::IDENTITY, true),
            (Mat3::from_axis_index(2, s, c), true),
            (quarter_x, false),
        ];
        for (rot, about_axis) in placements {
            let placement = Transform::new(rot, trans);
            let joint = Joint::revolute(Axis::Z);
            let q = [-1.3];
            let step = Spatial::joint_step(&joint, &placement, &q);
            assert_eq!(
                matches!(step, TransformStep::Axis { axis: 2, .. }),
                about_axis
            );
            let mut fast = [f];
            Spatial::step_forces(&step, &mut fast);
            let slow = joint.placed_transform(&placement, &q).act_force(&f);
            for j in 0..6 {
                let (a, b) = (fast[0].component(j), slow.component(j));
                assert!(close(a, b), "component {j}: {a} against {b}");
            }
        }
    }
}
