//! Drives: forces and torques from controls and state, fed to the
//! algorithms as inputs.
//!
//! A drive never changes an algorithm. Every force element adds to a
//! [`DriveForces`]: one spatial force per body (body frame, the `f_ext`
//! convention of [`aba`](crate::algorithm::aba::aba) and
//! [`rnea`](crate::algorithm::rnea::rnea)) and one generalised force per
//! velocity coordinate (added to `tau`). [`forward_dynamics_with_drives`]
//! evaluates a set of elements and runs either forward-dynamics method on
//! the result.
//!
//! | element                     | acts on        | force                                  | reads input |
//! |-----------------------------|----------------|----------------------------------------|-------------|
//! | [`LinearSpring`]            | a [`Path`]     | `T = k (L - L₀)`                       | no          |
//! | [`NonlinearSpring`]         | a [`Path`]     | `T = k (L - L₀) + k₃ (L - L₀)³`        | no          |
//! | [`LinearDamper`]            | a [`Path`]     | `T = c L̇`                              | no          |
//! | [`ThelenMuscle`]            | a [`Path`]     | Hill-type, Thelen (2003), rigid tendon | activation  |
//! | [`DeGrooteMuscle`]          | a [`Path`]     | smooth Hill-type, De Groote et al. (2016), rigid tendon | activation |
//! | [`JointMotor`]              | a joint        | `τ = N k_t i`                          | current     |
//!
//! **Drive inputs `w`.** Elements read their inputs from one vector `w`.
//! Each element names its entry: a motor reads its current command, a
//! muscle its *activation* `a` (not its excitation: excitation `u` drives
//! activation through first-order dynamics, [`ThelenMuscle::activation_rate`],
//! so activation is a state of the simulation and enters the dynamics at an
//! instant). [`crate::sensitivity`] differentiates the joint accelerations
//! with respect to `w`.
//!
//! **A new element** is a type that implements [`ForceElement`]; it lives in
//! the user's crate. Arrays and tuples of elements are elements themselves,
//! so a whole drive set is one value:
//!
//! ```
//! use rodyn::algorithm::forward_dynamics::Aba;
//! use rodyn::drive::*;
//! use rodyn::prelude::*;
//! use rodyn::Endpoint;
//!
//! /// Viscous friction in every joint: τ = -b q̇ (a user's own element).
//! struct JointFriction(f64);
//! impl<G: Space, const NB: usize, const NV: usize> ForceElement<f64, G, NB, NV> for JointFriction {
//!     fn add_forces(&self, state: &DriveState<'_, f64, G, NB, NV>, _w: &[f64],
//!                   out: &mut DriveForces<f64, G, NB, NV>) -> rodyn::Result<()> {
//!         for (tau, v) in out.tau.iter_mut().zip(state.v) {
//!             *tau -= self.0 * v;
//!         }
//!         Ok(())
//!     }
//!     // Reads no input: the default `add_input_derivative` (adds nothing) fits.
//! }
//!
//! const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
//!     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
//!     [Inertia::point_mass(1.0, Vec3::new(0.0, -0.5, 0.0))],
//!     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
//! );
//! // A return spring from the link's end to a world anchor, a motor, and friction.
//! let spring = LinearSpring::new(
//!     Path::new([Endpoint::on_body(0, Vec3::new(0.0, -0.5, 0.0)),
//!                Endpoint::in_world(Vec3::new(0.4, 0.0, 0.0))]),
//!     80.0, 0.3);
//! let motor = JointMotor::new(0, 0, 50.0, 0.02, 1e-5);
//! let drives = (spring, motor, JointFriction(0.1));
//! let (mut data, mut forces) = (Data::new(), DriveForces::new());
//! let current = [0.5]; // A, the motor's drive input
//! let ddq = forward_dynamics_with_drives::<Aba, _, _, _, 1, 1, 1>(
//!     &PENDULUM, &mut data, &[0.3], &[1.0], &[0.0], &drives, &current, &mut forces)?;
//! assert!(ddq[0].is_finite());
//! assert!((forces.tau[0] - (50.0 * 0.02 * 0.5 - 0.1 * 1.0)).abs() < 1e-12);
//! # Ok::<(), rodyn::Error>(())
//! ```

