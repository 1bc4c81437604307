//! Centroidal dynamics: the centre of mass, its Jacobian, the centroidal
//! momentum matrix `A_g`, its product `Ȧ_g v`, and the centroidal composite
//! rigid-body inertia `I_g` (Orin, Goswami & Lee, "Centroidal dynamics of a
//! humanoid robot", Autonomous Robots 35, 2013; Pinocchio's `ccrba`,
//! `computeCentroidalMap`, `computeCentroidalMomentumTimeVariation`).
//!
//! The centroidal frame G has the world's axes and its origin at the centre
//! of mass c. With `ᵒIᶜᵢ` the composite inertia of body i's subtree in the
//! world, column k of joint i is `A_gₖ = ᴳX_o* ᵒIᶜᵢ ᵒJₖ` (the subtree's
//! momentum per unit rate about c); `h_G = A_g v` is the centroidal
//! momentum (`[k; l]`, rodyn's order: angular about c first, then linear).
//! Its time derivative is the sum of the bodies' net forces moved to G
//! (the momentum about the moving centre of mass changes only by them,
//! since ċ × m ċ = 0), so `Ȧ_g v` is that sum at zero joint accelerations.
//!
//! Bodies welded to the world (Pinocchio's universe inertia) are not part
//! of the model and do not count.

use super::common::poses;
use super::derivatives::{SpatialVariation, VariationMap};
use super::frames::FrameSpace;
use super::kinematics::{forward_kinematics_acceleration, forward_kinematics_velocity};
use crate::data::Data;
use crate::error::{Error, Quantity, Result};
use crate::model::{check_vectors_result, Model};
use crate::space::{BodyInertia, MotionVector, RigidTransform, Space, VectorOps};
use crate::spatial::{Force, Motion, Spatial, Transform, Vec3};
use crate::Scalar;

/// The centroidal algorithms' workspace. Its own type so that a firmware
/// without them pays no RAM for it.
#[derive(Clone, Debug)]
pub struct CentroidalData<S: Scalar, const NB: usize, const NV: usize, G: Space = Spatial> {
    /// `ᵒIᶜᵢ`: body i's subtree's composite inertia in the world frame.
    pub o_ic: [G::Inertia<S>; NB],
    /// The whole model's inertia in the world frame (its mass, kg, and
    /// centre of mass, m, through [`BodyInertia`]).
    pub total: G::Inertia<S>,
    /// `A_g`: one column per coordinate, a momentum in G (kg m²/s and
    /// kg m/s per unit rate).
    pub ag: [G::Force<S>; NV],
    /// `I_g`: the centroidal composite rigid-body inertia, in G (its centre
    /// of mass at G's origin).
    pub ig: G::Inertia<S>,
    /// `h_G = A_g v`, the centroidal momentum.
    pub hg: G::Force<S>,
    /// `ḣ_G = A_g a + Ȧ_g v`, its rate (N m, N); `Ȧ_g v` at `a = 0`.
    pub dhg: G::Force<S>,
}

impl<S: Scalar, const NB: usize, const NV: usize, G: Space> CentroidalData<S, NB, NV, G> {
    /// A zeroed workspace; `const`, so it can initialise a `static`.
    #[must_use]
    pub const fn new() -> Self {
        Self {
            o_ic: [<G::Inertia<S> as BodyInertia<S>>::ZERO; NB],
            total: <G::Inertia<S> as BodyInertia<S>>::ZERO,
            ag: [<G::Force<S> as VectorOps<S>>::ZERO; NV],
            ig: <G::Inertia<S> as BodyInertia<S>>::ZERO,
            hg: <G::Force<S> as VectorOps<S>>::ZERO,
            dhg: <G::Force<S> as VectorOps<S>>::ZERO,
        }
    }

    /// The model's mass (kg), valid after [`centroidal_map`].
    #[must_use]
    pub fn mass(&self) -> S {
        self.total.mass()
    }

    /// The centre of mass in the world (m), valid after [`centroidal_map`].
    #[must_use]
    pub fn com(&self) -> G::Point<S> {
        self.total.com()
    }
}

impl<S: Scalar, const NB: usize, const NV: usize, G: Space> Default
    for CentroidalData<S, NB, NV, G>
{
    fn default() -> Self {
        Self::new()
    }
}

/// The centroidal momentum matrix and the centroidal composite inertia at
/// `q` (NQ) (Pinocchio's `computeCentroidalMap` and, but for `h_G`,
/// `ccrba`). Runs [`forward_kinematics`](super::kinematics::forward_kinematics). Leaves valid `data.li_m_i`,
/// `data.o_m_i`, `cd.o_ic`, `cd.total`, `cd.ag`, `cd.ig`; `cd.hg` and
/// `cd.dhg` stale.
///
/// # Errors
/// As [`forward_kinematics`](super::kinematics::forward_kinematics);
/// [`Error::NonFiniteResult`] (`Quantity::CentroidalMap`) when the
/// bodies' inertias about the world's origin overflow (bodies 1e150 m or
/// more from it in f64).
pub fn centroidal_map<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    cd: &mut CentroidalData<S, NB, NV, G>,
    q: &[S; NQ],
) -> Result<()> {
    model.check_configuration(q)?;
    poses(model, data, q);
    map_pass(model, data, cd)
}

