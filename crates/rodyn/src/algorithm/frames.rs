//! Frames: placements, velocities and accelerations of bodies and of
//! [`Frame`]s, in Pinocchio's three reference frames.
//!
//! A spatial motion `(ω, v)` of a frame f can be expressed
//! ([`ReferenceFrame`]):
//!
//! * [`Local`](ReferenceFrame::Local): in f's own axes, `v` the velocity of
//!   f's origin (`ᶠX_o m`);
//! * [`World`](ReferenceFrame::World): in the world's axes, `v` the velocity
//!   of the body point that passes the world's origin (Featherstone's
//!   spatial velocity, `ᵒX_f m`);
//! * [`LocalWorldAligned`](ReferenceFrame::LocalWorldAligned): in the
//!   world's axes, `v` the velocity of f's origin (the usual "linear and
//!   angular velocity of the tool").
//!
//! The classical acceleration of a point is the time derivative of its
//! velocity, `v̇ = a + ω × v` with `(ω, v)` and the spatial acceleration
//! `a` at the point (Featherstone §2.11).
//!
//! Everything here reads the bodies' poses, velocities and accelerations
//! that [`kinematics`](crate::algorithm::kinematics) leaves in [`Data`].

use crate::data::Data;
use crate::error::{Error, Quantity, Result};
use crate::frame::Frame;
use crate::joint::{Joint, JointModel};
use crate::planar::{Planar, PlanarForce, PlanarMotion, PlanarTransform, Vec2};
use crate::space::{BodyInertia, MotionVector, RigidTransform, Space, VectorOps};
use crate::spatial::{Force, Inertia, Motion, Spatial, Sym3, Transform, Vec3};
use crate::Scalar;

/// The frame a frame's motion or Jacobian is expressed in (Pinocchio's
/// `ReferenceFrame`; see the [module](self) for each).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ReferenceFrame {
    /// The frame's own axes, at its origin.
    Local,
    /// The world's axes, at the world's origin.
    World,
    /// The world's axes, at the frame's origin.
    LocalWorldAligned,
}

