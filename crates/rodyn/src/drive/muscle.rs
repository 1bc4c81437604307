//! A Hill-type muscle after Thelen (2003), with a rigid tendon.
//!
//! D. G. Thelen, "Adjustment of muscle mechanics model parameters to
//! simulate dynamic contractions in older adults", *J. Biomech. Eng.* 125
//! (2003) 70–77. Symbols and default values are the paper's (young adults):
//!
//! | symbol   | field                          | default      | meaning                               |
//! |----------|--------------------------------|--------------|---------------------------------------|
//! | `F₀ᴹ`    | `max_isometric_force`          |              | maximum isometric force (N)           |
//! | `l₀ᴹ`    | `optimal_fiber_length`         |              | optimal fibre length (m)              |
//! | `lₛᵀ`    | `tendon_slack_length`          |              | tendon slack length (m)               |
//! | `α₀`     | `pennation_angle_at_optimal`   | 0            | pennation at `l₀ᴹ` (rad)              |
//! | `Vᴹ_max` | `max_contraction_velocity`     | 10           | in optimal fibre lengths per second   |
//! | `τ_act`  | `activation_time_constant`     | 0.015 s      |                                       |
//! | `τ_deact`| `deactivation_time_constant`   | 0.050 s      |                                       |
//! | `kᴾᴱ`    | `passive_shape_factor`         | 4            | exponential shape of passive force    |
//! | `ε₀ᴹ`    | `passive_strain_at_one`        | 0.6          | fibre strain where passive force = F₀ |
//! | `γ`      | `active_shape_factor`          | 0.45         | width of the active force-length curve|
//! | `A_f`    | `force_velocity_shape`         | 0.25         | curvature of the force-velocity curve |
//! | `F̃ᴹ_len` | `max_lengthening_force`        | 1.4          | normalised force at fast lengthening  |
//!
//! Relations (normalised length `l̃ = lᴹ/l₀ᴹ`, activation `a`):
//! * activation dynamics `ȧ = (u - a)/τ(a, u)` with
//!   `τ = τ_act (0.5 + 1.5 a)` when `u > a`, `τ_deact / (0.5 + 1.5 a)` otherwise;
//! * active force-length `f_L = exp(-(l̃ - 1)²/γ)`;
//! * passive force-length `f_PE = (exp(kᴾᴱ (l̃ - 1)/ε₀ᴹ) - 1)/(exp(kᴾᴱ) - 1)`
//!   for `l̃ > 1`, zero below (a passive element does not push);
//! * force-velocity: Thelen writes it as fibre velocity from force,
//!   `vᴹ = (0.25 + 0.75 a) Vᴹ_max (Fᴹ - a f_L)/b`. With a rigid tendon the
//!   fibre velocity is known, so rodyn uses the exact inverse: with
//!   `ṽ = vᴹ / ((0.25 + 0.75 a) Vᴹ_max l₀ᴹ)`, `Fᴹ = F₀ᴹ (a f_L f_V(ṽ) + f_PE)` and
//!   `f_V = (1 + ṽ)/(1 - ṽ/A_f)` while shortening (`ṽ ≤ 0`),
//!   `f_V = (F̃_len - 1 + β ṽ F̃_len)/(F̃_len - 1 + β ṽ)`, `β = 2 + 2/A_f`,
//!   while lengthening.
//!
//! **Rigid tendon and pennation** (constant-thickness fibres, as OpenSim's
//! `Thelen2003Muscle`): the fibre's height `h = l₀ᴹ sin α₀` is constant, the
//! fibre's projection on the tendon is `w = L - lₛᵀ`, so
//! `lᴹ = √(w² + h²)`, `cos α = w / lᴹ`, `vᴹ = L̇ cos α`, and the tendon (path)
//! tension is `T = Fᴹ cos α`.
//!
//! **Guards for the singular regions**, following OpenSim's Thelen model:
//! * fibre length near zero and pennation near 90°: the fibre is never
//!   shorter than `lᴹ_min = max(0.01 l₀ᴹ, h / sin α_max)` with
//!   `cos α_max = 0.1` ([`MIN_PENNATION_COSINE`]); a path so short that the
//!   fibre would be shorter holds the fibre at `lᴹ_min` with zero velocity;
//! * extreme shortening: at `ṽ ≤ -1` (faster than the maximum contraction
//!   velocity) the fibre produces no active force (`f_V = 0`) instead of
//!   the negative force of the hyperbola, and the lengthening branch is
//!   bounded by `F̃_len`;
//! * activation is clamped to `[0, 1]` where it enters the force.
//!
//! **Range.** The curves were fitted near the optimal length; past it the
//! passive force grows as `exp(kᴾᴱ l̃/ε₀ᴹ)` (15 `F₀ᴹ` at `l̃ = 2` with
//! Thelen's shape, 4e236 N for a 10 m path). A fibre longer than
//! [`MAX_NORMALIZED_FIBER_LENGTH`] `l₀ᴹ` is reported
//! ([`Error::OutOfRange`] naming the path length) instead of such a
//! force, as are a non-finite length, velocity or activation and a
//! tension that comes out non-finite.

