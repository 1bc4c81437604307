//! A smooth Hill-type muscle for optimal control, after De Groote et al.
//! (2016), with a rigid tendon.
//!
//! F. De Groote, A. L. Kinney, A. V. Rao, B. J. Fregly, "Evaluation of
//! direct collocation optimal control problem formulations for solving the
//! muscle redundancy problem", *Ann. Biomed. Eng.* 44 (2016) 2922–2936,
//! and its supplementary material. Its curves are sums of exponentials, a
//! logarithm and `tanh`: infinitely differentiable, with no branch at zero
//! fibre velocity or at `u = a` (Thelen's (2003) curves, [`ThelenMuscle`](crate::drive::ThelenMuscle),
//! change slope there, which makes Newton-type solvers chatter).
//!
//! Relations (normalised fibre length `l̃ = lᴹ/l₀ᴹ`, normalised fibre
//! velocity `ṽ = vᴹ/(Vᴹ_max l₀ᴹ)`, activation `a`, excitation `u`), with
//! the paper's constants ([`ACTIVE_FORCE_LENGTH`], [`FORCE_VELOCITY`],
//! [`TENDON_FORCE_LENGTH`]):
//! * active force-length, three Gaussian-like terms:
//!   `f_L = Σᵢ b₁ᵢ exp(−½ (l̃ − b₂ᵢ)² / (b₃ᵢ + b₄ᵢ l̃)²)`;
//! * passive force-length `f_PE = (exp(kᴾᴱ (l̃ − 1)/ε₀ᴹ) − 1)/(exp(kᴾᴱ) − 1)`,
//!   `kᴾᴱ = 4`, `ε₀ᴹ = 0.6`, as published: zero at `l̃ = 1` and slightly
//!   negative below (at least `−1/(e⁴ − 1) ≈ −0.019`), with no cut-off;
//! * force-velocity `f_V = d₁ ln(d₂ṽ + d₃ + √((d₂ṽ + d₃)² + 1)) + d₄`
//!   (`d₁ asinh(d₂ṽ + d₃) + d₄`; its inverse is a `sinh`);
//! * tendon force-length `f_T = c₁ exp(k_T (l̃ᵀ − c₂)) − c₃`, `k_T = 35`
//!   (for a compliant tendon; the muscle here has a rigid tendon, so the
//!   curve is offered as [`tendon_force_length`] and its inverse);
//! * activation dynamics, the two time constants blended by `tanh`:
//!   `ȧ = [(½ + f)/(τ_act (½ + 1.5a)) + (½ − f)(½ + 1.5a)/τ_deact] (u − a)`,
//!   `f = ½ tanh(b (u − a))`, `τ_act = 15 ms`, `τ_deact = 60 ms`; the
//!   paper's smoothing `b = 0.1` ([`DeGrooteParameters::de_groote_2016`])
//!   leaves `f` within ±0.05, so activation and deactivation run at nearly
//!   the mean of the two rates; a larger `b` (Moco uses 10) restores the
//!   asymmetry at the cost of sharper curvature.
//!
//! The tension along the path is `T = F₀ᴹ cos α (a f_L f_V + f_PE)`: affine
//! in the activation (`∂T/∂a = F₀ᴹ cos α f_L f_V`), which is not clamped
//! (bounds on `a` belong to the caller; a clamp would be a kink). The
//! pennation follows the same constant-thickness geometry as the Thelen
//! muscle, `lᴹ = √((L − lₛᵀ)² + h²)`, `h = l₀ᴹ sin α₀`, and the same guard
//! holds a fibre shorter than `max(0.01 l₀ᴹ, h / sin α_max)` at that length
//! with zero velocity (a region far from any working fibre). A fibre
//! longer than [`MAX_NORMALIZED_FIBER_LENGTH`] optimal lengths is reported
//! as [`Error::OutOfRange`], as by the Thelen muscle.

use crate::drive::derivatives::{add_tension_derivatives, DriveDerivativeState, DriveDerivatives};
use crate::drive::geometry::PointGeometry;
use crate::drive::muscle::{
    checked_curve, MAX_NORMALIZED_FIBER_LENGTH, MIN_FIBER_LENGTH_FRACTION, MIN_PENNATION_COSINE,
};
use crate::drive::{read_input, DriveForces, DriveState, ForceElement, Path};
use crate::error::{DriveProblem, Error, Quantity, Result};
use crate::Scalar;

