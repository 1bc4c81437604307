//! The muscle robot's energy-optimal muscle controls for desired joint
//! trajectories (Friedmann, Wojtusch & von Stryk, Fig. 4), by trapezoidal
//! direct collocation solved with IPOPT.
//!
//! `cargo run --release -p rodyn-optimal-control --example muscle_robot_optimal_control -- --out DIR`
//!
//! The solution shown is that of the smooth muscles (De Groote et al.
//! 2016) with rodyn's analytic Jacobians and the exact Hessian of the
//! Lagrangian. Beside it, the same problem on a grid twice as fine (mesh
//! refinement), the smooth muscles with IPOPT's quasi-Newton Hessian
//! instead, and the Thelen (2003) muscles as before (analytic Jacobians,
//! quasi-Newton Hessian); `--skip-thelen` leaves that slow row out. Writes:
//! - `DIR/controls.csv`: time, the four excitations and activations, the
//!   joint angles and their desired values at every node;
//! - `DIR/results.json`: every result that does not depend on the
//!   machine (convergence, iterations, objective, defects, tracking,
//!   each muscle's share of the effort, the comparison rows);
//! - `DIR/summary.json`: the same plus the solve times (s);
//! - `DIR/optimal_controls.svg`: desired and re-simulated joint angles
//!   above, optimal excitations and activations below.
//!
//! `controls.csv`, `results.json` and `optimal_controls.svg` are
//! bit-identical from run to run. The process exits with an error (after
//! writing the files) when the smooth solve does not converge to IPOPT's
//! tolerance, its defects exceed 1e-8 or its re-simulation misses the
//! desired angles by more than 1e-2 rad RMS.

use clap::Parser;
use plotters::coord::Shift;
use plotters::prelude::*;
use rodyn_cli::{writable_dir, Count, PositiveFinite};
use rodyn_optimal_control::collocation::{Hessian, Node};
use rodyn_optimal_control::ipopt::{Options, Status};
use rodyn_optimal_control::muscle_robot::{Derivatives, Task, EXCITATION_RATE_WEIGHT, NX};
use rodyn_optimal_control::smooth_muscle_robot::{
    effort_shares, solve_smooth, solve_thelen, Solved, MAX_DEFECT, MAX_TRACKING_RMS,
};
use rodyn_plot_markers::{marker, sparse};
use rodyn_scenarios::muscle_robot::{NU, NV};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Collocation nodes N: at least the three a trapezoidal transcription
/// needs; at most 1001 (the refined grid has `2 N − 1`).
type Nodes = Count<3, 1001>;
/// Longest motion accepted, s.
const MAX_DURATION: f64 = 20.0;

#[derive(Parser)]
#[command(
    about = "Energy-optimal muscle controls of the two-link, four-muscle robot (direct collocation, IPOPT)"
)]
struct Arguments {
    /// Output directory (created if missing; must be writable).
    #[arg(long)]
    out: PathBuf,
    /// Collocation nodes N, 3 to 1001 (the mesh-refinement solve uses
    /// 2 N − 1).
    #[arg(long, default_value_t = Count(Task::default().nodes), allow_hyphen_values = true)]
    nodes: Nodes,
    /// Duration of the motion, s: positive, at most 20.
    #[arg(long, default_value_t = PositiveFinite(Task::default().duration), allow_hyphen_values = true)]
    duration: PositiveFinite,
    /// Leave out the Thelen muscles' comparison solve (about half a
    /// minute).
    #[arg(long)]
    skip_thelen: bool,
}

/// The task the arguments describe, checked before any solve: the
/// duration within [`MAX_DURATION`] and the output directory writable (the
/// node count is checked by its type as it is parsed).
fn validate(arguments: &Arguments) -> Result<Task, String> {
    let duration = arguments
        .duration
        .at_most(MAX_DURATION, "s")
        .map_err(|e| format!("--duration: {e}"))?;
    writable_dir(&arguments.out).map_err(|e| format!("--out: {e}"))?;
    Ok(Task {
        duration: duration.get(),
        nodes: arguments.nodes.get(),
        ..Task::default()
    })
}

