//! `Ẏ`, the variation of a body's force with its velocity, as a linear map
//! that composites can sum: [`ColumnVariation`], the definition applied to
//! a basis (any geometry, the plane's), and [`SpatialVariation`], its
//! closed form in space, held to the former by the tests.

use core::fmt::Debug;

use crate::algorithm::frames::FrameSpace;
use crate::planar::{Planar, PlanarMotion, Vec2};
use crate::space::{BodyInertia, MotionVector, Space, VectorOps};
use crate::spatial::{Force, Inertia, Motion, Spatial, Sym3, Vec3};
use crate::Scalar;

/// The largest motion-vector dimension of a geometry (space's 6).
const MAX_DIM: usize = 6;

/// What the derivative passes need of a geometry beyond kinematics: a
/// basis of its motion vectors and its form of `Ẏ`.
pub trait DerivativeSpace: FrameSpace {
    /// The number of components of a motion vector: 6 in space, 3 in a plane.
    const MOTION_DIM: usize;
    /// `Ẏ` in this geometry.
    type Variation<S: Scalar>: VariationMap<S, Self>;
    /// The motion whose component `k` (rodyn's order, see
    /// [`VectorOps::component`]) is one and the others zero.
    fn unit_motion<S: Scalar>(k: usize) -> Self::Motion<S>;
}

/// `Ẏ δ = v ×* (Y δ) − Y (v × δ) + δ ×* h` (`h = Y v`): how a body's
/// velocity-dependent force changes with a change δ of its velocity,
/// beyond `Y δ̇`.
///
/// The first two terms are the rate `v ×* Y − Y v×` of the inertia as the
/// body moves (what `Y a` loses when the acceleration's `v × δ` part is
/// counted in the body's own frame), the third the change of `v ×* h`. It
/// is linear in the body, so a subtree's `Ẏᶜ` is the sum of its bodies',
/// but unlike `Y` it depends on each body's own velocity, so it is not an
/// inertia.
pub trait VariationMap<S: Scalar, G: Space>: Copy + Debug {
    /// A row `sᵀ Ẏ`, to apply to many motions.
    type Row: Copy;
    /// The zero map.
    const ZERO: Self;
    /// `Ẏ` of a body of inertia `y` moving with velocity `v`, both in the
    /// same frame.
    fn of_body(y: &G::Inertia<S>, v: &G::Motion<S>) -> Self;
    /// `Ẏ δ`.
    fn mul_motion(&self, delta: &G::Motion<S>) -> G::Force<S>;
    /// The row `sᵀ Ẏ` of a motion `s`.
    fn row(&self, s: &G::Motion<S>) -> Self::Row;
    /// `row δ`.
    fn dot_row(row: &Self::Row, delta: &G::Motion<S>) -> S;
    /// `self += other`.
    fn add_assign(&mut self, other: &Self);
}

impl DerivativeSpace for Spatial {
    const MOTION_DIM: usize = 6;
    type Variation<S: Scalar> = SpatialVariation<S>;
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
    type Variation<S: Scalar> = ColumnVariation<S, Planar>;
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

/// `Ẏ` as its definition applied to each basis motion: one force column
/// per motion component. Any geometry; the plane's `Ẏ`, and the oracle of
/// [`SpatialVariation`].
#[derive(Clone, Copy, Debug)]
pub struct ColumnVariation<S: Scalar, G: DerivativeSpace> {
    /// Column k is `Ẏ e_k`, for k below [`DerivativeSpace::MOTION_DIM`].
    columns: [G::Force<S>; MAX_DIM],
}

impl<S: Scalar, G: DerivativeSpace> VariationMap<S, G> for ColumnVariation<S, G> {
    type Row = [S; MAX_DIM];

    const ZERO: Self = Self {
        columns: [<G::Force<S> as VectorOps<S>>::ZERO; MAX_DIM],
    };

    fn of_body(y: &G::Inertia<S>, v: &G::Motion<S>) -> Self {
        let h = y.mul_motion(v);
        let mut out = Self::ZERO;
        for (k, column) in out.columns.iter_mut().enumerate().take(G::MOTION_DIM) {
            let e = G::unit_motion::<S>(k);
            *column = v.cross_force(&y.mul_motion(&e)) - y.mul_motion(&v.cross_motion(&e))
                + e.cross_force(&h);
        }
        out
    }

