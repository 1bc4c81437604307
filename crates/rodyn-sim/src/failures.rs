//! `rodyn-sim failures`: where each method breaks down, one plot each.

use crate::models::{chain, light_tip_pendulum, slider, tumbling_box};
use crate::plot::{plot, plot_panels, Curve, Figure, Mark, Panel, Scale, Series};
use crate::scenario::IntegratorKind;
use clap::ValueEnum;
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::sim::contact::NormalLaw;
use rodyn::sim::manifold::configuration_rate;
use rodyn::sim::{
    ConfigurationUpdate, ExplicitEuler, ImplicitEuler, Integrator, NoLoads, Rk4, SemiImplicitEuler,
    State,
};
use rodyn::spatial::Force;
use rodyn::{Data, Model, Scalar};
use rodyn_scenarios::quadruped::{self, QuadrupedLoads};
use std::path::Path;

type Res = Result<(), Box<dyn std::error::Error>>;
/// A drift curve and, if rodyn stopped the run, when and why.
type DriftRun = (Curve, Option<(f64, rodyn::Error)>);
/// A named error measurement.
type Case = (&'static str, fn(f64) -> Result<f64, rodyn::Error>);

/// The experiments.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Experiment {
    /// f32 against f64 error with chain length, ABA and CRBA.
    Chain,
    /// Largest stable step against spring stiffness, per integrator.
    Stiffness,
    /// A vanishing tip mass: error growth and the reported limit.
    Massless,
    /// Quaternion norm drift with and without renormalisation.
    Quaternion,
    /// Contact stiffness against step for the quadruped.
    Contact,
    /// All of them.
    All,
}

/// Runs `experiment` and writes its SVG (and prints its numbers).
pub fn failures_command(experiment: Experiment, out: &Path) -> Res {
    std::fs::create_dir_all(out)?;
    let all = experiment == Experiment::All;
    if all || experiment == Experiment::Chain {
        chain_length(out)?;
    }
    if all || experiment == Experiment::Stiffness {
        stiffness(out)?;
    }
    if all || experiment == Experiment::Massless {
        massless(out)?;
    }
    if all || experiment == Experiment::Quaternion {
        quaternion(out)?;
    }
    if all || experiment == Experiment::Contact {
        contact(out)?;
    }
    Ok(())
}

fn fig<'a>(title: &'a str, x: &'a str, y: &'a str, xs: Scale, ys: Scale) -> Figure<'a> {
    Figure {
        title,
        x_label: x,
        y_label: y,
        x_scale: xs,
        y_scale: ys,
    }
}

/// A deterministic state of `N` coordinates away from any symmetry.
fn chain_state<const N: usize>() -> ([f64; N], [f64; N]) {
    (
        core::array::from_fn(|k| 0.4 * (1.3 * k as f64 + 0.2).sin()),
        core::array::from_fn(|k| 0.5 * (0.7 * k as f64).cos()),
    )
}

/// Relative error `|ddq_f32 - ddq_f64|∞ / |ddq_f64|∞` of `F` in f32 on a
/// chain of `N` links; `None` when rodyn reported an error.
pub fn chain_error<F: ForwardDynamics, const N: usize>() -> (f64, Option<f64>) {
    let model64 = chain::<f64, N>();
    let model32 = chain::<f32, N>();
    let (q, v) = chain_state::<N>();
    let mut d64 = Box::new(Data::<f64, N, N>::new());
    let mut d32 = Box::new(Data::<f32, N, N>::new());
    let reference =
        *Aba::forward_dynamics(&model64, &mut d64, &q, &v, &[0.0; N], None).expect("f64 ABA");
    let scale = reference.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let f64_other = *F::forward_dynamics(&model64, &mut d64, &q, &v, &[0.0; N], None).expect("f64");
    let f64_err = f64_other
        .iter()
        .zip(&reference)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
        / scale;
    let q32 = q.map(|x| x as f32);
    let v32 = v.map(|x| x as f32);
    let f32_err = F::forward_dynamics(&model32, &mut d32, &q32, &v32, &[0.0; N], None)
        .ok()
        .map(|a| {
            a.iter()
                .zip(&reference)
                .fold(0.0f64, |m, (a, b)| m.max((*a as f64 - b).abs()))
                / scale
        });
    (f64_err, f32_err)
}