/// `(b₁ᵢ, b₂ᵢ, b₃ᵢ, b₄ᵢ)` of the three Gaussian-like terms of the active
/// force-length curve (De Groote et al. 2016, supplementary material).
pub const ACTIVE_FORCE_LENGTH: [[f64; 4]; 3] = [
    [0.815, 1.055, 0.162, 0.063],
    [0.433, 0.717, -0.030, 0.200],
    [0.100, 1.000, 0.354, 0.000],
];
/// `(d₁, d₂, d₃, d₄)` of the force-velocity curve (same source).
// d₁ = −0.318 is the paper's fitted constant, not −1/π.
#[allow(clippy::approx_constant)]
pub const FORCE_VELOCITY: [f64; 4] = [-0.318, -8.149, -0.374, 0.886];
/// `(c₁, c₂, c₃, k_T)` of the tendon force-length curve (same source).
pub const TENDON_FORCE_LENGTH: [f64; 4] = [0.200, 0.995, 0.250, 35.0];

/// The parameters of a De Groote (2016) muscle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeGrooteParameters<S> {
    /// `F₀ᴹ`, maximum isometric force (N).
    pub max_isometric_force: S,
    /// `l₀ᴹ`, optimal fibre length (m).
    pub optimal_fiber_length: S,
    /// `lₛᵀ`, tendon slack length (m).
    pub tendon_slack_length: S,
    /// `α₀`, pennation angle at optimal fibre length (rad).
    pub pennation_angle_at_optimal: S,
    /// `Vᴹ_max`, maximum contraction velocity (optimal fibre lengths per s).
    pub max_contraction_velocity: S,
    /// `τ_act`, activation time constant (s).
    pub activation_time_constant: S,
    /// `τ_deact`, deactivation time constant (s).
    pub deactivation_time_constant: S,
    /// `b`, the sharpness of the `tanh` blend of the two time constants.
    pub activation_smoothing: S,
    /// `kᴾᴱ`, exponential shape factor of the passive force-length curve.
    pub passive_shape_factor: S,
    /// `ε₀ᴹ`, passive fibre strain at which the passive force equals `F₀ᴹ`.
    pub passive_strain_at_one: S,
}

impl DeGrooteParameters<f64> {
    /// The paper's values (`Vᴹ_max = 10 l₀ᴹ/s`, `τ_act = 15 ms`,
    /// `τ_deact = 60 ms`, `b = 0.1`, `kᴾᴱ = 4`, `ε₀ᴹ = 0.6`) for a muscle
    /// of the given strength and geometry; `const`.
    #[must_use]
    pub const fn de_groote_2016(
        max_isometric_force: f64,
        optimal_fiber_length: f64,
        tendon_slack_length: f64,
        pennation_angle_at_optimal: f64,
    ) -> Self {
        Self {
            max_isometric_force,
            optimal_fiber_length,
            tendon_slack_length,
            pennation_angle_at_optimal,
            max_contraction_velocity: 10.0,
            activation_time_constant: 0.015,
            deactivation_time_constant: 0.060,
            activation_smoothing: 0.1,
            passive_shape_factor: 4.0,
            passive_strain_at_one: 0.6,
        }
    }
}

/// A Gaussian-like term `b₁ exp(−½ (l̃ − b₂)²/(b₃ + b₄ l̃)²)` and its slope.
fn gaussian_like<S: Scalar>(l: S, [b1, b2, b3, b4]: [f64; 4]) -> (S, S) {
    let c = S::from_f64;
    let width = c(b3) + c(b4) * l;
    let offset = l - c(b2);
    let value = c(b1) * (c(-0.5) * offset * offset / (width * width)).exp();
    // d/dl̃ of the exponent: −(l̃ − b₂)/w² + (l̃ − b₂)² b₄ / w³.
    let slope =
        value * (-offset / (width * width) + offset * offset * c(b4) / (width * width * width));
    (value, slope)
}

/// `asinh(x)`, odd-symmetric so that a large negative `x` does not cancel.
fn asinh<S: Scalar>(x: S) -> S {
    let magnitude = x.abs();
    let value = (magnitude + (magnitude * magnitude + S::ONE).sqrt()).ln();
    if x < S::ZERO {
        -value
    } else {
        value
    }
}