use crate::drive::derivatives::{add_tension_derivatives, DriveDerivativeState, DriveDerivatives};
use crate::drive::geometry::PointGeometry;
use crate::drive::path::PathKinematics;
use crate::drive::{read_input, DriveForces, DriveState, ForceElement, Path};
use crate::error::{DriveProblem, Error, Quantity, Result};
use crate::model::{check_finite, check_result};
use crate::Scalar;

/// Cosine of the largest pennation angle (about 84.3°), as OpenSim's default.
pub const MIN_PENNATION_COSINE: f64 = 0.1;
/// Shortest fibre, as a fraction of the optimal fibre length.
pub const MIN_FIBER_LENGTH_FRACTION: f64 = 0.01;
/// Longest fibre the force law is evaluated at, in optimal fibre lengths
/// (`l̃`): beyond it the passive force is an extrapolation growing
/// exponentially (15 `F₀ᴹ` at 2 with Thelen's shape), so a longer fibre is
/// an error rather than a force.
pub const MAX_NORMALIZED_FIBER_LENGTH: f64 = 2.0;

/// The parameters of a Thelen (2003) muscle; see the [module](crate::drive::muscle) table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThelenParameters<S> {
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
    /// `kᴾᴱ`, exponential shape factor of the passive force-length curve.
    pub passive_shape_factor: S,
    /// `ε₀ᴹ`, passive fibre strain at which the passive force equals `F₀ᴹ`.
    pub passive_strain_at_one: S,
    /// `γ`, shape factor (width) of the active force-length curve.
    pub active_shape_factor: S,
    /// `A_f`, force-velocity shape factor.
    pub force_velocity_shape: S,
    /// `F̃ᴹ_len`, normalised maximum force while lengthening.
    pub max_lengthening_force: S,
}

macro_rules! thelen_defaults {
    ($t:ty) => {
        impl ThelenParameters<$t> {
            /// Thelen's (2003) young-adult parameters for a muscle of the
            /// given strength and geometry; `const`.
            #[must_use]
            pub const fn thelen_2003(
                max_isometric_force: $t,
                optimal_fiber_length: $t,
                tendon_slack_length: $t,
                pennation_angle_at_optimal: $t,
            ) -> Self {
                Self {
                    max_isometric_force,
                    optimal_fiber_length,
                    tendon_slack_length,
                    pennation_angle_at_optimal,
                    max_contraction_velocity: 10.0,
                    activation_time_constant: 0.015,
                    deactivation_time_constant: 0.050,
                    passive_shape_factor: 4.0,
                    passive_strain_at_one: 0.6,
                    active_shape_factor: 0.45,
                    force_velocity_shape: 0.25,
                    max_lengthening_force: 1.4,
                }
            }
        }
    };
}
thelen_defaults!(f32);
thelen_defaults!(f64);