/// [`centroidal_map`] and the momentum and its rate at `(q, v, a)` (NQ, NV,
/// NV): `cd.hg = A_g v`, `cd.dhg = A_g a + Ȧ_g v` (with `a = 0`, `Ȧ_g v`),
/// as Pinocchio's `ccrba` and `computeCentroidalMomentumTimeVariation`.
/// Runs [`forward_kinematics_acceleration`]; leaves valid what it and
/// [`centroidal_map`] do, and `cd.hg`, `cd.dhg`.
///
/// # Errors
/// As [`forward_kinematics_acceleration`] and [`centroidal_map`], and
/// [`Error::NonFiniteResult`] (`Quantity::CentroidalMap`, index 0 for
/// `h_G`, 1 for `ḣ_G`) when the momentum or its rate overflows.
pub fn centroidal_momentum<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: FrameSpace,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    cd: &mut CentroidalData<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    a: &[S; NV],
) -> Result<()> {
    forward_kinematics_acceleration(model, data, q, v, a)?;
    map_pass(model, data, cd)?;
    let o_m_g = G::from_translation(&cd.com());
    let mut h = <G::Force<S> as VectorOps<S>>::ZERO;
    let mut dh = h;
    for i in 0..NB {
        let inertia = model.inertia(i);
        let x = &data.o_m_i[i];
        h += x.act_force(&inertia.mul_motion(&data.v[i]));
        dh += x.act_force(&inertia.net_force(&data.v[i], &data.a[i]));
    }
    cd.hg = o_m_g.act_inv_force(&h);
    cd.dhg = o_m_g.act_inv_force(&dh);
    check_vectors_result(&[cd.hg, cd.dhg], Quantity::CentroidalMap)
}

/// [`centroidal_map`] and its time derivative `Ȧ_g` at `(q, v)` into
/// `dag` (NV columns, rodyn's order: the rate of the momentum about the
/// centre of mass per unit rate, N m s and N s; Pinocchio's `dccrba`).
///
/// Column k of joint i is `A_gₖ = ᴳX* ᵒIᶜᵢ Sₖ`; as the model moves,
/// `d(Iᶜᵢ Sₖ)/dt = İᶜᵢ Sₖ + Iᶜᵢ (vᵢ × Sₖ)`, the subtree's inertia rate
/// `İᶜᵢ = Σⱼ (vⱼ ×* Iⱼ − Iⱼ vⱼ×)` being the composite [`SpatialVariation`]
/// less its momentum term, and G translates with the centre of mass's
/// velocity ċ, which adds `−(0, ċ) ×* A_gₖ`. Runs
/// [`forward_kinematics_velocity`]; leaves valid what it and
/// [`centroidal_map`] do.
///
/// # Errors
/// As [`forward_kinematics_velocity`] and [`centroidal_map`], and
/// [`Error::NonFiniteResult`] (`Quantity::CentroidalMap`, the column)
/// when `Ȧ_g` overflows.
pub fn centroidal_map_time_variation<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
>(
    model: &Model<S, NB, NQ, NV, Spatial>,
    data: &mut Data<S, NB, NV, Spatial>,
    cd: &mut CentroidalData<S, NB, NV, Spatial>,
    q: &[S; NQ],
    v: &[S; NV],
    dag: &mut [Force<S>; NV],
) -> Result<()> {
    forward_kinematics_velocity(model, data, q, v)?;
    map_pass(model, data, cd)?;
    // World velocities, and each subtree's Ẏ and momentum.
    let o_v: [Motion<S>; NB] = core::array::from_fn(|i| data.o_m_i[i].act_motion(&data.v[i]));
    let mut variation = [SpatialVariation::<S>::ZERO; NB];
    let mut momentum = [Force::ZERO; NB];
    for i in 0..NB {
        let y = model.inertia(i).act(&data.o_m_i[i]);
        variation[i] = SpatialVariation::of_body(&y, &o_v[i]);
        momentum[i] = y.mul_motion(&o_v[i]);
    }
    let mut total = Force::ZERO;
    for i in (0..NB).rev() {
        match model.parent(i) {
            Some(p) => {
                let (child, child_momentum) = (variation[i], momentum[i]);
                variation[p].add_assign(&child);
                momentum[p] += child_momentum;
            }
            None => total += momentum[i],
        }
    }
    let com_velocity = total.lin * (S::ONE / cd.mass().max(S::from_f64(S::EPSILON)));
    let g_velocity = Motion::new(Vec3::ZERO, com_velocity);
    let o_m_g = Transform::from_translation(cd.com());
    let t = model.topology();
    for i in 0..NB {
        let joint = model.joint(i);
        for k in 0..t.nv[i] {
            let c = t.idx_v[i] + k;
            let s = Spatial::act_subspace_column(&data.o_m_i[i], joint, k);
            // İᶜ S = Ẏᶜ S − S ×* Hᶜ, plus Iᶜ Ṡ with Ṡ = vᵢ × S.
            let rate = variation[i].mul_motion(&s) - s.cross_force(&momentum[i])
                + cd.o_ic[i].mul_motion(&o_v[i].cross_motion(&s));
            dag[c] = o_m_g.act_inv_force(&rate) - g_velocity.cross_force(&cd.ag[c]);
        }
    }
    check_vectors_result(dag, Quantity::CentroidalMap)
}

