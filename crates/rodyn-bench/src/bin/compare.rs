//! rodyn against Pinocchio on the same URDFs and the same states.
//!
//! Run through `tools/pinocchio/bench/compare.sh`, which builds the Pinocchio
//! timing program (`tools/pinocchio/bench/bench.cpp`) and passes its path:
//!
//! ```text
//! compare --pinocchio <program> [--rounds N] [--ms M]
//! ```
//!
//! Each round times every model and algorithm once in rodyn (this process)
//! and once in Pinocchio (a child process); the two alternate which goes
//! first, so that a machine shared with other work slows both alike. The
//! table reports the median over rounds. Before timing, the first state's
//! RNEA torques of both libraries are compared, to prove the models agree.

use clap::Parser;
use rodyn::space::Space;
use rodyn::spatial::Spatial;
use rodyn_bench::arguments::{milliseconds, Rounds};
use rodyn_bench::cases::{Case, ModelCase};
use rodyn_bench::models::{chains::CHAIN_GRAVITY, planar_chain, planar_chain_3d};
use rodyn_bench::models::{PANDA, PANDA_URDF, SOLO12, SOLO12_URDF, UR5, UR5_URDF};
use rodyn_bench::timing::median;
use rodyn_bench::Algorithm;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

const STATES: usize = 64;
const SEED: u64 = 0x0051_1AB5;

/// One row group of the table: a model in rodyn (3-D, and planar when it
/// has a planar form) and the URDF Pinocchio loads.
struct Entry {
    name: String,
    urdf: String,
    free_flyer: bool,
    gravity: [f64; 3],
    spatial: Box<dyn Case>,
    planar: Option<Box<dyn Case>>,
}

fn entry<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    urdf: &str,
    free_flyer: bool,
    case: ModelCase<f64, NB, NQ, NV, Spatial>,
    dir: &Path,
) -> std::io::Result<Entry> {
    let gravity = case.model().gravity().lin.to_array();
    write_states(&dir.join(format!("{name}.states")), &case)?;
    Ok(Entry {
        name: name.to_owned(),
        urdf: urdf.to_owned(),
        free_flyer,
        gravity,
        spatial: Box::new(case),
        planar: None,
    })
}

fn chain_entry<const N: usize>(dir: &Path) -> std::io::Result<Entry> {
    let name = format!("planar_chain_{N}");
    let mut e = entry(
        &name,
        &format!("models/urdf/{name}.urdf"),
        false,
        ModelCase::new(planar_chain_3d::<N>(), STATES, SEED),
        dir,
    )?;
    debug_assert_eq!(e.gravity, CHAIN_GRAVITY);
    e.planar = Some(Box::new(ModelCase::new(planar_chain::<N>(), STATES, SEED)));
    Ok(e)
}

fn write_states<const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    path: &Path,
    case: &ModelCase<f64, NB, NQ, NV, G>,
) -> std::io::Result<()> {
    let mut text = format!("{NQ} {NV} {}\n", case.states().len());
    for s in case.states() {
        let numbers = s.q.iter().chain(&s.v).chain(&s.a).chain(&s.tau);
        let line: Vec<String> = numbers.map(|x| format!("{x:e}")).collect();
        text.push_str(&line.join(" "));
        text.push('\n');
    }
    std::fs::write(path, text)
}

/// What the Pinocchio program printed in one round.
#[derive(Default)]
struct PinocchioRound {
    torques: BTreeMap<String, Vec<f64>>,
    ns: BTreeMap<(String, String), f64>,
}

