//! `rodyn-sim`: run rodyn simulations on a host, chart speed against
//! accuracy, and map where the methods fail.
//!
//! ```text
//! rodyn-sim run quadruped-trot --duration 5 --dt 1e-3 --method aba --integrator rk4 --scalar f64 -o out/
//! rodyn-sim run quadruped-trot --html out/trot.html
//! rodyn-sim chart -o docs/img/sim
//! rodyn-sim failures all -o docs/img/sim
//! ```

mod animate;
mod chart;
mod failures;
mod models;
mod plot;
mod run;
mod scenario;
mod trajectory;
mod viewer;

use clap::{Parser, Subcommand};
use scenario::{IntegratorKind, Method, RunConfig, ScalarType, Scenario};
use std::path::PathBuf;

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
    /// Run one scenario: CSV trajectory, SVG plot, GIF animation.
    Run {
        /// The scenario.
        scenario: Scenario,
        /// Simulated time (s).
        #[arg(long, default_value_t = 5.0)]
        duration: f64,
        /// Step (s); by default the scenario's own (0.5 ms for the
        /// quadruped, whose stiff feet the default semi-implicit Euler
        /// cannot hold at 1 ms; 1 ms otherwise).
        #[arg(long)]
        dt: Option<f64>,
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
            scenario,
            duration,
            dt,
            method,
            integrator,
            scalar,
            out,
            html,
        } => {
            let config = RunConfig {
                scenario,
                duration,
                dt: dt.unwrap_or_else(|| scenario.default_step()),
                method,
                scalar,
                integrator,
                sample_interval: 0.01,
            };
            run::run_command(&config, &out, html.as_deref())
        }
        Command::Chart { out } => chart::chart_command(&out),
        Command::Failures { experiment, out } => failures::failures_command(experiment, &out),
    };
    if let Err(e) = result {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}
