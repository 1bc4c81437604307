//! `rodyn-sim`: run rodyn simulations on a host, chart speed against
//! accuracy, and map where the methods fail.
//!
//! ```text
//! rodyn-sim run quadruped-trot --duration 5 --dt 1e-3 --method aba --integrator rk4 --scalar f64 -o out/
//! rodyn-sim run quadruped-trot --html out/trot.html
//! rodyn-sim run --model models/urdf/panda.urdf --integrator rk4 -o out/
//! rodyn-sim run --model models/solo12.toml --ground --duration 2 -o out/
//! rodyn-sim chart -o docs/img/sim
//! rodyn-sim chart --replot -o docs/img/sim
//! rodyn-sim failures all -o docs/img/sim
//! ```

mod animate;
mod chart;
mod failures;
mod file_run;
mod ground;
mod models;
mod plot;
mod progress;
mod run;
mod scenario;
mod trajectory;
mod viewer;

use clap::{Parser, Subcommand};
use ground::GroundOptions;
use rodyn_cli::{
    shown, step_count, writable_dir, writable_file, NonNegativeFinite, PositiveFinite,
};
use scenario::{IntegratorKind, Method, RunConfig, ScalarType, Scenario, MAX_DURATION, MAX_STEPS};
use std::path::{Path, PathBuf};

#[derive(Parser)]
#[command(
    name = "rodyn-sim",
    version,
    about = "Simulate rodyn models; chart speed against accuracy; map where methods fail"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run one scenario: CSV trajectory, SVG plot, GIF animation; or a
    /// model file (--model) under gravity, on the ground with --ground:
    /// CSV and plot.
    Run {
        /// The scenario (or give --model).
        #[arg(required_unless_present = "model")]
        scenario: Option<Scenario>,
        /// A URDF or rodyn TOML file to simulate instead of a scenario,
        /// read at run time: motion under gravity from its neutral
        /// configuration, no joint torques, the file's drives at zero
        /// input, contacts with --ground.
        #[arg(long, value_name = "FILE", conflicts_with = "scenario")]
        model: Option<PathBuf>,
        /// With --model: the URDF's root on a free-flyer.
        #[arg(long, requires = "model")]
        floating_base: bool,
        /// With --model: a compliant ground at z = 0 under contact points
        /// (--contact, else the file's contact tables, else every frame); a
        /// floating base starts above it (--drop-height).
        #[arg(long, requires = "model")]
        ground: bool,
        /// With --ground: a frame whose origin touches the ground
        /// (repeatable; replaces the file's contacts).
        #[arg(long, value_name = "FRAME", requires = "ground")]
        contact: Vec<String>,
        /// With --ground: the Coulomb friction coefficient, zero or
        /// positive, at most 10 (default: the file's, else 0.8).
        #[arg(long, requires = "ground", allow_hyphen_values = true)]
        friction: Option<NonNegativeFinite>,
        /// With --ground: the coefficient of restitution of every contact
        /// point, 0 (no bounce) to 1; sets its damping for an even share of
        /// the model's mass (default: the file's damping, else 0).
        #[arg(long, requires = "ground", allow_hyphen_values = true)]
        restitution: Option<NonNegativeFinite>,
        /// With --ground and a floating base: the height (m) of the lowest
        /// contact point at the start, zero or positive, at most 100 m
        /// (default 0.05).
        #[arg(long, requires = "ground", allow_hyphen_values = true)]
        drop_height: Option<NonNegativeFinite>,
        /// Simulated time (s), positive, at most 1000 s and 10 million steps.
        // Hyphen values reach the value parser, which names the argument,
        // instead of being taken for an unknown option.
        #[arg(long, default_value = "5", allow_hyphen_values = true)]
        duration: PositiveFinite,
        /// Step (s); by default the scenario's own (0.5 ms for the
        /// quadruped, whose stiff feet the default semi-implicit Euler
        /// cannot hold at 1 ms; 1 ms otherwise).
        #[arg(long, allow_hyphen_values = true)]
        dt: Option<PositiveFinite>,
        /// Forward-dynamics method.
        #[arg(long, value_enum, default_value_t = Method::Aba)]
        method: Method,
        /// Integrator.
        #[arg(long, value_enum, default_value_t = IntegratorKind::SemiImplicitEuler)]
        integrator: IntegratorKind,
        /// Scalar type.
        #[arg(long, value_enum, default_value_t = ScalarType::F64)]
        scalar: ScalarType,
        /// Output directory.
        #[arg(short, long, default_value = "out")]
        out: PathBuf,
        /// Also write the run as a 3-D viewer page (one HTML file that
        /// opens in any browser, offline).
        #[arg(long, value_name = "FILE")]
        html: Option<PathBuf>,
    },
    /// The speed-versus-accuracy chart for the arm, the quadruped and the muscle robot.
    Chart {
        /// Output directory.
        #[arg(short, long, default_value = "docs/img/sim")]
        out: PathBuf,
        /// Redraw the charts from the chart-*.csv already in the output
        /// directory, without running (the costs are host timings).
        #[arg(long)]
        replot: bool,
        /// Only this scenario's chart (arm-swing, quadruped-stand or muscle-robot).
        #[arg(long, value_enum)]
        scenario: Option<Scenario>,
    },
    /// The maps of where methods fail.
    Failures {
        /// Which experiment.
        #[arg(value_enum, default_value_t = failures::Experiment::All)]
        experiment: failures::Experiment,
        /// Output directory.
        #[arg(short, long, default_value = "docs/img/sim")]
        out: PathBuf,
    },
}

