//! Analytic first-order derivatives of the dynamics with respect to the
//! state: `∂τ/∂q`, `∂τ/∂v` (and `∂τ/∂a = M`) of inverse dynamics, and
//! `∂q̈/∂q`, `∂q̈/∂v`, `∂q̈/∂τ = M⁻¹` of forward dynamics.
//!
//! The method is Carpentier & Mansard's ("Analytical derivatives of rigid
//! body dynamics algorithms", Robotics: Science and Systems 2018), which is
//! also Pinocchio's `computeRNEADerivatives` and `computeABADerivatives`:
//! RNEA written in the world frame, where a joint's coordinate moves only
//! the bodies it supports. Moving `q_c` of body j turns j's subtree rigidly
//! about `ᵒS_c`, and that turn changes the subtree's velocities and
//! accelerations by what the turn does to the motion the subtree
//! inherits from j's parent λ: the same extra `ᵒv_λ × ᵒS_c` (velocity)
//! and `ᵒa_λ × ᵒS_c + ᵒv_λ × (ᵒv_λ × ᵒS_c)` (acceleration, gravity
//! included) for every body below j. Summed over a subtree these terms meet
//! only its composite inertia `ᵒYᶜ` and the composite of the inertias'
//! velocity variations `ᵒẎᶜ` (see [`VariationMap`]), which is why
//! the whole Jacobian costs O(n d) for a tree of n bodies and depth d.
//!
//! Derivatives with respect to `q` are taken in the tangent space: column
//! c is the derivative along `q ⊕ ε e_c` (the joint's own
//! [`integrate`](crate::Model::integrate)), so a free-flyer has six
//! columns, body-frame linear then angular, as Pinocchio's. Rows and
//! columns follow `v`'s order: `dtau_dq[r][c] = ∂τ_r/∂q_c`.
//!
//! | function                | computes                                         |
//! |-------------------------|--------------------------------------------------|
//! | [`rnea_derivatives`]    | `τ`, `∂τ/∂q`, `∂τ/∂v` and `M = ∂τ/∂a`             |
//! | [`aba_derivatives`]     | `q̈`, `∂q̈/∂q`, `∂q̈/∂v` and `M⁻¹ = ∂q̈/∂τ`          |

mod forward_dynamics;
mod inertia_variation;
mod inverse_dynamics;

pub use forward_dynamics::{aba_derivatives, aba_derivatives_by_solves};
pub use inertia_variation::{ColumnVariation, DerivativeSpace, SpatialVariation, VariationMap};
pub use inverse_dynamics::rnea_derivatives;

use crate::space::{BodyInertia, VectorOps};
use crate::spatial::Spatial;
use crate::Scalar;

/// The derivative algorithms' results and workspace. Its own type so that a
/// firmware without derivatives pays no RAM for them.
///
/// Matrices are row-major, rows and columns in `v`'s order.
#[derive(Clone, Debug)]
pub struct DerivativeData<S: Scalar, const NB: usize, const NV: usize, G: DerivativeSpace = Spatial>
{
    /// `∂τ/∂q` (N m per rad, N per m; tangent space for a free-flyer).
    pub dtau_dq: [[S; NV]; NV],
    /// `∂τ/∂v` (N m s per rad, N s per m).
    pub dtau_dv: [[S; NV]; NV],
    /// `∂q̈/∂q` from [`aba_derivatives`] (s⁻²).
    pub ddq_dq: [[S; NV]; NV],
    /// `∂q̈/∂v` from [`aba_derivatives`] (s⁻¹).
    pub ddq_dv: [[S; NV]; NV],
    /// `∂q̈/∂τ = M⁻¹` from [`aba_derivatives`], both triangles.
    pub minv: [[S; NV]; NV],
    // Per body, in the world frame: velocity, acceleration minus gravity,
    // composite inertia, composite inertia variation, composite force.
    pub(crate) o_v: [G::Motion<S>; NB],
    pub(crate) o_a: [G::Motion<S>; NB],
    pub(crate) o_yc: [G::Inertia<S>; NB],
    pub(crate) o_dyc: [G::Variation<S>; NB],
    pub(crate) o_fc: [G::Force<S>; NB],
    // Per coordinate, in the world frame: `ᵒS_c` and the motion and force
    // derivatives named in `inverse_dynamics`.
    pub(crate) s: [G::Motion<S>; NV],
    pub(crate) dv_dq: [G::Motion<S>; NV],
    pub(crate) da_dq: [G::Motion<S>; NV],
    pub(crate) da_dv: [G::Motion<S>; NV],
    pub(crate) df_dq: [G::Force<S>; NV],
    pub(crate) df_dv: [G::Force<S>; NV],
    pub(crate) df_da: [G::Force<S>; NV],
}

impl<S: Scalar, const NB: usize, const NV: usize, G: DerivativeSpace> DerivativeData<S, NB, NV, G> {
    /// A zeroed workspace; `const`, so it can initialise a `static`.
    #[must_use]
    pub const fn new() -> Self {
        let motion = <G::Motion<S> as VectorOps<S>>::ZERO;
        let force = <G::Force<S> as VectorOps<S>>::ZERO;
        Self {
            dtau_dq: [[S::ZERO; NV]; NV],
            dtau_dv: [[S::ZERO; NV]; NV],
            ddq_dq: [[S::ZERO; NV]; NV],
            ddq_dv: [[S::ZERO; NV]; NV],
            minv: [[S::ZERO; NV]; NV],
            o_v: [motion; NB],
            o_a: [motion; NB],
            o_yc: [<G::Inertia<S> as BodyInertia<S>>::ZERO; NB],
            o_dyc: [<G::Variation<S> as VariationMap<S, G>>::ZERO; NB],
            o_fc: [force; NB],
            s: [motion; NV],
            dv_dq: [motion; NV],
            da_dq: [motion; NV],
            da_dv: [motion; NV],
            df_dq: [force; NV],
            df_dv: [force; NV],
            df_da: [force; NV],
        }
    }
}

impl<S: Scalar, const NB: usize, const NV: usize, G: DerivativeSpace> Default
    for DerivativeData<S, NB, NV, G>
{
    fn default() -> Self {
        Self::new()
    }
}
