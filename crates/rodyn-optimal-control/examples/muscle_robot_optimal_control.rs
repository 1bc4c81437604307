//! The first seed's second example: energy-optimal muscle controls of the
//! two-link, four-muscle robot for desired joint trajectories, by direct
//! collocation (trapezoidal) solved with IPOPT.
//!
//! `cargo run --release -p rodyn-optimal-control --example muscle_robot_optimal_control -- --out DIR`
//!
//! Solves the problem once per derivative route (rodyn's analytic
//! derivatives, dual numbers throughout, finite differences) and writes,
//! from the first route that converged (analytic first; else the most
//! nearly feasible):
//! - `DIR/controls.csv`: time, the four excitations and activations, the
//!   joint angles and their desired values;
//! - `DIR/summary.json`: convergence, iterations, solve time, objective,
//!   largest defect, the re-simulated tracking error, each route's figures;
//! - `DIR/optimal_controls.svg`: the figure in the style of the seed's
//!   Fig. 4 (desired joint trajectories above, optimal controls below).

use clap::Parser;
use plotters::prelude::*;
use rodyn_cli::{writable_dir, Count, PositiveFinite};
use rodyn_optimal_control::collocation::Node;
use rodyn_optimal_control::ipopt::{solve, Options, Solution, Status};
use rodyn_optimal_control::muscle_robot::{
    resimulate, Derivatives, Task, EXCITATION_RATE_WEIGHT, NX,
};
use rodyn_scenarios::muscle_robot::{NU, NV};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

#[derive(Parser)]
#[command(
    about = "Energy-optimal muscle controls of the seed's two-link robot (direct collocation, IPOPT)"
)]
struct Arguments {
    /// Output directory (created if missing).
    #[arg(long)]
    out: PathBuf,
    /// Collocation nodes, 3 to 5000.
    #[arg(long, default_value_t = Count(Task::default().nodes), allow_hyphen_values = true)]
    nodes: Nodes,
    /// Duration of the motion, s, positive and at most 60 s.
    #[arg(long, default_value_t = PositiveFinite(Task::default().duration), allow_hyphen_values = true)]
    duration: PositiveFinite,
    /// Only the analytic route (skips the comparison of derivative routes).
    #[arg(long)]
    single: bool,
}

/// The objective's relative change over 10 iterations below which, with
/// the defects below 1e-7, the solve counts
/// as converged: Thelen's muscle has kinks (the force-velocity curve's
/// slopes differ either side of zero fibre velocity; activation and
/// deactivation have different time constants), so the dual infeasibility
/// stalls above IPOPT's `tol` and is reported beside.
const STATIONARY_OBJECTIVE: f64 = 1e-8;

/// Collocation nodes: at least the three a trapezoidal transcription
/// needs; at most 5000, whose problem IPOPT still holds in memory and
/// solves in minutes.
type Nodes = Count<3, 5000>;

/// The longest motion `--duration` takes (s): the re-simulation at
/// [`RESIMULATION_STEP`] is then 600 000 RK4 steps.
const MAX_DURATION: f64 = 60.0;

