//! Benchmarks of rodyn, shared by the criterion benches (`benches/`) and the
//! measuring binaries (`src/bin/`):
//!
//! * `cargo bench -p rodyn-bench`: criterion, every model and algorithm,
//!   `f64` and `f32`, planar and 3-D;
//! * `tools/pinocchio/bench/compare.sh`: rodyn against Pinocchio, same
//!   URDFs, same states, interleaved runs;
//! * `cargo run -p rodyn-bench --release --bin crossover`: ABA against CRBA
//!   forward dynamics for chains of 1 to 120 links, as an SVG chart.
//!
//! Benchmarks are never part of `cargo test`: timings belong in reports,
//! not in assertions.

pub mod arguments;
pub mod cases;
pub mod models;
pub mod state;
pub mod timing;

use rodyn::algorithm::crba::{crba_planned, CrbaPlan};
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::algorithm::rnea::rnea;
use rodyn::space::Space;
use rodyn::{Data, Model, Scalar};
use state::State;

/// The algorithms that are timed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Algorithm {
    /// Inverse dynamics, `rnea(q, v, a)`.
    Rnea,
    /// The mass matrix, `crba_planned(q)` (the plan built once, as a
    /// model compiler's is).
    Crba,
    /// Forward dynamics by bias forces, CRBA (planned), `Lᵀ D L`
    /// factorisation and solve.
    CrbaForwardDynamics,
    /// Forward dynamics by the articulated-body algorithm.
    Aba,
}

impl Algorithm {
    /// Every algorithm, in report order.
    pub const ALL: [Self; 4] = [Self::Rnea, Self::Crba, Self::CrbaForwardDynamics, Self::Aba];

    /// The name used in reports and by the Pinocchio timing program.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Rnea => "rnea",
            Self::Crba => "crba",
            Self::CrbaForwardDynamics => "crba_fd",
            Self::Aba => "aba",
        }
    }

    /// Runs the algorithm once on `state` and returns one entry of its
    /// result, so that the optimiser cannot drop the call. CRBA takes
    /// `plan`, which must be `model`'s.
    ///
    /// # Errors
    /// As the algorithm: e.g. a mass matrix that is not numerically
    /// positive definite in `f32`.
    #[inline]
    pub fn try_run<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
        self,
        model: &Model<S, NB, NQ, NV, G>,
        plan: &CrbaPlan<S, NB, G>,
        data: &mut Data<S, NB, NV, G>,
        state: &State<S, NQ, NV>,
    ) -> rodyn::Result<S> {
        let last = NV - 1;
        let (q, v, tau) = (&state.q, &state.v, &state.tau);
        Ok(match self {
            Self::Rnea => rnea(model, data, q, v, &state.a, None)?[last],
            Self::Crba => crba_planned(model, plan, data, q)?[last][0],
            Self::CrbaForwardDynamics => {
                Crba::forward_dynamics_planned(model, plan, data, q, v, tau, None)?[last]
            }
            Self::Aba => {
                Aba::forward_dynamics(model, data, &state.q, &state.v, &state.tau, None)?[last]
            }
        })
    }

    /// [`try_run`](Self::try_run) for states known to be valid.
    ///
    /// # Panics
    /// When the algorithm reports an error.
    #[inline]
    pub fn run<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
        self,
        model: &Model<S, NB, NQ, NV, G>,
        plan: &CrbaPlan<S, NB, G>,
        data: &mut Data<S, NB, NV, G>,
        state: &State<S, NQ, NV>,
    ) -> S {
        match self.try_run(model, plan, data, state) {
            Ok(x) => x,
            Err(e) => panic!("{} failed on a benchmark state: {e:?}", self.name()),
        }
    }
}
