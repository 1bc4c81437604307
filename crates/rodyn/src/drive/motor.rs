//! Joint motors: an electric motor driving one joint coordinate through a
//! gearbox.
//!
//! The motor's current `i` (A, the drive input) makes the rotor torque
//! `k_t i`; the gearbox of ratio `N` (rotor turns per joint turn) multiplies
//! it, so the joint receives `τ = N k_t i`. The rotor spins `N` times as
//! fast as the joint, so its inertia `J_r` appears at the joint as the
//! reflected inertia `N² J_r`. That inertia is not a force: it belongs on the
//! diagonal of the mass matrix, where the model's per-coordinate armature
//! puts it ([`JointMotor::reflected_inertia`], added with
//! [`Model::set_armature`](crate::Model::set_armature)). The rotor's
//! gyroscopic coupling with the link it rides on is neglected, as in
//! Pinocchio's and MuJoCo's armature.

use crate::drive::{
    read_input, DriveDerivativeState, DriveDerivatives, DriveForces, DriveState, ForceElement,
};
use crate::error::{DriveProblem, Error, Quantity, Result};
use crate::space::Space;
use crate::Scalar;

/// A geared motor on velocity coordinate `dof`, commanded by its current.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointMotor<S> {
    /// The velocity coordinate it drives (index into `v` and `tau`).
    pub dof: usize,
    /// The entry of the drive-input vector `w` holding the current (A).
    pub input: usize,
    /// Gear ratio `N`: rotor angle per joint angle (dimensionless).
    pub gear_ratio: S,
    /// Torque constant `k_t` (N m/A).
    pub torque_constant: S,
    /// Rotor inertia `J_r` about its axis (kg m²).
    pub rotor_inertia: S,
}

impl<S: Scalar> JointMotor<S> {
    /// A motor with gear ratio `N`, torque constant `k_t` (N m/A) and rotor
    /// inertia `J_r` (kg m²) on coordinate `dof`, reading current `w[input]`.
    ///
    /// # Example
    ///
    /// ```
    /// use rodyn::drive::JointMotor;
    /// // 50:1 gearbox, 0.02 N m/A, rotor 2e-5 kg m², on coordinate 0, current in w[0].
    /// let motor = JointMotor::<f64>::new(0, 0, 50.0, 0.02, 2e-5);
    /// assert!((motor.torque_per_current()? - 1.0).abs() < 1e-12); // N k_t, N m/A
    /// assert!((motor.reflected_inertia()? - 0.05).abs() < 1e-12); // N² J_r, kg m²
    /// # Ok::<(), rodyn::Error>(())
    /// ```
    #[must_use]
    pub const fn new(
        dof: usize,
        input: usize,
        gear_ratio: S,
        torque_constant: S,
        rotor_inertia: S,
    ) -> Self {
        Self {
            dof,
            input,
            gear_ratio,
            torque_constant,
            rotor_inertia,
        }
    }
    /// Joint torque per ampere, `N k_t` (N m/A).
    ///
    /// # Errors
    /// [`Error::NonFinite`] (`Quantity::Drive`, 0: gear ratio, 1: torque
    /// constant, 2: rotor inertia) for a non-finite parameter,
    /// [`Error::NonFiniteResult`] when the product overflows.
    pub fn torque_per_current(&self) -> Result<S> {
        self.checked(self.gain())
    }
    /// The rotor inertia seen at the joint, `N² J_r` (kg m²).
    ///
    /// # Errors
    /// As [`torque_per_current`](Self::torque_per_current).
    pub fn reflected_inertia(&self) -> Result<S> {
        self.checked(self.gear_ratio * self.gear_ratio * self.rotor_inertia)
    }
    /// `N k_t`, unchecked: the drive's torques are checked where they are
    /// summed.
    fn gain(&self) -> S {
        self.gear_ratio * self.torque_constant
    }
    /// `value` when finite, otherwise the error naming a non-finite
    /// parameter or the overflow.
    fn checked(&self, value: S) -> Result<S> {
        if value.is_finite() {
            return Ok(value);
        }
        let parameters = [self.gear_ratio, self.torque_constant, self.rotor_inertia];
        Err(match parameters.iter().position(|p| !p.is_finite()) {
            Some(index) => Error::NonFinite {
                quantity: Quantity::Drive,
                index,
            },
            None => Error::NonFiniteResult {
                quantity: Quantity::Drive,
                index: 0,
            },
        })
    }
    fn check_dof<const NV: usize>(&self) -> Result<()> {
        if self.dof < NV {
            Ok(())
        } else {
            Err(Error::InvalidDrive {
                problem: DriveProblem::DofOutOfRange { dof: self.dof },
            })
        }
    }
}

impl<S: Scalar, G: Space, const NB: usize, const NV: usize> ForceElement<S, G, NB, NV>
    for JointMotor<S>
{
    fn add_forces(
        &self,
        _state: &DriveState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        self.check_dof::<NV>()?;
        out.tau[self.dof] += self.gain() * read_input(w, self.input)?;
        Ok(())
    }
    fn add_input_derivative(
        &self,
        _state: &DriveState<'_, S, G, NB, NV>,
        _w: &[S],
        input: usize,
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        self.check_dof::<NV>()?;
        if input == self.input {
            out.tau[self.dof] += self.gain();
        }
        Ok(())
    }
    /// The motor's torque depends on its current alone: no state
    /// derivatives.
    fn add_state_derivatives(
        &self,
        _state: &DriveDerivativeState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveDerivatives<S, NV>,
    ) -> Result<()> {
        self.check_dof::<NV>()?;
        out.tau[self.dof] += self.gain() * read_input(w, self.input)?;
        Ok(())
    }
}