macro_rules! chain_rows {
    ($($n:literal),*) => {
        [$(($n, chain_error::<Aba, $n>(), chain_error::<Crba, $n>())),*]
    };
}

fn chain_length(out: &Path) -> Res {
    let rows = chain_rows!(1, 2, 5, 10, 20, 30, 40, 60, 80, 100, 120);
    rodyn_cli::outln!("chain: links, f32 ABA rel. error, f32 CRBA rel. error, f64 CRBA vs f64 ABA");
    let mut s: [Curve; 3] = [Vec::new(), Vec::new(), Vec::new()];
    for (n, (_, aba32), (crba64, crba32)) in &rows {
        let show = |e: &Option<f64>| e.map_or("error".to_string(), |e| format!("{e:.2e}"));
        rodyn_cli::outln!(
            "  {n:>4} {:>10} {:>10} {crba64:>10.2e}",
            show(aba32),
            show(crba32)
        );
        let x = *n as f64;
        if let Some(e) = aba32 {
            s[0].push((x, *e));
        }
        if let Some(e) = crba32 {
            s[1].push((x, *e));
        }
        s[2].push((x, crba64.max(1e-17)));
    }
    plot(
        &out.join("failure-chain-length.svg"),
        &fig(
            "f32 against f64: joint-acceleration error with chain length",
            "links (1 m, 1 kg chain)",
            "relative error of the joint accelerations",
            Scale::Linear,
            Scale::Log,
        ),
        &[
            Series::new("ABA f32", s[0].clone(), Mark::LinePoints, 0),
            Series::new("CRBA f32", s[1].clone(), Mark::LinePoints, 1),
            Series::new("CRBA f64 vs ABA f64", s[2].clone(), Mark::LinePoints, 2),
        ],
    )
}

/// A 1 kg slider on a spring `k` (N/m): `true` when `steps` steps of `dt`
/// keep the amplitude below twice its start, without an error.
pub fn spring_stays_bounded<I: Integrator>(
    mut integrator: I,
    k: f64,
    dt: f64,
    steps: usize,
) -> bool {
    let model = slider::<f64>();
    let mut data = Data::new();
    let mut state = State::new([0.01], [0.0]);
    let mut spring = |_: &Model<f64, 1, 1, 1>,
                      _: &mut Data<f64, 1, 1>,
                      _: f64,
                      q: &[f64; 1],
                      _: &[f64; 1],
                      tau: &mut [f64; 1],
                      _: &mut [Force<f64>; 1]| {
        tau[0] -= k * q[0];
        Ok(())
    };
    for _ in 0..steps {
        if integrator
            .step(Aba, &model, &mut data, &mut state, dt, &mut spring)
            .is_err()
        {
            return false;
        }
        // Energy-like amplitude: position and velocity scaled by ω.
        let amplitude = (state.q[0].powi(2) + state.v[0].powi(2) / k).sqrt();
        if amplitude > 0.02 {
            return false;
        }
    }
    true
}

/// The largest step (s) for which [`spring_stays_bounded`] holds, by
/// bisection in log(dt) between 1e-9 s and 10 s.
pub fn largest_stable_step(kind: IntegratorKind, k: f64, steps: usize) -> f64 {
    let stable = |dt: f64| match kind {
        IntegratorKind::ExplicitEuler => {
            spring_stays_bounded(ExplicitEuler::default(), k, dt, steps)
        }
        IntegratorKind::SemiImplicitEuler => {
            spring_stays_bounded(SemiImplicitEuler::default(), k, dt, steps)
        }
        IntegratorKind::Rk4 => spring_stays_bounded(Rk4::default(), k, dt, steps),
        IntegratorKind::ImplicitEuler => {
            spring_stays_bounded(ImplicitEuler::default(), k, dt, steps)
        }
        // Rigid contact is a scheme for feet, not an ODE integrator:
        // `IntegratorKind::ALL` leaves it out of these maps.
        IntegratorKind::RigidContact => false,
    };
    let (mut lo, mut hi) = (1e-9f64.ln(), 10f64.ln());
    if stable(hi.exp()) {
        return hi.exp();
    }
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if stable(mid.exp()) {
            lo = mid
        } else {
            hi = mid
        }
    }
    lo.exp()
}