/// The tendon force-length curve `f_T(l̃ᵀ) = c₁ exp(k_T (l̃ᵀ − c₂)) − c₃`
/// (normalised tendon length `l̃ᵀ = lᵀ/lₛᵀ`) and its slope.
///
/// # Errors
/// [`Error::NonFinite`] with [`Quantity::MuscleCurve`] (argument 0) for a
/// non-finite `l̃ᵀ`; [`Error::NonFiniteResult`] when the exponential
/// overflows (a tendon stretched to a few times its slack length).
pub fn tendon_force_length<S: Scalar>(normalized_tendon_length: S) -> Result<(S, S)> {
    let (f, slope) = tendon_force_length_unchecked(normalized_tendon_length);
    let [f, slope] = checked_curve([normalized_tendon_length], [f, slope], || Ok(()))?;
    Ok((f, slope))
}

/// [`tendon_force_length`] without its checks.
fn tendon_force_length_unchecked<S: Scalar>(normalized_tendon_length: S) -> (S, S) {
    let [c1, c2, c3, k] = TENDON_FORCE_LENGTH.map(S::from_f64);
    let e = c1 * (k * (normalized_tendon_length - c2)).exp();
    (e - c3, k * e)
}

/// The inverse of [`tendon_force_length`]: the normalised tendon length
/// at normalised tendon force `f_T`.
///
/// # Errors
/// [`Error::NonFinite`] with [`Quantity::MuscleCurve`] (argument 0) for a
/// non-finite `f_T`; [`Error::OutOfRange`] (argument 0) for `f_T ≤ −c₃`,
/// a force the curve never reaches.
pub fn tendon_length_from_force<S: Scalar>(normalized_tendon_force: S) -> Result<S> {
    let [c1, c2, c3, k] = TENDON_FORCE_LENGTH.map(S::from_f64);
    let length = ((normalized_tendon_force + c3) / c1).ln() / k + c2;
    match checked_curve([normalized_tendon_force], [length], || Ok(())) {
        Ok([length]) => Ok(length),
        Err(Error::NonFiniteResult { .. }) => Err(Error::OutOfRange {
            quantity: Quantity::MuscleCurve,
            index: 0,
        }),
        Err(e) => Err(e),
    }
}

impl<S: Scalar> DeGrooteParameters<S> {
    /// [`de_groote_2016`](DeGrooteParameters::<f64>::de_groote_2016) for
    /// any scalar type (e.g. [`Dual`](crate::Dual)).
    #[must_use]
    pub fn de_groote_2016_in(
        max_isometric_force: S,
        optimal_fiber_length: S,
        tendon_slack_length: S,
        pennation_angle_at_optimal: S,
    ) -> Self {
        let d = DeGrooteParameters::<f64>::de_groote_2016(0.0, 0.0, 0.0, 0.0);
        let c = S::from_f64;
        Self {
            max_isometric_force,
            optimal_fiber_length,
            tendon_slack_length,
            pennation_angle_at_optimal,
            max_contraction_velocity: c(d.max_contraction_velocity),
            activation_time_constant: c(d.activation_time_constant),
            deactivation_time_constant: c(d.deactivation_time_constant),
            activation_smoothing: c(d.activation_smoothing),
            passive_shape_factor: c(d.passive_shape_factor),
            passive_strain_at_one: c(d.passive_strain_at_one),
        }
    }