/// RK4 step of the re-simulation, s.
const RESIMULATION_STEP: f64 = 1e-4;

fn progress(iteration: usize, objective: f64, infeasibility: f64, dual: f64) {
    if iteration.is_multiple_of(50) {
        eprintln!(
            "    iteration {iteration:4}: objective {objective:.6e}, largest defect {infeasibility:.2e}, dual infeasibility {dual:.2e}"
        );
    }
}

fn options() -> Options {
    Options {
        progress: Some(progress),
        ..Options::default()
    }
}

fn report(name: &str, run: &Solved) {
    eprintln!(
        "  {name}: {:?} after {} iterations, {:.2} s, objective {:.9e}, largest defect {:.1e}, tracking RMS {:.2e} rad",
        run.solution.status,
        run.solution.iterations,
        run.solution.seconds,
        run.solution.objective,
        run.max_defect,
        run.tracking_rms
    );
}

fn main() -> ExitCode {
    rodyn_plot_markers::register_sans_serif();
    match run(&Arguments::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("error: {error}");
            ExitCode::FAILURE
        }
    }
}

fn run(arguments: &Arguments) -> Result<(), Box<dyn std::error::Error>> {
    let task = validate(arguments)?;
    eprintln!(
        "muscle robot: {} nodes over {} s, {} variables",
        task.nodes,
        task.duration,
        task.nodes * (NX + NU)
    );

    eprintln!("  smooth muscles, analytic Jacobian, exact Hessian:");
    let exact = Task {
        hessian: Hessian::Exact,
        ..task
    };
    let main = solve_smooth(&exact, &options(), RESIMULATION_STEP)?;
    report("smooth, exact Hessian", &main);
    let fine_task = Task {
        nodes: 2 * task.nodes - 1,
        ..exact
    };
    eprintln!("  the same on {} nodes:", fine_task.nodes);
    let fine = solve_smooth(&fine_task, &options(), RESIMULATION_STEP)?;
    report("smooth, exact Hessian, refined grid", &fine);
    eprintln!("  smooth muscles, analytic Jacobian, quasi-Newton Hessian:");
    let quasi_newton = Task {
        hessian: Hessian::QuasiNewton,
        ..task
    };
    let lbfgs = solve_smooth(&quasi_newton, &options(), RESIMULATION_STEP)?;
    report("smooth, quasi-Newton", &lbfgs);
    let thelen = if arguments.skip_thelen {
        None
    } else {
        eprintln!("  Thelen muscles, analytic Jacobian, quasi-Newton Hessian:");
        let run = solve_thelen(
            &quasi_newton,
            Derivatives::Analytic,
            &options(),
            RESIMULATION_STEP,
        )?;
        report("Thelen, quasi-Newton", &run);
        Some(run)
    };

    let out = &arguments.out;
    write_controls(&out.join("controls.csv"), &task, &main.nodes)?;
    let mut rows = vec![
        row("De Groote 2016 (smooth)", "exact", &main),
        row("De Groote 2016 (smooth)", "exact", &fine),
        row("De Groote 2016 (smooth)", "quasi-Newton (L-BFGS)", &lbfgs),
    ];
    if let Some(run) = &thelen {
        rows.push(row("Thelen 2003", "quasi-Newton (L-BFGS)", run));
    }
    let refinement =
        (fine.solution.objective - main.solution.objective).abs() / main.solution.objective.abs();
    let results = results(&task, &main, &fine, refinement, thelen.as_ref(), rows);
    write_json(&out.join("results.json"), &results)?;
    let mut summary = results.clone();
    summary["solve_seconds"] = main.solution.seconds.into();
    summary["solve_seconds_per_row"] = [Some(&main), Some(&fine), Some(&lbfgs), thelen.as_ref()]
        .iter()
        .flatten()
        .map(|run| run.solution.seconds)
        .collect::<Vec<_>>()
        .into();
    write_json(&out.join("summary.json"), &summary)?;
    plot(&out.join("optimal_controls.svg"), &task, &main)?;
    eprintln!(
        "wrote controls.csv, results.json, summary.json and optimal_controls.svg to {}",
        out.display()
    );
    for (k, share) in effort_shares(&main.nodes).iter().enumerate() {
        eprintln!(
            "  m{}: {:.1} % of the activation effort",
            k + 1,
            100.0 * share
        );
    }
    eprintln!("  objective on 2N - 1 nodes differs by {refinement:.2e} (relative)");
    if !certified(&main) {
        return Err(format!(
            "the smooth solve is not certified: {:?}, largest defect {:.1e} (limit {MAX_DEFECT:e}), tracking RMS {:.2e} rad (limit {MAX_TRACKING_RMS:e})",
            main.solution.status, main.max_defect, main.tracking_rms
        )
        .into());
    }
    Ok(())
}