/// What the frame and centroidal algorithms need of a geometry beyond
/// [`Space`]: pure translations and linear parts (implemented for
/// [`Spatial`] and [`Planar`]).
pub trait FrameSpace: Space {
    /// The transform that moves the origin to `p` and keeps the axes.
    fn from_translation<S: Scalar>(p: &Self::Point<S>) -> Self::Transform<S>;
    /// The linear part of `m`, angular part zero.
    fn linear_part<S: Scalar>(m: &Self::Motion<S>) -> Self::Motion<S>;
    /// The linear part of `m` as a vector (m/s for a velocity).
    fn linear_vector<S: Scalar>(m: &Self::Motion<S>) -> Self::Point<S>;
    /// The linear part of `f` as a vector (N, or kg m/s for a momentum).
    fn force_linear_vector<S: Scalar>(f: &Self::Force<S>) -> Self::Point<S>;
    /// `p s`.
    fn scale_point<S: Scalar>(p: &Self::Point<S>, s: S) -> Self::Point<S>;
    /// Body inertia `i` (in its own frame) moved into the world by its
    /// pose `x`: [`BodyInertia::act`], which a geometry may override with
    /// an equal form for inertias it recognises.
    #[inline(always)]
    fn world_inertia<S: Scalar>(i: &Self::Inertia<S>, x: &Self::Transform<S>) -> Self::Inertia<S> {
        i.act(x)
    }
    /// `i` moved by the translation that takes its centre of mass to the
    /// origin (the centroidal inertia `I_g` of a model whose composite is
    /// `i`). A geometry may override it with an equal form that skips the
    /// rotation by the identity.
    #[inline(always)]
    fn about_own_centre<S: Scalar>(i: &Self::Inertia<S>) -> Self::Inertia<S> {
        i.act(&Self::from_translation(&i.com()).inverse())
    }
    /// The transform with `x`'s translation and no rotation.
    #[inline]
    fn translation_only<S: Scalar>(x: &Self::Transform<S>) -> Self::Transform<S> {
        Self::from_translation(&x.translation())
    }
    /// `m` (a motion at the world's origin) seen at `p` with the world's
    /// axes: `X(p)⁻¹ m`, the move into LOCAL_WORLD_ALIGNED. A geometry may
    /// override it with an equal form that skips the identity rotation.
    #[inline(always)]
    fn shift_motion<S: Scalar>(m: &Self::Motion<S>, p: &Self::Point<S>) -> Self::Motion<S> {
        Self::from_translation(p).act_inv_motion(m)
    }
    /// `x Sₖ`: column k of joint `j`'s motion subspace moved by `x` (into
    /// the world, for a body pose).
    #[inline(always)]
    fn act_subspace_column<S: Scalar>(
        x: &Self::Transform<S>,
        j: &Self::Joint<S>,
        k: usize,
    ) -> Self::Motion<S> {
        x.act_motion(&j.subspace_column(k))
    }
    /// `ᴳX_o* Iᶜ (x Sₖ)`: column k of joint `j` (its body's pose `x`) moved
    /// into the world, times `ic` (a world-frame inertia, the composite of
    /// the joint's subtree) and moved to the frame with the world's axes at
    /// `g`: a column of the centroidal momentum matrix. This is the book's
    /// form; a geometry may override it with an equal one that skips
    /// products with zeros.
    #[inline(always)]
    fn centroidal_column<S: Scalar>(
        x: &Self::Transform<S>,
        j: &Self::Joint<S>,
        k: usize,
        ic: &Self::Inertia<S>,
        g: &Self::Point<S>,
    ) -> Self::Force<S> {
        Self::from_translation(g).act_inv_force(&ic.mul_motion(&Self::act_subspace_column(x, j, k)))
    }
    /// Every column of joint `j` at once into `out` (its `nv` columns):
    /// [`Self::centroidal_column`] for each. A geometry may override it
    /// with an equal form that shares the columns' common terms.
    #[inline(always)]
    fn centroidal_columns<S: Scalar>(
        x: &Self::Transform<S>,
        j: &Self::Joint<S>,
        ic: &Self::Inertia<S>,
        g: &Self::Point<S>,
        out: &mut [Self::Force<S>],
    ) {
        for (k, column) in out.iter_mut().enumerate() {
            *column = Self::centroidal_column(x, j, k, ic, g);
        }
    }
}

