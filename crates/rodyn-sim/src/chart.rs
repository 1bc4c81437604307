//! `rodyn-sim chart`: cost per simulated second against error, for every
//! combination of method, scalar, integrator and step, with the Pareto front.

use crate::plot::{plot_panels, Figure, Mark, Panel, Scale, Series};
use crate::scenario::{run, IntegratorKind, Method, RunConfig, ScalarType, Scenario};
use crate::trajectory::Trajectory;
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
    /// Largest angle error against the reference (rad): the joint angles
    /// and, for a floating base, its rotation angle; infinite on failure.
    pub error: f64,
    /// Largest error of a floating base's position against the reference
    /// (m); NaN for a fixed base, infinite on failure.
    pub position_error: f64,
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
        let against = match (&rigid_reference, integrator) {
            (Some(rigid), IntegratorKind::RigidContact) => rigid,
            _ => &reference,
        };
        let (error, position_error) = if scenario.has_feet() {
            floating_base_errors(&t, against)
        } else {
            (t.max_error_against(against), f64::NAN)
        };
        points.push(Point {
            method,
            scalar,
            integrator,
            dt,
            cost: costs[REPEATS / 2],
            error,
            position_error,
            failure: t.failure.clone(),
        });
        bar.inc(1);
    }
    bar.finish_and_clear();
    points
}