/// Converged to IPOPT's tolerance, feasible to 1e-8, and tracking when
/// replayed.
fn certified(run: &Solved) -> bool {
    run.solution.status == Status::Solved
        && run.max_defect <= MAX_DEFECT
        && run.tracking_rms <= MAX_TRACKING_RMS
}

fn row(muscles: &str, hessian: &str, run: &Solved) -> serde_json::Value {
    serde_json::json!({
        "muscles": muscles,
        "jacobian": run.jacobian,
        "hessian": hessian,
        "nodes": run.nodes.len(),
        "converged": run.solution.status == Status::Solved,
        "status": format!("{:?}", run.solution.status),
        "iterations": run.solution.iterations,
        "objective": run.solution.objective,
        "constraint_violation": run.max_defect,
        "final_dual_infeasibility": run.solution.dual_infeasibility,
        "resimulated_tracking_rms_rad": run.tracking_rms,
        "resimulated_tracking_max_rad": run.tracking_max,
        "activation_effort_share": effort_shares(&run.nodes),
        "dynamics_evaluations": run.evaluations,
    })
}

fn results(
    task: &Task,
    main: &Solved,
    fine: &Solved,
    refinement: f64,
    thelen: Option<&Solved>,
    rows: Vec<serde_json::Value>,
) -> serde_json::Value {
    serde_json::json!({
        "problem": "two-link, four-muscle robot (models/two_link_muscles.toml): joint angles held to q_d(t) = peak (1 - cos 2 pi t / T) / 2 at every node, start at rest, minimise the integral of the sum of squared activations plus r times the integral of the sum of squared excitation rates",
        "excitation_rate_weight_s2": EXCITATION_RATE_WEIGHT,
        "transcription": "trapezoidal direct collocation, controls linear between nodes",
        "solver": "IPOPT (MUMPS), tol 1e-8, constr_viol_tol 1e-8",
        "duration_s": task.duration,
        "nodes": task.nodes,
        "peak_angles_rad": task.peak,
        "muscles": "De Groote et al. 2016 (smooth curves and activation dynamics), rigid tendons",
        "jacobian": main.jacobian,
        "hessian": "exact: dual numbers over rodyn's analytic Jacobian",
        "converged": certified(main),
        "status": format!("{:?}", main.solution.status),
        "iterations": main.solution.iterations,
        "objective": main.solution.objective,
        "constraint_violation": main.max_defect,
        "final_dual_infeasibility": main.solution.dual_infeasibility,
        "resimulated_tracking_rms_rad": main.tracking_rms,
        "resimulated_tracking_max_rad": main.tracking_max,
        "resimulation": format!("rodyn RK4, step {RESIMULATION_STEP} s, from the first node's state, excitations linear between nodes"),
        "activation_effort_share": effort_shares(&main.nodes),
        "mesh_refinement": {
            "nodes": fine.nodes.len(),
            "objective": fine.solution.objective,
            "relative_objective_difference": refinement,
        },
        "thelen_comparison": thelen.map(|run| serde_json::json!({
            "converged": run.solution.status == Status::Solved,
            "status": format!("{:?}", run.solution.status),
            "objective": run.solution.objective,
            "constraint_violation": run.max_defect,
            "resimulated_tracking_rms_rad": run.tracking_rms,
        })),
        "rows": rows,
    })
}