impl FrameSpace for Spatial {
    #[inline]
    fn from_translation<S: Scalar>(p: &Vec3<S>) -> Transform<S> {
        Transform::from_translation(*p)
    }
    #[inline(always)]
    fn shift_motion<S: Scalar>(m: &Motion<S>, p: &Vec3<S>) -> Motion<S> {
        // (ω, v − p × ω): the products with the identity's ones and zeros
        // left out (the same values for finite entries).
        Motion::new(m.ang, m.lin - p.cross(&m.ang))
    }
    #[inline(always)]
    fn world_inertia<S: Scalar>(i: &Inertia<S>, x: &Transform<S>) -> Inertia<S> {
        // A rotational inertia diagonal in the body's frame turns as the
        // sum of its three entries times the outer products of the
        // rotation's columns (27 products instead of the 45 of a general
        // one); three entries tell.
        let r = &i.rot_inertia;
        if !S::all_zero([r.xy, r.xz, r.yz]) {
            return general_world_inertia(i, x);
        }
        let m = &x.rot.m;
        let u = |k: usize, d: S| [m[0][k] * d, m[1][k] * d, m[2][k] * d];
        let (u0, u1, u2) = (u(0, r.xx), u(1, r.yy), u(2, r.zz));
        let entry = |a: usize, b: usize| u0[a] * m[b][0] + u1[a] * m[b][1] + u2[a] * m[b][2];
        Inertia::new(
            i.mass,
            x.act_point(&i.com),
            Sym3::new(
                entry(0, 0),
                entry(0, 1),
                entry(0, 2),
                entry(1, 1),
                entry(1, 2),
                entry(2, 2),
            ),
        )
    }
    #[inline(always)]
    fn about_own_centre<S: Scalar>(i: &Inertia<S>) -> Inertia<S> {
        Inertia::new(i.mass, Vec3::ZERO, i.rot_inertia)
    }
    #[inline]
    fn linear_part<S: Scalar>(m: &Motion<S>) -> Motion<S> {
        Motion::new(Vec3::ZERO, m.lin)
    }
    #[inline]
    fn linear_vector<S: Scalar>(m: &Motion<S>) -> Vec3<S> {
        m.lin
    }
    #[inline]
    fn force_linear_vector<S: Scalar>(f: &Force<S>) -> Vec3<S> {
        f.lin
    }
    #[inline]
    fn scale_point<S: Scalar>(p: &Vec3<S>, s: S) -> Vec3<S> {
        *p * s
    }
    #[inline(always)]
    fn act_subspace_column<S: Scalar>(x: &Transform<S>, j: &Joint<S>, k: usize) -> Motion<S> {
        if let Some(a) = j.revolute_axis_index() {
            // `x [e_a; 0]`: a column of the rotation, and its moment.
            let ang = x.rot.column(a);
            return Motion::new(ang, x.trans.cross(&ang));
        }
        match j {
            // Linear coordinates first: `x [0; e_k]` is a column of the
            // rotation; `x [e_k; 0]` one and its moment.
            Joint::FreeFlyer(_) if k < 3 => Motion::new(Vec3::ZERO, x.rot.column(k)),
            Joint::FreeFlyer(_) => {
                let ang = x.rot.column(k - 3);
                Motion::new(ang, x.trans.cross(&ang))
            }
            _ => x.act_motion(&j.subspace_column(k)),
        }
    }
    #[inline(always)]
    fn centroidal_column<S: Scalar>(
        x: &Transform<S>,
        j: &Joint<S>,
        k: usize,
        ic: &Inertia<S>,
        g: &Vec3<S>,
    ) -> Force<S> {
        // The momentum of the subtree (mass m, centre c, rotational inertia
        // I_c) moving at the twist (ω, v at the world's origin) about g:
        // linear m (v - c × ω), angular I_c ω + (c - g) × linear. The
        // columns of a revolute joint and of a free flyer's rotations are
        // (a, t × a), a an axis through t, so that v - c × ω = (t - c) × a;
        // a free flyer's translations (0, a) have no angular momentum about
        // c.
        let lever = ic.com - *g;
        let about_axis = |a: Vec3<S>| {
            let lin = (x.trans - ic.com).cross(&a) * ic.mass;
            Force::new(ic.rot_inertia.mul_vec(&a) + lever.cross(&lin), lin)
        };
        if let Some(a) = j.revolute_axis_index() {
            return about_axis(x.rot.column(a));
        }
        match j {
            Joint::FreeFlyer(_) if k < 3 => {
                let lin = x.rot.column(k) * ic.mass;
                Force::new(lever.cross(&lin), lin)
            }
            Joint::FreeFlyer(_) => about_axis(x.rot.column(k - 3)),
            _ => {
                let s = x.act_motion(&j.subspace_column(k));
                let lin = (s.lin - ic.com.cross(&s.ang)) * ic.mass;
                Force::new(ic.rot_inertia.mul_vec(&s.ang) + lever.cross(&lin), lin)
            }
        }
    }
    #[inline(always)]
    fn centroidal_columns<S: Scalar>(
        x: &Transform<S>,
        j: &Joint<S>,
        ic: &Inertia<S>,
        g: &Vec3<S>,
        out: &mut [Force<S>],
    ) {
        // A free flyer's six columns share the lever and the subtree's
        // offset; where the lever is zero (the sole root, whose subtree is
        // the whole model and whose centre is G) its terms are zero and
        // are not formed. The values of `centroidal_column`, to rounding
        // (the offset is scaled by the mass before the cross products).
        if let (Joint::FreeFlyer(_), Some(out)) = (j, out.first_chunk_mut::<6>()) {
            let lever = ic.com - *g;
            let offset = (x.trans - ic.com) * ic.mass;
            let axes = [x.rot.column(0), x.rot.column(1), x.rot.column(2)];
            let (translations, rotations) = out.split_at_mut(3);
            if S::all_zero([lever.x, lever.y, lever.z]) {
                for ((t, r), a) in translations.iter_mut().zip(rotations).zip(axes) {
                    *t = Force::new(Vec3::ZERO, a * ic.mass);
                    *r = Force::new(ic.rot_inertia.mul_vec(&a), offset.cross(&a));
                }
            } else {
                for ((t, r), a) in translations.iter_mut().zip(rotations).zip(axes) {
                    let lin = a * ic.mass;
                    *t = Force::new(lever.cross(&lin), lin);
                    let lin = offset.cross(&a);
                    *r = Force::new(ic.rot_inertia.mul_vec(&a) + lever.cross(&lin), lin);
                }
            }
            return;
        }
        for (k, column) in out.iter_mut().enumerate() {
            *column = Self::centroidal_column(x, j, k, ic, g);
        }
    }
}