    /// The same parameters in another scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> DeGrooteParameters<T> {
        let c = |x: S| T::from_f64(x.to_f64());
        DeGrooteParameters {
            max_isometric_force: c(self.max_isometric_force),
            optimal_fiber_length: c(self.optimal_fiber_length),
            tendon_slack_length: c(self.tendon_slack_length),
            pennation_angle_at_optimal: c(self.pennation_angle_at_optimal),
            max_contraction_velocity: c(self.max_contraction_velocity),
            activation_time_constant: c(self.activation_time_constant),
            deactivation_time_constant: c(self.deactivation_time_constant),
            activation_smoothing: c(self.activation_smoothing),
            passive_shape_factor: c(self.passive_shape_factor),
            passive_strain_at_one: c(self.passive_strain_at_one),
        }
    }

    /// Active force-length multiplier `f_L(l̃)` and its slope `df_L/dl̃`
    /// at the normalised fibre length `l̃`.
    ///
    /// # Errors
    /// The error of [`validate`](Self::validate) for a bad parameter;
    /// [`Error::NonFinite`] with [`Quantity::MuscleCurve`] (argument 0) for
    /// a non-finite `l̃`; [`Error::NonFiniteResult`] when a value
    /// overflows.
    pub fn active_force_length(&self, normalized_length: S) -> Result<(S, S)> {
        let (f, slope) = self.active_force_length_unchecked(normalized_length);
        let [f, slope] = self.checked_curve([normalized_length], [f, slope])?;
        Ok((f, slope))
    }

    /// A curve's `values` at `arguments`, checked as
    /// [`active_force_length`](Self::active_force_length) says.
    fn checked_curve<const A: usize, const N: usize>(
        &self,
        arguments: [S; A],
        values: [S; N],
    ) -> Result<[S; N]> {
        checked_curve(arguments, values, || self.validate())
    }

    /// [`active_force_length`](Self::active_force_length) without its
    /// checks, for the force computation (which checks its tension).
    pub(crate) fn active_force_length_unchecked(&self, normalized_length: S) -> (S, S) {
        ACTIVE_FORCE_LENGTH
            .iter()
            .fold((S::ZERO, S::ZERO), |(f, df), &b| {
                let (g, dg) = gaussian_like(normalized_length, b);
                (f + g, df + dg)
            })
    }

    /// Passive force-length multiplier `f_PE(l̃)` and its slope.
    ///
    /// # Errors
    /// As [`active_force_length`](Self::active_force_length); `l̃` a little
    /// past one is enough to overflow the scalar type.
    pub fn passive_force_length(&self, normalized_length: S) -> Result<(S, S)> {
        let (f, slope) = self.passive_force_length_unchecked(normalized_length);
        let [f, slope] = self.checked_curve([normalized_length], [f, slope])?;
        Ok((f, slope))
    }

    /// [`passive_force_length`](Self::passive_force_length) without its checks.
    pub(crate) fn passive_force_length_unchecked(&self, normalized_length: S) -> (S, S) {
        let k = self.passive_shape_factor;
        let strain = self.passive_strain_at_one;
        let scale = S::ONE / (k.exp() - S::ONE);
        let e = (k * (normalized_length - S::ONE) / strain).exp();
        ((e - S::ONE) * scale, k / strain * e * scale)
    }

    /// Force-velocity multiplier `f_V(ṽ)` and its slope `df_V/dṽ`
    /// (`ṽ` negative while shortening).
    ///
    /// # Errors
    /// As [`active_force_length`](Self::active_force_length), for `ṽ`.
    pub fn force_velocity(&self, normalized_velocity: S) -> Result<(S, S)> {
        let (f, slope) = self.force_velocity_unchecked(normalized_velocity);
        let [f, slope] = self.checked_curve([normalized_velocity], [f, slope])?;
        Ok((f, slope))
    }

    /// [`force_velocity`](Self::force_velocity) without its checks.
    pub(crate) fn force_velocity_unchecked(&self, normalized_velocity: S) -> (S, S) {
        let [d1, d2, d3, d4] = FORCE_VELOCITY.map(S::from_f64);
        let x = d2 * normalized_velocity + d3;
        (d1 * asinh(x) + d4, d1 * d2 / (x * x + S::ONE).sqrt())
    }

    /// The inverse of [`force_velocity`](Self::force_velocity): the
    /// normalised fibre velocity at force-velocity multiplier `f_V`.
    ///
    /// # Errors
    /// As [`active_force_length`](Self::active_force_length), for `f_V`
    /// (the velocity overflows for an `f_V` far outside the curve's range).
    pub fn velocity_from_force_multiplier(&self, force_velocity: S) -> Result<S> {
        let [d1, d2, d3, d4] = FORCE_VELOCITY.map(S::from_f64);
        let y = (force_velocity - d4) / d1;
        // sinh y = (eʸ − e⁻ʸ)/2.
        let sinh = (y.exp() - (-y).exp()) * S::from_f64(0.5);
        let [v] = self.checked_curve([force_velocity], [(sinh - d3) / d2])?;
        Ok(v)
    }

    /// Activation rate `ȧ` (1/s) at excitation `u` and activation `a`, and
    /// its partial derivatives `∂ȧ/∂u`, `∂ȧ/∂a` (neither input clamped).
    ///
    /// # Errors
    /// The error of [`validate`](Self::validate) for a bad parameter;
    /// [`Error::NonFinite`] with [`Quantity::MuscleCurve`] naming `u`
    /// (argument 0) or `a` (argument 1); [`Error::NonFiniteResult`] naming
    /// the rate (0) or a partial (1, 2) when one overflows.
    pub fn activation_rate_partials(&self, excitation: S, activation: S) -> Result<(S, S, S)> {
        let (rate, d_du, d_da) = self.activation_rate_partials_unchecked(excitation, activation);
        let [rate, d_du, d_da] =
            self.checked_curve([excitation, activation], [rate, d_du, d_da])?;
        Ok((rate, d_du, d_da))
    }

    /// [`activation_rate_partials`](Self::activation_rate_partials) without
    /// its checks.
    fn activation_rate_partials_unchecked(&self, excitation: S, activation: S) -> (S, S, S) {
        let c = S::from_f64;
        let gap = excitation - activation;
        let t = (self.activation_smoothing * gap).tanh();
        let f = c(0.5) * t;
        // df/d(gap) = ½ b (1 − tanh²).
        let df = c(0.5) * self.activation_smoothing * (S::ONE - t * t);
        let shape = c(0.5) + c(1.5) * activation;
        let rising = S::ONE / (self.activation_time_constant * shape);
        let falling = shape / self.deactivation_time_constant;
        let (d_rising, d_falling) = (
            -c(1.5) * rising / shape,
            c(1.5) / self.deactivation_time_constant,
        );
        let rate_per_gap = (c(0.5) + f) * rising + (c(0.5) - f) * falling;
        // ∂(rate per gap)/∂gap at fixed shape, and ∂/∂a through the shape.
        let blend = df * (rising - falling);
        let through_shape = (c(0.5) + f) * d_rising + (c(0.5) - f) * d_falling;
        let d_du = rate_per_gap + blend * gap;
        let d_da = -rate_per_gap - blend * gap + through_shape * gap;
        (rate_per_gap * gap, d_du, d_da)
    }

    /// Activation rate `ȧ` (1/s) at excitation `u` and activation `a`.
    ///
    /// # Errors
    /// As [`activation_rate_partials`](Self::activation_rate_partials).
    pub fn activation_rate(&self, excitation: S, activation: S) -> Result<S> {
        let rate = self
            .activation_rate_partials_unchecked(excitation, activation)
            .0;
        let [rate] = self.checked_curve([excitation, activation], [rate])?;
        Ok(rate)
    }

    /// Checks every parameter: finite; forces, the tendon slack length,
    /// the pennation angle and the smoothing not negative; the pennation
    /// below a right angle; lengths, speeds, time constants and shape
    /// factors positive.
    ///
    /// # Errors
    /// [`Error::InvalidDrive`] with [`DriveProblem::MuscleParameter`]
    /// whose `index` counts this struct's fields in order (0: maximum
    /// isometric force … 9: passive strain at one).
    pub fn validate(&self) -> Result<()> {
        let f = |x: S| x.to_f64();
        let fields = [
            (f(self.max_isometric_force), false),
            (f(self.optimal_fiber_length), true),
            (f(self.tendon_slack_length), false),
            (f(self.pennation_angle_at_optimal), false),
            (f(self.max_contraction_velocity), true),
            (f(self.activation_time_constant), true),
            (f(self.deactivation_time_constant), true),
            (f(self.activation_smoothing), false),
            (f(self.passive_shape_factor), true),
            (f(self.passive_strain_at_one), true),
        ];
        let bad = fields
            .iter()
            .position(|&(x, strict)| !x.is_finite() || x < 0.0 || (strict && x == 0.0));
        let right_angle = f(self.pennation_angle_at_optimal) >= core::f64::consts::FRAC_PI_2;
        match bad.or(right_angle.then_some(3)) {
            Some(index) => Err(Error::InvalidDrive {
                problem: DriveProblem::MuscleParameter { index },
            }),
            None => Ok(()),
        }
    }
}