fn write_json(path: &Path, value: &serde_json::Value) -> std::io::Result<()> {
    std::fs::write(path, serde_json::to_string_pretty(value)? + "\n")
}

fn write_controls(path: &Path, task: &Task, nodes: &[Node<NX, NU>]) -> std::io::Result<()> {
    let mut text = String::from(
        "time_s,u1,u2,u3,u4,a1,a2,a3,a4,q1_rad,q2_rad,q1_desired_rad,q2_desired_rad\n",
    );
    for node in nodes {
        let (desired, _) = task.desired(node.t);
        let _ = write!(text, "{:.6}", node.t);
        for value in node
            .u
            .iter()
            .chain(&node.x[2 * NV..])
            .chain(&node.x[..NV])
            .chain(&desired)
        {
            let _ = write!(text, ",{value:.9e}");
        }
        text.push('\n');
    }
    std::fs::write(path, text)
}

const MUSCLE_COLORS: [RGBColor; NU] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
];
/// Largest excitation and activation of a muscle the figure calls idle.
const IDLE: f64 = 1e-3;
/// Markers on each muscle's curves.
const MARKERS_PER_CURVE: usize = 10;
const JOINT_COLORS: [RGBColor; NV] = [RGBColor(0, 0, 0), RGBColor(120, 120, 120)];

/// One legend entry: a line (solid or dashed) or a dot, its marker
/// (index into [`rodyn_plot_markers::SHAPES`]) if it has one, and its text.
struct Entry {
    color: RGBColor,
    style: Mark,
    shape: Option<usize>,
    text: String,
}

#[derive(Clone, Copy, PartialEq)]
enum Mark {
    Line,
    Dashed,
    Dot,
}

/// A legend in its own area beside the chart, so that it covers no data.
fn legend(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    entries: &[Entry],
) -> Result<(), Box<dyn std::error::Error>> {
    for (k, entry) in entries.iter().enumerate() {
        let y = 40 + 22 * i32::try_from(k)?;
        let style = entry.color.stroke_width(2);
        match entry.style {
            Mark::Line => area.draw(&PathElement::new([(8, y), (36, y)], style))?,
            Mark::Dashed => {
                for x in [8, 20, 32] {
                    area.draw(&PathElement::new([(x, y), (x + 6, y)], style))?;
                }
            }
            Mark::Dot => {
                if entry.shape.is_none() {
                    area.draw(&Circle::new((22, y), 3, entry.color.filled()))?
                }
            }
        }
        if let Some(shape) = entry.shape {
            area.draw(&marker(shape, entry.color, (22, y)))?;
        }
        area.draw(&Text::new(
            entry.text.clone(),
            (44, y - 7),
            ("sans-serif", 14).into_font(),
        ))?;
    }
    Ok(())
}

/// Dashes along a polyline: every other one of its segments.
fn dashed(points: Vec<(f64, f64)>, color: RGBColor) -> Vec<PathElement<(f64, f64)>> {
    points
        .windows(2)
        .step_by(2)
        .map(|pair| PathElement::new(pair.to_vec(), color.stroke_width(2)))
        .collect()
}