impl<S: Scalar> ThelenParameters<S> {
    /// [`thelen_2003`](ThelenParameters::<f64>::thelen_2003) for any scalar
    /// type (e.g. [`Dual`](crate::Dual)).
    #[must_use]
    pub fn thelen_2003_in(
        max_isometric_force: S,
        optimal_fiber_length: S,
        tendon_slack_length: S,
        pennation_angle_at_optimal: S,
    ) -> Self {
        ThelenParameters::<f64>::thelen_2003(0.0, 0.0, 0.0, 0.0).cast_with(
            max_isometric_force,
            optimal_fiber_length,
            tendon_slack_length,
            pennation_angle_at_optimal,
        )
    }
    /// The same parameters in another scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> ThelenParameters<T> {
        let c = |x: S| T::from_f64(x.to_f64());
        self.cast_with(
            c(self.max_isometric_force),
            c(self.optimal_fiber_length),
            c(self.tendon_slack_length),
            c(self.pennation_angle_at_optimal),
        )
    }
    /// Converts the shape parameters and takes the four muscle-specific ones.
    fn cast_with<T: Scalar>(&self, f0: T, l0: T, lts: T, alpha0: T) -> ThelenParameters<T> {
        let c = |x: S| T::from_f64(x.to_f64());
        ThelenParameters {
            max_isometric_force: f0,
            optimal_fiber_length: l0,
            tendon_slack_length: lts,
            pennation_angle_at_optimal: alpha0,
            max_contraction_velocity: c(self.max_contraction_velocity),
            activation_time_constant: c(self.activation_time_constant),
            deactivation_time_constant: c(self.deactivation_time_constant),
            passive_shape_factor: c(self.passive_shape_factor),
            passive_strain_at_one: c(self.passive_strain_at_one),
            active_shape_factor: c(self.active_shape_factor),
            force_velocity_shape: c(self.force_velocity_shape),
            max_lengthening_force: c(self.max_lengthening_force),
        }
    }

    /// Active force-length multiplier `f_L(l̃)` at the normalised fibre
    /// length `l̃`.
    ///
    /// # Errors
    /// The error of [`validate`](Self::validate) for a bad parameter;
    /// [`Error::NonFinite`] with [`Quantity::MuscleCurve`] (argument 0) for
    /// a non-finite `l̃`; [`Error::NonFiniteResult`] when the value
    /// overflows.
    pub fn active_force_length(&self, normalized_length: S) -> Result<S> {
        let [f] = self.checked_curve(
            [normalized_length],
            [self.active_force_length_unchecked(normalized_length)],
        )?;
        Ok(f)
    }

    /// [`active_force_length`](Self::active_force_length) without its
    /// checks, for the force computation (which checks its tension).
    pub(crate) fn active_force_length_unchecked(&self, normalized_length: S) -> S {
        (-(normalized_length - S::ONE).squared() / self.active_shape_factor).exp()
    }

    /// Passive force-length multiplier `f_PE(l̃)`, zero for `l̃ ≤ 1`.
    ///
    /// # Errors
    /// As [`active_force_length`](Self::active_force_length); `l̃` a little
    /// past one is enough to overflow the scalar type.
    pub fn passive_force_length(&self, normalized_length: S) -> Result<S> {
        let [f] = self.checked_curve(
            [normalized_length],
            [self.passive_force_length_unchecked(normalized_length)],
        )?;
        Ok(f)
    }

    /// [`passive_force_length`](Self::passive_force_length) without its checks.
    pub(crate) fn passive_force_length_unchecked(&self, normalized_length: S) -> S {
        if normalized_length <= S::ONE {
            return S::ZERO;
        }
        let k = self.passive_shape_factor;
        ((k * (normalized_length - S::ONE) / self.passive_strain_at_one).exp() - S::ONE)
            / (k.exp() - S::ONE)
    }

    /// Force-velocity multiplier `f_V(ṽ)` and its slope `df_V/dṽ`, for the
    /// normalised fibre velocity `ṽ` (negative while shortening).
    ///
    /// # Errors
    /// As [`active_force_length`](Self::active_force_length), for `ṽ`.
    pub fn force_velocity(&self, normalized_velocity: S) -> Result<(S, S)> {
        let (f, slope) = self.force_velocity_unchecked(normalized_velocity);
        let [f, slope] = self.checked_curve([normalized_velocity], [f, slope])?;
        Ok((f, slope))
    }

    /// A curve's `values` at `arguments`, checked: the parameters
    /// ([`validate`](Self::validate)), the arguments finite
    /// ([`Error::NonFinite`]), then the values ([`Error::NonFiniteResult`]).
    fn checked_curve<const A: usize, const N: usize>(
        &self,
        arguments: [S; A],
        values: [S; N],
    ) -> Result<[S; N]> {
        checked_curve(arguments, values, || self.validate())
    }

    /// [`force_velocity`](Self::force_velocity) without its checks.
    pub(crate) fn force_velocity_unchecked(&self, normalized_velocity: S) -> (S, S) {
        let v = normalized_velocity;
        let af = self.force_velocity_shape;
        if v <= -S::ONE {
            (S::ZERO, S::ZERO)
        } else if v <= S::ZERO {
            let den = S::ONE - v / af;
            ((S::ONE + v) / den, (S::ONE + S::ONE / af) / (den * den))
        } else {
            let f_len = self.max_lengthening_force;
            let beta = S::from_f64(2.0) + S::from_f64(2.0) / af;
            let a0 = f_len - S::ONE;
            let den = a0 + beta * v;
            ((a0 + beta * v * f_len) / den, beta * a0 * a0 / (den * den))
        }
    }

    /// Checks every parameter: finite, and in its physical range (forces,
    /// the tendon slack length and the pennation angle not negative, the
    /// pennation below a right angle, the other lengths, speeds, time
    /// constants and shape factors positive, the lengthening force above
    /// the isometric one). Call it after changing parameters at run time:
    /// the force computation itself only reports a tension that comes out
    /// non-finite.
    ///
    /// # Errors
    /// [`Error::InvalidDrive`] with [`DriveProblem::MuscleParameter`]
    /// naming the first bad field.
    pub fn validate(&self) -> Result<()> {
        let f = |x: S| x.to_f64();
        let fields = [
            (f(self.max_isometric_force), 0.0, false),
            (f(self.optimal_fiber_length), 0.0, true),
            (f(self.tendon_slack_length), 0.0, false),
            (f(self.pennation_angle_at_optimal), 0.0, false),
            (f(self.max_contraction_velocity), 0.0, true),
            (f(self.activation_time_constant), 0.0, true),
            (f(self.deactivation_time_constant), 0.0, true),
            (f(self.passive_shape_factor), 0.0, true),
            (f(self.passive_strain_at_one), 0.0, true),
            (f(self.active_shape_factor), 0.0, true),
            (f(self.force_velocity_shape), 0.0, true),
            (f(self.max_lengthening_force), 1.0, true),
        ];
        let bad = fields
            .iter()
            .position(|&(x, low, strict)| !x.is_finite() || x < low || (strict && x == low));
        let right_angle = f(self.pennation_angle_at_optimal) >= core::f64::consts::FRAC_PI_2;
        match bad.or(right_angle.then_some(3)) {
            Some(index) => Err(Error::InvalidDrive {
                problem: DriveProblem::MuscleParameter { index },
            }),
            None => Ok(()),
        }
    }

    /// Activation rate `ȧ` (1/s) for excitation `u` and activation `a`
    /// (both clamped to `[0, 1]` in the time constant's shape).
    ///
    /// # Errors
    /// The error of [`validate`](Self::validate) for a bad parameter;
    /// [`Error::NonFinite`] with [`Quantity::MuscleCurve`] naming `u`
    /// (argument 0) or `a` (argument 1); [`Error::NonFiniteResult`] when
    /// the rate overflows.
    pub fn activation_rate(&self, excitation: S, activation: S) -> Result<S> {
        let [rate] = self.checked_curve(
            [excitation, activation],
            [self.activation_rate_unchecked(excitation, activation)],
        )?;
        Ok(rate)
    }

    /// [`activation_rate`](Self::activation_rate) without its checks.
    pub(crate) fn activation_rate_unchecked(&self, excitation: S, activation: S) -> S {
        let u = excitation.max(S::ZERO).min(S::ONE);
        let a = activation.max(S::ZERO).min(S::ONE);
        let shape = S::from_f64(0.5) + S::from_f64(1.5) * a;
        let tau = if u > a {
            self.activation_time_constant * shape
        } else {
            self.deactivation_time_constant / shape
        };
        (u - activation) / tau
    }
}