/// The largest angle error (rad: the joints' and the base's rotation angle
/// from the quaternions' product) and the largest base position error (m)
/// of a floating-base run `run` against `reference`, q laid out as
/// `[x y z, qx qy qz qw, joints…]`; infinite when the run failed.
fn floating_base_errors(run: &Trajectory, reference: &Trajectory) -> (f64, f64) {
    if run.failure.is_some() || run.t.len() < reference.t.len() {
        return (f64::INFINITY, f64::INFINITY);
    }
    let (mut angle, mut position) = (0.0f64, 0.0f64);
    for (a, b) in run.q.iter().zip(&reference.q) {
        for k in 0..3 {
            position = position.max((a[k] - b[k]).abs());
        }
        // The angle between two orientations: 2 acos |⟨q_a, q_b⟩| for unit
        // quaternions (normalised here, so drift does not count twice).
        let dot: f64 = (3..7).map(|k| a[k] * b[k]).sum();
        let norms = (3..7).map(|k| a[k] * a[k]).sum::<f64>().sqrt()
            * (3..7).map(|k| b[k] * b[k]).sum::<f64>().sqrt();
        angle = angle.max(2.0 * (dot.abs() / norms).min(1.0).acos());
        for k in 7..a.len().min(b.len()) {
            angle = angle.max((a[k] - b[k]).abs());
        }
    }
    if angle.is_finite() && position.is_finite() {
        (angle, position)
    } else {
        (f64::INFINITY, f64::INFINITY)
    }
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

/// The scenarios the chart covers.
const CHART_SCENARIOS: [Scenario; 3] = [
    Scenario::ArmSwing,
    Scenario::QuadrupedStand,
    Scenario::MuscleRobot,
];

/// Runs the sweep for the arm, the quadruped and the muscle robot, writes
/// `chart-<scenario>.svg` and `.csv` into `out`, and prints the front and the
/// 1 kHz candidates. With `replot`, runs nothing: reads the points back
/// from the `.csv` files already in `out` (the costs are host timings, which
/// a new sweep would not reproduce) and redraws the `.svg` files.
pub fn chart_command(
    out: &Path,
    replot: bool,
    only: Option<Scenario>,
) -> Result<(), Box<dyn std::error::Error>> {
    std::fs::create_dir_all(out)?;
    if let Some(scenario) = only.filter(|s| !CHART_SCENARIOS.contains(s)) {
        return Err(format!(
            "{} has no chart; charts: arm-swing, quadruped-stand, muscle-robot",
            scenario.name()
        )
        .into());
    }
    for scenario in CHART_SCENARIOS
        .into_iter()
        .filter(|s| only.is_none_or(|o| o == *s))
    {
        let name = scenario.name();
        let csv_path = out.join(format!("chart-{name}.csv"));
        let (points, front) = if replot {
            read_csv(&csv_path)?
        } else {
            let points = sweep(scenario);
            let front = pareto_front(&points);
            write_csv(&csv_path, &points, &front)?;
            (points, front)
        };
        draw(
            scenario,
            &points,
            &front,
            Quantity::Angle,
            &out.join(format!("chart-{name}.svg")),
        )?;
        if scenario.has_feet() {
            // The base's position error (m) on a chart of its own: one
            // unit per axis.
            let by_position: Vec<Point> = points
                .iter()
                .map(|p| Point {
                    error: p.position_error,
                    ..p.clone()
                })
                .collect();
            let position_front = pareto_front(&by_position);
            draw(
                scenario,
                &by_position,
                &position_front,
                Quantity::Position,
                &out.join(format!("chart-{name}-position.svg")),
            )?;
        }
        print_summary(name, &points, &front);
    }
    Ok(())
}

/// The points and the front, as `chart-<scenario>.csv`.
fn write_csv(path: &Path, points: &[Point], front: &[usize]) -> std::io::Result<()> {
    let mut csv = std::fs::File::create(path)?;
    writeln!(
        csv,
        "method,scalar,integrator,dt,cost_s_per_s,max_error,max_position_error_m,pareto,failure"
    )?;
    for (i, p) in points.iter().enumerate() {
        let position = if p.position_error.is_nan() {
            String::new()
        } else {
            format!("{:.4e}", p.position_error)
        };
        writeln!(
            csv,
            "{},{},{},{:e},{:.4e},{:.4e},{},{},{}",
            method_name(p),
            p.scalar.name(),
            p.integrator.name(),
            p.dt,
            p.cost,
            p.error,
            position,
            front.contains(&i),
            p.failure.as_deref().unwrap_or("").replace(',', ";")
        )?;
    }
    Ok(())
}

/// The points and the front back from a file [`write_csv`] wrote; an
/// error names the file, the line and the field it cannot read.
fn read_csv(path: &Path) -> Result<(Vec<Point>, Vec<usize>), Box<dyn std::error::Error>> {
    let text = std::fs::read_to_string(path).map_err(|e| {
        format!(
            "{}: {e} (run `rodyn-sim chart` without --replot first to measure the points)",
            path.display()
        )
    })?;
    let mut points = Vec::new();
    let mut front = Vec::new();
    for (n, line) in text.lines().enumerate().skip(1) {
        let at = |what: &str| format!("{} line {}: {what}", path.display(), n + 1);
        let fields: Vec<&str> = line.splitn(9, ',').collect();
        if fields.len() != 9 {
            return Err(at("expected 9 comma-separated fields").into());
        }
        let number = |k: usize, what: &str| -> Result<f64, String> {
            fields[k]
                .parse::<f64>()
                .map_err(|_| at(&format!("{what} '{}' is not a number", fields[k])))
        };
        let integrator = IntegratorKind::ALL
            .into_iter()
            .chain([IntegratorKind::RigidContact])
            .find(|i| i.name() == fields[2])
            .ok_or_else(|| at(&format!("unknown integrator '{}'", fields[2])))?;
        let method = match fields[0] {
            "ABA" => Method::Aba,
            "CRBA" | "KKT" => Method::Crba,
            other => return Err(at(&format!("unknown method '{other}'")).into()),
        };
        let scalar = [ScalarType::F32, ScalarType::F64]
            .into_iter()
            .find(|s| s.name() == fields[1])
            .ok_or_else(|| at(&format!("unknown scalar '{}'", fields[1])))?;
        if fields[7] == "true" {
            front.push(points.len());
        }
        points.push(Point {
            method,
            scalar,
            integrator,
            dt: number(3, "dt")?,
            cost: number(4, "cost")?,
            error: number(5, "error")?,
            position_error: match fields[6] {
                "" => f64::NAN,
                _ => number(6, "position error")?,
            },
            failure: (!fields[8].is_empty()).then(|| fields[8].to_owned()),
        });
    }
    Ok((points, front))
}

/// Colour of a scalar type: the same in every panel.
fn scalar_color(scalar: ScalarType) -> usize {
    match scalar {
        ScalarType::F32 => 1,
        ScalarType::F64 => 0,
    }
}

/// The chart: one panel per integrator (and one for rigid feet), each with
/// at most four point series and the Pareto front of all the runs, on
/// shared axes. Colour is the scalar, the marker the method.
/// What a chart's y axis shows.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Quantity {
    /// The largest angle error (rad).
    Angle,
    /// The largest error of the floating base's position (m).
    Position,
}

