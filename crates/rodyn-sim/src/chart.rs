//! `rodyn-sim chart`: cost per simulated second against error, for every
//! combination of method, scalar, integrator and step, with the Pareto front.

use crate::plot::{plot, Figure, Mark, Scale, Series};
use crate::scenario::{run, IntegratorKind, Method, RunConfig, ScalarType, Scenario};
use indicatif::ProgressBar;
use std::io::Write;
use std::path::Path;

/// Steps tried (s).
pub const STEPS: [f64; 6] = [1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 5e-3];
/// Step of the reference run (f64, ABA, RK4).
pub const REFERENCE_STEP: f64 = 1e-5;
/// Step of the rigid-contact reference run (f64): the rigid-contact points
/// are held to a rigid run, not to the compliant feet's.
pub const RIGID_REFERENCE_STEP: f64 = 2e-5;
/// Simulated time of each run (s).
pub const DURATION: f64 = 1.0;
/// Timing repeats; the median is reported.
pub const REPEATS: usize = 3;

/// One point of the chart.
#[derive(Clone, Debug)]
pub struct Point {
    /// Forward dynamics.
    pub method: Method,
    /// Scalar.
    pub scalar: ScalarType,
    /// Integrator.
    pub integrator: IntegratorKind,
    /// Step (s).
    pub dt: f64,
    /// Median host seconds per simulated second.
    pub cost: f64,
    /// Largest configuration error against the reference (rad / m), infinite on failure.
    pub error: f64,
    /// The error message of a failed run.
    pub failure: Option<String>,
}

/// Runs the sweep for `scenario`.
pub fn sweep(scenario: Scenario) -> Vec<Point> {
    let base = RunConfig {
        scenario,
        duration: DURATION,
        dt: REFERENCE_STEP,
        method: Method::Aba,
        scalar: ScalarType::F64,
        integrator: IntegratorKind::Rk4,
        sample_interval: 0.01,
    };
    let reference = run(&base, None);
    assert!(
        reference.failure.is_none(),
        "reference run failed: {:?}",
        reference.failure
    );
    let mut combos: Vec<_> = [Method::Aba, Method::Crba]
        .into_iter()
        .flat_map(|m| {
            [ScalarType::F32, ScalarType::F64]
                .into_iter()
                .map(move |s| (m, s))
        })
        .flat_map(|(m, s)| IntegratorKind::ALL.into_iter().map(move |i| (m, s, i)))
        .flat_map(|(m, s, i)| STEPS.into_iter().map(move |dt| (m, s, i, dt)))
        .collect();
    // Rigid feet for a robot that has them, against a rigid reference.
    let rigid_reference = scenario.has_feet().then(|| {
        let reference = run(
            &RunConfig {
                dt: RIGID_REFERENCE_STEP,
                integrator: IntegratorKind::RigidContact,
                ..base
            },
            None,
        );
        assert!(
            reference.failure.is_none(),
            "rigid reference run failed: {:?}",
            reference.failure
        );
        for scalar in [ScalarType::F32, ScalarType::F64] {
            for dt in STEPS {
                combos.push((Method::Crba, scalar, IntegratorKind::RigidContact, dt));
            }
        }
        reference
    });
    let bar = ProgressBar::new(combos.len() as u64);
    bar.set_message(scenario.name());
    let mut points = Vec::new();
    for (method, scalar, integrator, dt) in combos {
        let config = RunConfig {
            dt,
            method,
            scalar,
            integrator,
            ..base
        };
        let mut costs = Vec::new();
        let mut last = None;
        for _ in 0..REPEATS {
            let t = run(&config, None);
            costs.push(t.wall_time.as_secs_f64() / DURATION);
            last = Some(t);
        }
        costs.sort_by(f64::total_cmp);
        let t = last.expect("at least one repeat");
        points.push(Point {
            method,
            scalar,
            integrator,
            dt,
            cost: costs[REPEATS / 2],
            error: match (&rigid_reference, integrator) {
                (Some(rigid), IntegratorKind::RigidContact) => t.max_error_against(rigid),
                _ => t.max_error_against(&reference),
            },
            failure: t.failure.clone(),
        });
        bar.inc(1);
    }
    bar.finish_and_clear();
    points
}

/// Indices of the points no other point beats on both cost and error,
/// among the runs held to the main reference (rigid-contact runs are held
/// to their own, so their errors are not comparable with the others').
pub fn pareto_front(points: &[Point]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..points.len())
        .filter(|&i| {
            points[i].error.is_finite() && points[i].integrator != IntegratorKind::RigidContact
        })
        .collect();
    order.sort_by(|&a, &b| points[a].cost.total_cmp(&points[b].cost));
    let mut front = Vec::new();
    let mut best = f64::INFINITY;
    for i in order {
        if points[i].error < best {
            best = points[i].error;
            front.push(i);
        }
    }
    front
}