/// The state of a De Groote muscle's fibre at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeGrooteState<S> {
    /// Fibre length `lᴹ` (m).
    pub fiber_length: S,
    /// Fibre velocity `vᴹ` (m/s), negative while shortening.
    pub fiber_velocity: S,
    /// `cos α`, the pennation cosine.
    pub cos_pennation: S,
    /// Active force-length multiplier `f_L`.
    pub active_force_length: S,
    /// Passive force-length multiplier `f_PE`.
    pub passive_force_length: S,
    /// Force-velocity multiplier `f_V`.
    pub force_velocity: S,
    /// Tension along the path, `Fᴹ cos α` (N).
    pub tension: S,
    /// `∂T/∂a` at fixed path length and velocity (N).
    pub tension_per_activation: S,
    /// `∂T/∂L` at fixed activation (N/m).
    pub tension_per_length: S,
    /// `∂T/∂L̇` at fixed activation (N s/m).
    pub tension_per_velocity: S,
}

/// A De Groote (2016) muscle with a rigid tendon along a path.
#[derive(Clone, Copy, Debug)]
pub struct DeGrooteMuscle<S: Scalar, G: PointGeometry, const K: usize> {
    /// The muscle-tendon path from origin to insertion.
    pub path: Path<S, G, K>,
    /// The muscle's parameters.
    pub params: DeGrooteParameters<S>,
    /// The entry of the drive-input vector `w` holding its activation.
    pub input: usize,
}