fn main() {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Run {
            scenario: None,
            model: Some(model),
            floating_base,
            ground,
            contact,
            friction,
            restitution,
            drop_height,
            duration,
            dt,
            method,
            integrator,
            scalar,
            out,
            html,
        } => {
            let run = file_run::FileRun {
                model: &model,
                floating_base,
                duration: duration.get(),
                dt: dt.map_or(1e-3, PositiveFinite::get),
                method,
                integrator,
                sample_interval: 0.01,
                ground: ground.then(|| GroundOptions {
                    contacts: contact,
                    friction: friction.map(NonNegativeFinite::get),
                    restitution: restitution.map(NonNegativeFinite::get),
                }),
                drop_height: drop_height.map(NonNegativeFinite::get),
            };
            check_file_run(&run, scalar, &out, html.as_deref())
                .and_then(|()| file_run::run_file(&run, &out, html.as_deref()))
        }
        Command::Run {
            scenario: Some(scenario),
            duration,
            dt,
            method,
            integrator,
            scalar,
            out,
            html,
            ..
        } => {
            let config = RunConfig {
                scenario,
                duration: duration.get(),
                dt: dt.map_or_else(|| scenario.default_step(), PositiveFinite::get),
                method,
                scalar,
                integrator,
                sample_interval: 0.01,
            };
            check_run(config.duration, config.dt, &out, html.as_deref())
                .and_then(|()| run::run_command(&config, &out, html.as_deref()))
        }
        Command::Run { .. } => Err("give a scenario or --model FILE".into()),
        Command::Chart {
            out,
            replot,
            scenario,
        } => check_output(&out).and_then(|()| chart::chart_command(&out, replot, scenario)),
        Command::Failures { experiment, out } => {
            check_output(&out).and_then(|()| failures::failures_command(experiment, &out))
        }
    };
    if let Err(e) = result {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}

/// Refuses, before any work, a run that would not end in reasonable time
/// or would take no step, and an output directory or page that cannot be
/// written.
fn check_run(
    duration: f64,
    dt: f64,
    out: &Path,
    html: Option<&Path>,
) -> Result<(), Box<dyn std::error::Error>> {
    if duration > MAX_DURATION {
        return Err(format!(
            "--duration {} s is above the limit of {MAX_DURATION} s of simulated time",
            shown(duration)
        )
        .into());
    }
    step_count(duration, dt, MAX_STEPS, "--duration", "--dt")?;
    if let Some(page) = html {
        let folder = page.parent().filter(|f| !f.as_os_str().is_empty());
        if let Some(folder) = folder {
            std::fs::create_dir_all(folder).map_err(|e| {
                format!(
                    "--html: cannot create the folder of {}: {e}",
                    page.display()
                )
            })?;
        }
        writable_file(page).map_err(|e| format!("--html: {e}"))?;
    }
    check_output(out)
}

/// The largest `--friction` a run takes.
const MAX_FRICTION: f64 = 10.0;
/// The largest `--drop-height` (m) a run takes.
const MAX_DROP_HEIGHT: f64 = 100.0;

/// Refuses a file run's settings the run-time model cannot honour, the
/// limits of [`check_run`], and an unreadable model file, before any work.
fn check_file_run(
    run: &file_run::FileRun<'_>,
    scalar: ScalarType,
    out: &Path,
    html: Option<&Path>,
) -> Result<(), Box<dyn std::error::Error>> {
    if scalar != ScalarType::F64 {
        return Err("--scalar: a model file runs in f64 (the run-time model's scalar)".into());
    }
    file_run::check_integrator(run.integrator)?;
    if let Some(ground) = &run.ground {
        for (option, value, max, what) in [
            (
                "--friction",
                ground.friction,
                MAX_FRICTION,
                "a friction coefficient",
            ),
            (
                "--restitution",
                ground.restitution,
                1.0,
                "a coefficient of restitution",
            ),
        ] {
            if let Some(x) = value {
                NonNegativeFinite(x)
                    .at_most(max, what)
                    .map_err(|e| format!("{option}: {e}"))?;
            }
        }
    }
    if let Some(h) = run.drop_height {
        NonNegativeFinite(h)
            .at_most(MAX_DROP_HEIGHT, "a drop height (m)")
            .map_err(|e| format!("--drop-height: {e}"))?;
    }
    if !run.model.is_file() {
        return Err(format!("--model {}: no such file", run.model.display()).into());
    }
    check_run(run.duration, run.dt, out, html)
}

/// The output directory, created and checked for writing.
fn check_output(out: &Path) -> Result<(), Box<dyn std::error::Error>> {
    writable_dir(out).map_err(|e| format!("--out: {e}").into())
}