fn run_pinocchio(program: &Path, manifest: &Path, ms: f64) -> Result<PinocchioRound, String> {
    let out = Command::new(program)
        .arg(manifest)
        .arg(ms.to_string())
        .output()
        .map_err(|e| format!("cannot run {}: {e}", program.display()))?;
    if !out.status.success() {
        return Err(format!(
            "{} failed: {}",
            program.display(),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    let mut round = PinocchioRound::default();
    for line in String::from_utf8_lossy(&out.stdout).lines() {
        let fields: Vec<&str> = line.split_whitespace().collect();
        // A field that is not a finite number would become NaN in the
        // table without a word: refuse the line instead.
        let number = |x: &str| -> Result<f64, String> {
            x.parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or(format!(
                    "`{x}` is not a finite number in Pinocchio's line: {line}"
                ))
        };
        match fields.as_slice() {
            ["check", name, rest @ ..] => {
                let tau = rest.iter().map(|x| number(x)).collect::<Result<_, _>>()?;
                round.torques.insert((*name).to_owned(), tau);
            }
            ["time", name, algorithm, ns] => {
                let ns = number(ns)?;
                round
                    .ns
                    .insert(((*name).to_owned(), (*algorithm).to_owned()), ns);
            }
            _ => return Err(format!("unexpected line from Pinocchio: {line}")),
        }
    }
    Ok(round)
}

/// Pinocchio's name for an algorithm, and whether it has two conventions.
fn pinocchio_names(algorithm: Algorithm) -> Vec<String> {
    match algorithm {
        Algorithm::Rnea => vec!["rnea".into()],
        a => ["local", "world"]
            .iter()
            .map(|c| format!("{}_{c}", a.name()))
            .collect(),
    }
}

fn cpu_model() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|info| {
            info.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|s| s.trim().to_owned())
        })
        .unwrap_or_else(|| "unknown CPU".to_owned())
}

/// rodyn against Pinocchio on the same URDFs and the same states.
#[derive(Parser)]
struct Options {
    /// Pinocchio's timing program.
    #[arg(long, required_unless_present = "inputs_only")]
    pinocchio: Option<PathBuf>,
    /// Rounds, each timing every model and algorithm once in each library
    /// (1 to 100).
    #[arg(long, default_value = "7", allow_hyphen_values = true)]
    rounds: Rounds,
    /// Milliseconds per measurement (at most 10000).
    #[arg(long, default_value = "20", value_parser = milliseconds, allow_hyphen_values = true)]
    ms: f64,
    /// Write the models' manifest and states, then stop (for profiling
    /// Pinocchio on the same inputs: `cargo xtask host-profile --pinocchio`).
    #[arg(long)]
    inputs_only: bool,
}

