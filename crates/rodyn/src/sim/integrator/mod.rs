//! Time-stepping schemes for `q̇ = Q(q) v`, `v̇ = FD(q, v, τ, f_ext)` and
//! the drives' auxiliary states `ż = g(t, q, v, z)`.
//!
//! | integrator            | order | dynamics calls per step | stable for                          |
//! |-----------------------|-------|-------------------------|-------------------------------------|
//! | [`ExplicitEuler`]     | 1     | 1                       | damped systems only; gains energy on an undamped oscillator |
//! | [`SemiImplicitEuler`] | 1     | 1                       | oscillators with `ω dt < 2` (symplectic: energy bounded) |
//! | [`Rk4`]               | 4     | 4                       | oscillators with `ω dt < 2.78`      |
//! | [`ImplicitEuler`]     | 1     | 2 NV + NZ + 1, an NZ x NZ and an NV x NV solve | stiff springs, dampers, contacts and fast auxiliary states at any step (A-stable, dissipative) |
//!
//! How each scheme moves the auxiliary states `z` (see
//! [`AuxiliaryLoads`]):
//!
//! * [`ExplicitEuler`] and [`SemiImplicitEuler`]: `z₁ = z + ż(t, q, v, z) dt`
//!   from the one evaluation at the start, like `v`; the semi-implicit
//!   scheme's implicit part is the configuration update with `v₁` only.
//! * [`Rk4`]: `z` is one more block of the ODE, with the same four stages.
//! * [`ImplicitEuler`]: `z` is in the linearisation, so a stiff `ż` (a fast
//!   activation) is as stable as a stiff spring.
//!
//! Each is a value implementing [`Integrator`]; the forward-dynamics method
//! is a type parameter given by value (`Aba` or `Crba`):
//!
//! ```
//! use rodyn::algorithm::forward_dynamics::Aba;
//! use rodyn::sim::{Integrator, NoLoads, Rk4, State};
//! # use rodyn::{Data, Model, joint::{Axis, Joint}, spatial::*};
//! # const M: Model<f64, 1, 1, 1> = Model::new([None], [Joint::revolute(Axis::Z)],
//! #     [Transform::IDENTITY], [Inertia::point_mass(1.0, Vec3::new(0.5, 0.0, 0.0))],
//! #     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)));
//! let mut data = Data::new();
//! let mut state = State::new([0.3], [0.0]);
//! let mut rk4 = Rk4::default();
//! for _ in 0..1000 {
//!     rk4.step(Aba, &M, &mut data, &mut state, 1e-3, &mut NoLoads)?;
//! }
//! assert!((state.t - 1.0).abs() < 1e-9);
//! # Ok::<(), rodyn::Error>(())
//! ```

mod euler;
mod implicit_euler;
mod rk4;

pub use euler::{ExplicitEuler, SemiImplicitEuler};
pub use implicit_euler::ImplicitEuler;
pub use rk4::Rk4;

use super::loads::AuxiliaryLoads;
use super::manifold::ConfigurationRate;
use super::state::State;
use crate::algorithm::forward_dynamics::ForwardDynamics;
use crate::data::Data;
use crate::error::Result;
use crate::model::Model;
use crate::space::{Space, VectorOps};
use crate::Scalar;

/// One step of a time-stepping scheme.
pub trait Integrator {
    /// A short name for reports ("RK4").
    const NAME: &'static str;

    /// Advances `state` (with its `NZ` auxiliary states; `NZ = 0` for a
    /// plain [`Loads`](crate::sim::Loads)) by `dt` seconds under `loads`,
    /// with forward dynamics by `method` (ABA or CRBA).
    ///
    /// Leaves `data` as the last dynamics evaluation left it (not
    /// necessarily at the new state).
    ///
    /// # Errors
    /// Any error of the loads or the dynamics at any evaluation (a singular
    /// articulated inertia, a mass matrix that is not positive definite, a
    /// configuration off its manifold), or [`Error::NonFinite`](crate::Error::NonFinite)
    /// for a non-finite time or step (`Quantity::Time`) or when the new
    /// state would not be finite. On error `state` is unchanged.
    #[allow(clippy::too_many_arguments)]
    fn step<F, L, S, const NB: usize, const NQ: usize, const NV: usize, const NZ: usize, G>(
        &mut self,
        method: F,
        model: &Model<S, NB, NQ, NV, G>,
        data: &mut Data<S, NB, NV, G>,
        state: &mut State<S, NQ, NV, NZ>,
        dt: S,
        loads: &mut L,
    ) -> Result<()>
    where
        F: ForwardDynamics,
        L: AuxiliaryLoads<S, NB, NQ, NV, NZ, G>,
        S: Scalar,
        G: ConfigurationRate;
}

/// `q̈` and `ż` at `(t, q, v, z)`: the loads and rates, then the forward
/// dynamics.
#[allow(clippy::too_many_arguments)]
pub(crate) fn derivatives<
    F,
    L,
    S,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NZ: usize,
    G,
>(
    _method: &F,
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    loads: &mut L,
    t: S,
    q: &[S; NQ],
    v: &[S; NV],
    z: &[S; NZ],
) -> Result<([S; NV], [S; NZ])>
where
    F: ForwardDynamics,
    L: AuxiliaryLoads<S, NB, NQ, NV, NZ, G>,
    S: Scalar,
    G: Space,
{
    let mut tau = [S::ZERO; NV];
    let mut f_ext = [<G::Force<S> as VectorOps<S>>::ZERO; NB];
    let mut z_rate = [S::ZERO; NZ];
    loads.loads_and_rates(model, data, t, q, v, z, &mut tau, &mut f_ext, &mut z_rate)?;
    let acceleration = *F::forward_dynamics(model, data, q, v, &tau, Some(&f_ext))?;
    Ok((acceleration, z_rate))
}

/// The step's time `t` and length `dt` must be finite: a NaN in either
/// would otherwise surface later as a bad configuration or a NaN time.
#[inline]
pub(crate) fn check_time<S: Scalar>(t: S, dt: S) -> Result<()> {
    if t.is_finite() && dt.is_finite() {
        Ok(())
    } else {
        Err(crate::Error::NonFinite {
            quantity: crate::error::Quantity::Time,
            index: 0,
        })
    }
}

/// Writes the new state only when it is finite.
#[inline]
pub(crate) fn commit<S: Scalar, const NQ: usize, const NV: usize, const NZ: usize>(
    state: &mut State<S, NQ, NV, NZ>,
    next: State<S, NQ, NV, NZ>,
) -> Result<()> {
    next.check_finite()?;
    *state = next;
    Ok(())
}