fn draw(
    scenario: Scenario,
    points: &[Point],
    front: &[usize],
    quantity: Quantity,
    path: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let mut front_points: Vec<(f64, f64)> = front
        .iter()
        .map(|&i| (points[i].cost, points[i].error))
        .collect();
    front_points.sort_by(|a, b| a.0.total_cmp(&b.0));
    let front_line = Series::new(
        "Pareto front of all compliant runs",
        front_points,
        Mark::ThinLine,
        10,
    );
    let mut integrators = IntegratorKind::ALL.to_vec();
    if scenario.has_feet() {
        integrators.push(IntegratorKind::RigidContact);
    }
    let panels: Vec<Panel> = integrators
        .into_iter()
        .map(|integrator| {
            let runs: Vec<&Point> = points
                .iter()
                .filter(|p| p.integrator == integrator)
                .collect();
            let failed = runs.iter().filter(|p| !p.error.is_finite()).count();
            let mut series = Vec::new();
            for scalar in [ScalarType::F32, ScalarType::F64] {
                for method in [Method::Aba, Method::Crba] {
                    let pts: Vec<(f64, f64)> = runs
                        .iter()
                        .filter(|p| p.scalar == scalar && p.method == method)
                        .map(|p| (p.cost, p.error))
                        .collect();
                    if pts.is_empty() {
                        continue;
                    }
                    let (mark, method_label) = match (integrator, method) {
                        (IntegratorKind::RigidContact, _) => (Mark::Triangles, "KKT, rigid feet"),
                        (_, Method::Aba) => (Mark::Rings, "ABA"),
                        (_, Method::Crba) => (Mark::Crosses, "CRBA"),
                    };
                    series.push(Series::new(
                        format!("{method_label}, {}", scalar.name()),
                        pts,
                        mark,
                        scalar_color(scalar),
                    ));
                }
            }
            series.push(front_line.clone());
            let mut title = integrator.name().to_owned();
            if integrator == IntegratorKind::RigidContact {
                title.push_str(" (error against a rigid reference)");
            }
            if failed > 0 {
                title.push_str(&format!(
                    " ({failed} of {} runs failed, not drawn)",
                    runs.len()
                ));
            }
            Panel { title, series }
        })
        .collect();
    let (what, y_label) = match (quantity, scenario.has_feet()) {
        (Quantity::Position, _) => ("trunk position error", "max |p - p_ref| of the trunk (m)"),
        (Quantity::Angle, true) => (
            "angle error",
            "max angle error (rad; joints and trunk rotation)",
        ),
        (Quantity::Angle, false) => ("error", "max |q - q_ref| (rad)"),
    };
    let title = format!(
        "{}: cost against {what}, {DURATION} s simulated, steps 0.1 to 5 ms",
        scenario.name()
    );
    plot_panels(
        path,
        &Figure {
            title: &title,
            x_label: "cost (host s per simulated s, median of 3)",
            y_label,
            x_scale: Scale::Log,
            y_scale: Scale::Log,
        },
        &panels,
        3,
    )
}