/// A muscle curve's `values` at `arguments`, as its checked public form
/// returns them: the error of `parameters` (the parameters' own check),
/// then [`Error::NonFinite`] naming the first non-finite argument, then
/// [`Error::NonFiniteResult`] naming the first non-finite value (0) or
/// slope (1, 2).
pub(crate) fn checked_curve<S: Scalar, const A: usize, const N: usize>(
    arguments: [S; A],
    values: [S; N],
    parameters: impl FnOnce() -> Result<()>,
) -> Result<[S; N]> {
    parameters()?;
    check_finite(&arguments, Quantity::MuscleCurve)?;
    check_result(&values, Quantity::MuscleCurve)?;
    Ok(values)
}

/// The state of a muscle's fibre and its tendon tension at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MuscleState<S> {
    /// Fibre length `lᴹ` (m).
    pub fiber_length: S,
    /// Fibre velocity `vᴹ` (m/s), negative while shortening.
    pub fiber_velocity: S,
    /// `cos α`, the pennation cosine.
    pub cos_pennation: S,
    /// Normalised fibre velocity `ṽ`.
    pub normalized_velocity: S,
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
}

/// A Thelen (2003) muscle with a rigid tendon along a path.
#[derive(Clone, Copy, Debug)]
pub struct ThelenMuscle<S: Scalar, G: PointGeometry, const K: usize> {
    /// The muscle-tendon path from origin to insertion.
    pub path: Path<S, G, K>,
    /// The muscle's parameters.
    pub params: ThelenParameters<S>,
    /// The entry of the drive-input vector `w` holding its activation.
    pub input: usize,
}