impl FrameSpace for Planar {
    #[inline]
    fn from_translation<S: Scalar>(p: &Vec2<S>) -> PlanarTransform<S> {
        PlanarTransform::from_translation(*p)
    }
    #[inline]
    fn linear_part<S: Scalar>(m: &PlanarMotion<S>) -> PlanarMotion<S> {
        PlanarMotion::new(S::ZERO, m.lin)
    }
    #[inline]
    fn linear_vector<S: Scalar>(m: &PlanarMotion<S>) -> Vec2<S> {
        m.lin
    }
    #[inline]
    fn force_linear_vector<S: Scalar>(f: &PlanarForce<S>) -> Vec2<S> {
        f.lin
    }
    #[inline]
    fn scale_point<S: Scalar>(p: &Vec2<S>, s: S) -> Vec2<S> {
        *p * s
    }
}

/// [`BodyInertia::act`] for a general body inertia `i` and pose `x`, in the
/// order of `T = R [I_c | c]`: T's rows as sums of the rows of `I_c`
/// beside the centre's coordinate, scaled by R's entries (36 products),
/// then `ᵒI_c = T Rᵀ` on the upper triangle (18) and the centre `R c + t`
/// from T's last column. The same products as `act`, whose `I_c rⱼ` are
/// dot products; this order pairs into SSE2 instructions with fewer
/// shuffles (in `Sym3::rotate`, for every algorithm, it cost CRBA and ABA
/// instructions).
#[inline(always)]
fn general_world_inertia<S: Scalar>(i: &Inertia<S>, x: &Transform<S>) -> Inertia<S> {
    let (rows, c, m) = (i.rot_inertia.rows(), &i.com, &x.rot.m);
    let ext = [
        [rows[0][0], rows[0][1], rows[0][2], c.x],
        [rows[1][0], rows[1][1], rows[1][2], c.y],
        [rows[2][0], rows[2][1], rows[2][2], c.z],
    ];
    let t = |a: usize| -> [S; 4] {
        core::array::from_fn(|k| m[a][0] * ext[0][k] + m[a][1] * ext[1][k] + m[a][2] * ext[2][k])
    };
    let (t0, t1, t2) = (t(0), t(1), t(2));
    let entry = |t: &[S; 4], b: usize| t[0] * m[b][0] + t[1] * m[b][1] + t[2] * m[b][2];
    Inertia::new(
        i.mass,
        Vec3::new(t0[3], t1[3], t2[3]) + x.trans,
        Sym3::new(
            entry(&t0, 0),
            entry(&t0, 1),
            entry(&t0, 2),
            entry(&t1, 1),
            entry(&t1, 2),
            entry(&t2, 2),
        ),
    )
}

/// `m`, a motion of a frame whose pose is `o_m_f` given in the world
/// (`ᵒX_f`-form, at the world's origin), expressed in `reference`.
#[inline]
pub(crate) fn express_world_motion<S: Scalar, G: FrameSpace>(
    o_m_f: &G::Transform<S>,
    m: &G::Motion<S>,
    reference: ReferenceFrame,
) -> G::Motion<S> {
    match reference {
        ReferenceFrame::World => *m,
        ReferenceFrame::Local => o_m_f.act_inv_motion(m),
        ReferenceFrame::LocalWorldAligned => G::translation_only(o_m_f).act_inv_motion(m),
    }
}

