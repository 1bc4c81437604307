//! The state a simulation advances.

use crate::error::{Error, Quantity, Result};
use crate::Scalar;

/// Time, configuration, velocity and `NZ` auxiliary first-order states of a
/// model with `NQ` configuration and `NV` velocity coordinates.
///
/// `q` follows the joints' conventions (a free flyer stores
/// `[x y z qx qy qz qw]`), `v` is in the joints' velocity coordinates (body
/// frame for a free flyer). Time in seconds.
///
/// `z` holds states of the drives that obey first-order equations
/// `ż = g(t, q, v, z)` of their own, such as muscle activations
/// (`ȧ = (u − a) / τ(u, a)`) or a motor's current. Their rates come from an
/// [`AuxiliaryLoads`](super::AuxiliaryLoads) and every integrator advances
/// them with `q` and `v`. A model without such states uses the default
/// `NZ = 0`: `z` is an empty array and costs nothing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct State<S: Scalar, const NQ: usize, const NV: usize, const NZ: usize = 0> {
    /// Time (s).
    pub t: S,
    /// Configuration.
    pub q: [S; NQ],
    /// Velocity.
    pub v: [S; NV],
    /// Auxiliary first-order states, in the units their loads define.
    pub z: [S; NZ],
}

impl<S: Scalar, const NQ: usize, const NV: usize> State<S, NQ, NV> {
    /// A state without auxiliary states at time zero.
    #[must_use]
    pub const fn new(q: [S; NQ], v: [S; NV]) -> Self {
        Self {
            t: S::ZERO,
            q,
            v,
            z: [],
        }
    }
}

impl<S: Scalar, const NQ: usize, const NV: usize, const NZ: usize> State<S, NQ, NV, NZ> {
    /// A state with auxiliary states `z` at time zero.
    #[must_use]
    pub const fn with_auxiliary(q: [S; NQ], v: [S; NV], z: [S; NZ]) -> Self {
        Self {
            t: S::ZERO,
            q,
            v,
            z,
        }
    }

    /// Checks that every entry is finite.
    ///
    /// # Errors
    /// [`Error::NonFinite`] naming the first bad entry: of `q`
    /// ([`Quantity::Configuration`]), of `z` ([`Quantity::AuxiliaryState`])
    /// or of `v` ([`Quantity::Velocity`]).
    pub fn check_finite(&self) -> Result<()> {
        if !self.t.is_finite() {
            return Err(Error::NonFinite {
                quantity: Quantity::Time,
                index: 0,
            });
        }
        if let Some(index) = self.q.iter().position(|x| !x.is_finite()) {
            return Err(Error::NonFinite {
                quantity: Quantity::Configuration,
                index,
            });
        }
        if let Some(index) = self.z.iter().position(|x| !x.is_finite()) {
            return Err(Error::NonFinite {
                quantity: Quantity::AuxiliaryState,
                index,
            });
        }
        if let Some(index) = self.v.iter().position(|x| !x.is_finite()) {
            return Err(Error::NonFinite {
                quantity: Quantity::Velocity,
                index,
            });
        }
        Ok(())
    }

    /// The same state in another scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> State<T, NQ, NV, NZ> {
        State {
            t: T::from_f64(self.t.to_f64()),
            q: self.q.map(|x| T::from_f64(x.to_f64())),
            v: self.v.map(|x| T::from_f64(x.to_f64())),
            z: self.z.map(|x| T::from_f64(x.to_f64())),
        }
    }
}