fn stiffness(out: &Path) -> Res {
    let ks: Vec<f64> = (0..=14).map(|e| 10f64.powf(1.0 + 0.5 * e as f64)).collect();
    let mut series = Vec::new();
    rodyn_cli::outln!(
        "stiffness: largest stable step (s) of a 1 kg spring over 2000 steps, k in N/m"
    );
    for (c, kind) in IntegratorKind::ALL.into_iter().enumerate() {
        let pts: Vec<(f64, f64)> = ks
            .iter()
            .map(|&k| (k, largest_stable_step(kind, k, 2000)))
            .collect();
        rodyn_cli::outln!(
            "  {:<20} {}",
            kind.name(),
            pts.iter()
                .map(|(k, dt)| format!("k={k:.0e}:{dt:.2e}"))
                .collect::<Vec<_>>()
                .join(" ")
        );
        series.push(Series::new(kind.name(), pts, Mark::LinePoints, c));
    }
    series.push(Series::new(
        "2/ω (symplectic Euler theory)",
        ks.iter().map(|&k| (k, 2.0 / k.sqrt())).collect(),
        Mark::ThinLine,
        7,
    ));
    series.push(Series::new(
        "2.785/ω (RK4 theory)",
        ks.iter().map(|&k| (k, 2.785 / k.sqrt())).collect(),
        Mark::Dotted,
        8,
    ));
    plot(
        &out.join("failure-stiffness.svg"),
        &fig(
            "Largest stable step against spring stiffness (1 kg, 2000 steps)",
            "stiffness k (N/m)",
            "largest stable step (s)",
            Scale::Log,
            Scale::Log,
        ),
        &series,
    )
}

/// Forward dynamics of the light-tip pendulum at a fixed state in scalar
/// `S`, against ABA in f64; `Err` carries rodyn's message.
pub fn light_tip_error<F: ForwardDynamics, S: Scalar>(tip_mass: f64) -> Result<f64, rodyn::Error> {
    let (q, v) = ([0.4, -0.9], [0.3, 1.1]);
    let reference = *Aba::forward_dynamics(
        &light_tip_pendulum::<f64>(tip_mass),
        &mut Data::new(),
        &q,
        &v,
        &[0.0; 2],
        None,
    )?;
    let model = light_tip_pendulum::<S>(tip_mass);
    let a = *F::forward_dynamics(
        &model,
        &mut Data::new(),
        &q.map(S::from_f64),
        &v.map(S::from_f64),
        &[S::ZERO; 2],
        None,
    )?;
    let scale = reference.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    Ok(a.iter()
        .zip(&reference)
        .fold(0.0f64, |m, (a, b)| m.max((a.to_f64() - b).abs()))
        / scale)
}