fn main() -> Result<(), String> {
    let opts = Options::parse();
    let program = opts.pinocchio.clone().unwrap_or_default();
    if !opts.inputs_only && !program.is_file() {
        return Err(format!("--pinocchio: {} is not a file", program.display()));
    }
    let dir = PathBuf::from("target/pinocchio-bench");
    std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let io = |e: std::io::Error| e.to_string();
    let mut entries = vec![
        entry(
            "panda",
            PANDA_URDF,
            false,
            ModelCase::new(PANDA, STATES, SEED),
            &dir,
        )
        .map_err(io)?,
        entry(
            "ur5",
            UR5_URDF,
            false,
            ModelCase::new(UR5, STATES, SEED),
            &dir,
        )
        .map_err(io)?,
        entry(
            "solo12",
            SOLO12_URDF,
            true,
            ModelCase::new(SOLO12, STATES, SEED),
            &dir,
        )
        .map_err(io)?,
        chain_entry::<5>(&dir).map_err(io)?,
        chain_entry::<10>(&dir).map_err(io)?,
        chain_entry::<20>(&dir).map_err(io)?,
        chain_entry::<60>(&dir).map_err(io)?,
    ];
    let mut manifest = String::new();
    for e in &entries {
        let [gx, gy, gz] = e.gravity;
        let states = dir.join(format!("{}.states", e.name));
        writeln!(
            manifest,
            "model {} {} {} {gx:e} {gy:e} {gz:e} {}",
            e.name,
            e.urdf,
            u8::from(e.free_flyer),
            states.display()
        )
        .map_err(|e| e.to_string())?;
    }
    let manifest_path = dir.join("manifest.txt");
    std::fs::write(&manifest_path, manifest).map_err(io)?;
    if opts.inputs_only {
        rodyn_cli::outln!("{}", manifest_path.display());
        return Ok(());
    }

    // Calibrate rodyn's call counts once, so every round does the same work.
    let target_ns = opts.ms * 1.0e6;
    let mut calls = BTreeMap::new();
    for (i, e) in entries.iter_mut().enumerate() {
        for a in Algorithm::ALL {
            calls.insert((i, a.name(), false), e.spatial.calibrate(a, target_ns));
            if let Some(p) = e.planar.as_mut() {
                calls.insert((i, a.name(), true), p.calibrate(a, target_ns));
            }
        }
    }

    let mut rodyn_ns: BTreeMap<(usize, &str, bool), Vec<f64>> = BTreeMap::new();
    let mut pinocchio_ns: BTreeMap<(String, String), Vec<f64>> = BTreeMap::new();
    for round in 0..opts.rounds.get() {
        eprint!("round {}/{}\r", round + 1, opts.rounds.get());
        let _ = std::io::stderr().flush();
        let mut pinocchio = None;
        if round % 2 == 1 {
            pinocchio = Some(run_pinocchio(&program, &manifest_path, opts.ms)?);
        }
        for (i, e) in entries.iter_mut().enumerate() {
            for a in Algorithm::ALL {
                let ns = e.spatial.time(a, calls[&(i, a.name(), false)]);
                rodyn_ns.entry((i, a.name(), false)).or_default().push(ns);
                if let Some(p) = e.planar.as_mut() {
                    let ns = p.time(a, calls[&(i, a.name(), true)]);
                    rodyn_ns.entry((i, a.name(), true)).or_default().push(ns);
                }
            }
        }
        let pinocchio = match pinocchio {
            Some(p) => p,
            None => run_pinocchio(&program, &manifest_path, opts.ms)?,
        };
        if round == 0 {
            check_agreement(&mut entries, &pinocchio)?;
        }
        for (key, ns) in pinocchio.ns {
            pinocchio_ns.entry(key).or_default().push(ns);
        }
    }
    eprintln!();

    rodyn_cli::outln!(
        "CPU: {} ({} logical cores); {} rounds, {} random states per model, medians.\n",
        cpu_model(),
        std::thread::available_parallelism().map_or(0, usize::from),
        opts.rounds.get(),
        STATES
    );
    rodyn_cli::outln!("| model | nv | algorithm | rodyn 3-D (ns) | rodyn planar (ns) | Pinocchio (ns) | rodyn / Pinocchio |");
    rodyn_cli::outln!("|---|---:|---|---:|---:|---:|---:|");
    let mut worst: f64 = 0.0;
    for (i, e) in entries.iter().enumerate() {
        for a in Algorithm::ALL {
            let spatial = median(rodyn_ns.get_mut(&(i, a.name(), false)).expect("timed"));
            let planar = rodyn_ns
                .get_mut(&(i, a.name(), true))
                .map_or(String::from("–"), |v| format!("{:.0}", median(v)));
            // Pinocchio is credited with the faster of its two conventions.
            let (pin_ns, convention) = pinocchio_names(a)
                .into_iter()
                .filter_map(|n| {
                    let v = pinocchio_ns.get_mut(&(e.name.clone(), n.clone()))?;
                    Some((median(v), n))
                })
                .min_by(|x, y| x.0.total_cmp(&y.0))
                .ok_or(format!("no Pinocchio timing for {} {}", e.name, a.name()))?;
            let convention = convention
                .rsplit_once('_')
                .filter(|_| a != Algorithm::Rnea)
                .map_or(String::new(), |(_, c)| format!(" ({c})"));
            let ratio = spatial / pin_ns;
            worst = worst.max(ratio);
            rodyn_cli::outln!(
                "| {} | {} | {} | {spatial:.0} | {planar} | {pin_ns:.0}{convention} | {ratio:.2} |",
                e.name,
                e.spatial.nv(),
                a.name()
            );
        }
    }
    rodyn_cli::outln!("\nLargest ratio rodyn 3-D / Pinocchio: {worst:.2}");
    Ok(())
}

/// Fails unless both libraries give the same RNEA torques on the first state.
fn check_agreement(entries: &mut [Entry], pinocchio: &PinocchioRound) -> Result<(), String> {
    for e in entries {
        let theirs = pinocchio
            .torques
            .get(&e.name)
            .ok_or(format!("Pinocchio did not report {}", e.name))?;
        let ours = e.spatial.first_torques();
        let scale = ours.iter().fold(1.0f64, |m, t| m.max(t.abs()));
        let error = ours
            .iter()
            .zip(theirs)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        if ours.len() != theirs.len() || error.is_nan() || error > 1e-9 * scale {
            return Err(format!(
                "{}: rodyn and Pinocchio disagree (max torque difference {error:e}); the models differ",
                e.name
            ));
        }
    }
    Ok(())
}
