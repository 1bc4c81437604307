//! `cargo xtask docs [--check]`: the figures and tables of the docs that a
//! command of the repository draws bit for bit the same on every run.
//!
//! Every generator writes into a fresh temporary directory. Without
//! `--check` the files it wrote replace the committed ones; with `--check`
//! nothing is written, and the command fails listing each committed file
//! that differs from its regenerated self or is missing.
//!
//! Not regenerated here, and why (each says so where it is shown):
//! * timings (the Pinocchio comparisons, the ABA/CRBA crossover, the
//!   speed-against-accuracy charts, criterion): wall clock, so labelled with
//!   the machine, the date and the command instead (the crossover and the
//!   charts keep their timings in committed CSV files, and only their
//!   drawings are regenerated here);
//! * the example-robot-data sweep and the host arithmetic table
//!   (`cargo xtask host-profile --table`): they need Pinocchio, which the
//!   repository does not hold;
//! * the optimal-control example's `summary.json`: the same results as
//!   its `results.json` (which is checked) plus the solve times.

use crate::costs::{self, ProbeRuns};
use crate::shell;
use anyhow::{bail, Context, Result};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// How the generators run.
#[derive(Clone, Copy, Debug)]
pub struct Options {
    /// Where the firmware cost tables take their probes' output from.
    pub cost_runs: ProbeRuns,
}

/// One command that writes part of the docs.
struct Generator {
    /// A short name for the report.
    name: &'static str,
    /// Runs the command with its output in `out`.
    run: fn(out: &Path, options: Options) -> Result<()>,
    /// (file the command writes under `out`, the committed file it becomes,
    /// both from the repository root's point of view).
    files: &'static [(&'static str, &'static str)],
}

/// The model pictures of `docs/sections/models.md`: (model file, the
/// `render` arguments after it, picture).
const MODEL_PICTURES: [(&str, &[&str], &str); 6] = [
    (
        "models/pendulum.toml",
        &["--q", "0.6", "--view", "xy"],
        "pendulum.svg",
    ),
    (
        "models/two_link_muscles.toml",
        &["--q", "0.5,0.8"],
        "two_link_muscles.svg",
    ),
    (
        "models/gait_planar.toml",
        &["--q", "0,0,0,0.05,0.35,-0.1,-0.05,-0.3,-0.6,0.15"],
        "gait_planar.svg",
    ),
    (
        "models/aibo.toml",
        &[
            "--q",
            "0,0,0,0,0,0,1,0.4,0,-0.7,0.4,0,-0.7,-0.5,0,0.9,-0.5,0,0.9",
        ],
        "aibo.svg",
    ),
    (
        "models/panda.toml",
        &["--q", "0,-0.6,0,-2.2,0,1.6,0.8"],
        "panda.svg",
    ),
    (
        "models/solo12.toml",
        &[
            "--q",
            "0,0,0.3,0,0,0,1,0,0.8,-1.6,0,0.8,-1.6,0,-0.8,1.6,0,-0.8,1.6",
        ],
        "solo12.svg",
    ),
];

/// Where the measured walking data lives (OpenSim's subject01).
const GAIT_DATA: &str = "data/gait";