/// World frame from frame f (`ᵒMf`), from the body poses in
/// `data.o_m_i` (valid after any of the `forward_kinematics*` functions).
///
/// # Errors
/// [`Error::FrameBodyOutOfRange`] when `frame.body` is not below `NB`;
/// [`Error::NonFinite`] (`Quantity::FramePlacement`, the frame's body) for
/// a frame whose placement is not finite, [`Error::NonFiniteResult`] for a
/// pose that overflows.
///
/// # Example
///
/// ```
/// use rodyn::algorithm::{frames::frame_placement, kinematics::forward_kinematics};
/// use rodyn::Frame;
/// # use rodyn::prelude::*;
/// # // Two 1 m links about z, 1 kg point masses at the tips, gravity -y.
/// # const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
/// # const DOUBLE: Model<f64, 2, 2, 2> = Model::new(
/// #     [None, Some(0)], [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
/// #     [Transform::IDENTITY, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))],
/// #     [LINK, LINK], Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// # );
/// let mut data = Data::new();
/// let (q1, q2) = (0.4, -0.7);
/// forward_kinematics(&DOUBLE, &mut data, &[q1, q2])?;
/// // A tool frame 1 m along the second link: the arm's tip.
/// let tip = Frame::new(1, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0)));
/// let o_m_tip = frame_placement(&data, &tip)?;
/// let (x, y) = (f64::cos(q1) + f64::cos(q1 + q2), f64::sin(q1) + f64::sin(q1 + q2));
/// assert!((o_m_tip.trans.x - x).abs() < 1e-12 && (o_m_tip.trans.y - y).abs() < 1e-12);
/// // A frame on a body the model does not have is an error, not a panic.
/// assert!(frame_placement(&data, &Frame::new(5, Transform::IDENTITY)).is_err());
/// # Ok::<(), rodyn::Error>(())
/// ```
#[inline]
pub fn frame_placement<S: Scalar, const NB: usize, const NV: usize, G: Space>(
    data: &Data<S, NB, NV, G>,
    frame: &Frame<S, G>,
) -> Result<G::Transform<S>> {
    let o_m_f = frame
        .world_placement(&data.o_m_i)
        .ok_or(Error::FrameBodyOutOfRange { body: frame.body })?;
    // One test of the result covers a NaN or infinite placement (a
    // `Frame` is plain data, so nothing checked it when it was made) and
    // the readers and Jacobians built on this pose.
    if o_m_f.is_finite() {
        Ok(o_m_f)
    } else {
        Err(frame_error(frame))
    }
}

/// The error for a frame whose pose or motion came out non-finite: its
/// placement's fault when that is not finite, otherwise an overflow.
#[cold]
pub(crate) fn frame_error<S: Scalar, G: Space>(frame: &Frame<S, G>) -> Error {
    let (quantity, index) = (Quantity::FramePlacement, frame.body);
    if frame.placement.is_finite() {
        Error::NonFiniteResult { quantity, index }
    } else {
        Error::NonFinite { quantity, index }
    }
}

/// The spatial velocity of frame f in `reference` (rad/s, m/s; rodyn's
/// component order, angular first), from `data.o_m_i` and `data.v`, valid
/// after [`forward_kinematics_velocity`](crate::algorithm::kinematics::forward_kinematics_velocity)
/// or [`forward_kinematics_acceleration`](crate::algorithm::kinematics::forward_kinematics_acceleration).
/// A body's own velocity is that of a frame with the identity placement.
///
/// # Errors
/// [`Error::FrameBodyOutOfRange`] when `frame.body` is not below `NB`;
/// [`Error::NonFinite`] (`Quantity::FramePlacement`, the frame's body) for
/// a frame whose placement is not finite where it enters the result (in
/// [`ReferenceFrame::World`] a motion is the body's, whatever the
/// placement), [`Error::NonFiniteResult`] for a result that overflows.
pub fn frame_velocity<S: Scalar, const NB: usize, const NV: usize, G: FrameSpace>(
    data: &Data<S, NB, NV, G>,
    frame: &Frame<S, G>,
    reference: ReferenceFrame,
) -> Result<G::Motion<S>> {
    frame_motion(data, frame, &data.v, reference)
}