fn plot(path: &Path, task: &Task, run: &Solved) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (1060, 760)).into_drawing_area();
    root.fill(&WHITE)?;
    let (upper, lower) = root.split_vertically(370);
    let (upper_chart, upper_legend) = upper.split_horizontally(720);
    let (lower_chart, lower_legend) = lower.split_horizontally(720);
    let samples: Vec<f64> = (0..=400)
        .map(|i| task.duration * f64::from(i) / 400.0)
        .collect();

    let peak = task.peak.iter().fold(0.0_f64, |m, p| m.max(p.abs()));
    let mut chart = ChartBuilder::on(&upper_chart)
        .caption("Desired and re-simulated joint angles", ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..task.duration, -0.05 * peak..1.1 * peak)?;
    chart
        .configure_mesh()
        .x_desc("time (s)")
        .y_desc("joint angle (rad)")
        .draw()?;
    let mut entries = Vec::new();
    for (j, name) in ["q1, shoulder", "q2, elbow"].into_iter().enumerate() {
        // The elbow's line dashed and its points squares: the joints
        // differ by more than their grey.
        let color = JOINT_COLORS[j];
        let desired: Vec<(f64, f64)> = samples.iter().map(|&t| (t, task.desired(t).0[j])).collect();
        if j == 0 {
            chart.draw_series(LineSeries::new(desired, color.stroke_width(2)))?;
        } else {
            chart.draw_series(dashed(desired, color))?;
        }
        let shape = 2 * j; // circle, square
        chart.draw_series(
            run.resimulated
                .iter()
                .step_by(run.resimulated.len() / 40)
                .map(|&(t, q)| EmptyElement::at((t, q[j])) + marker(shape, color, (0, 0))),
        )?;
        entries.push(Entry {
            color,
            style: if j == 0 { Mark::Line } else { Mark::Dashed },
            shape: None,
            text: format!("{name}, desired"),
        });
        entries.push(Entry {
            color,
            style: Mark::Dot,
            shape: Some(shape),
            text: format!("{name}, re-simulated"),
        });
    }
    legend(&upper_legend, &entries)?;

    let mut chart = ChartBuilder::on(&lower_chart)
        .caption(
            "Optimal excitations and resulting activations",
            ("sans-serif", 20),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..task.duration, 0.0..1.0)?;
    chart
        .configure_mesh()
        .x_desc("time (s)")
        .y_desc("excitation u, activation a (0-1)")
        .draw()?;
    let mut entries = Vec::new();
    for (i, color) in MUSCLE_COLORS.into_iter().enumerate() {
        // Idle muscles' curves lie on the time axis, one over the other:
        // the legend says so rather than leave them unseen.
        let largest = run
            .nodes
            .iter()
            .fold(0.0_f64, |m, n| m.max(n.u[i]).max(n.x[2 * NV + i]));
        let idle = if largest < IDLE {
            format!(" (below {IDLE:.0e})")
        } else {
            String::new()
        };
        let excitation: Vec<(f64, f64)> = run.nodes.iter().map(|n| (n.t, n.u[i])).collect();
        let activation: Vec<(f64, f64)> =
            run.nodes.iter().map(|n| (n.t, n.x[2 * NV + i])).collect();
        chart.draw_series(LineSeries::new(
            excitation.iter().copied(),
            color.stroke_width(2),
        ))?;
        // Markers on the excitation and (half a spacing on) the activation,
        // shifted per muscle so that the idle ones' do not hide each other:
        // muscles differ by more than their colour.
        let half_spacing = run.nodes.len() / (2 * MARKERS_PER_CURVE);
        chart.draw_series(
            sparse(&excitation, i, MARKERS_PER_CURVE)
                .chain(sparse(&activation[half_spacing..], i, MARKERS_PER_CURVE))
                .map(|p| EmptyElement::at(p) + marker(i, color, (0, 0))),
        )?;
        chart.draw_series(dashed(activation, color))?;
        entries.push(Entry {
            color,
            style: Mark::Line,
            shape: Some(i),
            text: format!("u{}, excitation of m{}{idle}", i + 1, i + 1),
        });
        entries.push(Entry {
            color,
            style: Mark::Dashed,
            shape: Some(i),
            text: format!("a{}, activation of m{}{idle}", i + 1, i + 1),
        });
    }
    legend(&lower_legend, &entries)?;
    root.present()?;
    Ok(())
}
