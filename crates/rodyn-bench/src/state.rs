//! Random states for benchmarks: reproducible, valid for any joint type.

use rodyn::algorithm::rnea::rnea;
use rodyn::space::Space;
use rodyn::{Data, Model, Scalar};

/// One state of a model and the torques that go with it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct State<S, const NQ: usize, const NV: usize> {
    /// Configuration.
    pub q: [S; NQ],
    /// Velocity.
    pub v: [S; NV],
    /// Acceleration (input of RNEA).
    pub a: [S; NV],
    /// `rnea(q, v, a)`: the torques that produce `a` (input of forward dynamics).
    pub tau: [S; NV],
}

impl<const NQ: usize, const NV: usize> State<f64, NQ, NV> {
    /// The same state in another scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> State<T, NQ, NV> {
        State {
            q: self.q.map(T::from_f64),
            v: self.v.map(T::from_f64),
            a: self.a.map(T::from_f64),
            tau: self.tau.map(T::from_f64),
        }
    }
}

/// SplitMix64: a tiny, well-mixed generator, so that benchmarks need no
/// dependency and every run sees the same states.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator from a seed.
    #[must_use]
    pub const fn new(seed: u64) -> Self {
        Self(seed)
    }
    /// Uniform in [-1, 1).
    pub fn symmetric(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        // The top 53 bits as a fraction in [0, 1).
        let unit = (z >> 11) as f64 / (1u64 << 53) as f64;
        2.0 * unit - 1.0
    }
}

/// `count` random states of `model`: configurations reached from the neutral
/// one by a random displacement (so quaternions stay unit), velocities and
/// accelerations uniform in [-1, 1], torques from RNEA.
///
/// # Panics
/// When `integrate` or RNEA fails on the model: benchmark models are valid.
#[must_use]
pub fn random_states<const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<f64, NB, NQ, NV, G>,
    count: usize,
    seed: u64,
) -> Vec<State<f64, NQ, NV>> {
    let mut rng = SplitMix64::new(seed);
    let mut data = Box::new(Data::<f64, NB, NV, G>::new());
    let neutral = model.neutral_configuration();
    (0..count)
        .map(|_| {
            // Joint angles spread over about ±π.
            let displacement: [f64; NV] = core::array::from_fn(|_| 3.0 * rng.symmetric());
            let q = model
                .integrate(&neutral, &displacement, 1.0)
                .expect("a benchmark model's displaced neutral configuration");
            let v = core::array::from_fn(|_| rng.symmetric());
            let a = core::array::from_fn(|_| rng.symmetric());
            let tau = *rnea(model, &mut data, &q, &v, &a, None).expect("rnea on a benchmark state");
            State { q, v, a, tau }
        })
        .collect()
}
