//! The robot itself, simulated: forward dynamics by ABA, stepped finer than
//! the controller ticks.

use super::{Signals, PWM_PERIOD};
use crate::drivers::duty_to_torque;
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::sim::{Integrator, SemiImplicitEuler, State};
use rodyn::spatial::Force;
use rodyn::{Data, Model, Result};

/// A fixed-base chain of `N` revolute joints, simulated by ABA and
/// `rodyn::sim`'s semi-implicit (symplectic) Euler: `v ← v + h q̈(q, v, τ)`,
/// then `q ← q + h v`. It keeps the energy of an undriven chain bounded,
/// which explicit Euler does not.
#[derive(Debug)]
pub struct ArmPlant<'m, const N: usize> {
    model: &'m Model<f32, N, N, N>,
    data: Data<f32, N, N>,
    /// Time (s), joint angles `q` (rad) and rates `v` (rad/s).
    pub state: State<f32, N, N>,
    /// Full-scale torque of each drive (N m).
    limits: [f32; N],
    integrator: SemiImplicitEuler,
}

impl<'m, const N: usize> ArmPlant<'m, N> {
    /// A plant at rest at `q`, driven by drives of full-scale `limits` (N m).
    pub fn new(model: &'m Model<f32, N, N, N>, q: [f32; N], limits: [f32; N]) -> Self {
        Self {
            model,
            data: Data::new(),
            state: State::new(q, [0.0; N]),
            limits,
            integrator: SemiImplicitEuler::default(),
        }
    }

    /// The torques the drives currently apply, read from the PWM duty cycles.
    #[must_use]
    pub fn drive_torques(&self, signals: &Signals<N>) -> [f32; N] {
        core::array::from_fn(|k| {
            duty_to_torque(signals.duties[k].get(), PWM_PERIOD, self.limits[k])
        })
    }

    /// Advances `dt` seconds in `substeps` equal steps under the drives' torques,
    /// then publishes the new joint angles to the encoders.
    ///
    /// # Errors
    /// ABA's errors (a non-finite state after divergence).
    pub fn advance(&mut self, signals: &Signals<N>, dt: f32, substeps: u32) -> Result<()> {
        let tau = self.drive_torques(signals);
        // The drives hold their torques over the controller tick.
        let mut loads = |_: &Model<f32, N, N, N>,
                         _: &mut Data<f32, N, N>,
                         _: f32,
                         _: &[f32; N],
                         _: &[f32; N],
                         tau_out: &mut [f32; N],
                         _: &mut [Force<f32>; N]|
         -> Result<()> {
            *tau_out = tau;
            Ok(())
        };
        let h = dt / substeps as f32;
        for _ in 0..substeps {
            self.integrator.step(
                Aba,
                self.model,
                &mut self.data,
                &mut self.state,
                h,
                &mut loads,
            )?;
        }
        self.publish(signals);
        Ok(())
    }

    /// Writes the joint angles where the simulated encoders read them.
    pub fn publish(&self, signals: &Signals<N>) {
        for (cell, q) in signals.angles.iter().zip(self.state.q) {
            cell.set(q);
        }
    }
}