/// The task the arguments describe, checked before any solve: the
/// duration within [`MAX_DURATION`] and the output directory writable
/// (the node count is checked by its type as it is parsed).
fn checked_task(arguments: &Arguments) -> Result<Task, String> {
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

struct Run {
    route: Derivatives,
    solution: Solution,
    max_defect: f64,
    evaluations: usize,
    nodes: Vec<Node<NX, NU>>,
}

fn run(task: &Task, route: Derivatives) -> Result<Run, Box<dyn std::error::Error>> {
    eprintln!("  derivatives by {}:", route.name());
    let mut problem = task.transcribe(route)?;
    let options = Options {
        progress: Some(progress),
        stationary_objective: Some(STATIONARY_OBJECTIVE),
        ..Options::default()
    };
    let solution = solve(&mut problem, &options)?;
    let max_defect = problem
        .max_defect(&solution.x)
        .ok_or("the dynamics cannot be evaluated at the solution")?;
    eprintln!(
        "    {:?} after {} iterations, {:.2} s, effort {:.6e}, largest defect {:.1e}",
        solution.status, solution.iterations, solution.seconds, solution.objective, max_defect
    );
    Ok(Run {
        route,
        nodes: problem.unpack(&solution.x),
        evaluations: problem.dynamics.evaluations,
        solution,
        max_defect,
    })
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let arguments = Arguments::parse();
    let task = checked_task(&arguments)?;
    eprintln!(
        "muscle robot: {} nodes over {} s, {} variables",
        task.nodes,
        task.duration,
        task.nodes * (NX + NU)
    );
    let routes: &[Derivatives] = if arguments.single {
        &[Derivatives::Analytic]
    } else {
        &Derivatives::ALL
    };
    let runs = routes
        .iter()
        .map(|&route| run(&task, route))
        .collect::<Result<Vec<_>, _>>()?;
    let main = best(&runs).ok_or("no derivative route ran")?;
    eprintln!(
        "  writing the solution of the {} route; re-simulating its controls by RK4 at {RESIMULATION_STEP} s",
        main.route.name()
    );
    let (tracking_rms, tracking_max) = resimulate(&task, &main.nodes, RESIMULATION_STEP)?;

    write_controls(&arguments.out.join("controls.csv"), &task, &main.nodes)?;
    let participation = participation(&main.nodes);
    write_summary(
        &arguments.out.join("summary.json"),
        &task,
        main,
        &runs,
        tracking_rms,
        tracking_max,
        &participation,
    )?;
    plot(
        &arguments.out.join("optimal_controls.svg"),
        &task,
        &main.nodes,
    )?;
    eprintln!(
        "wrote controls.csv, summary.json and optimal_controls.svg to {}; re-simulated tracking RMS {tracking_rms:.2e} rad (largest {tracking_max:.2e} rad)",
        arguments.out.display()
    );
    for (k, share) in participation.iter().enumerate() {
        eprintln!(
            "  m{}: {:.1} % of the activation effort",
            k + 1,
            100.0 * share
        );
    }
    Ok(())
}

/// Each muscle's share of the activation effort `∫ Σᵢ aᵢ² dt`
/// (trapezoidal, as the objective).
fn participation(nodes: &[Node<NX, NU>]) -> [f64; NU] {
    let h = nodes[1].t - nodes[0].t;
    let integrals: [f64; NU] = core::array::from_fn(|i| {
        nodes
            .iter()
            .enumerate()
            .map(|(k, n)| {
                let w = if k == 0 || k + 1 == nodes.len() {
                    0.5
                } else {
                    1.0
                };
                w * h * n.x[2 * NV + i] * n.x[2 * NV + i]
            })
            .sum()
    });
    let total: f64 = integrals.iter().sum();
    integrals.map(|i| i / total)
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

/// The solution the files show: the first route (in [`Derivatives::ALL`]'s
/// order, analytic first) that converged, else the most nearly feasible.
fn best(runs: &[Run]) -> Option<&Run> {
    runs.iter().find(|run| converged(run)).or_else(|| {
        runs.iter()
            .min_by(|a, b| a.max_defect.total_cmp(&b.max_defect))
    })
}

fn converged(run: &Run) -> bool {
    matches!(
        run.solution.status,
        Status::Solved | Status::SolvedToAcceptableLevel
    )
}

#[allow(clippy::too_many_arguments)]
fn write_summary(
    path: &Path,
    task: &Task,
    main: &Run,
    runs: &[Run],
    tracking_rms: f64,
    tracking_max: f64,
    participation: &[f64; NU],
) -> std::io::Result<()> {
    let route = |run: &Run| {
        serde_json::json!({
            "derivatives": run.route.name(),
            "converged": converged(run),
            "status": format!("{:?}", run.solution.status),
            "iterations": run.solution.iterations,
            "final_dual_infeasibility": run.solution.dual_infeasibility,
            "solve_seconds": run.solution.seconds,
            "objective": run.solution.objective,
            "constraint_violation": run.max_defect,
            "dynamics_evaluations": run.evaluations,
        })
    };
    let summary = serde_json::json!({
        "problem": "two-link, four-muscle robot (models/two_link_muscles.toml): joint angles held to q_d(t) = peak (1 - cos 2 pi t / T) / 2 at every node, start at rest, minimise the integral of the sum of squared activations plus r times the integral of the sum of squared excitation rates",
        "excitation_rate_weight_s2": EXCITATION_RATE_WEIGHT,
        "transcription": "trapezoidal direct collocation, controls linear between nodes",
        "solver": "IPOPT (MUMPS), limited-memory quasi-Newton Hessian",
        "duration_s": task.duration,
        "nodes": task.nodes,
        "peak_angles_rad": task.peak,
        "derivatives": main.route.name(),
        "solution_shown": "the first route that converged (analytic, dual, finite-difference in that order), else the most nearly feasible",
        "converged": converged(main),
        "status": format!("{:?}", main.solution.status),
        "convergence_test": format!("IPOPT acceptable level: defects below 1e-7 and the objective's relative change below {STATIONARY_OBJECTIVE:e} for 10 iterations (the muscle model's kinks keep the dual infeasibility above IPOPT's tol)"),
        "final_dual_infeasibility": main.solution.dual_infeasibility,
        "iterations": main.solution.iterations,
        "solve_seconds": main.solution.seconds,
        "objective": main.solution.objective,
        "constraint_violation": main.max_defect,
        "resimulated_tracking_rms_rad": tracking_rms,
        "resimulated_tracking_max_rad": tracking_max,
        "resimulation": format!("rodyn RK4, step {RESIMULATION_STEP} s, from the first node's state, excitations linear between nodes"),
        "activation_effort_share": participation,
        "routes": runs.iter().map(route).collect::<Vec<_>>(),
    });
    std::fs::write(path, serde_json::to_string_pretty(&summary)? + "\n")
}

const MUSCLE_COLORS: [RGBColor; NU] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
];

fn plot(
    path: &Path,
    task: &Task,
    nodes: &[Node<NX, NU>],
) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (900, 760)).into_drawing_area();
    root.fill(&WHITE)?;
    let (upper, lower) = root.split_vertically(360);
    let samples: Vec<f64> = (0..=400)
        .map(|i| task.duration * f64::from(i) / 400.0)
        .collect();

    let peak = task.peak.iter().fold(0.0_f64, |m, p| m.max(p.abs()));
    let mut chart = ChartBuilder::on(&upper)
        .caption("Desired joint trajectories", ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..task.duration, -0.05 * peak..1.1 * peak)?;
    chart
        .configure_mesh()
        .x_desc("time (s)")
        .y_desc("joint angle (rad)")
        .draw()?;
    for (j, (name, color)) in [
        ("q1, shoulder", BLACK),
        ("q2, elbow", RGBColor(120, 120, 120)),
    ]
    .into_iter()
    .enumerate()
    {
        chart
            .draw_series(LineSeries::new(
                samples.iter().map(|&t| (t, task.desired(t).0[j])),
                color.stroke_width(2),
            ))?
            .label(format!("{name}, desired"))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color.stroke_width(2)));
        chart
            .draw_series(
                nodes
                    .iter()
                    .step_by(4)
                    .map(|n| Circle::new((n.t, n.x[j]), 3, color.filled())),
            )?
            .label(format!("{name}, collocation nodes"))
            .legend(move |(x, y)| Circle::new((x + 10, y), 3, color.filled()));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()?;

    let mut chart = ChartBuilder::on(&lower)
        .caption(
            "Optimised controls (muscle excitations)",
            ("sans-serif", 20),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..task.duration, 0.0..1.0)?;
    chart
        .configure_mesh()
        .x_desc("time (s)")
        .y_desc("excitation u (0-1)")
        .draw()?;
    for (i, color) in MUSCLE_COLORS.into_iter().enumerate() {
        chart
            .draw_series(LineSeries::new(
                nodes.iter().map(|n| (n.t, n.u[i])),
                color.stroke_width(2),
            ))?
            .label(format!("u{}, muscle m{}", i + 1, i + 1))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()?;
    root.present()?;
    Ok(())
}