impl<S: Scalar, G: PointGeometry, const K: usize> ThelenMuscle<S, G, K> {
    /// A muscle along `path` reading its activation from `w[input]`.
    #[must_use]
    pub const fn new(path: Path<S, G, K>, params: ThelenParameters<S>, input: usize) -> Self {
        Self {
            path,
            params,
            input,
        }
    }

    /// Activation rate `ȧ` for excitation `u` ([`ThelenParameters::activation_rate`]).
    ///
    /// # Errors
    /// As [`ThelenParameters::activation_rate`].
    pub fn activation_rate(&self, excitation: S, activation: S) -> Result<S> {
        self.params.activation_rate(excitation, activation)
    }

    /// The fibre's length, pennation and velocity for a path of length `L`
    /// lengthening at `L̇` (rigid tendon, constant muscle height), with
    /// their slopes in `L` and `L̇`; at the shortest fibre the geometry
    /// stops and the slopes are zero.
    fn fiber_geometry(&self, length: S, lengthening_velocity: S) -> FiberGeometry<S> {
        let p = &self.params;
        let l_opt = p.optimal_fiber_length;
        let height = l_opt * p.pennation_angle_at_optimal.sin();
        let cos_max = S::from_f64(MIN_PENNATION_COSINE);
        let sin_max = (S::ONE - cos_max * cos_max).sqrt();
        let min_length = (S::from_f64(MIN_FIBER_LENGTH_FRACTION) * l_opt).max(height / sin_max);
        let min_projection = (min_length * min_length - height * height)
            .max(S::ZERO)
            .sqrt();
        let projection = length - p.tendon_slack_length;
        // Tested this way round so that a NaN length (an overflowed path)
        // gives a NaN force, not the shortest fibre's finite one.
        if projection <= min_projection {
            FiberGeometry {
                fiber_length: min_length,
                cos_pennation: min_projection / min_length,
                fiber_velocity: S::ZERO,
                dlength_dl: S::ZERO,
                dcos_dl: S::ZERO,
                dvelocity_dl: S::ZERO,
                dvelocity_dv: S::ZERO,
            }
        } else {
            let l = (projection * projection + height * height).sqrt();
            let cos = projection / l;
            // d cos/dL = h² / l³.
            let dcos = height * height / (l * l * l);
            FiberGeometry {
                fiber_length: l,
                cos_pennation: cos,
                fiber_velocity: lengthening_velocity * cos,
                dlength_dl: cos,
                dcos_dl: dcos,
                dvelocity_dl: lengthening_velocity * dcos,
                dvelocity_dv: cos,
            }
        }
    }