/// Composite inertias in the world, `I_g` and `A_g`, from `data.o_m_i`.
///
/// # Errors
/// [`Error::NonFiniteResult`] (`Quantity::CentroidalMap`) when `I_g` is not
/// finite: one test for the whole map, since every composite inertia, and
/// so every column of `A_g`, is bounded by the total whose `I_g` it is
/// (positive semi-definite inertias), and it is the world-frame inertias
/// (`m |c|²` of a body far from the origin) that overflow.
fn map_pass<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: FrameSpace>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    cd: &mut CentroidalData<S, NB, NV, G>,
) -> Result<()> {
    // One backward pass: each body's inertia is moved into the world where
    // its composite is summed, so that `o_ic` is written once a body (as
    // the composite) rather than written, read back and written again.
    // Body i + 1's composite is added to body i's when i is its parent at
    // i's turn rather than at its own: a chain's sum then starts from
    // registers rather than from the composite just stored, which loads
    // laid out otherwise than the stores do not get forwarded. Another
    // child's composite waits in its parent's `o_ic` slot (the parent's
    // own inertia is not formed yet), which `pending` marks as holding
    // such a sum.
    let mut pending = [false; NB];
    let mut total: Option<G::Inertia<S>> = None;
    let mut next = <G::Inertia<S> as BodyInertia<S>>::ZERO;
    for i in (0..NB).rev() {
        let mut ic = G::world_inertia(model.inertia(i), &data.o_m_i[i]);
        if i + 1 < NB && model.parent(i + 1) == Some(i) {
            ic = ic.combine(&next);
        }
        if pending[i] {
            ic = ic.combine(&cd.o_ic[i]);
        }
        cd.o_ic[i] = ic;
        match model.parent(i) {
            Some(p) if p + 1 == i => {}
            Some(p) if pending[p] => cd.o_ic[p] = cd.o_ic[p].combine(&ic),
            Some(p) => {
                cd.o_ic[p] = ic;
                pending[p] = true;
            }
            // The first root's composite is the total so far as it is, not
            // its sum with a massless one.
            None => total = Some(total.map_or(ic, |t| t.combine(&ic))),
        }
        next = ic;
    }
    let total = total.unwrap_or(<G::Inertia<S> as BodyInertia<S>>::ZERO);
    cd.total = total;
    let com = total.com();
    cd.ig = G::about_own_centre(&total);
    let t = model.topology();
    for i in 0..NB {
        let joint = model.joint(i);
        let (iv, nv) = t.velocity_range(i);
        let (x, ic) = (&data.o_m_i[i], &cd.o_ic[i]);
        // Most joints have one coordinate: its column without the loop's
        // setup and end test.
        if nv == 1 {
            cd.ag[iv] = G::centroidal_column(x, joint, 0, ic, &com);
            continue;
        }
        G::centroidal_columns(x, joint, ic, &com, &mut cd.ag[iv..iv + nv]);
    }
    if cd.ig.is_finite() {
        Ok(())
    } else {
        Err(Error::NonFiniteResult {
            quantity: Quantity::CentroidalMap,
            index: 0,
        })
    }
}

/// The centre-of-mass Jacobian into `out` (NV columns, m per unit rate, in
/// the world): `out[k]` is the linear part of `A_gₖ` over the mass
/// (Pinocchio's `jacobianCenterOfMass`), so that `Σₖ out[k] vₖ` is the
/// centre of mass's velocity. Reads `cd.ag` and `cd.total`, valid after
/// [`centroidal_map`].
pub fn com_jacobian<S: Scalar, const NB: usize, const NV: usize, G: FrameSpace>(
    cd: &CentroidalData<S, NB, NV, G>,
    out: &mut [G::Point<S>; NV],
) {
    let inv_mass = S::ONE / cd.mass().max(S::from_f64(S::EPSILON));
    for k in 0..NV {
        out[k] = G::scale_point(&G::force_linear_vector(&cd.ag[k]), inv_mass);
    }
}

/// The centre of mass's velocity (m/s) and acceleration (m/s², gravity
/// excluded) in the world: the linear parts of `cd.hg` and `cd.dhg` over
/// the mass, valid after [`centroidal_momentum`].
#[must_use]
pub fn com_velocity_acceleration<S: Scalar, const NB: usize, const NV: usize, G: FrameSpace>(
    cd: &CentroidalData<S, NB, NV, G>,
) -> (G::Point<S>, G::Point<S>) {
    let inv_mass = S::ONE / cd.mass().max(S::from_f64(S::EPSILON));
    (
        G::scale_point(&G::force_linear_vector(&cd.hg), inv_mass),
        G::scale_point(&G::force_linear_vector(&cd.dhg), inv_mass),
    )
}
