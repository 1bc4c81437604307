//! Springs along paths: a linear spring and a hardening (cubic) spring.
//!
//! Both are bilateral: stretched beyond the rest length `L₀` they pull
//! (tension `T > 0`), compressed below it they push. Both are conservative,
//! with the potential energies documented on each, so a model driven only by
//! springs conserves `kinetic + gravitational + spring` energy.

use crate::drive::derivatives::{add_tension_derivatives, DriveDerivativeState, DriveDerivatives};
use crate::drive::geometry::PointGeometry;
use crate::drive::{DriveForces, DriveState, ForceElement, Path};
use crate::error::{Error, Quantity, Result};
use crate::Scalar;

/// `value` when it is finite; otherwise the error that names why: a
/// non-finite `length` (`Quantity::PathLength`), a non-finite parameter
/// (`Quantity::Drive`, its index in `parameters`), or finite numbers whose
/// result overflows (`Quantity::Drive`). One test on the way out, the
/// search only on failure.
#[inline]
fn checked<S: Scalar>(value: S, length: S, parameters: &[S]) -> Result<S> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(why_not_finite(length, parameters))
    }
}

/// [`checked`]'s error, out of line: it runs only on failure, and a
/// firmware's image should not carry a copy at every call.
#[cold]
#[inline(never)]
fn why_not_finite<S: Scalar>(length: S, parameters: &[S]) -> Error {
    if !length.is_finite() {
        Error::NonFinite {
            quantity: Quantity::PathLength,
            index: 0,
        }
    } else if let Some(index) = parameters.iter().position(|p| !p.is_finite()) {
        Error::NonFinite {
            quantity: Quantity::Drive,
            index,
        }
    } else {
        Error::NonFiniteResult {
            quantity: Quantity::Drive,
            index: 0,
        }
    }
}

/// A linear spring along a path: `T = k (L - L₀)`, energy `½ k (L - L₀)²`.
#[derive(Clone, Copy, Debug)]
pub struct LinearSpring<S: Scalar, G: PointGeometry, const K: usize> {
    /// The path the spring follows.
    pub path: Path<S, G, K>,
    /// Stiffness `k` (N/m).
    pub stiffness: S,
    /// Rest length `L₀` (m).
    pub rest_length: S,
}

impl<S: Scalar, G: PointGeometry, const K: usize> LinearSpring<S, G, K> {
    /// A spring of stiffness `k` (N/m) and rest length `L₀` (m) along `path`.
    #[must_use]
    pub const fn new(path: Path<S, G, K>, stiffness: S, rest_length: S) -> Self {
        Self {
            path,
            stiffness,
            rest_length,
        }
    }
    /// Tension (N) at path length `length` (m).
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite length (`Quantity::PathLength`)
    /// or parameter (`Quantity::Drive`, 0: stiffness, 1: rest length),
    /// [`Error::NonFiniteResult`] when the tension overflows.
    pub fn tension(&self, length: S) -> Result<S> {
        checked(
            self.stiffness * (length - self.rest_length),
            length,
            &[self.stiffness, self.rest_length],
        )
    }
    /// Stored energy (J) at path length `length` (m).
    ///
    /// # Errors
    /// As [`tension`](Self::tension).
    pub fn potential_energy(&self, length: S) -> Result<S> {
        checked(
            S::from_f64(0.5) * self.stiffness * (length - self.rest_length).squared(),
            length,
            &[self.stiffness, self.rest_length],
        )
    }
}

impl<S: Scalar, G: PointGeometry, const K: usize, const NB: usize, const NV: usize>
    ForceElement<S, G, NB, NV> for LinearSpring<S, G, K>
{
    fn add_forces(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        _w: &[S],
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        let kin = self.path.kinematics_in_element(state.data)?;
        self.path.add_tension_in_element(
            &kin,
            self.tension(kin.length)?,
            state.data,
            &mut out.f_ext,
        )
    }
    fn add_state_derivatives(
        &self,
        state: &DriveDerivativeState<'_, S, G, NB, NV>,
        _w: &[S],
        out: &mut DriveDerivatives<S, NV>,
    ) -> Result<()> {
        let path = self.path.length_derivatives(state)?;
        let tension = (self.tension(path.length)?, self.stiffness, S::ZERO);
        add_tension_derivatives(&path, state.v, tension, out);
        Ok(())
    }
}