/// The spatial acceleration of frame f in `reference` (rad/s², m/s²),
/// gravity excluded, from `data.o_m_i` and `data.a`, valid after
/// [`forward_kinematics_acceleration`](crate::algorithm::kinematics::forward_kinematics_acceleration).
/// Its linear part is not the acceleration of f's origin: see
/// [`frame_classical_acceleration`].
///
/// # Errors
/// [`Error::FrameBodyOutOfRange`] when `frame.body` is not below `NB`;
/// [`Error::NonFinite`] (`Quantity::FramePlacement`, the frame's body) for
/// a frame whose placement is not finite where it enters the result (in
/// [`ReferenceFrame::World`] a motion is the body's, whatever the
/// placement), [`Error::NonFiniteResult`] for a result that overflows.
pub fn frame_acceleration<S: Scalar, const NB: usize, const NV: usize, G: FrameSpace>(
    data: &Data<S, NB, NV, G>,
    frame: &Frame<S, G>,
    reference: ReferenceFrame,
) -> Result<G::Motion<S>> {
    frame_motion(data, frame, &data.a, reference)
}

/// The classical acceleration of frame f in `reference`: the spatial
/// acceleration plus `ω × v` on the linear part, with `(ω, v)` the frame's
/// velocity in the same reference (Pinocchio's
/// `getFrameClassicalAcceleration`). In
/// [`Local`](ReferenceFrame::Local) and
/// [`LocalWorldAligned`](ReferenceFrame::LocalWorldAligned) its linear part
/// is the acceleration of f's origin (m/s²) in f's or the world's axes, and
/// its angular part the angular acceleration; in
/// [`World`](ReferenceFrame::World) the linear part belongs to no point and
/// is given for comparison with Pinocchio only. Reads `data.o_m_i`,
/// `data.v`, `data.a`, valid after
/// [`forward_kinematics_acceleration`](crate::algorithm::kinematics::forward_kinematics_acceleration);
/// with zero joint accelerations it is `J̇ v` for f's classical Jacobian.
///
/// # Errors
/// [`Error::FrameBodyOutOfRange`] when `frame.body` is not below `NB`;
/// [`Error::NonFinite`] (`Quantity::FramePlacement`, the frame's body) for
/// a frame whose placement is not finite where it enters the result (in
/// [`ReferenceFrame::World`] a motion is the body's, whatever the
/// placement), [`Error::NonFiniteResult`] for a result that overflows.
pub fn frame_classical_acceleration<S: Scalar, const NB: usize, const NV: usize, G: FrameSpace>(
    data: &Data<S, NB, NV, G>,
    frame: &Frame<S, G>,
    reference: ReferenceFrame,
) -> Result<G::Motion<S>> {
    let v = frame_velocity(data, frame, reference)?;
    let a = frame_acceleration(data, frame, reference)?;
    // (ω, v) × (0, v) = (0, ω × v).
    Ok(a + v.cross_motion(&G::linear_part(&v)))
}

/// `motions[frame.body]` (a body-frame quantity) seen at frame f in `reference`.
fn frame_motion<S: Scalar, const NB: usize, const NV: usize, G: FrameSpace>(
    data: &Data<S, NB, NV, G>,
    frame: &Frame<S, G>,
    motions: &[G::Motion<S>; NB],
    reference: ReferenceFrame,
) -> Result<G::Motion<S>> {
    let body = frame.body;
    let (Some(o_m_i), Some(m)) = (data.o_m_i.get(body), motions.get(body)) else {
        return Err(Error::FrameBodyOutOfRange { body });
    };
    let motion = match reference {
        ReferenceFrame::Local => frame.placement.act_inv_motion(m),
        ReferenceFrame::World => o_m_i.act_motion(m),
        ReferenceFrame::LocalWorldAligned => {
            let o_m_f = o_m_i.compose(&frame.placement);
            G::translation_only(&o_m_f).act_inv_motion(&o_m_i.act_motion(m))
        }
    };
    // One test of the result: a non-finite placement shows in it (in the
    // world frame it does not enter, and the body's motion is the answer).
    if motion.is_finite() {
        Ok(motion)
    } else {
        Err(frame_error(frame))
    }
}