const GENERATORS: &[Generator] = &[
    Generator {
        name: "model pictures (rodyn-model render)",
        run: model_pictures,
        files: &[
            ("pendulum.svg", "docs/img/models/pendulum.svg"),
            (
                "two_link_muscles.svg",
                "docs/img/models/two_link_muscles.svg",
            ),
            ("gait_planar.svg", "docs/img/models/gait_planar.svg"),
            ("aibo.svg", "docs/img/models/aibo.svg"),
            ("panda.svg", "docs/img/models/panda.svg"),
            ("solo12.svg", "docs/img/models/solo12.svg"),
        ],
    },
    Generator {
        name: "failure maps (rodyn-sim failures all)",
        run: failure_maps,
        files: &[
            (
                "failure-chain-length.svg",
                "docs/img/sim/failure-chain-length.svg",
            ),
            (
                "failure-stiffness.svg",
                "docs/img/sim/failure-stiffness.svg",
            ),
            ("failure-massless.svg", "docs/img/sim/failure-massless.svg"),
            (
                "failure-quaternion.svg",
                "docs/img/sim/failure-quaternion.svg",
            ),
            ("failure-contact.svg", "docs/img/sim/failure-contact.svg"),
        ],
    },
    Generator {
        name: "quadruped trot (rodyn-sim run quadruped-trot)",
        run: quadruped_trot,
        files: &[
            ("quadruped-trot.svg", "docs/img/sim/quadruped-trot.svg"),
            (
                "quadruped-trot-forces.svg",
                "docs/img/sim/quadruped-trot-forces.svg",
            ),
            ("quadruped-trot.gif", "docs/img/sim/quadruped-trot.gif"),
        ],
    },
    Generator {
        name:
            "speed-against-accuracy charts, redrawn from their timings (rodyn-sim chart --replot)",
        run: charts_replotted,
        files: &[
            ("chart-arm-swing.svg", "docs/img/sim/chart-arm-swing.svg"),
            (
                "chart-quadruped-stand.svg",
                "docs/img/sim/chart-quadruped-stand.svg",
            ),
            (
                "chart-quadruped-stand-position.svg",
                "docs/img/sim/chart-quadruped-stand-position.svg",
            ),
            (
                "chart-muscle-robot.svg",
                "docs/img/sim/chart-muscle-robot.svg",
            ),
        ],
    },
    Generator {
        name: "ABA/CRBA crossover chart, redrawn from its timings (crossover --replot)",
        run: crossover_replotted,
        files: &[("crossover.svg", "docs/img/perf/crossover.svg")],
    },
    Generator {
        name: "optimal control of the muscle robot (example muscle_robot_optimal_control)",
        run: optimal_control,
        files: &[
            ("results.json", "docs/img/optimal_control/results.json"),
            ("controls.csv", "docs/img/optimal_control/controls.csv"),
            (
                "optimal_controls.svg",
                "docs/img/optimal_control/optimal_controls.svg",
            ),
        ],
    },
    Generator {
        name: "muscle robot figures (rodyn-drive-plots)",
        run: drive_plots,
        files: &[
            (
                "muscle_robot_trajectory.svg",
                "docs/img/drives/muscle_robot_trajectory.svg",
            ),
            (
                "muscle_robot_sensitivity.svg",
                "docs/img/drives/muscle_robot_sensitivity.svg",
            ),
        ],
    },
    Generator {
        name: "synthetic gait cycle (example gait_prosthesis)",
        run: gait_synthetic,
        files: &[
            ("joint_moments.svg", "docs/img/gait/joint_moments.svg"),
            ("socket_torque.svg", "docs/img/gait/socket_torque.svg"),
            ("socket_forces.svg", "docs/img/gait/socket_forces.svg"),
            ("joint_angles.svg", "docs/img/gait/joint_angles.svg"),
            ("ground_reaction.svg", "docs/img/gait/ground_reaction.svg"),
        ],
    },
    Generator {
        name: "measured gait, subject01 (example gait_subject01)",
        run: gait_subject01,
        files: &[
            ("joint_loads.csv", "docs/img/gait_subject01/joint_loads.csv"),
            ("summary.txt", "docs/img/gait_subject01/summary.txt"),
            (
                "joint_moments.svg",
                "docs/img/gait_subject01/joint_moments.svg",
            ),
            ("residuals.svg", "docs/img/gait_subject01/residuals.svg"),
            (
                "socket_loads.svg",
                "docs/img/gait_subject01/socket_loads.svg",
            ),
        ],
    },
    Generator {
        name: "f32 and f64 error tables (example f32_error_table)",
        run: error_tables,
        files: &[("docs/sections/accuracy.md", "docs/sections/accuracy.md")],
    },
    Generator {
        name: "Cortex-M cost, size and stack tables (cargo xtask costs)",
        run: cost_tables,
        files: &[
            ("docs/sections/firmware.md", "docs/sections/firmware.md"),
            (
                "docs/sections/cortex_m_family.md",
                "docs/sections/cortex_m_family.md",
            ),
            ("README.md", "README.md"),
            ("firmware/expected/sizes.txt", "firmware/expected/sizes.txt"),
            (
                "firmware/expected/panic_sites.txt",
                "firmware/expected/panic_sites.txt",
            ),
        ],
    },
];

/// The check `cargo xtask test` runs, after its firmware runs: the cost
/// tables from those runs' logs rather than from new ones.
pub fn check_after_test() -> Result<()> {
    check(Options {
        cost_runs: ProbeRuns::LastLogs,
    })
}

/// `cargo xtask docs [--check]`.
pub fn run(args: &[String]) -> Result<()> {
    match args {
        [] => regenerate(Options {
            cost_runs: ProbeRuns::Fresh,
        }),
        [flag] if flag == "--check" => check(Options {
            cost_runs: ProbeRuns::Fresh,
        }),
        _ => bail!("usage: cargo xtask docs [--check]"),
    }
}