/// Prints the front and every combination at 1 ms.
fn print_summary(name: &str, points: &[Point], front: &[usize]) {
    rodyn_cli::outln!("{name}: Pareto front (cheapest first)");
    for &i in front {
        let p = &points[i];
        rodyn_cli::outln!(
            "  {:<45} cost {:.2e} s/s  error {:.2e}",
            label(p),
            p.cost,
            p.error
        );
    }
    rodyn_cli::outln!("{name}: every combination at dt = 1 ms (a 1 kHz loop)");
    for p in points.iter().filter(|p| p.dt == 1e-3) {
        rodyn_cli::outln!(
            "  {:<45} cost {:.2e} s/s  error {:.2e}",
            label(p),
            p.cost,
            p.error
        );
    }
    let failed = points.iter().filter(|p| p.failure.is_some()).count();
    rodyn_cli::outln!(
        "{name}: {failed} of {} runs stopped with an error",
        points.len()
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `chart --replot` draws from what the sweep wrote: every field and
    /// the front come back from the CSV, a failure's message included.
    #[test]
    fn the_csv_reads_back_what_the_sweep_wrote() {
        let points = vec![
            Point {
                method: Method::Aba,
                scalar: ScalarType::F32,
                integrator: IntegratorKind::Rk4,
                dt: 1e-3,
                cost: 3.5e-3,
                error: 4.2e-3,
                position_error: f64::NAN,
                failure: None,
            },
            Point {
                method: Method::Crba,
                scalar: ScalarType::F64,
                integrator: IntegratorKind::RigidContact,
                dt: 5e-3,
                cost: 1.0e-3,
                error: 2.7e-2,
                position_error: 1.5e-3,
                failure: None,
            },
            Point {
                method: Method::Crba,
                scalar: ScalarType::F64,
                integrator: IntegratorKind::ExplicitEuler,
                dt: 5e-3,
                cost: 2.0e-4,
                error: f64::INFINITY,
                position_error: f64::INFINITY,
                failure: Some("step 12: state not finite, joint 3".into()),
            },
        ];
        let path = std::env::temp_dir().join(format!("rodyn-chart-{}.csv", std::process::id()));
        write_csv(&path, &points, &[0]).unwrap();
        let (back, front) = read_csv(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        assert_eq!(front, vec![0]);
        assert_eq!(back.len(), 3);
        for (a, b) in points.iter().zip(&back) {
            assert_eq!(
                (a.method, a.scalar, a.integrator),
                (b.method, b.scalar, b.integrator)
            );
            assert_eq!(a.dt, b.dt);
            // Written to 5 significant digits.
            assert!((a.cost - b.cost).abs() <= 1e-4 * a.cost);
            assert!(a.error == b.error || (a.error - b.error).abs() <= 1e-4 * a.error);
        }
        assert!(back[0].position_error.is_nan());
        assert!((back[1].position_error - 1.5e-3).abs() <= 1e-4 * 1.5e-3);
        assert_eq!(
            back[2].failure.as_deref(),
            Some("step 12: state not finite; joint 3")
        );
    }

    /// A damaged file is refused with its name, line and field.
    #[test]
    fn a_bad_field_is_named_with_its_line() {
        let path = std::env::temp_dir().join(format!("rodyn-chart-bad-{}.csv", std::process::id()));
        std::fs::write(
            &path,
            "method,scalar,integrator,dt,cost_s_per_s,max_error,max_position_error_m,pareto,failure\n\
             ABA,f32,rk4,1e-3,fast,1e-3,,false,\n",
        )
        .unwrap();
        let message = read_csv(&path).unwrap_err().to_string();
        std::fs::remove_file(&path).unwrap();
        assert!(message.contains("line 2"), "{message}");
        assert!(message.contains("cost 'fast'"), "{message}");
    }
}