pub mod damper;
pub mod derivatives;
pub mod geometry;
pub mod motor;
pub mod muscle;
pub mod muscle_de_groote;
pub mod path;
pub mod spring;

pub use damper::LinearDamper;
pub use derivatives::{
    aba_derivatives_with_drives, drive_force_derivatives, DriveDerivativeState, DriveDerivatives,
    PathDerivatives,
};
pub use geometry::PointGeometry;
pub use motor::JointMotor;
pub use muscle::{ThelenMuscle, ThelenParameters};
pub use muscle_de_groote::{DeGrooteMuscle, DeGrooteParameters};
pub use path::{Path, PathKinematics, MIN_SEGMENT_LENGTH};
pub use spring::{LinearSpring, NonlinearSpring};

use crate::algorithm::forward_dynamics::ForwardDynamics;
use crate::algorithm::kinematics::forward_kinematics_velocity;
use crate::error::{DriveProblem, Error, Quantity, Result};
use crate::model::{check_finite, check_result};
use crate::space::{Space, VectorOps};
use crate::{Data, Model, Scalar};

/// The forces a set of drives applies: external forces per body and
/// generalised forces per joint coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DriveForces<S: Scalar, G: Space, const NB: usize, const NV: usize> {
    /// Spatial force on each body, in that body's frame (N m, N).
    pub f_ext: [G::Force<S>; NB],
    /// Generalised force on each velocity coordinate (N m or N).
    pub tau: [S; NV],
}

impl<S: Scalar, G: Space, const NB: usize, const NV: usize> DriveForces<S, G, NB, NV> {
    /// No force anywhere; `const`, so it can initialise a `static`.
    #[must_use]
    pub const fn new() -> Self {
        Self {
            f_ext: [<G::Force<S> as VectorOps<S>>::ZERO; NB],
            tau: [S::ZERO; NV],
        }
    }
    /// Resets every force to zero.
    pub fn clear(&mut self) {
        *self = Self::new();
    }
}

impl<S: Scalar, G: Space, const NB: usize, const NV: usize> Default for DriveForces<S, G, NB, NV> {
    fn default() -> Self {
        Self::new()
    }
}

/// The state a force element sees: body poses and velocities in `data`
/// (`o_m_i`, `v`, as forward kinematics with velocities leaves them) and the
/// joint coordinates.
#[derive(Clone, Copy, Debug)]
pub struct DriveState<'a, S: Scalar, G: Space, const NB: usize, const NV: usize> {
    /// Kinematics at the state (reads `o_m_i`, `v`).
    pub data: &'a Data<S, NB, NV, G>,
    /// Joint configuration (NQ entries).
    pub q: &'a [S],
    /// Joint velocity.
    pub v: &'a [S; NV],
}