    #[inline]
    fn mul_motion(&self, delta: &G::Motion<S>) -> G::Force<S> {
        let mut f = <G::Force<S> as VectorOps<S>>::ZERO;
        for (k, column) in self.columns.iter().enumerate().take(G::MOTION_DIM) {
            f += *column * delta.component(k);
        }
        f
    }

    #[inline]
    fn row(&self, s: &G::Motion<S>) -> [S; MAX_DIM] {
        let mut row = [S::ZERO; MAX_DIM];
        for (r, column) in row.iter_mut().zip(&self.columns).take(G::MOTION_DIM) {
            *r = s.dot(column);
        }
        row
    }

    #[inline]
    fn dot_row(row: &[S; MAX_DIM], delta: &G::Motion<S>) -> S {
        let mut sum = S::ZERO;
        for (k, r) in row.iter().enumerate().take(G::MOTION_DIM) {
            sum += *r * delta.component(k);
        }
        sum
    }

    #[inline]
    fn add_assign(&mut self, other: &Self) {
        for (a, b) in self.columns.iter_mut().zip(&other.columns) {
            *a += *b;
        }
    }
}

/// `Ẏ` in space in closed form. With the body's mass m, centre of mass c,
/// inertia `Ī_c` about it, velocity `v = (ω_v, s)`, momentum `h = (h_ang,
/// h_lin)` and `ċ = s + ω_v × c`:
///
/// ```text
/// Ẏ (ω, u) = (Σ ω + ω × h_ang,  2 ω × h_lin),
/// Σ = [ω_v×] Ī_c − Ī_c [ω_v×] + m (2 (c·ċ) 1 − ċ cᵀ − c ċᵀ)
/// ```
///
/// (`Σ` is the rate of the inertia about the origin as the body moves; `Ẏ`
/// does not depend on the linear part u). Twelve numbers instead of 36,
/// and sums of them are sums of the parts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpatialVariation<S> {
    /// `Σ`, symmetric.
    rate: Sym3<S>,
    /// The angular momentum about the origin, `h_ang`.
    angular: Vec3<S>,
    /// The linear momentum, `h_lin`.
    linear: Vec3<S>,
}

impl<S: Scalar> VariationMap<S, Spatial> for SpatialVariation<S> {
    /// `sᵀ Ẏ` acts on ω alone: a 3-vector.
    type Row = Vec3<S>;

    const ZERO: Self = Self {
        rate: Sym3::ZERO,
        angular: Vec3::ZERO,
        linear: Vec3::ZERO,
    };

    // Out of line, the call made the world pass spill its vector registers
    // around it once per body (all are caller-saved on x86-64).
    #[cfg_attr(rodyn_tuning = "out_of_order", inline(always))]
    fn of_body(y: &Inertia<S>, v: &Motion<S>) -> Self {
        let (m, c) = (y.mass, y.com);
        let c_dot = v.lin + v.ang.cross(&c);
        let linear = c_dot * m;
        let angular = y.rot_inertia.mul_vec(&v.ang) + c.cross(&linear);
        // [ω×] Ī_c − Ī_c [ω×] = B + Bᵀ for B = [ω×] Ī_c, Ī_c symmetric.
        let turning = crate::spatial::Mat3::cross_mul(&v.ang, &y.rot_inertia.to_mat3()).sym_sum();
        let shifting =
            Sym3::identity_scaled((m + m) * c.dot(&c_dot)) - Sym3::outer_sym(&c_dot, &c, m);
        Self {
            rate: turning + shifting,
            angular,
            linear,
        }
    }

    #[inline]
    fn mul_motion(&self, delta: &Motion<S>) -> Force<S> {
        let w = &delta.ang;
        Force::new(
            self.rate.mul_vec(w) + w.cross(&self.angular),
            w.cross(&self.linear) * S::from_f64(2.0),
        )
    }

    #[inline]
    fn row(&self, s: &Motion<S>) -> Vec3<S> {
        // σ·(Σω + ω × h_ang) + w·(2 ω × h_lin) = (Σσ + h_ang × σ + 2 h_lin × w)·ω.
        self.rate.mul_vec(&s.ang)
            + self.angular.cross(&s.ang)
            + self.linear.cross(&s.lin) * S::from_f64(2.0)
    }

    #[inline]
    fn dot_row(row: &Vec3<S>, delta: &Motion<S>) -> S {
        row.dot(&delta.ang)
    }

    #[inline]
    fn add_assign(&mut self, other: &Self) {
        self.rate += other.rate;
        self.angular += other.angular;
        self.linear += other.linear;
    }
}
