//! The data: every intermediate and result of the algorithms, preallocated.
//!
//! A [`Data`] is plain arrays sized by the model's const parameters, so it
//! can live on the stack, in a `static` on a microcontroller
//! ([`Data::new`] is `const`), or in a `Box` on a host. Each algorithm
//! documents which fields it leaves valid; all others are stale.
//!
//! Frame of every field (Pinocchio's naming: `oMi` is world from body i):
//!
//! | field          | meaning                                             | frame       |
//! |----------------|-----------------------------------------------------|-------------|
//! | `li_m_i`       | parent's frame from body i's frame                  | parent      |
//! | `o_m_i`        | world frame from body i's frame (the body pose)     | world       |
//! | `v`            | body velocity                                       | body i      |
//! | `a`            | body acceleration (without gravity)                 | body i      |
//! | `a_gf`         | body acceleration minus gravity (RNEA's `a - g`)    | body i      |
//! | `f`            | force transmitted across joint i to body i          | body i      |
//! | `ic`           | composite inertia of the subtree of i (CRBA)        | body i, turned¹ |
//! | `ia`, `pa`     | projected articulated inertia and bias force (ABA)  | body i      |
//!
//! ¹ Body i's own frame after [`crba`](crate::algorithm::crba::crba);
//! after the planned entries, its frame turned by
//! [`TurnedFrame::turn`](crate::algorithm::crba::TurnedFrame::turn) of the plan's
//! [`CrbaPlan::frame`](crate::algorithm::crba::CrbaPlan::frame)`(i)` (the
//! quarter turns of the placements above it; the identity at a root).

use crate::joint::MAX_JOINT_NV;
use crate::space::{ArticulatedInertia, BodyInertia, RigidTransform, Space, VectorOps};
use crate::spatial::Spatial;
use crate::Scalar;

/// The workspace of every algorithm for a model of `NB` bodies and `NV`
/// velocity coordinates.
#[derive(Clone, Debug)]
pub struct Data<S: Scalar, const NB: usize, const NV: usize, G: Space = Spatial> {
    /// Parent frame from body frame at the current `q` (`ˡⁱMᵢ`).
    pub li_m_i: [G::Transform<S>; NB],
    /// World frame from body frame: the body poses (`ᵒMᵢ`).
    pub o_m_i: [G::Transform<S>; NB],
    /// Body velocities in their own frames.
    pub v: [G::Motion<S>; NB],
    /// Body accelerations in their own frames, gravity excluded.
    pub a: [G::Motion<S>; NB],
    /// Body accelerations minus gravity, as RNEA propagates them.
    pub a_gf: [G::Motion<S>; NB],
    /// Velocity-product accelerations `c = v × (S qd)`.
    pub c: [G::Motion<S>; NB],
    /// Spatial forces across the joints (RNEA), in the child's frame.
    pub f: [G::Force<S>; NB],
    /// Generalised forces from RNEA, bias forces or gravity torques.
    pub tau: [S; NV],
    /// Joint accelerations from forward dynamics.
    pub ddq: [S; NV],
    /// The joint-space mass matrix `M` (both triangles filled by CRBA; CRBA
    /// forward dynamics fill the lower one).
    pub mass_matrix: [[S; NV]; NV],
    /// `M` factored as `Lᵀ D L`: `D` on the diagonal, `L` transposed above it
    /// (`ltdl[i][k] = L[k][i]`, i < k). The lower triangle is the
    /// factorisation's working storage (on long chains, `L` untransposed).
    pub ltdl: [[S; NV]; NV],
    /// Composite rigid-body inertias.
    pub ic: [G::Inertia<S>; NB],
    /// Articulated-body inertias: after ABA, each body's `I^a = I^A - U D⁻¹ Uᵀ`
    /// (the inertia its parent receives; a root keeps `I^A`).
    pub ia: [G::Articulated<S>; NB],
    /// Articulated-body bias forces `p^A`.
    pub pa: [G::Force<S>; NB],
    /// Columns of `U = I^A S`, one per velocity coordinate.
    pub u_cols: [G::Force<S>; NV],
    /// Rows of each joint's `D⁻¹ = (Sᵀ I^A S)⁻¹` block.
    pub d_inv: [[S; MAX_JOINT_NV]; NV],
    /// `u = tau - Sᵀ p^A`, one per velocity coordinate.
    pub u: [S; NV],
    /// Scratch vector for bias forces.
    pub h: [S; NV],
}

impl<S: Scalar, const NB: usize, const NV: usize, G: Space> Data<S, NB, NV, G> {
    /// A zeroed workspace; `const`, so it can initialise a `static`.
    ///
    /// # Example
    ///
    /// ```
    /// use rodyn::prelude::*;
    /// use rodyn::algorithm::rnea::gravity_torques;
    /// // Sized by the model's body and velocity counts; no allocation, so it can
    /// // be built in a `const` (or a `static` behind a cell on firmware).
    /// const EMPTY: Data<f64, 1, 1> = Data::new();
    /// let mut data = EMPTY;
    /// # const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
    /// #     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
    /// #     [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
    /// #     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
    /// # );
    /// let tau = *gravity_torques(&PENDULUM, &mut data, &[0.0])?;
    /// // An algorithm returns a view of its result field and leaves it in `data`.
    /// assert_eq!(tau, data.tau);
    /// assert!((tau[0] - 9.81).abs() < 1e-12);
    /// # Ok::<(), rodyn::Error>(())
    /// ```
    #[must_use]
    pub const fn new() -> Self {
        Self {
            li_m_i: [<G::Transform<S> as RigidTransform<S>>::IDENTITY; NB],
            o_m_i: [<G::Transform<S> as RigidTransform<S>>::IDENTITY; NB],
            v: [<G::Motion<S> as VectorOps<S>>::ZERO; NB],
            a: [<G::Motion<S> as VectorOps<S>>::ZERO; NB],
            a_gf: [<G::Motion<S> as VectorOps<S>>::ZERO; NB],
            c: [<G::Motion<S> as VectorOps<S>>::ZERO; NB],
            f: [<G::Force<S> as VectorOps<S>>::ZERO; NB],
            tau: [S::ZERO; NV],
            ddq: [S::ZERO; NV],
            mass_matrix: [[S::ZERO; NV]; NV],
            ltdl: [[S::ZERO; NV]; NV],
            ic: [<G::Inertia<S> as BodyInertia<S>>::ZERO; NB],
            ia: [<G::Articulated<S> as ArticulatedInertia<S>>::ZERO; NB],
            pa: [<G::Force<S> as VectorOps<S>>::ZERO; NB],
            u_cols: [<G::Force<S> as VectorOps<S>>::ZERO; NV],
            d_inv: [[S::ZERO; MAX_JOINT_NV]; NV],
            u: [S::ZERO; NV],
            h: [S::ZERO; NV],
        }
    }
}

impl<S: Scalar, const NB: usize, const NV: usize, G: Space> Default for Data<S, NB, NV, G> {
    fn default() -> Self {
        Self::new()
    }
}