fn massless(out: &Path) -> Res {
    let masses: Vec<f64> = (0..=46).map(|e| 10f64.powi(-e)).chain([0.0]).collect();
    let mut series = Vec::new();
    let mut reported = Vec::new();
    rodyn_cli::outln!("massless: tip mass (kg, first link 1 kg) -> relative error of q̈, or the error rodyn returns");
    let cases: [Case; 4] = [
        ("ABA f32", light_tip_error::<Aba, f32>),
        ("CRBA f32", light_tip_error::<Crba, f32>),
        (
            "ABA f64 (reference: exact to rounding)",
            light_tip_error::<Aba, f64>,
        ),
        ("CRBA f64", light_tip_error::<Crba, f64>),
    ];
    for (c, (name, f)) in cases.iter().enumerate() {
        let mut pts = Vec::new();
        let mut first_error = None;
        for &m in &masses {
            match f(m) {
                Ok(e) => pts.push((m.max(1e-50), e.max(1e-17))),
                Err(e) => {
                    if first_error.is_none() {
                        first_error = Some((m, e));
                        reported.push((m.max(1e-50), 1.0));
                    }
                }
            }
        }
        let table: Vec<String> = pts
            .iter()
            .step_by(2)
            .map(|(m, e)| format!("{m:.0e}:{e:.1e}"))
            .collect();
        rodyn_cli::outln!("  {name:<40} {}", table.join(" "));
        match first_error {
            Some((m, e)) => rodyn_cli::outln!("  {name:<40} first error at tip mass {m:.0e}: {e}"),
            None => rodyn_cli::outln!("  {name:<40} no error down to 1e-46 kg"),
        }
        series.push(Series::new(*name, pts, Mark::LinePoints, c));
    }
    series.push(Series::new(
        "rodyn reports an error (first mass)",
        reported,
        Mark::Crosses,
        3,
    ));
    plot(
        &out.join("failure-massless.svg"),
        &fig(
            "A vanishing tip link: error growth, then rodyn's error (massless = 1e-50 on the axis)",
            "tip mass (kg)",
            "relative error of the joint accelerations (floored at 1e-17)",
            Scale::Log,
            Scale::Log,
        ),
        &series,
    )
}

/// Largest `||q| - 1|` over `steps` steps of the tumbling box, and the
/// step at which rodyn rejected the configuration (if it did).
pub fn quaternion_drift<S: Scalar, I: Integrator>(
    mut integrator: I,
    dt: f64,
    steps: usize,
) -> DriftRun {
    let model = tumbling_box::<S>();
    let mut data = Data::new();
    let w = [0.5, 3.0, 0.2].map(S::from_f64);
    let mut state = State::new(
        [S::ZERO, S::ZERO, S::ZERO, S::ZERO, S::ZERO, S::ZERO, S::ONE],
        [S::ZERO, S::ZERO, S::ZERO, w[0], w[1], w[2]],
    );
    let mut out = Vec::new();
    for n in 0..steps {
        if let Err(e) = integrator.step(
            Aba,
            &model,
            &mut data,
            &mut state,
            S::from_f64(dt),
            &mut NoLoads,
        ) {
            return (out, Some((n as f64 * dt, e)));
        }
        let norm = state.q[3..7]
            .iter()
            .map(|x| x.to_f64().powi(2))
            .sum::<f64>()
            .sqrt();
        out.push((state.t.to_f64(), (norm - 1.0).abs().max(1e-17)));
    }
    (out, None)
}