/// Regenerates every file and replaces the committed ones that differ.
fn regenerate(options: Options) -> Result<()> {
    let out = Scratch::new()?;
    generate_all(&out.0, options)?;
    let root = shell::root();
    for generator in GENERATORS {
        for (generated, committed) in generator.files {
            let from = out.0.join(generated_path(generator, generated));
            let to = root.join(committed);
            let new = std::fs::read(&from)
                .with_context(|| format!("{} did not write {generated}", generator.name))?;
            if std::fs::read(&to).ok().as_deref() == Some(&new[..]) {
                continue;
            }
            if let Some(dir) = to.parent() {
                std::fs::create_dir_all(dir)?;
            }
            std::fs::write(&to, new).with_context(|| format!("cannot write {}", to.display()))?;
            println!("updated {committed}");
        }
    }
    println!("xtask docs: regenerated");
    Ok(())
}

/// Regenerates every file into a temporary directory and fails naming
/// each committed file that differs or is missing.
pub fn check(options: Options) -> Result<()> {
    let started = Instant::now();
    let out = Scratch::new()?;
    generate_all(&out.0, options)?;
    let mut stale = Vec::new();
    for generator in GENERATORS {
        let files: Vec<(PathBuf, &str)> = generator
            .files
            .iter()
            .map(|(generated, committed)| {
                (out.0.join(generated_path(generator, generated)), *committed)
            })
            .collect();
        stale.extend(compare(&shell::root(), &files)?);
    }
    if !stale.is_empty() {
        bail!(
            "the docs differ from what their commands produce (`cargo xtask docs` rewrites them):\n  {}",
            stale.join("\n  ")
        );
    }
    println!(
        "xtask docs --check: every generated figure and table is up to date ({:.0} s)",
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// Each of `files` (a freshly generated file, the committed path from
/// `root` it should equal) whose committed copy is missing or differs, as
/// a line naming it.
fn compare(root: &Path, files: &[(PathBuf, &str)]) -> Result<Vec<String>> {
    let mut stale = Vec::new();
    for (generated, committed) in files {
        let new = std::fs::read(generated)
            .with_context(|| format!("the generator did not write {}", generated.display()))?;
        match std::fs::read(root.join(committed)) {
            Err(_) => stale.push(format!("{committed}: missing")),
            Ok(old) if old != new => stale.push(format!(
                "{committed}: differs ({} bytes committed, {} regenerated{})",
                old.len(),
                new.len(),
                first_difference(&old, &new)
                    .map(|at| format!(", first at byte {at}"))
                    .unwrap_or_default()
            )),
            Ok(_) => {}
        }
    }
    Ok(stale)
}

/// The first byte at which `a` and `b` differ, when one is not a prefix
/// of the other.
fn first_difference(a: &[u8], b: &[u8]) -> Option<usize> {
    a.iter().zip(b).position(|(x, y)| x != y)
}

/// Runs every generator into its own directory under `out`.
fn generate_all(out: &Path, options: Options) -> Result<()> {
    for generator in GENERATORS {
        let started = Instant::now();
        let dir = out.join(directory_name(generator));
        std::fs::create_dir_all(&dir)?;
        println!("xtask docs: {}", generator.name);
        (generator.run)(&dir, options)
            .with_context(|| format!("while generating {}", generator.name))?;
        println!(
            "xtask docs: {} in {:.0} s",
            generator.name,
            started.elapsed().as_secs_f64()
        );
    }
    Ok(())
}

/// A generator's directory under the scratch directory: its position in
/// [`GENERATORS`], so that two generators' files never meet.
fn directory_name(generator: &Generator) -> String {
    let index = GENERATORS
        .iter()
        .position(|g| std::ptr::eq(g, generator))
        .unwrap_or(GENERATORS.len());
    format!("{index}")
}

/// Where `file` of `generator` lands under the scratch directory.
fn generated_path(generator: &Generator, file: &str) -> PathBuf {
    Path::new(&directory_name(generator)).join(file)
}

/// A temporary directory removed when dropped.
struct Scratch(PathBuf);

impl Scratch {
    fn new() -> Result<Self> {
        let dir = std::env::temp_dir().join(format!("rodyn-docs-{}", std::process::id()));
        if dir.exists() {
            std::fs::remove_dir_all(&dir)?;
        }
        std::fs::create_dir_all(&dir)
            .with_context(|| format!("cannot create {}", dir.display()))?;
        Ok(Self(dir))
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// `cargo run --release --quiet -p PACKAGE --no-default-features
/// [--bin|--example NAME] -- ARGS` at the repository root; its standard
/// output. Without default features: the only ones (rodyn-sim's and the
/// host tests') add the run-time model's size classes, minutes of release
/// compiling that no figure needs.
fn cargo_run(package: &str, target: &[&str], args: &[&str]) -> Result<String> {
    let mut command = shell::cargo_command(&shell::root());
    command
        .args(["run", "--release", "--quiet", "-p", package])
        .arg("--no-default-features")
        .args(target)
        .arg("--")
        .args(args);
    run_quietly(&mut command)
}

/// Runs `command` with its output kept back unless it fails; returns its
/// standard output.
fn run_quietly(command: &mut Command) -> Result<String> {
    println!("$ {}", shell::describe(command));
    let output = command
        .output()
        .with_context(|| format!("cannot start {}", shell::describe(command)))?;
    if !output.status.success() {
        bail!(
            "`{}` failed with {}:\n{}{}",
            shell::describe(command),
            output.status,
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        );
    }
    Ok(String::from_utf8_lossy(&output.stdout).into_owned())
}

fn text(path: &Path) -> Result<&str> {
    path.to_str()
        .with_context(|| format!("{} is not UTF-8", path.display()))
}

fn model_pictures(out: &Path, _: Options) -> Result<()> {
    for (model, args, picture) in MODEL_PICTURES {
        let picture = out.join(picture);
        let mut all = vec!["render", model];
        all.extend_from_slice(args);
        all.extend_from_slice(&["-o", text(&picture)?]);
        cargo_run("rodyn-model", &[], &all)?;
    }
    Ok(())
}

fn failure_maps(out: &Path, _: Options) -> Result<()> {
    cargo_run("rodyn-sim", &[], &["failures", "all", "-o", text(out)?]).map(drop)
}

fn quadruped_trot(out: &Path, _: Options) -> Result<()> {
    cargo_run(
        "rodyn-sim",
        &[],
        &["run", "quadruped-trot", "-o", text(out)?],
    )
    .map(drop)
}

/// The charts' timings are wall clock, so their CSV files are committed
/// and only the drawing is regenerated from them.
fn charts_replotted(out: &Path, _: Options) -> Result<()> {
    for chart in ["arm-swing", "quadruped-stand", "muscle-robot"] {
        let csv = format!("chart-{chart}.csv");
        std::fs::copy(
            shell::root().join("docs/img/sim").join(&csv),
            out.join(&csv),
        )
        .with_context(|| format!("copying docs/img/sim/{csv}"))?;
    }
    cargo_run("rodyn-sim", &[], &["chart", "--replot", "-o", text(out)?]).map(drop)
}

/// The crossover's timings are wall clock: its CSV file is committed and
/// only the chart is redrawn from it.
fn crossover_replotted(out: &Path, _: Options) -> Result<()> {
    std::fs::copy(
        shell::root().join("docs/img/perf/crossover.csv"),
        out.join("crossover.csv"),
    )
    .context("copying docs/img/perf/crossover.csv")?;
    let chart = out.join("crossover.svg");
    cargo_run(
        "rodyn-bench",
        &["--bin", "crossover"],
        &["--replot", "--out", text(&chart)?],
    )
    .map(drop)
}

/// The solve is deterministic; only `summary.json`'s seconds are not, and
/// that file is left out.
fn optimal_control(out: &Path, _: Options) -> Result<()> {
    cargo_run(
        "rodyn-optimal-control",
        &["--example", "muscle_robot_optimal_control"],
        &["--out", text(out)?],
    )
    .map(drop)
}

fn drive_plots(out: &Path, _: Options) -> Result<()> {
    cargo_run("rodyn-drive-plots", &[], &["--out", text(out)?]).map(drop)
}

fn gait_synthetic(out: &Path, _: Options) -> Result<()> {
    cargo_run(
        "rodyn-host-tests",
        &["--example", "gait_prosthesis"],
        &["--out", text(out)?],
    )
    .map(drop)
}

fn gait_subject01(out: &Path, _: Options) -> Result<()> {
    let data = shell::root().join(GAIT_DATA);
    if !data.is_dir() {
        bail!(
            "{} is missing: the measured walking data (OpenSim's subject01) lives there",
            data.display()
        );
    }
    cargo_run(
        "rodyn-host-tests",
        &["--example", "gait_subject01"],
        &["--out", text(out)?, "--data", text(&data)?],
    )
    .map(drop)
}

/// The two tables `f32_error_table` prints, put between the
/// `f32-errors` and `f64-errors` markers of the accuracy page.
fn error_tables(out: &Path, _: Options) -> Result<()> {
    const PAGE: &str = "docs/sections/accuracy.md";
    let printed = cargo_run("rodyn-host-tests", &["--example", "f32_error_table"], &[])?;
    let tables = markdown_tables(&printed);
    let [f32_table, f64_table] = tables.as_slice() else {
        bail!(
            "f32_error_table printed {} tables, not the two (f32, f64) the accuracy page shows",
            tables.len()
        );
    };
    let page = std::fs::read_to_string(shell::root().join(PAGE))
        .with_context(|| format!("cannot read {PAGE}"))?;
    let page = costs::replace_between(&page, "f32-errors", f32_table)
        .and_then(|page| costs::replace_between(&page, "f64-errors", f64_table))
        .with_context(|| format!("in {PAGE}"))?;
    let path = out.join(PAGE);
    std::fs::create_dir_all(path.parent().context("a page's directory")?)?;
    std::fs::write(&path, page).with_context(|| format!("cannot write {}", path.display()))
}

/// The Markdown tables in `text`: each run of lines starting with `|`,
/// with its final newline.
fn markdown_tables(text: &str) -> Vec<String> {
    let mut tables = Vec::new();
    let mut current = String::new();
    for line in text.lines() {
        if line.starts_with('|') {
            current.push_str(line);
            current.push('\n');
        } else if !current.is_empty() {
            tables.push(std::mem::take(&mut current));
        }
    }
    if !current.is_empty() {
        tables.push(current);
    }
    tables
}

fn cost_tables(out: &Path, options: Options) -> Result<()> {
    for (path, contents) in costs::generated_files(options.cost_runs)? {
        let path = out.join(path);
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)?;
        }
        std::fs::write(&path, contents)
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A copy of the repository's files in a temporary directory, removed
    /// when dropped.
    struct Copy(PathBuf);

    impl Copy {
        fn new(name: &str) -> Self {
            let dir =
                std::env::temp_dir().join(format!("rodyn-docs-test-{name}-{}", std::process::id()));
            let _ = std::fs::remove_dir_all(&dir);
            std::fs::create_dir_all(dir.join("docs/img/models")).unwrap();
            Self(dir)
        }
    }

    impl Drop for Copy {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }

    /// The check reports a stale figure and a missing one, and only them:
    /// a committed picture with one byte changed, against the picture as
    /// committed in the repository standing for its regenerated self.
    #[test]
    fn check_names_a_stale_and_a_missing_figure_and_passes_a_current_one() {
        let repo = shell::root();
        let committed = |name: &str| format!("docs/img/models/{name}");
        let copy = Copy::new("stale");
        for name in ["pendulum.svg", "panda.svg"] {
            std::fs::copy(repo.join(committed(name)), copy.0.join(committed(name))).unwrap();
        }
        // One byte of the copy's pendulum picture changed: a stale figure.
        let stale = copy.0.join(committed("pendulum.svg"));
        let mut bytes = std::fs::read(&stale).unwrap();
        let at = bytes.len() / 2;
        bytes[at] = bytes[at].wrapping_add(1);
        std::fs::write(&stale, bytes).unwrap();

        let regenerated = |name: &str| (repo.join(committed(name)), committed(name));
        let files: Vec<(PathBuf, String)> = ["pendulum.svg", "panda.svg", "aibo.svg"]
            .into_iter()
            .map(regenerated)
            .collect();
        let files: Vec<(PathBuf, &str)> =
            files.iter().map(|(p, c)| (p.clone(), c.as_str())).collect();
        let report = compare(&copy.0, &files).unwrap();
        assert_eq!(report.len(), 2, "{report:?}");
        assert!(
            report[0].starts_with("docs/img/models/pendulum.svg: differs")
                && report[0].ends_with(&format!("first at byte {at})")),
            "{}",
            report[0]
        );
        assert_eq!(report[1], "docs/img/models/aibo.svg: missing");
    }

    #[test]
    fn markdown_tables_are_the_runs_of_table_lines() {
        let printed = "### f32\n\n| a |\n|---|\n| 1 |\n\n### f64\n| b |\n| 2 |\n";
        assert_eq!(
            markdown_tables(printed),
            ["| a |\n|---|\n| 1 |\n", "| b |\n| 2 |\n"]
        );
        assert!(markdown_tables("no table\n").is_empty());
    }

    /// Every committed path is named once: two generators writing the same
    /// file would make the check depend on their order.
    #[test]
    fn every_committed_file_has_one_generator() {
        let mut all: Vec<&str> = GENERATORS
            .iter()
            .flat_map(|g| g.files.iter().map(|(_, committed)| *committed))
            .collect();
        let count = all.len();
        all.sort_unstable();
        all.dedup();
        assert_eq!(all.len(), count);
        for path in all {
            assert!(
                shell::root().join(path).is_file(),
                "{path} is not committed"
            );
        }
    }
}
