//! A recorded trajectory and its CSV form.

use rodyn::sim::State;
use std::io::Write;
use std::path::Path;
use std::time::Duration;

/// Samples of `(t, q, v)` in f64, whatever scalar the run used.
#[derive(Clone, Debug, Default)]
pub struct Trajectory {
    /// Sample times (s).
    pub t: Vec<f64>,
    /// Configurations, one per sample.
    pub q: Vec<Vec<f64>>,
    /// Velocities, one per sample.
    pub v: Vec<Vec<f64>>,
    /// First-order states beside `(q, v)` (the muscle robot's activations),
    /// one row per sample; empty for scenarios without any.
    pub internal: Vec<Vec<f64>>,
    /// Names of the internal states, for the CSV header.
    pub internal_names: Vec<String>,
    /// Why the run stopped early, if it did.
    pub failure: Option<String>,
    /// Host time spent stepping.
    pub wall_time: Duration,
    /// Steps asked for.
    pub steps: usize,
    nq: usize,
    nv: usize,
}

impl Trajectory {
    /// An empty trajectory of a model with `nq` and `nv` coordinates.
    pub fn new(nq: usize, nv: usize) -> Self {
        Self {
            nq,
            nv,
            ..Self::default()
        }
    }

    /// A trajectory of a run that could not start, with the reason.
    pub fn failed(nq: usize, nv: usize, reason: String) -> Self {
        Self {
            failure: Some(reason),
            ..Self::new(nq, nv)
        }
    }

    /// An empty trajectory that also records the internal states `names`.
    pub fn with_internal_states(nq: usize, nv: usize, names: Vec<String>) -> Self {
        Self {
            internal_names: names,
            ..Self::new(nq, nv)
        }
    }

    /// Appends a sample; its auxiliary states `z`, if it has any, become
    /// the sample's internal states.
    pub fn record<const NQ: usize, const NV: usize, const NZ: usize>(
        &mut self,
        s: &State<f64, NQ, NV, NZ>,
    ) {
        self.t.push(s.t);
        self.q.push(s.q.to_vec());
        self.v.push(s.v.to_vec());
        if NZ > 0 {
            self.internal.push(s.z.to_vec());
        }
    }

    /// Host seconds per simulated second.
    pub fn cost_per_simulated_second(&self) -> f64 {
        let simulated = self.t.last().copied().unwrap_or(0.0);
        if simulated > 0.0 {
            self.wall_time.as_secs_f64() / simulated
        } else {
            f64::INFINITY
        }
    }

    /// Largest deviation of the configuration from `reference` over the
    /// samples both share (same sample times assumed), in the units of q
    /// (rad, m, quaternion components); infinite when this run failed early.
    pub fn max_error_against(&self, reference: &Trajectory) -> f64 {
        if self.failure.is_some() || self.t.len() < reference.t.len() {
            return f64::INFINITY;
        }
        let mut worst = 0.0f64;
        for (a, b) in self.q.iter().zip(&reference.q) {
            for (x, y) in a.iter().zip(b) {
                let d = (x - y).abs();
                if !d.is_finite() {
                    return f64::INFINITY;
                }
                worst = worst.max(d);
            }
        }
        worst
    }

    /// Writes `t, q0.., v0..` and the internal states as CSV.
    pub fn write_csv(&self, path: &Path, q_names: &[String]) -> std::io::Result<()> {
        let mut out = std::io::BufWriter::new(std::fs::File::create(path)?);
        write!(out, "t")?;
        for k in 0..self.nq {
            match q_names.get(k) {
                Some(name) => write!(out, ",q_{name}")?,
                None => write!(out, ",q{k}")?,
            }
        }
        for k in 0..self.nv {
            write!(out, ",v{k}")?;
        }
        for name in &self.internal_names {
            write!(out, ",{name}")?;
        }
        writeln!(out)?;
        for (n, ((t, q), v)) in self.t.iter().zip(&self.q).zip(&self.v).enumerate() {
            write!(out, "{t:.6}")?;
            let internal = self.internal.get(n).map_or(&[][..], Vec::as_slice);
            for x in q.iter().chain(v).chain(internal) {
                write!(out, ",{x:.9e}")?;
            }
            writeln!(out)?;
        }
        Ok(())
    }
}