/// A force element: anything that turns state and drive inputs into forces.
///
/// Implement it in your own crate to add an element without editing rodyn.
/// Both methods *add* to `out`, so elements compose by calling them in turn.
pub trait ForceElement<S: Scalar, G: Space, const NB: usize, const NV: usize> {
    /// Adds the element's forces at drive inputs `w`.
    ///
    /// # Errors
    /// [`Error::InvalidDrive`] when the element does not fit the model or `w`.
    fn add_forces(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()>;

    /// Adds the partial derivative of the element's forces with respect to
    /// input `w[input]` at fixed state; adds nothing when the element does
    /// not read that input. The default is for passive elements (springs,
    /// dampers), which read no input at all.
    ///
    /// # Errors
    /// As [`add_forces`](Self::add_forces).
    fn add_input_derivative(
        &self,
        _state: &DriveState<'_, S, G, NB, NV>,
        _w: &[S],
        _input: usize,
        _out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        Ok(())
    }

    /// Adds the element's generalised force `Q` at drive inputs `w` and its
    /// derivatives `∂Q/∂q`, `∂Q/∂v` at fixed inputs (see
    /// [`derivatives`]). The default reports
    /// [`DriveProblem::NotDifferentiable`]: an element must opt in.
    ///
    /// # Errors
    /// As [`add_forces`](Self::add_forces).
    fn add_state_derivatives(
        &self,
        _state: &DriveDerivativeState<'_, S, G, NB, NV>,
        _w: &[S],
        _out: &mut DriveDerivatives<S, NV>,
    ) -> Result<()> {
        Err(Error::InvalidDrive {
            problem: DriveProblem::NotDifferentiable,
        })
    }
}

/// Reads `w[input]` or says which input is missing.
#[inline]
pub(crate) fn read_input<S: Scalar>(w: &[S], input: usize) -> Result<S> {
    w.get(input).copied().ok_or(Error::InvalidDrive {
        problem: DriveProblem::InputOutOfRange { input },
    })
}

impl<S, G, E, const NB: usize, const NV: usize> ForceElement<S, G, NB, NV> for &E
where
    S: Scalar,
    G: Space,
    E: ForceElement<S, G, NB, NV> + ?Sized,
{
    fn add_forces(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        (**self).add_forces(state, w, out)
    }
    fn add_input_derivative(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        w: &[S],
        input: usize,
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        (**self).add_input_derivative(state, w, input, out)
    }
    fn add_state_derivatives(
        &self,
        state: &DriveDerivativeState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveDerivatives<S, NV>,
    ) -> Result<()> {
        (**self).add_state_derivatives(state, w, out)
    }
}

impl<S, G, E, const N: usize, const NB: usize, const NV: usize> ForceElement<S, G, NB, NV>
    for [E; N]
where
    S: Scalar,
    G: Space,
    E: ForceElement<S, G, NB, NV>,
{
    fn add_forces(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        self.as_slice().add_forces(state, w, out)
    }
    fn add_input_derivative(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        w: &[S],
        input: usize,
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        self.as_slice().add_input_derivative(state, w, input, out)
    }
    fn add_state_derivatives(
        &self,
        state: &DriveDerivativeState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveDerivatives<S, NV>,
    ) -> Result<()> {
        self.as_slice().add_state_derivatives(state, w, out)
    }
}

impl<S, G, E, const NB: usize, const NV: usize> ForceElement<S, G, NB, NV> for [E]
where
    S: Scalar,
    G: Space,
    E: ForceElement<S, G, NB, NV>,
{
    fn add_forces(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        self.iter().try_for_each(|e| e.add_forces(state, w, out))
    }
    fn add_input_derivative(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        w: &[S],
        input: usize,
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        self.iter()
            .try_for_each(|e| e.add_input_derivative(state, w, input, out))
    }
    fn add_state_derivatives(
        &self,
        state: &DriveDerivativeState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveDerivatives<S, NV>,
    ) -> Result<()> {
        self.iter()
            .try_for_each(|e| e.add_state_derivatives(state, w, out))
    }
}

/// Tuples of elements (of different types) are elements.
macro_rules! tuple_element {
    ($($name:ident : $idx:tt),+) => {
        impl<S, G, $($name,)+ const NB: usize, const NV: usize> ForceElement<S, G, NB, NV>
            for ($($name,)+)
        where
            S: Scalar,
            G: Space,
            $($name: ForceElement<S, G, NB, NV>,)+
        {
            fn add_forces(
                &self,
                state: &DriveState<'_, S, G, NB, NV>,
                w: &[S],
                out: &mut DriveForces<S, G, NB, NV>,
            ) -> Result<()> {
                $(self.$idx.add_forces(state, w, out)?;)+
                Ok(())
            }
            fn add_input_derivative(
                &self,
                state: &DriveState<'_, S, G, NB, NV>,
                w: &[S],
                input: usize,
                out: &mut DriveForces<S, G, NB, NV>,
            ) -> Result<()> {
                $(self.$idx.add_input_derivative(state, w, input, out)?;)+
                Ok(())
            }
            fn add_state_derivatives(
                &self,
                state: &DriveDerivativeState<'_, S, G, NB, NV>,
                w: &[S],
                out: &mut DriveDerivatives<S, NV>,
            ) -> Result<()> {
                $(self.$idx.add_state_derivatives(state, w, out)?;)+
                Ok(())
            }
        }
    };
}
tuple_element!(A: 0);
tuple_element!(A: 0, B: 1);
tuple_element!(A: 0, B: 1, C: 2);
tuple_element!(A: 0, B: 1, C: 2, D: 3);
tuple_element!(A: 0, B: 1, C: 2, D: 3, E: 4);
tuple_element!(A: 0, B: 1, C: 2, D: 3, E: 4, F: 5);

/// The forces of `elements` at state `(q, v)` and drive inputs `w`.
///
/// Runs forward kinematics with velocities, then clears `out` and lets each
/// element add its forces. Leaves valid: `li_m_i`, `o_m_i`, `v`, `c` in
/// `data`; `out` holds the total drive forces.
///
/// # Errors
/// Invalid or non-finite state or inputs `w`, [`Error::InvalidDrive`] for
/// an element that does not fit the model or `w` or has a bad parameter,
/// and [`Error::NonFiniteResult`] for forces that overflow.
pub fn drive_forces<S, G, E, const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    elements: &E,
    w: &[S],
    out: &mut DriveForces<S, G, NB, NV>,
) -> Result<()>
where
    S: Scalar,
    G: Space,
    E: ForceElement<S, G, NB, NV> + ?Sized,
{
    check_finite(w, Quantity::DriveInput)?;
    forward_kinematics_velocity(model, data, q, v)?;
    out.clear();
    let state = DriveState { data, q: &q[..], v };
    elements.add_forces(&state, w, out)?;
    // One check per output: an element given finite inputs may still
    // overflow (a spring stretched 1e200 m) or meet a parameter it does
    // not check.
    check_result(&out.tau, Quantity::Torque)?;
    match out.f_ext.iter().position(|f| !f.is_finite()) {
        Some(index) => Err(Error::NonFiniteResult {
            quantity: Quantity::ExternalForce,
            index,
        }),
        None => Ok(()),
    }
}

