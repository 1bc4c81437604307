//! The robot itself, simulated: forward dynamics by ABA, stepped finer than
//! the controller ticks.

use super::{Signals, PWM_PERIOD};
use crate::drivers::duty_to_torque;
use rodyn::algorithm::aba::aba;
use rodyn::{Data, Model, Result};

/// A fixed-base chain of `N` revolute joints, simulated with semi-implicit
/// (symplectic) Euler: `v ← v + h q̈(q, v, τ)`, then `q ← q + h v`. It keeps
/// the energy of an undriven chain bounded, which explicit Euler does not.
#[derive(Debug)]
pub struct ArmPlant<'m, const N: usize> {
    model: &'m Model<f32, N, N, N>,
    data: Data<f32, N, N>,
    /// Joint angles (rad).
    pub q: [f32; N],
    /// Joint rates (rad/s).
    pub v: [f32; N],
    /// Full-scale torque of each drive (N m).
    limits: [f32; N],
}

impl<'m, const N: usize> ArmPlant<'m, N> {
    /// A plant at rest at `q`, driven by drives of full-scale `limits` (N m).
    pub fn new(model: &'m Model<f32, N, N, N>, q: [f32; N], limits: [f32; N]) -> Self {
        Self {
            model,
            data: Data::new(),
            q,
            v: [0.0; N],
            limits,
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
        let h = dt / substeps as f32;
        for _ in 0..substeps {
            let ddq = aba(self.model, &mut self.data, &self.q, &self.v, &tau, None)?;
            for ((q, v), ddq) in self.q.iter_mut().zip(&mut self.v).zip(ddq) {
                *v += h * ddq;
                *q += h * *v;
            }
        }
        self.publish(signals);
        Ok(())
    }

    /// Writes the joint angles where the simulated encoders read them.
    pub fn publish(&self, signals: &Signals<N>) {
        for (cell, q) in signals.angles.iter().zip(self.q) {
            cell.set(q);
        }
    }
}