    /// The fibre velocity that normalises to 1: `(0.25 + 0.75 a) v_max l_opt`.
    fn velocity_scale(&self, clamped_activation: S) -> S {
        let p = &self.params;
        (S::from_f64(0.25) + S::from_f64(0.75) * clamped_activation)
            * p.max_contraction_velocity
            * p.optimal_fiber_length
    }

    /// The tension `T` (N) and its partial derivatives `∂T/∂L` (N/m) and
    /// `∂T/∂L̇` (N s/m) at fixed activation, for a path of length `L`
    /// lengthening at `L̇`: the tension of [`state`](Self::state),
    /// differentiated through the pennation, the force-length curves and
    /// the force-velocity curve (one-sided at its kinks).
    ///
    /// # Errors
    /// As [`state`](Self::state).
    pub fn tension_partials(
        &self,
        length: S,
        lengthening_velocity: S,
        activation: S,
    ) -> Result<(S, S, S)> {
        self.check_inputs(length, lengthening_velocity, activation)?;
        let (partials, fiber_length) =
            self.tension_partials_unvalidated(length, lengthening_velocity, activation);
        self.check_output(fiber_length, &[partials.0, partials.1, partials.2])?;
        Ok(partials)
    }

    /// [`tension_partials`](Self::tension_partials) without the checks,
    /// with the fibre length for [`check_output`](Self::check_output).
    fn tension_partials_unvalidated(
        &self,
        length: S,
        lengthening_velocity: S,
        activation: S,
    ) -> ((S, S, S), S) {
        let p = &self.params;
        let l_opt = p.optimal_fiber_length;
        let g = self.fiber_geometry(length, lengthening_velocity);
        let a = activation.max(S::ZERO).min(S::ONE);
        let scale = self.velocity_scale(a);
        let (l_norm, v_norm) = (g.fiber_length / l_opt, g.fiber_velocity / scale);
        let f_l = p.active_force_length_unchecked(l_norm);
        let df_l = f_l * S::from_f64(-2.0) * (l_norm - S::ONE) / p.active_shape_factor;
        let f_pe = p.passive_force_length_unchecked(l_norm);
        let df_pe = if l_norm <= S::ONE {
            S::ZERO
        } else {
            let k = p.passive_shape_factor;
            let strain = p.passive_strain_at_one;
            (k / strain) * (k * (l_norm - S::ONE) / strain).exp() / (k.exp() - S::ONE)
        };
        let (f_v, df_v) = p.force_velocity_unchecked(v_norm);
        let f0 = p.max_isometric_force;
        let fiber_force = a * f_l * f_v + f_pe;
        let tension = f0 * g.cos_pennation * fiber_force;
        let (dl_norm, dv_norm) = (g.dlength_dl / l_opt, g.dvelocity_dl / scale);
        let dforce_dl = a * (df_l * f_v * dl_norm + f_l * df_v * dv_norm) + df_pe * dl_norm;
        let tension_dl = f0 * (g.dcos_dl * fiber_force + g.cos_pennation * dforce_dl);
        let tension_dv = f0 * g.cos_pennation * a * f_l * df_v * g.dvelocity_dv / scale;
        ((tension, tension_dl, tension_dv), g.fiber_length)
    }