/// A zero motion, for callers that fill arrays of them.
#[inline]
pub(crate) fn zero_motion<S: Scalar, G: Space>() -> G::Motion<S> {
    <G::Motion<S> as VectorOps<S>>::ZERO
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::FrameSpace;
    use crate::joint::{Axis, Joint, JointModel};
    use crate::space::{BodyInertia, RigidTransform, VectorOps};
    use crate::spatial::{Force, Inertia, Mat3, Motion, Spatial, Sym3, Transform, Vec3};

    /// The 3-D shortcut for a body's world inertia gives `Inertia::act`'s
    /// result, to rounding, for inertias diagonal in the body's frame (the
    /// shortcut) and others (the book's form itself).
    #[test]
    fn world_inertia_is_the_moved_inertia() {
        let x = Transform::new(
            Mat3::from_axis_angle(&Vec3::new(0.36, -0.48, 0.8), 0.9),
            Vec3::new(0.4, -1.3, 0.7),
        );
        let com = Vec3::new(0.2, -0.9, 1.1);
        let inertias = [
            Inertia::new(3.5, com, Sym3::diagonal(0.4, 0.5, 0.3)),
            Inertia::new(3.5, com, Sym3::new(0.4, 0.0, -0.03, 0.5, 0.0, 0.3)),
            Inertia::new(3.5, com, Sym3::new(0.4, 0.02, -0.03, 0.5, 0.01, 0.3)),
            Inertia::point_mass(2.0, com),
        ];
        for i in &inertias {
            let (fast, book) = (Spatial::world_inertia(i, &x), i.act(&x));
            assert_eq!((fast.mass, fast.com), (book.mass, book.com), "{i:?}");
            assert!(
                largest_entry(&(fast.rot_inertia - book.rot_inertia)) <= 1e-15,
                "{i:?}: {fast:?} against {book:?}"
            );
        }
    }

    /// The 3-D shift into LOCAL_WORLD_ALIGNED is the book's `X(p)⁻¹ m`,
    /// bit for bit.
    #[test]
    fn shift_motion_is_the_inverse_translation() {
        let m = Motion::new(Vec3::new(0.3, -1.2, 2.5), Vec3::new(-0.7, 0.4, 1.9));
        for p in [
            Vec3::new(0.4, -1.3, 0.7),
            Vec3::ZERO,
            Vec3::new(1e3, 2e-3, -5.0),
        ] {
            assert_eq!(
                Spatial::shift_motion(&m, &p),
                Transform::from_translation(p).act_inv_motion(&m),
                "{p:?}"
            );
        }
    }

    /// The largest entry of `d` in size (NaN propagates as a failure of
    /// the callers' `<=`).
    fn largest_entry(d: &Sym3<f64>) -> f64 {
        [d.xx, d.xy, d.xz, d.yy, d.yz, d.zz]
            .iter()
            .fold(0.0, |m: f64, e| {
                if e.abs() > m || e.is_nan() {
                    e.abs()
                } else {
                    m
                }
            })
    }

    /// The centroidal pass's forms of a general body's world inertia
    /// (`world_inertia`) and of `I_g` (`about_own_centre`) give the book's
    /// (`Inertia::act` by the pose, by the translation to the centre), to
    /// rounding, on a spread of poses and inertias.
    #[test]
    fn centroidal_forms_are_the_book_forms() {
        // Deterministic, well spread values without a generator.
        let v = |k: f64| {
            Vec3::new(
                (1.3 * k).sin(),
                (0.7 * k + 0.2).cos(),
                (2.1 * k + 0.4).sin(),
            )
        };
        for n in 0..40 {
            let k = f64::from(n);
            let axis = v(k);
            let rot = Mat3::from_axis_angle(&(axis * (1.0 / axis.norm())), 3.0 * (0.9 * k).sin());
            let (d, o) = (v(k + 0.5), v(k + 1.5));
            let sym = Sym3::new(
                1.0 + d.x.abs(),
                0.1 * o.x,
                0.1 * o.y,
                1.0 + d.y.abs(),
                0.1 * o.z,
                1.0 + d.z.abs(),
            );
            let body = Inertia::new(1.5 + o.x.abs(), v(k + 3.5), sym);
            let x = Transform::new(rot, v(k + 4.5) * 2.0);
            let (fast, book) = (Spatial::world_inertia(&body, &x), body.act(&x));
            assert_eq!(
                (fast.mass, fast.com),
                (book.mass, book.com),
                "{body:?} {x:?}"
            );
            assert!(
                largest_entry(&(fast.rot_inertia - book.rot_inertia)) <= 1e-14,
                "{body:?} {x:?}"
            );
            let total = Inertia::new(2.0 + d.x.abs(), v(k + 2.5) * 3.0, sym);
            let centred = Spatial::about_own_centre(&total);
            let moved = total.act(&Transform::from_translation(total.com).inverse());
            assert_eq!(centred.mass, moved.mass);
            assert!(
                centred.com.norm() == 0.0 && moved.com.norm() <= 1e-15,
                "{moved:?}"
            );
            assert!(
                largest_entry(&(centred.rot_inertia - moved.rot_inertia)) <= 1e-15,
                "{centred:?} against {moved:?}"
            );
        }
    }

    /// The 3-D shortcuts for a joint's world column and its centroidal
    /// columns, one at a time and all at once, give the book's forms (`x
    /// Sₖ`, `ᴳX_o* Iᶜ x Sₖ`) for every joint type and column, about a
    /// point G off the subtree's centre and about the centre itself (a
    /// sole root's case, where the columns skip the lever).
    #[test]
    fn shortcuts_give_the_book_forms() {
        let x = Transform::new(
            Mat3::from_axis_angle(&Vec3::new(0.36, -0.48, 0.8), 0.9),
            Vec3::new(0.4, -1.3, 0.7),
        );
        let ic = Inertia::new(
            3.5,
            Vec3::new(0.2, -0.9, 1.1),
            Sym3::new(0.4, 0.02, -0.03, 0.5, 0.01, 0.3),
        );
        let joints = [
            Joint::revolute(Axis::X),
            Joint::revolute(Axis::Y),
            Joint::revolute(Axis::Z),
            Joint::revolute(Axis::Unit(Vec3::new(0.0, 0.6, 0.8))),
            Joint::prismatic(Axis::Y),
            Joint::free_flyer(),
        ];
        let close = |a: Force<f64>, b: Force<f64>| {
            let d = a - b;
            d.ang.norm() + d.lin.norm() <= 1e-14 * (1.0 + b.ang.norm() + b.lin.norm())
        };
        for g in [Vec3::new(-0.3, 0.25, 0.6), ic.com] {
            for j in &joints {
                let nv = JointModel::<f64, Spatial>::nv(j);
                let mut all = [Force::ZERO; 6];
                Spatial::centroidal_columns(&x, j, &ic, &g, &mut all[..nv]);
                for k in 0..nv {
                    let column = x.act_motion(&j.subspace_column(k));
                    assert_eq!(Spatial::act_subspace_column(&x, j, k), column, "{j:?} {k}");
                    let book =
                        Transform::from_translation(g).act_inv_force(&ic.mul_motion(&column));
                    let fast = Spatial::centroidal_column(&x, j, k, &ic, &g);
                    assert!(close(fast, book), "{j:?} {k}: {fast:?} against {book:?}");
                    assert!(
                        close(all[k], book),
                        "{j:?} {k}: {:?} against {book:?}",
                        all[k]
                    );
                }
            }
        }
    }
}