/// The method's name as the chart shows it (rigid contact: its KKT solve).
fn method_name(p: &Point) -> &'static str {
    if p.integrator == IntegratorKind::RigidContact {
        "KKT"
    } else {
        p.method.name()
    }
}

fn label(p: &Point) -> String {
    format!(
        "{} {} {} dt={:.0e}",
        method_name(p),
        p.scalar.name(),
        p.integrator.name(),
        p.dt
    )
}

/// Runs the sweep for the arm, the quadruped and the muscle robot, writes
/// `chart-<scenario>.svg` and `.csv` into `out`, and prints the front and the
/// 1 kHz candidates.
pub fn chart_command(out: &Path) -> Result<(), Box<dyn std::error::Error>> {
    std::fs::create_dir_all(out)?;
    for scenario in [
        Scenario::ArmSwing,
        Scenario::QuadrupedStand,
        Scenario::MuscleRobot,
    ] {
        let points = sweep(scenario);
        let front = pareto_front(&points);
        let name = scenario.name();
        let mut csv = std::fs::File::create(out.join(format!("chart-{name}.csv")))?;
        writeln!(
            csv,
            "method,scalar,integrator,dt,cost_s_per_s,max_error,pareto,failure"
        )?;
        for (i, p) in points.iter().enumerate() {
            writeln!(
                csv,
                "{},{},{},{:e},{:.4e},{:.4e},{},{}",
                method_name(p),
                p.scalar.name(),
                p.integrator.name(),
                p.dt,
                p.cost,
                p.error,
                front.contains(&i),
                p.failure.as_deref().unwrap_or("").replace(',', ";")
            )?;
        }
        let mut series = Vec::new();
        for (ii, integrator) in IntegratorKind::ALL.into_iter().enumerate() {
            for (si, scalar) in [ScalarType::F32, ScalarType::F64].into_iter().enumerate() {
                for method in [Method::Aba, Method::Crba] {
                    let pts: Vec<(f64, f64)> = points
                        .iter()
                        .filter(|p| {
                            p.integrator == integrator && p.scalar == scalar && p.method == method
                        })
                        .map(|p| (p.cost, p.error))
                        .collect();
                    let mark = if method == Method::Aba {
                        Mark::Points
                    } else {
                        Mark::Crosses
                    };
                    series.push(Series::new(
                        format!("{} {} {}", integrator.name(), scalar.name(), method.name()),
                        pts,
                        mark,
                        2 * ii + si,
                    ));
                }
            }
        }
        if scenario.has_feet() {
            for (si, scalar) in [ScalarType::F32, ScalarType::F64].into_iter().enumerate() {
                let pts: Vec<(f64, f64)> = points
                    .iter()
                    .filter(|p| p.integrator == IntegratorKind::RigidContact && p.scalar == scalar)
                    .map(|p| (p.cost, p.error))
                    .collect();
                series.push(Series::new(
                    format!("rigid contact {} (vs rigid ref.)", scalar.name()),
                    pts,
                    Mark::Triangles,
                    10 + si,
                ));
            }
        }
        let front_points = front
            .iter()
            .map(|&i| (points[i].cost, points[i].error))
            .collect();
        series.push(Series::new("Pareto front", front_points, Mark::ThinLine, 9));
        let title = if scenario.has_feet() {
            format!(
                "{name}: cost against error ({DURATION} s simulated; circles ABA, crosses CRBA, triangles rigid feet)"
            )
        } else {
            format!(
                "{name}: cost against error ({DURATION} s simulated; circles ABA, crosses CRBA)"
            )
        };
        plot(
            &out.join(format!("chart-{name}.svg")),
            &Figure {
                title: &title,
                x_label: "host seconds per simulated second (median of 3)",
                y_label: "max |q - q_ref| over the run",
                x_scale: Scale::Log,
                y_scale: Scale::Log,
            },
            &series,
        )?;
        println!("{name}: Pareto front (cheapest first)");
        for &i in &front {
            let p = &points[i];
            println!(
                "  {:<45} cost {:.2e} s/s  error {:.2e}",
                label(p),
                p.cost,
                p.error
            );
        }
        println!("{name}: every combination at dt = 1 ms (a 1 kHz loop)");
        for p in points.iter().filter(|p| p.dt == 1e-3) {
            println!(
                "  {:<45} cost {:.2e} s/s  error {:.2e}",
                label(p),
                p.cost,
                p.error
            );
        }
        let failed = points.iter().filter(|p| p.failure.is_some()).count();
        println!(
            "{name}: {failed} of {} runs stopped with an error",
            points.len()
        );
    }
    Ok(())
}
