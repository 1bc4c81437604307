//! Periodic signals as truncated Fourier series, differentiated analytically.

use std::f64::consts::TAU;

/// `y(t) = mean + slope·t + Σₖ cosₖ cos(kωt) + sinₖ sin(kωt)`, `ω = 2π / period`.
///
/// The slope carries a steady drift (the forward progression of the pelvis);
/// every other term repeats with the period.
#[derive(Clone, Debug, PartialEq)]
pub struct FourierSeries {
    /// Period T (s).
    pub period: f64,
    /// Constant term.
    pub mean: f64,
    /// Drift per second (unit of `y` per s).
    pub slope: f64,
    /// Cosine coefficients of harmonics 1..=n.
    pub cos: Vec<f64>,
    /// Sine coefficients of harmonics 1..=n.
    pub sin: Vec<f64>,
}

impl FourierSeries {
    /// The least-squares fit of `harmonics` harmonics to `samples` of one
    /// period taken at `t = j T / N`, `j = 0..N`, after removing `slope·t`.
    /// For uniform samples the least-squares coefficients are the discrete
    /// Fourier projections, so no linear system is solved.
    ///
    /// # Panics
    /// When there are not more than `2 · harmonics` samples (the fit would
    /// not be unique).
    #[must_use]
    pub fn fit(samples: &[f64], period: f64, slope: f64, harmonics: usize) -> Self {
        let n = samples.len();
        assert!(
            n > 2 * harmonics,
            "{n} samples cannot determine {harmonics} harmonics"
        );
        let detrended = |j: usize| samples[j] - slope * period * j as f64 / n as f64;
        let mean = (0..n).map(detrended).sum::<f64>() / n as f64;
        let projection = |k: usize, basis: fn(f64) -> f64| {
            2.0 / n as f64
                * (0..n)
                    .map(|j| detrended(j) * basis(TAU * (k * j) as f64 / n as f64))
                    .sum::<f64>()
        };
        Self {
            period,
            mean,
            slope,
            cos: (1..=harmonics).map(|k| projection(k, f64::cos)).collect(),
            sin: (1..=harmonics).map(|k| projection(k, f64::sin)).collect(),
        }
    }

    /// Value, first and second time derivatives at time `t` (s).
    #[must_use]
    pub fn evaluate(&self, t: f64) -> [f64; 3] {
        let omega = TAU / self.period;
        let mut y = [self.mean + self.slope * t, self.slope, 0.0];
        for (k, (c, s)) in self.cos.iter().zip(&self.sin).enumerate() {
            let w = omega * (k + 1) as f64;
            let (sin, cos) = (w * t).sin_cos();
            y[0] += c * cos + s * sin;
            y[1] += w * (s * cos - c * sin);
            y[2] -= w * w * (c * cos + s * sin);
        }
        y
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fit_recovers_a_series_and_derivatives_match_differences() {
        let period = 1.1;
        let truth = FourierSeries {
            period,
            mean: 0.3,
            slope: 1.2,
            cos: vec![0.5, -0.1, 0.02],
            sin: vec![-0.2, 0.05, 0.0],
        };
        let samples: Vec<f64> = (0..64)
            .map(|j| truth.evaluate(period * j as f64 / 64.0)[0])
            .collect();
        let fitted = FourierSeries::fit(&samples, period, 1.2, 3);
        for (x, y) in fitted
            .cos
            .iter()
            .chain(&fitted.sin)
            .zip(truth.cos.iter().chain(&truth.sin))
        {
            assert!((x - y).abs() < 1e-12, "{x} vs {y}");
        }
        let (t, h) = (0.37, 1e-5);
        let [_, rate, acc] = truth.evaluate(t);
        let [minus, ..] = truth.evaluate(t - h);
        let [plus, ..] = truth.evaluate(t + h);
        let [mid, ..] = truth.evaluate(t);
        assert!((rate - (plus - minus) / (2.0 * h)).abs() < 1e-8);
        assert!((acc - (plus - 2.0 * mid + minus) / (h * h)).abs() < 1e-3);
    }
}