impl<S: Scalar, G: PointGeometry, const K: usize> DeGrooteMuscle<S, G, K> {
    /// A muscle along `path` reading its activation from `w[input]`.
    #[must_use]
    pub const fn new(path: Path<S, G, K>, params: DeGrooteParameters<S>, input: usize) -> Self {
        Self {
            path,
            params,
            input,
        }
    }

    /// Activation rate `ȧ` for excitation `u` ([`DeGrooteParameters::activation_rate`]).
    ///
    /// # Errors
    /// As [`DeGrooteParameters::activation_rate`].
    pub fn activation_rate(&self, excitation: S, activation: S) -> Result<S> {
        self.params.activation_rate(excitation, activation)
    }

    /// The same muscle in another scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> DeGrooteMuscle<T, G, K> {
        DeGrooteMuscle {
            path: self.path.cast(),
            params: self.params.cast(),
            input: self.input,
        }
    }

    /// Fibre state, tension and its partials for a path of length `L` (m)
    /// lengthening at `L̇` (m/s), at activation `a`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] naming a non-finite `L`
    /// ([`Quantity::PathLength`]), `L̇` ([`Quantity::PathVelocity`]) or `a`
    /// ([`Quantity::DriveInput`]); [`Error::OutOfRange`] with
    /// [`Quantity::PathLength`] for a fibre longer than
    /// [`MAX_NORMALIZED_FIBER_LENGTH`] optimal lengths;
    /// [`Error::NonFiniteResult`] with [`Quantity::ExternalForce`] for a
    /// tension that comes out non-finite (see
    /// [`DeGrooteParameters::validate`]). Each names the muscle by its
    /// input index.
    pub fn state(
        &self,
        length: S,
        lengthening_velocity: S,
        activation: S,
    ) -> Result<DeGrooteState<S>> {
        let named = |quantity, ok: bool| {
            if ok {
                Ok(())
            } else {
                Err(Error::NonFinite {
                    quantity,
                    index: self.input,
                })
            }
        };
        named(Quantity::PathLength, length.is_finite())?;
        named(Quantity::PathVelocity, lengthening_velocity.is_finite())?;
        named(Quantity::DriveInput, activation.is_finite())?;
        let state = self.state_unvalidated(length, lengthening_velocity, activation);
        self.check_output(&state)?;
        Ok(state)
    }

    /// [`state`](Self::state) without the checks.
    fn state_unvalidated(&self, length: S, lengthening_velocity: S, a: S) -> DeGrooteState<S> {
        let p = &self.params;
        let l_opt = p.optimal_fiber_length;
        let v_scale = p.max_contraction_velocity * l_opt;
        // Constant-thickness pennation, as the Thelen muscle.
        let height = l_opt * p.pennation_angle_at_optimal.sin();
        let cos_max = S::from_f64(MIN_PENNATION_COSINE);
        let sin_max = (S::ONE - cos_max * cos_max).sqrt();
        let min_length = (S::from_f64(MIN_FIBER_LENGTH_FRACTION) * l_opt).max(height / sin_max);
        let min_projection = (min_length * min_length - height * height)
            .max(S::ZERO)
            .sqrt();
        let projection = length - p.tendon_slack_length;
        // (l, cos α, v, ∂l/∂L, ∂cos α/∂L, ∂v/∂L, ∂v/∂L̇); tested this way
        // round so that a NaN length gives a NaN force.
        let (l, cos, v, dl, dcos, dv_dl, dv_dv) = if projection <= min_projection {
            let zero = S::ZERO;
            (
                min_length,
                min_projection / min_length,
                zero,
                zero,
                zero,
                zero,
                zero,
            )
        } else {
            let l = (projection * projection + height * height).sqrt();
            let cos = projection / l;
            let dcos = height * height / (l * l * l);
            let v = lengthening_velocity * cos;
            (l, cos, v, cos, dcos, lengthening_velocity * dcos, cos)
        };
        let (l_norm, v_norm) = (l / l_opt, v / v_scale);
        let (f_l, df_l) = p.active_force_length_unchecked(l_norm);
        let (f_pe, df_pe) = p.passive_force_length_unchecked(l_norm);
        let (f_v, df_v) = p.force_velocity_unchecked(v_norm);
        let f0 = p.max_isometric_force;
        let fiber = a * f_l * f_v + f_pe;
        let dfiber_dl = (a * df_l * f_v + df_pe) * dl / l_opt + a * f_l * df_v * dv_dl / v_scale;
        DeGrooteState {
            fiber_length: l,
            fiber_velocity: v,
            cos_pennation: cos,
            active_force_length: f_l,
            passive_force_length: f_pe,
            force_velocity: f_v,
            tension: f0 * cos * fiber,
            tension_per_activation: f0 * cos * f_l * f_v,
            tension_per_length: f0 * (dcos * fiber + cos * dfiber_dl),
            tension_per_velocity: f0 * cos * a * f_l * df_v * dv_dv / v_scale,
        }
    }

    /// A fibre within [`MAX_NORMALIZED_FIBER_LENGTH`] and a finite tension
    /// and partials; the errors name the muscle's input.
    fn check_output(&self, s: &DeGrooteState<S>) -> Result<()> {
        let l_opt = self.params.optimal_fiber_length;
        if l_opt > S::ZERO && s.fiber_length > S::from_f64(MAX_NORMALIZED_FIBER_LENGTH) * l_opt {
            return Err(Error::OutOfRange {
                quantity: Quantity::PathLength,
                index: self.input,
            });
        }
        let values = [
            s.tension,
            s.tension_per_activation,
            s.tension_per_length,
            s.tension_per_velocity,
        ];
        if values.iter().all(|x| x.is_finite()) {
            Ok(())
        } else {
            Err(Error::NonFiniteResult {
                quantity: Quantity::ExternalForce,
                index: self.input,
            })
        }
    }

    /// The muscle's activation `w[input]`, which must be finite.
    fn activation(&self, w: &[S]) -> Result<S> {
        let activation = read_input(w, self.input)?;
        if activation.is_finite() {
            Ok(activation)
        } else {
            Err(Error::NonFinite {
                quantity: Quantity::DriveInput,
                index: self.input,
            })
        }
    }
}

