//! A model with its workspace and states, behind an object-safe interface, so
//! that binaries can time models of different const sizes in one list.

use crate::state::{random_states, State};
use crate::timing::{calls_for, ns_per_call};
use crate::Algorithm;
use rodyn::algorithm::crba::CrbaPlan;
use rodyn::space::Space;
use rodyn::{Data, Model, Scalar};

/// A model that can be timed.
pub trait Case {
    /// Number of velocity coordinates.
    fn nv(&self) -> usize;
    /// `false` when `algorithm` reports an error on one of the states
    /// (such a case is not timed).
    fn succeeds(&mut self, algorithm: Algorithm) -> bool;
    /// Calls of `algorithm` that take about `target_ns`.
    fn calibrate(&mut self, algorithm: Algorithm, target_ns: f64) -> usize;
    /// Nanoseconds per call of `algorithm`, over `calls` calls.
    ///
    /// # Panics
    /// When the algorithm fails: check [`succeeds`](Self::succeeds) first.
    fn time(&mut self, algorithm: Algorithm, calls: usize) -> f64;
    /// RNEA torques of the first state, in f64.
    fn first_torques(&mut self) -> Vec<f64>;
}

/// A model in scalar `S` and geometry `G` with its CRBA plan and its
/// random states.
pub struct ModelCase<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space> {
    model: Model<S, NB, NQ, NV, G>,
    plan: CrbaPlan<S, NB, G>,
    data: Box<Data<S, NB, NV, G>>,
    states: Vec<State<S, NQ, NV>>,
}

impl<const NB: usize, const NQ: usize, const NV: usize, G: Space> ModelCase<f64, NB, NQ, NV, G> {
    /// `model` with `count` random states from `seed`.
    #[must_use]
    pub fn new(model: Model<f64, NB, NQ, NV, G>, count: usize, seed: u64) -> Self {
        let states = random_states(&model, count, seed);
        Self {
            plan: CrbaPlan::new(&model),
            model,
            data: Box::new(Data::new()),
            states,
        }
    }
    /// The same model and states in `f32`.
    ///
    /// # Panics
    /// For a model with custom joints, which cannot change scalar type.
    #[must_use]
    pub fn to_f32(&self) -> ModelCase<f32, NB, NQ, NV, G> {
        let model = self.model.cast().expect("built-in joints cast");
        ModelCase {
            plan: CrbaPlan::new(&model),
            model,
            data: Box::new(Data::new()),
            states: self.states.iter().map(State::cast).collect(),
        }
    }
    /// The states, for handing to another library.
    #[must_use]
    pub fn states(&self) -> &[State<f64, NQ, NV>] {
        &self.states
    }
    /// The model.
    #[must_use]
    pub fn model(&self) -> &Model<f64, NB, NQ, NV, G> {
        &self.model
    }
}

impl<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space> Case
    for ModelCase<S, NB, NQ, NV, G>
{
    fn nv(&self) -> usize {
        NV
    }
    fn succeeds(&mut self, algorithm: Algorithm) -> bool {
        let Self {
            model,
            plan,
            data,
            states,
        } = self;
        states
            .iter()
            .all(|s| algorithm.try_run(model, plan, data, s).is_ok())
    }
    fn calibrate(&mut self, algorithm: Algorithm, target_ns: f64) -> usize {
        let Self {
            model,
            plan,
            data,
            states,
        } = self;
        calls_for(target_ns, states.len(), |k| {
            algorithm.run(model, plan, data, &states[k])
        })
    }
    fn time(&mut self, algorithm: Algorithm, calls: usize) -> f64 {
        let Self {
            model,
            plan,
            data,
            states,
        } = self;
        ns_per_call(calls, states.len(), |k| {
            algorithm.run(model, plan, data, &states[k])
        })
    }
    fn first_torques(&mut self) -> Vec<f64> {
        let s = &self.states[0];
        rodyn::algorithm::rnea::rnea(&self.model, &mut self.data, &s.q, &s.v, &s.a, None)
            .expect("rnea")
            .iter()
            .map(|t| t.to_f64())
            .collect()
    }
}