    /// Finite inputs: a NaN length would otherwise read as a path too
    /// short (the fibre held at its shortest, a finite force) and a NaN
    /// activation as zero.
    fn check_inputs(&self, length: S, lengthening_velocity: S, activation: S) -> Result<()> {
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
        check_activation(activation, self.input)
    }

    /// A fibre within [`MAX_NORMALIZED_FIBER_LENGTH`] and finite tensions
    /// (or slopes); the errors name the muscle's input. Checked after the
    /// force law, so that the hot path (`add_forces`) pays a few
    /// comparisons and no second pass.
    fn check_output(&self, fiber_length: S, values: &[S]) -> Result<()> {
        let l_opt = self.params.optimal_fiber_length;
        // Only for a valid l₀ᴹ: a zero or NaN one is a parameter problem,
        // which the non-finite tension reports.
        if l_opt > S::ZERO && fiber_length > S::from_f64(MAX_NORMALIZED_FIBER_LENGTH) * l_opt {
            return Err(Error::OutOfRange {
                quantity: Quantity::PathLength,
                index: self.input,
            });
        }
        if values.iter().all(|x| x.is_finite()) {
            Ok(())
        } else {
            Err(Error::NonFiniteResult {
                quantity: Quantity::ExternalForce,
                index: self.input,
            })
        }
    }

    /// Fibre state and tension for a path of length `L` (m) lengthening at
    /// `L̇` (m/s), at activation `a` (clamped to `[0, 1]`).
    ///
    /// # Errors
    /// [`Error::NonFinite`] naming a non-finite `L`
    /// ([`Quantity::PathLength`]), `L̇` ([`Quantity::PathVelocity`]) or `a`
    /// ([`Quantity::DriveInput`]); [`Error::OutOfRange`] with
    /// [`Quantity::PathLength`] for a fibre longer than
    /// [`MAX_NORMALIZED_FIBER_LENGTH`] optimal lengths;
    /// [`Error::NonFiniteResult`] with [`Quantity::ExternalForce`] for a
    /// tension that comes out non-finite (parameters that break the force
    /// law, see [`ThelenParameters::validate`]). Each names the muscle by
    /// its input index.
    pub fn state(
        &self,
        length: S,
        lengthening_velocity: S,
        activation: S,
    ) -> Result<MuscleState<S>> {
        self.check_inputs(length, lengthening_velocity, activation)?;
        let state = self.state_unvalidated(length, lengthening_velocity, activation);
        self.check_output(
            state.fiber_length,
            &[state.tension, state.tension_per_activation],
        )?;
        Ok(state)
    }

    /// [`state`](Self::state) without the checks.
    fn state_unvalidated(
        &self,
        length: S,
        lengthening_velocity: S,
        activation: S,
    ) -> MuscleState<S> {
        let p = &self.params;
        let l_opt = p.optimal_fiber_length;
        let FiberGeometry {
            fiber_length,
            cos_pennation,
            fiber_velocity,
            ..
        } = self.fiber_geometry(length, lengthening_velocity);
        let clamped = activation.max(S::ZERO).min(S::ONE);
        let a_in_range = activation > S::ZERO && activation < S::ONE;
        let velocity_scale = self.velocity_scale(clamped);
        let v_norm = fiber_velocity / velocity_scale;
        let l_norm = fiber_length / l_opt;
        let f_l = p.active_force_length_unchecked(l_norm);
        let f_pe = p.passive_force_length_unchecked(l_norm);
        let (f_v, df_v) = p.force_velocity_unchecked(v_norm);
        let f0_cos = p.max_isometric_force * cos_pennation;
        let tension = f0_cos * (clamped * f_l * f_v + f_pe);
        // ṽ depends on a through the velocity scale: dṽ/da = -ṽ 0.75/(0.25 + 0.75 a).
        let dv_da = -v_norm * S::from_f64(0.75) / (S::from_f64(0.25) + S::from_f64(0.75) * clamped);
        let tension_per_activation = if a_in_range {
            f0_cos * f_l * (f_v + clamped * df_v * dv_da)
        } else {
            S::ZERO
        };
        MuscleState {
            fiber_length,
            fiber_velocity,
            cos_pennation,
            normalized_velocity: v_norm,
            active_force_length: f_l,
            passive_force_length: f_pe,
            force_velocity: f_v,
            tension,
            tension_per_activation,
        }
    }

