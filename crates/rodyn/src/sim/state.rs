//! The state a simulation advances.

use crate::error::{Error, Quantity, Result};
use crate::Scalar;

/// Time, configuration and velocity of a model with `NQ` configuration and
/// `NV` velocity coordinates.
///
/// `q` follows the joints' conventions (a free flyer stores
/// `[x y z qx qy qz qw]`), `v` is in the joints' velocity coordinates (body
/// frame for a free flyer). Time in seconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct State<S: Scalar, const NQ: usize, const NV: usize> {
    /// Time (s).
    pub t: S,
    /// Configuration.
    pub q: [S; NQ],
    /// Velocity.
    pub v: [S; NV],
}

impl<S: Scalar, const NQ: usize, const NV: usize> State<S, NQ, NV> {
    /// A state at time zero.
    #[must_use]
    pub const fn new(q: [S; NQ], v: [S; NV]) -> Self {
        Self { t: S::ZERO, q, v }
    }

    /// Checks that every entry is finite.
    ///
    /// # Errors
    /// [`Error::NonFinite`] naming the first bad entry of `q` or `v`.
    pub fn check_finite(&self) -> Result<()> {
        if let Some(index) = self.q.iter().position(|x| !x.is_finite()) {
            return Err(Error::NonFinite {
                quantity: Quantity::Configuration,
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
    pub fn cast<T: Scalar>(&self) -> State<T, NQ, NV> {
        State {
            t: T::from_f64(self.t.to_f64()),
            q: self.q.map(|x| T::from_f64(x.to_f64())),
            v: self.v.map(|x| T::from_f64(x.to_f64())),
        }
    }
}