/// Joint accelerations `q̈ = M⁻¹ (τ + τ_drive - h + Jᵀ f_drive)` under the
/// drive `elements` at inputs `w`, with any further joint forces `tau`, by
/// the forward-dynamics method `M` ([`Aba`](crate::algorithm::forward_dynamics::Aba)
/// or [`Crba`](crate::algorithm::forward_dynamics::Crba)).
///
/// `forces` receives the drive forces (its `tau` excludes the caller's
/// `tau`). Returns `data.ddq`; leaves valid what the method leaves.
///
/// # Errors
/// As [`drive_forces`] and the method's own errors.
#[allow(clippy::too_many_arguments)]
pub fn forward_dynamics_with_drives<
    'd,
    M,
    S,
    G,
    E,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &'d mut Data<S, NB, NV, G>,
    q: &[S; NQ],
    v: &[S; NV],
    tau: &[S; NV],
    elements: &E,
    w: &[S],
    forces: &mut DriveForces<S, G, NB, NV>,
) -> Result<&'d [S; NV]>
where
    M: ForwardDynamics,
    S: Scalar,
    G: Space,
    E: ForceElement<S, G, NB, NV> + ?Sized,
{
    drive_forces(model, data, q, v, elements, w, forces)?;
    let mut total = forces.tau;
    for (t, extra) in total.iter_mut().zip(tau) {
        *t += *extra;
    }
    M::forward_dynamics(model, data, q, v, &total, Some(&forces.f_ext))
}
