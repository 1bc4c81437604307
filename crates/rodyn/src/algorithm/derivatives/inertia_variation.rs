//! `Ẏ`, the variation of a body's force with its velocity, as a linear map
//! that composites can sum.

use crate::algorithm::frames::FrameSpace;
use crate::planar::{Planar, PlanarMotion, Vec2};
use crate::space::{BodyInertia, MotionVector, VectorOps};
use crate::spatial::{Motion, Spatial, Vec3};
use crate::Scalar;

/// The largest motion-vector dimension of a geometry (space's 6).
const MAX_DIM: usize = 6;

/// What the derivative passes need of a geometry beyond kinematics: a
/// basis of its motion vectors.
pub trait DerivativeSpace: FrameSpace {
    /// The number of components of a motion vector: 6 in space, 3 in a plane.
    const MOTION_DIM: usize;
    /// The motion whose component `k` (rodyn's order, see
    /// [`VectorOps::component`]) is one and the others zero.
    fn unit_motion<S: Scalar>(k: usize) -> Self::Motion<S>;
}

impl DerivativeSpace for Spatial {
    const MOTION_DIM: usize = 6;
    #[inline]
    fn unit_motion<S: Scalar>(k: usize) -> Motion<S> {
        let e = |j: usize| Vec3::new(unit(j == 0), unit(j == 1), unit(j == 2));
        if k < 3 {
            Motion::new(e(k), Vec3::ZERO)
        } else {
            Motion::new(Vec3::ZERO, e(k - 3))
        }
    }
}

impl DerivativeSpace for Planar {
    const MOTION_DIM: usize = 3;
    #[inline]
    fn unit_motion<S: Scalar>(k: usize) -> PlanarMotion<S> {
        PlanarMotion::new(unit(k == 0), Vec2::new(unit(k == 1), unit(k == 2)))
    }
}

#[inline]
fn unit<S: Scalar>(one: bool) -> S {
    if one {
        S::ONE
    } else {
        S::ZERO
    }
}

/// `Ẏ`: the derivative of a body's velocity-dependent force along a change
/// δ of its velocity, beyond the inertia's own `Y δ̇`,
///
/// `Ẏ δ = v ×* (Y δ) − Y (v × δ) + δ ×* h`, with `h = Y v`.
///
/// The first two terms are the rate `v ×* Y − Y v×` of the inertia as the
/// body moves (what `Y a` loses when the acceleration's `v × δ` part is
/// counted in the body's own frame), the third the change of `v ×* h`. It
/// is linear in the body, so a subtree's `Ẏᶜ` is the sum of its bodies',
/// but unlike `Y` it depends on each body's own velocity: it is kept as a
/// matrix (one force column per motion component) rather than as mass,
/// centre and inertia.
#[derive(Clone, Copy, Debug)]
pub struct InertiaVariation<S: Scalar, G: DerivativeSpace> {
    /// Column k is `Ẏ e_k`, for k below [`DerivativeSpace::MOTION_DIM`].
    columns: [G::Force<S>; MAX_DIM],
}

impl<S: Scalar, G: DerivativeSpace> InertiaVariation<S, G> {
    /// The zero map.
    pub const ZERO: Self = Self {
        columns: [<G::Force<S> as VectorOps<S>>::ZERO; MAX_DIM],
    };

    /// `Ẏ` of a body of inertia `y` moving with velocity `v`, both in the
    /// same frame.
    #[must_use]
    pub fn of_body(y: &G::Inertia<S>, v: &G::Motion<S>) -> Self {
        let h = y.mul_motion(v);
        let mut out = Self::ZERO;
        for (k, column) in out.columns.iter_mut().enumerate().take(G::MOTION_DIM) {
            let e = G::unit_motion::<S>(k);
            *column = v.cross_force(&y.mul_motion(&e)) - y.mul_motion(&v.cross_motion(&e))
                + e.cross_force(&h);
        }
        out
    }

    /// `Ẏ δ`.
    #[must_use]
    #[inline]
    pub fn mul_motion(&self, delta: &G::Motion<S>) -> G::Force<S> {
        let mut f = <G::Force<S> as VectorOps<S>>::ZERO;
        for (k, column) in self.columns.iter().enumerate().take(G::MOTION_DIM) {
            f += *column * delta.component(k);
        }
        f
    }

    /// The row `sᵀ Ẏ` for a motion `s`, to be applied to many motions by
    /// [`dot_row`](Self::dot_row): one product per column instead of a
    /// matrix-vector product each time.
    #[must_use]
    #[inline]
    pub fn row(&self, s: &G::Motion<S>) -> [S; MAX_DIM] {
        let mut row = [S::ZERO; MAX_DIM];
        for (r, column) in row.iter_mut().zip(&self.columns).take(G::MOTION_DIM) {
            *r = s.dot(column);
        }
        row
    }

    /// `row δ`, for a row from [`row`](Self::row).
    #[must_use]
    #[inline]
    pub fn dot_row(row: &[S; MAX_DIM], delta: &G::Motion<S>) -> S {
        let mut sum = S::ZERO;
        for (k, r) in row.iter().enumerate().take(G::MOTION_DIM) {
            sum += *r * delta.component(k);
        }
        sum
    }

    /// `self += other`.
    #[inline]
    pub fn add_assign(&mut self, other: &Self) {
        for (a, b) in self.columns.iter_mut().zip(&other.columns) {
            *a += *b;
        }
    }
}