impl<S: Scalar, G: PointGeometry, const K: usize, const NB: usize, const NV: usize>
    ForceElement<S, G, NB, NV> for DeGrooteMuscle<S, G, K>
{
    fn add_forces(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        let activation = self.activation(w)?;
        let kin = self.path.kinematics_in_element(state.data)?;
        let muscle = self.state_unvalidated(kin.length, kin.lengthening_velocity, activation);
        self.check_output(&muscle)?;
        self.path
            .add_tension_in_element(&kin, muscle.tension, state.data, &mut out.f_ext)
    }
    fn add_input_derivative(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        w: &[S],
        input: usize,
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        let activation = self.activation(w)?;
        if input != self.input {
            return Ok(());
        }
        let kin = self.path.kinematics_in_element(state.data)?;
        let muscle = self.state_unvalidated(kin.length, kin.lengthening_velocity, activation);
        self.check_output(&muscle)?;
        self.path.add_tension_in_element(
            &kin,
            muscle.tension_per_activation,
            state.data,
            &mut out.f_ext,
        )
    }
    fn add_state_derivatives(
        &self,
        state: &DriveDerivativeState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveDerivatives<S, NV>,
    ) -> Result<()> {
        let activation = self.activation(w)?;
        let path = self.path.length_derivatives(state)?;
        let muscle = self.state_unvalidated(path.length, path.lengthening_velocity, activation);
        self.check_output(&muscle)?;
        let partials = (
            muscle.tension,
            muscle.tension_per_length,
            muscle.tension_per_velocity,
        );
        add_tension_derivatives(&path, state.v, partials, out);
        Ok(())
    }
}