/// The norm drift of the quaternion kinematics alone (`q̇ = ½ q ⊗ ω`,
/// constant body rate, no dynamics and so no check), explicit Euler or RK4
/// in the embedding space without renormalisation.
///
/// # Errors
/// When the rates come out non-finite ([`configuration_rate`]).
pub fn kinematic_drift(rk4: bool, dt: f64, steps: usize) -> rodyn::Result<Vec<(f64, f64)>> {
    // `q + q̇ h`, coordinate by coordinate (no projection).
    let add_scaled = |q: &[f64; 7], q_dot: &[f64; 7], h: f64| -> [f64; 7] {
        core::array::from_fn(|k| q[k] + q_dot[k] * h)
    };
    let model = tumbling_box::<f64>();
    let v = [0.0, 0.0, 0.0, 0.5, 3.0, 0.2];
    let mut q = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0];
    let mut out = Vec::new();
    for n in 1..=steps {
        q = if rk4 {
            let k1 = configuration_rate(&model, &q, &v)?;
            let k2 = configuration_rate(&model, &add_scaled(&q, &k1, dt / 2.0), &v)?;
            let k3 = configuration_rate(&model, &add_scaled(&q, &k2, dt / 2.0), &v)?;
            let k4 = configuration_rate(&model, &add_scaled(&q, &k3, dt), &v)?;
            core::array::from_fn(|i| q[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
        } else {
            add_scaled(&q, &configuration_rate(&model, &q, &v)?, dt)
        };
        if n % 10 == 0 {
            let norm = q[3..7].iter().map(|x| x * x).sum::<f64>().sqrt();
            out.push((n as f64 * dt, (norm - 1.0).abs().max(1e-17)));
        }
    }
    Ok(out)
}

fn quaternion(out: &Path) -> Res {
    let (dt, steps) = (1e-3, 10_000);
    let no = ConfigurationUpdate::Embedded { renormalize: false };
    let yes = ConfigurationUpdate::Embedded { renormalize: true };
    let exp = ConfigurationUpdate::ExponentialMap;
    let runs: Vec<(String, DriftRun)> = vec![
        (
            "RK4 f64 renormalised".into(),
            quaternion_drift::<f64, _>(Rk4 { update: yes }, dt, steps),
        ),
        (
            "RK4 f32 renormalised".into(),
            quaternion_drift::<f32, _>(Rk4 { update: yes }, dt, steps),
        ),
        (
            "semi-implicit Euler f32, exponential map".into(),
            quaternion_drift::<f32, _>(SemiImplicitEuler { update: exp }, dt, steps),
        ),
        (
            "explicit Euler f32, not renormalised".into(),
            quaternion_drift::<f32, _>(ExplicitEuler { update: no }, dt, steps),
        ),
        (
            "explicit Euler f64, not renormalised".into(),
            quaternion_drift::<f64, _>(ExplicitEuler { update: no }, dt, steps),
        ),
    ];
    // Two panels: the updates that keep |q| = 1 and those that let it
    // drift, each with rodyn's tolerances, so no panel holds more than
    // seven series.
    let mut kept = Vec::new();
    let mut drifting = Vec::new();
    let mut rejected = Vec::new();
    rodyn_cli::outln!("quaternion: tumbling box, dt = 1 ms, 10 s; max ||q|-1| and rodyn's verdict");
    for (c, (name, (pts, failure))) in runs.into_iter().enumerate() {
        let worst = pts.iter().fold(0.0f64, |m, p| m.max(p.1));
        match &failure {
            Some((t, e)) => {
                rodyn_cli::outln!(
                    "  {name:<45} max drift {worst:.2e}; rejected at t = {t:.3} s: {e}"
                );
                rejected.push((t.max(1e-3), pts.last().map_or(1e-17, |p| p.1)));
            }
            None => rodyn_cli::outln!("  {name:<45} max drift {worst:.2e}; never rejected"),
        }
        let thinned = pts
            .into_iter()
            .enumerate()
            .filter(|(i, _)| i % 10 == 0)
            .map(|(_, p)| p)
            .collect();
        let panel = if name.contains("not renormalised") {
            &mut drifting
        } else {
            &mut kept
        };
        panel.push(Series::new(name, thinned, Mark::Line, c));
    }
    drifting.push(Series::new(
        "kinematics only: explicit Euler, no renormalisation",
        kinematic_drift(false, dt, steps)?,
        Mark::Line,
        5,
    ));
    drifting.push(Series::new(
        "kinematics only: RK4, no renormalisation",
        kinematic_drift(true, dt, steps)?,
        Mark::Line,
        6,
    ));
    let tolerances = [
        Series::new(
            "rodyn's tolerance, f32 (1e3 ε)",
            vec![
                (1e-3, 1e3 * f32::EPSILON as f64),
                (10.0, 1e3 * f32::EPSILON as f64),
            ],
            Mark::ThinLine,
            7,
        ),
        Series::new(
            "rodyn's tolerance, f64 (1e3 ε)",
            vec![(1e-3, 1e3 * f64::EPSILON), (10.0, 1e3 * f64::EPSILON)],
            Mark::Dotted,
            8,
        ),
    ];
    kept.extend(tolerances.iter().cloned());
    drifting.extend(tolerances);
    drifting.push(Series::new(
        "rodyn rejects the configuration",
        rejected,
        Mark::Crosses,
        3,
    ));
    plot_panels(
        &out.join("failure-quaternion.svg"),
        &fig(
            "Quaternion norm drift of a tumbling box (dt = 1 ms)",
            "time (s)",
            "| |q| - 1 | (norm error, no unit)",
            Scale::Linear,
            Scale::Log,
        ),
        &[
            Panel {
                title: "|q| kept at 1 (renormalised or exponential map)".into(),
                series: kept,
            },
            Panel {
                title: "|q| left to drift (not renormalised)".into(),
                series: drifting,
            },
        ],
        3,
    )
}

/// Lands the quadruped on a ground of stiffness `k` (N/m; damping scaled
/// with √k from 10 N s/m at 5 kN/m) for 1 s: `Ok(true)` when it ends at
/// rest within 5 mm of the reference height, `Ok(false)` when it ends
/// elsewhere or moving, `Err` when rodyn stopped the run.
pub fn quadruped_lands<I: Integrator>(
    mut integrator: I,
    k: f64,
    dt: f64,
) -> Result<bool, rodyn::Error> {
    let model = quadruped::model::<f64>()?;
    let mut loads = QuadrupedLoads::<f64>::standing();
    loads.ground.normal = NormalLaw::LinearSpringDamper {
        stiffness: k,
        damping: 10.0 * (k / 5.0e3).sqrt(),
    };
    let stance = loads.stance_height();
    let mut state = loads.initial_state(stance + 0.03);
    let mut data = Data::new();
    let steps = (1.0 / dt).round() as usize;
    for _ in 0..steps {
        integrator.step(Aba, &model, &mut data, &mut state, dt, &mut loads)?;
    }
    let speed = state.v[..6].iter().fold(0.0f64, |m, v| m.max(v.abs()));
    // Expected height: stance minus the static sag of the legs, 2.0 mm, and
    // of the ground, m g / (4 k).
    let expected = stance - 0.002 - model.total_mass() * 9.81 / (4.0 * k);
    let height = quadruped::trunk_position(&state.q).z;
    Ok(speed < 0.02 && (height - expected).abs() < 0.005)
}

fn contact(out: &Path) -> Res {
    let ks = [1e3, 3e3, 1e4, 3e4, 1e5, 3e5, 1e6];
    let steps = [5e-5, 1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 5e-3];
    let mut series = Vec::new();
    rodyn_cli::outln!("contact: largest step (s) at which the dropped quadruped comes to rest, per ground stiffness");
    for (c, kind) in IntegratorKind::ALL.into_iter().enumerate() {
        let mut pts = Vec::new();
        for &k in &ks {
            let ok = |dt: f64| {
                let r = match kind {
                    IntegratorKind::ExplicitEuler => {
                        quadruped_lands(ExplicitEuler::default(), k, dt)
                    }
                    IntegratorKind::SemiImplicitEuler => {
                        quadruped_lands(SemiImplicitEuler::default(), k, dt)
                    }
                    IntegratorKind::Rk4 => quadruped_lands(Rk4::default(), k, dt),
                    IntegratorKind::ImplicitEuler => {
                        quadruped_lands(ImplicitEuler::default(), k, dt)
                    }
                    // No ground stiffness to vary: not in `ALL`.
                    IntegratorKind::RigidContact => Ok(false),
                };
                matches!(r, Ok(true))
            };
            // Implicit Euler's cost grows with 1/dt: try it from the largest step down.
            let best = steps.iter().rev().copied().find(|&dt| ok(dt));
            if let Some(dt) = best {
                pts.push((k, dt));
            }
            rodyn_cli::outln!(
                "  {:<20} k = {k:.0e} N/m: {}",
                kind.name(),
                best.map_or("none of the steps".into(), |dt| format!("{dt:e} s"))
            );
        }
        series.push(Series::new(kind.name(), pts, Mark::LinePoints, c));
    }
    plot(
        &out.join("failure-contact.svg"),
        &fig(
            "Quadruped landing: largest step that comes to rest, against ground stiffness",
            "ground stiffness k (N/m)",
            "largest good step (s)",
            Scale::Log,
            Scale::Log,
        ),
        &series,
    )
}
