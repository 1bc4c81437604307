//! `cargo xtask run EXAMPLE --html PAGE`: a firmware example's run replayed
//! in the viewer.
//!
//! The example is built with the firmware's `pose-log` feature (into its
//! own target folder, so the checked images stay as they are), run in QEMU,
//! and its `pose t = … ms: q = […]` lines (every 20 ms) become a CSV file
//! that `rodyn-model view MODEL --trajectory CSV` draws: the model file the
//! firmware compiled, posed by rodyn's forward kinematics on the host.

use crate::firmware::{self, Example};
use crate::setup::TARGET;
use crate::shell;
use anyhow::{bail, ensure, Context, Result};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The examples that log their poses, with the model file each compiles.
const REPLAYABLE: [(&str, &str); 2] = [
    ("arm_control", "models/panda.toml"),
    ("quadruped", "models/aibo.toml"),
];

/// The model file of a replayable example, or an error naming those there are.
pub fn model_of(example: &Example) -> Result<&'static str> {
    REPLAYABLE
        .iter()
        .find(|(name, _)| *name == example.name)
        .map(|(_, model)| *model)
        .with_context(|| {
            let names: Vec<_> = REPLAYABLE.iter().map(|(name, _)| *name).collect();
            format!(
                "{} logs no poses to replay; --html works for {}",
                example.name,
                names.join(" and ")
            )
        })
}

/// Builds and runs `example` with its pose log, passing every other log
/// line to `on_line`, and writes the replay page to `html` with the
/// `rodyn-model` binary `rodyn_model`. Fails if the example's checks fail.
pub fn write_page(
    example: &Example,
    html: &Path,
    rodyn_model: &Path,
    mut on_line: impl FnMut(&str),
) -> Result<()> {
    let model = model_of(example)?;
    let target_dir = shell::target_dir().join("firmware-pose-log");
    shell::run(
        firmware::cargo_command()
            .args(["build", "--release", "--features", "pose-log", "--bin"])
            .arg(example.name)
            .arg("--target-dir")
            .arg(&target_dir),
    )?;
    let elf = target_dir.join(TARGET).join("release").join(example.name);
    let mut samples = Vec::new();
    let mut bad_line = None;
    let outcome = firmware::run_elf(&elf, &[], |line| match parse_pose(line) {
        Some(Ok(sample)) => samples.push(sample),
        Some(Err(e)) => {
            bad_line.get_or_insert(format!("{e}: `{line}`"));
        }
        None => on_line(line),
    })?;
    if let Some(e) = bad_line {
        bail!("{}'s pose log: {e}", example.name);
    }
    if outcome.exit_code != 0 {
        bail!("{} exited with code {}", example.name, outcome.exit_code);
    }
    ensure!(
        samples.len() >= 2,
        "{} logged {} poses; a replay needs two at least (was it built with pose-log?)",
        example.name,
        samples.len()
    );
    let csv = shell::target_dir()
        .join("firmware-replays")
        .join(format!("{}.csv", example.name));
    std::fs::create_dir_all(csv.parent().context("the replay folder")?)?;
    std::fs::write(&csv, to_csv(&samples))
        .with_context(|| format!("cannot write {}", csv.display()))?;
    if let Some(dir) = html.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    shell::run(
        Command::new(rodyn_model)
            .arg("view")
            .arg(shell::root().join(model))
            .args(["--silence", "all", "--trajectory"])
            .arg(&csv)
            .arg("-o")
            .arg(html),
    )?;
    println!(
        "{}: {} poses over {:.2} s replayed in {}",
        example.name,
        samples.len(),
        samples.last().map_or(0.0, |s| s.0),
        html.display()
    );
    Ok(())
}

/// The `rodyn-model` binary, built in the debug profile.
pub fn build_rodyn_model() -> Result<PathBuf> {
    shell::cargo(&["build", "-p", "rodyn-model", "--bin", "rodyn-model"])?;
    Ok(shell::target_dir().join("debug").join("rodyn-model"))
}

/// One logged pose: time (s) and configuration.
type Sample = (f64, Vec<f64>);

/// `pose t = 20 ms: q = [0.1, -0.7, …]` as (0.02 s, q); `None` for any
/// other line, an error for a pose line that does not read.
fn parse_pose(line: &str) -> Option<Result<Sample>> {
    let rest = line.strip_prefix("pose t = ")?;
    Some((|| {
        let (ms, q) = rest.split_once(" ms: q = ").context("no ` ms: q = `")?;
        let ms: u32 = ms.parse().with_context(|| format!("time `{ms}`"))?;
        let list = q
            .strip_prefix('[')
            .and_then(|q| q.strip_suffix(']'))
            .context("q is not a [list]")?;
        let q = list
            .split(',')
            .map(|x| {
                let x = x.trim();
                x.parse::<f64>()
                    .ok()
                    .filter(|x| x.is_finite())
                    .with_context(|| format!("coordinate `{x}` is not a finite number"))
            })
            .collect::<Result<Vec<f64>>>()?;
        Ok((f64::from(ms) / 1000.0, q))
    })())
}

/// The samples as `t,q0,q1,…` lines under a header.
fn to_csv(samples: &[Sample]) -> String {
    let nq = samples.first().map_or(0, |s| s.1.len());
    let mut csv = String::from("t");
    for k in 0..nq {
        csv.push_str(&format!(",q{k}"));
    }
    csv.push('\n');
    for (t, q) in samples {
        csv.push_str(&format!("{t}"));
        for x in q {
            csv.push_str(&format!(",{x}"));
        }
        csv.push('\n');
    }
    csv
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pose_line_reads_and_others_pass() {
        let (t, q) = parse_pose("pose t = 40 ms: q = [0.5, -0.25, 3e-3]")
            .expect("a pose line")
            .expect("it reads");
        assert_eq!(t, 0.04);
        assert_eq!(q, vec![0.5, -0.25, 3e-3]);
        assert!(parse_pose("t = 1000 ms: q = [0.0]").is_none());
        let bad = parse_pose("pose t = 40 ms: q = [0.5, NaN]").expect("a pose line");
        assert!(format!("{:#}", bad.unwrap_err()).contains("`NaN`"));
        assert_eq!(
            to_csv(&[(0.0, vec![1.0, 2.0]), (0.02, vec![1.5, 2.5])]),
            "t,q0,q1\n0,1,2\n0.02,1.5,2.5\n"
        );
    }
}
