//! What acts on a model during a simulation: joint torques and external
//! forces, and the rates of the drives' own first-order states.
//!
//! [`Loads`] is a function of `(t, q, v)`. [`AuxiliaryLoads`] adds `NZ`
//! auxiliary states `z` (muscle activations, motor currents): its forces
//! may read `z`, and it gives `ż`. The integrators take an
//! [`AuxiliaryLoads`]; every [`Loads`] is one with `NZ = 0`.

use crate::data::Data;
use crate::error::Result;
use crate::model::Model;
use crate::space::Space;
use crate::Scalar;

/// Joint torques `τ` and external forces `f_ext` as functions of `(t, q, v)`.
///
/// The integrator zeroes `tau` (NV, N or N m per coordinate) and `f_ext`
/// (one force per body, in that body's frame, Pinocchio's `fext`
/// convention) before each call; an implementation adds what it produces, so
/// contacts, drives and a controller can be stacked. `data` is free scratch:
/// the forward dynamics overwrite it right after the call.
///
/// An integrator may evaluate the loads several times per step, at trial
/// states (RK4's stages, the implicit Euler's finite differences), so the
/// loads must be a function of `(t, q, v)` only: update a controller's
/// internal state between steps, not inside this call.
///
/// Any `FnMut(&Model, &mut Data, t, &q, &v, &mut tau, &mut f_ext) -> Result<()>`
/// is a `Loads`.
pub trait Loads<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space> {
    /// Adds the loads at `(t, q, v)` to `tau` and `f_ext`.
    ///
    /// # Errors
    /// Whatever the load model reports (e.g. an invalid configuration met
    /// while computing contact points); the step is then abandoned.
    #[allow(clippy::too_many_arguments)]
    fn loads(
        &mut self,
        model: &Model<S, NB, NQ, NV, G>,
        data: &mut Data<S, NB, NV, G>,
        t: S,
        q: &[S; NQ],
        v: &[S; NV],
        tau: &mut [S; NV],
        f_ext: &mut [G::Force<S>; NB],
    ) -> Result<()>;
}

/// No torques and no external forces: the model moves under gravity alone.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoLoads;

impl<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space> Loads<S, NB, NQ, NV, G>
    for NoLoads
{
    #[inline]
    fn loads(
        &mut self,
        _model: &Model<S, NB, NQ, NV, G>,
        _data: &mut Data<S, NB, NV, G>,
        _t: S,
        _q: &[S; NQ],
        _v: &[S; NV],
        _tau: &mut [S; NV],
        _f_ext: &mut [G::Force<S>; NB],
    ) -> Result<()> {
        Ok(())
    }
}

impl<S, F, const NB: usize, const NQ: usize, const NV: usize, G> Loads<S, NB, NQ, NV, G> for F
where
    S: Scalar,
    G: Space,
    F: FnMut(
        &Model<S, NB, NQ, NV, G>,
        &mut Data<S, NB, NV, G>,
        S,
        &[S; NQ],
        &[S; NV],
        &mut [S; NV],
        &mut [G::Force<S>; NB],
    ) -> Result<()>,
{
    #[inline]
    fn loads(
        &mut self,
        model: &Model<S, NB, NQ, NV, G>,
        data: &mut Data<S, NB, NV, G>,
        t: S,
        q: &[S; NQ],
        v: &[S; NV],
        tau: &mut [S; NV],
        f_ext: &mut [G::Force<S>; NB],
    ) -> Result<()> {
        self(model, data, t, q, v, tau, f_ext)
    }
}

/// Loads of drives with `NZ` first-order states of their own: joint torques
/// `τ` and external forces `f_ext` as functions of `(t, q, v, z)`, and the
/// rates `ż = g(t, q, v, z)`.
///
/// A Thelen muscle is the example: its force depends on its activation `a`,
/// a state with `ȧ = (u(t) − a) / τ(u, a)`. The integrators carry `z` in
/// [`State::z`](super::State::z) and advance it with `q` and `v`, each by its
/// own rule (see [`Integrator`](super::Integrator)).
///
/// The contract of [`Loads`] holds: `tau` and `f_ext` are zeroed before each
/// call and the implementation adds to them; `z_rate` is zeroed too and the
/// implementation writes `ż` (per second) into it; `data` is scratch; the
/// call may be made at trial states, so it must be a function of
/// `(t, q, v, z)` only.
///
/// Every [`Loads`] is an `AuxiliaryLoads` with `NZ = 0` (a blanket
/// implementation), so the integrators serve both without a second code
/// path, and a model without auxiliary states pays nothing for them.
pub trait AuxiliaryLoads<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const NZ: usize,
    G: Space,
>
{
    /// Adds the loads at `(t, q, v, z)` to `tau` and `f_ext`, and writes
    /// `ż` into `z_rate`.
    ///
    /// # Errors
    /// Whatever the load model reports; the step is then abandoned.
    #[allow(clippy::too_many_arguments)]
    fn loads_and_rates(
        &mut self,
        model: &Model<S, NB, NQ, NV, G>,
        data: &mut Data<S, NB, NV, G>,
        t: S,
        q: &[S; NQ],
        v: &[S; NV],
        z: &[S; NZ],
        tau: &mut [S; NV],
        f_ext: &mut [G::Force<S>; NB],
        z_rate: &mut [S; NZ],
    ) -> Result<()>;
}

impl<S, L, const NB: usize, const NQ: usize, const NV: usize, G> AuxiliaryLoads<S, NB, NQ, NV, 0, G>
    for L
where
    S: Scalar,
    G: Space,
    L: Loads<S, NB, NQ, NV, G>,
{
    #[inline]
    fn loads_and_rates(
        &mut self,
        model: &Model<S, NB, NQ, NV, G>,
        data: &mut Data<S, NB, NV, G>,
        t: S,
        q: &[S; NQ],
        v: &[S; NV],
        _z: &[S; 0],
        tau: &mut [S; NV],
        f_ext: &mut [G::Force<S>; NB],
        _z_rate: &mut [S; 0],
    ) -> Result<()> {
        self.loads(model, data, t, q, v, tau, f_ext)
    }
}