    /// The fibre state on a path whose kinematics are known.
    ///
    /// # Errors
    /// As [`state`](Self::state).
    pub fn state_on(&self, kin: &PathKinematics<S, G, K>, activation: S) -> Result<MuscleState<S>> {
        self.state(kin.length, kin.lengthening_velocity, activation)
    }

    /// The same muscle in another scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> ThelenMuscle<T, G, K> {
        ThelenMuscle {
            path: self.path.cast(),
            params: self.params.cast(),
            input: self.input,
        }
    }
}

/// A muscle's activation `w[input]` must be finite.
fn check_activation<S: Scalar>(activation: S, input: usize) -> Result<()> {
    if activation.is_finite() {
        Ok(())
    } else {
        Err(Error::NonFinite {
            quantity: Quantity::DriveInput,
            index: input,
        })
    }
}

impl<S: Scalar, G: PointGeometry, const K: usize, const NB: usize, const NV: usize>
    ForceElement<S, G, NB, NV> for ThelenMuscle<S, G, K>
{
    fn add_forces(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        let activation = read_input(w, self.input)?;
        check_activation(activation, self.input)?;
        // Parameters are not validated here (per call, a large share of
        // the muscle robot's forward dynamics on the Cortex-M4; see
        // docs/sections/performance_notebook.md, "Drives"): one
        // that breaks the force law makes the tension non-finite, which is
        // reported; `ThelenParameters::validate` names the field. The path
        // comes from a finite state: only an overflow makes it non-finite,
        // and then the tension too.
        let kin = self.path.kinematics_in_element(state.data)?;
        let muscle = self.state_unvalidated(kin.length, kin.lengthening_velocity, activation);
        self.check_output(muscle.fiber_length, &[muscle.tension])?;
        let tension = muscle.tension;
        self.path
            .add_tension_in_element(&kin, tension, state.data, &mut out.f_ext)
    }
    fn add_input_derivative(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        w: &[S],
        input: usize,
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        let activation = read_input(w, self.input)?;
        if input != self.input {
            return Ok(());
        }
        check_activation(activation, self.input)?;
        let kin = self.path.kinematics_in_element(state.data)?;
        let muscle = self.state_unvalidated(kin.length, kin.lengthening_velocity, activation);
        self.check_output(muscle.fiber_length, &[muscle.tension_per_activation])?;
        let slope = muscle.tension_per_activation;
        self.path
            .add_tension_in_element(&kin, slope, state.data, &mut out.f_ext)
    }
    fn add_state_derivatives(
        &self,
        state: &DriveDerivativeState<'_, S, G, NB, NV>,
        w: &[S],
        out: &mut DriveDerivatives<S, NV>,
    ) -> Result<()> {
        let activation = read_input(w, self.input)?;
        check_activation(activation, self.input)?;
        let path = self.path.length_derivatives(state)?;
        let (tension, fiber_length) =
            self.tension_partials_unvalidated(path.length, path.lengthening_velocity, activation);
        self.check_output(fiber_length, &[tension.0, tension.1, tension.2])?;
        add_tension_derivatives(&path, state.v, tension, out);
        Ok(())
    }
}

/// A fibre's geometry from its path, and its slopes (see
/// `ThelenMuscle::fiber_geometry`).
#[derive(Clone, Copy, Debug)]
struct FiberGeometry<S> {
    fiber_length: S,
    cos_pennation: S,
    fiber_velocity: S,
    /// `∂l/∂L`.
    dlength_dl: S,
    /// `∂cos α/∂L`.
    dcos_dl: S,
    /// `∂l̇/∂L`.
    dvelocity_dl: S,
    /// `∂l̇/∂L̇`.
    dvelocity_dv: S,
}