/// A hardening spring along a path: `T = k δ + k₃ δ³` with `δ = L - L₀`,
/// energy `½ k δ² + ¼ k₃ δ⁴`.
#[derive(Clone, Copy, Debug)]
pub struct NonlinearSpring<S: Scalar, G: PointGeometry, const K: usize> {
    /// The path the spring follows.
    pub path: Path<S, G, K>,
    /// Linear stiffness `k` (N/m).
    pub stiffness: S,
    /// Cubic stiffness `k₃` (N/m³).
    pub cubic_stiffness: S,
    /// Rest length `L₀` (m).
    pub rest_length: S,
}

impl<S: Scalar, G: PointGeometry, const K: usize> NonlinearSpring<S, G, K> {
    /// A spring with linear and cubic stiffness along `path`.
    #[must_use]
    pub const fn new(
        path: Path<S, G, K>,
        stiffness: S,
        cubic_stiffness: S,
        rest_length: S,
    ) -> Self {
        Self {
            path,
            stiffness,
            cubic_stiffness,
            rest_length,
        }
    }
    /// Tension (N) at path length `length` (m).
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite length (`Quantity::PathLength`)
    /// or parameter (`Quantity::Drive`, 0: stiffness, 1: cubic stiffness,
    /// 2: rest length), [`Error::NonFiniteResult`] when the result
    /// overflows.
    pub fn tension(&self, length: S) -> Result<S> {
        let delta = length - self.rest_length;
        checked(
            delta * (self.stiffness + self.cubic_stiffness * delta * delta),
            length,
            &self.parameters(),
        )
    }
    /// The tangent stiffness `dT/dL = k + 3 k₃ (L − L₀)²` (N/m).
    ///
    /// # Errors
    /// As [`tension`](Self::tension).
    pub fn stiffness_at(&self, length: S) -> Result<S> {
        let delta = length - self.rest_length;
        checked(
            self.stiffness + S::from_f64(3.0) * self.cubic_stiffness * delta * delta,
            length,
            &self.parameters(),
        )
    }
    /// Stored energy (J) at path length `length` (m).
    ///
    /// # Errors
    /// As [`tension`](Self::tension).
    pub fn potential_energy(&self, length: S) -> Result<S> {
        let d2 = (length - self.rest_length).squared();
        checked(
            d2 * (S::from_f64(0.5) * self.stiffness
                + S::from_f64(0.25) * self.cubic_stiffness * d2),
            length,
            &self.parameters(),
        )
    }
    fn parameters(&self) -> [S; 3] {
        [self.stiffness, self.cubic_stiffness, self.rest_length]
    }
}

impl<S: Scalar, G: PointGeometry, const K: usize, const NB: usize, const NV: usize>
    ForceElement<S, G, NB, NV> for NonlinearSpring<S, G, K>
{
    fn add_forces(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        _w: &[S],
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        let kin = self.path.kinematics_in_element(state.data)?;
        self.path.add_tension_in_element(
            &kin,
            self.tension(kin.length)?,
            state.data,
            &mut out.f_ext,
        )
    }
    fn add_state_derivatives(
        &self,
        state: &DriveDerivativeState<'_, S, G, NB, NV>,
        _w: &[S],
        out: &mut DriveDerivatives<S, NV>,
    ) -> Result<()> {
        let path = self.path.length_derivatives(state)?;
        let tension = (
            self.tension(path.length)?,
            self.stiffness_at(path.length)?,
            S::ZERO,
        );
        add_tension_derivatives(&path, state.v, tension, out);
        Ok(())
    }
}
