//! `cargo xtask host-profile <algorithm> <model> [--pinocchio]`: where a
//! call's instructions go on the host (x86-64, `f64`), line by line, and
//! how much floating-point arithmetic it performed.
//!
//! Runs `rodyn-bench`'s `profile` binary under callgrind twice, for
//! [`CALLS`] and twice as many calls, with a count per instruction address.
//! The difference of the two runs is what the extra calls executed, without
//! the set-up; divided by [`CALLS`], it is one call's instructions. Each
//! address is then charged through the binary's debug information to the
//! innermost line of `rodyn`'s algorithms it was inlined into, as
//! [`profile`](crate::profile) does for the firmware, and its mnemonic gives
//! its arithmetic ([`fp_ops`]). Counts are exact for the
//! binary, inputs and environment: timings on a shared machine are not.
//!
//! With `--pinocchio` the same is done for Pinocchio's timing program
//! (`tools/pinocchio/bench/compare.sh --build-only` builds it and writes
//! the same models and states), with Pinocchio's algorithm names
//! (`crba_local`, `aba_world`, ...); `--table` prints both libraries'
//! instructions and arithmetic per call for every algorithm and model,
//! side by side on the same inputs.

use crate::fp_ops;
use crate::profile::{print_table, Lines};
use crate::{setup, shell};
use anyhow::{bail, Context, Result};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Calls in the first run (the second runs twice as many).
const CALLS: u64 = 500;

const USAGE: &str = "usage: cargo xtask host-profile <rnea|crba|crba_fd|aba> <model> \
     (panda, ur5, solo12, chainN, chainN_planar with N in 5, 10, 20, 60)\n       \
     cargo xtask host-profile <rnea|crba_local|crba_world|crba_fd_local|crba_fd_world|\
     aba_local|aba_world> <model> --pinocchio (models as above, chainN 3-D only)\n       \
     cargo xtask host-profile --table (both libraries, every algorithm and model)";

/// Instruction counts per address, per object file (the binary and the
/// shared libraries it calls into).
type Counts = HashMap<String, HashMap<u64, u64>>;

/// Profiles `args = [algorithm, model]` (as the `profile` binary names
/// them), or Pinocchio's with `--pinocchio` after them; `args = [--table]`
/// compares the two on every model.
pub fn run(args: &[String]) -> Result<()> {
    setup::ensure_valgrind()?;
    setup::ensure_objdump()?;
    let (algorithm, model, pinocchio) = match args {
        [flag] if flag == "--table" => return table(),
        [a, m] => (a, m.clone(), false),
        [a, m, flag] if flag == "--pinocchio" => (a, pinocchio_model(m), true),
        _ => bail!("{USAGE}"),
    };
    let program = if pinocchio {
        Program::pinocchio()?
    } else {
        Program::rodyn()?
    };
    let extra = program.one_call(algorithm, &model)?;
    let library = if pinocchio { "Pinocchio" } else { "rodyn" };
    let own = program.binary.display().to_string();
    let lines = Lines::new(&program.binary)?;
    let in_binary = extra.get(&own).cloned().unwrap_or_default();
    let ops_at: HashMap<u64, u64> = fp_ops::arithmetic(&program.binary)?
        .into_iter()
        .map(|(pc, ops)| (pc, ops.total()))
        .collect();
    print_table(
        &format!("{library}: {algorithm} {model} (host, f64, callgrind)"),
        &in_binary,
        &lines,
        CALLS,
        Some(&ops_at),
    )?;
    for (object, counts) in &extra {
        if *object != own {
            let name = Path::new(object)
                .file_name()
                .map_or(object.as_str(), |n| n.to_str().unwrap_or(object.as_str()));
            let n: u64 = counts.values().sum();
            println!("plus {} instructions per call in {name}", per_call(n));
        }
    }
    let total: u64 = extra.values().flat_map(HashMap::values).sum();
    let ops = fp_ops::count(&extra)?.per_call(CALLS);
    println!(
        "\nfloating-point operations per call: {ops}; {:.2} instructions per operation",
        total as f64 / CALLS as f64 / ops.total().max(1) as f64
    );
    Ok(())
}

/// One call's instructions, rounded.
fn per_call(n: u64) -> u64 {
    (n + CALLS / 2) / CALLS
}

/// The models of the comparison, as the `profile` binary names them.
const MODELS: [&str; 7] = [
    "panda", "ur5", "solo12", "chain5", "chain10", "chain20", "chain60",
];

/// rodyn's algorithms and Pinocchio's counterparts (both conventions,
/// where Pinocchio offers two; the table shows the one with fewer
/// instructions).
const ALGORITHMS: [(&str, &[&str]); 4] = [
    ("rnea", &["rnea"]),
    ("crba", &["crba_local", "crba_world"]),
    ("crba_fd", &["crba_fd_local", "crba_fd_world"]),
    ("aba", &["aba_local", "aba_world"]),
];

/// Instructions and floating-point operations per call of every algorithm
/// on every model, rodyn beside Pinocchio, as a markdown table.
fn table() -> Result<()> {
    let rodyn = Program::rodyn()?;
    let pinocchio = Program::pinocchio()?;
    let mut disassembly = HashMap::new();
    let mut measure = |program: &Program, algorithm: &str, model: &str| -> Result<(u64, u64)> {
        let extra = program.one_call(algorithm, model)?;
        let instructions = per_call(extra.values().flat_map(HashMap::values).sum());
        let ops = fp_ops::count_cached(&extra, &mut disassembly)?.per_call(CALLS);
        Ok((instructions, ops.total()))
    };
    let cases = MODELS.len() * ALGORITHMS.len();
    println!("| model | algorithm | rodyn instructions | rodyn fp ops | rodyn instr/op | Pinocchio instructions | Pinocchio fp ops | Pinocchio instr/op | fp ops rodyn / Pinocchio |");
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|");
    let mut done = 0;
    for model in MODELS {
        for (algorithm, theirs) in ALGORITHMS {
            done += 1;
            eprint!("host-profile: {done}/{cases} {algorithm} {model}        \r");
            let (ri, ro) = measure(&rodyn, algorithm, model)?;
            let mut best: Option<(u64, u64, &str)> = None;
            for name in theirs {
                let (pi, po) = measure(&pinocchio, name, &pinocchio_model(model))?;
                if best.is_none_or(|b| pi < b.0) {
                    best = Some((pi, po, name));
                }
            }
            let Some((pi, po, name)) = best else {
                continue;
            };
            let convention = name.rsplit_once('_').map_or("", |(_, c)| c);
            let convention = match convention {
                "local" | "world" => format!(" ({convention})"),
                _ => String::new(),
            };
            let ratio = |i: u64, o: u64| i as f64 / o.max(1) as f64;
            println!(
                "| {model} | {algorithm} | {ri} | {ro} | {:.2} | {pi}{convention} | {po} | {:.2} | {:.2} |",
                ratio(ri, ro),
                ratio(pi, po),
                ro as f64 / po.max(1) as f64
            );
        }
    }
    eprintln!();
    Ok(())
}

/// A program that runs `<prefix> <algorithm> <model> <calls>`.
struct Program {
    binary: PathBuf,
    prefix: Vec<String>,
}

impl Program {
    /// rodyn-bench's `profile` binary.
    fn rodyn() -> Result<Self> {
        shell::cargo(&[
            "build",
            "-p",
            "rodyn-bench",
            "--release",
            "--bin",
            "profile",
        ])?;
        Ok(Self {
            binary: shell::target_dir().join("release").join("profile"),
            prefix: vec![],
        })
    }

    /// Pinocchio's timing program in its profiling mode.
    fn pinocchio() -> Result<Self> {
        let binary = pinocchio_program()?;
        let manifest = shell::target_dir()
            .join("pinocchio-bench")
            .join("manifest.txt");
        Ok(Self {
            binary,
            prefix: vec!["--profile".to_owned(), manifest.display().to_string()],
        })
    }

    /// What [`CALLS`] calls executed, without the set-up: the counts of a
    /// run of twice as many calls minus those of a run of [`CALLS`].
    fn one_call(&self, algorithm: &str, model: &str) -> Result<Counts> {
        let run = |calls: u64| {
            let mut args = self.prefix.clone();
            args.extend([algorithm.to_owned(), model.to_owned(), calls.to_string()]);
            address_counts(&self.binary, &args)
        };
        let once = run(CALLS)?;
        let twice = run(2 * CALLS)?;
        Ok(twice
            .into_iter()
            .map(|(object, counts)| {
                let before = once.get(&object);
                let extra = counts
                    .into_iter()
                    .filter_map(|(pc, n)| {
                        let before = before.and_then(|b| b.get(&pc)).copied().unwrap_or(0);
                        let d = n.saturating_sub(before);
                        (d > 0).then_some((pc, d))
                    })
                    .collect::<HashMap<_, _>>();
                (object, extra)
            })
            .filter(|(_, counts)| !counts.is_empty())
            .collect())
    }
}

/// Pinocchio's name for a model of the `profile` binary (`chain20` is the
/// 3-D `planar_chain_20`).
fn pinocchio_model(model: &str) -> String {
    match model.strip_prefix("chain") {
        Some(n) if n.chars().all(|c| c.is_ascii_digit()) => format!("planar_chain_{n}"),
        _ => model.to_owned(),
    }
}

/// Builds Pinocchio's timing program and writes its inputs.
fn pinocchio_program() -> Result<PathBuf> {
    let script = shell::root().join("tools/pinocchio/bench/compare.sh");
    let out = setup::output(Command::new(&script).arg("--build-only"))
        .context("building Pinocchio's timing program (needs `pip install pin cmeel-eigen cmeel-urdfdom-headers`)")?;
    match out.lines().last() {
        Some(path) => Ok(PathBuf::from(path.trim())),
        None => bail!("{} printed no program path", script.display()),
    }
}

/// Instructions executed at each address in one run of `binary args`.
fn address_counts(binary: &Path, args: &[String]) -> Result<Counts> {
    let out = shell::target_dir().join(format!("host-profile-{}.callgrind", std::process::id()));
    let status = Command::new("valgrind")
        .args([
            "--tool=callgrind",
            "--dump-instr=yes",
            "--compress-pos=no",
            "--compress-strings=no",
        ])
        .arg(format!("--callgrind-out-file={}", out.display()))
        .arg(binary)
        .args(args)
        .current_dir(shell::root())
        .output()
        .context("running valgrind")?;
    if !status.status.success() {
        bail!(
            "{} failed under callgrind: {}",
            binary.display(),
            String::from_utf8_lossy(&status.stderr).trim()
        );
    }
    let text =
        std::fs::read_to_string(&out).with_context(|| format!("reading {}", out.display()))?;
    std::fs::remove_file(&out).ok();
    Ok(parse_callgrind(&text))
}

/// The self cost of every address in a callgrind file written with
/// `--dump-instr=yes --compress-pos=no --compress-strings=no`, by object
/// file: `ob=` names the object of the cost lines that follow, which read
/// `0xADDR LINE IR`; the line after a `calls=` line is the call's inclusive
/// cost and is skipped.
fn parse_callgrind(text: &str) -> Counts {
    let mut counts: Counts = HashMap::new();
    let mut object = String::new();
    let mut after_call = false;
    for line in text.lines() {
        if let Some(name) = line.strip_prefix("ob=") {
            object = name.to_owned();
            continue;
        }
        if line.starts_with("calls=") {
            after_call = true;
            continue;
        }
        if std::mem::take(&mut after_call) {
            continue;
        }
        let mut fields = line.split_whitespace();
        let (Some(address), Some(_line), Some(cost)) =
            (fields.next(), fields.next(), fields.next())
        else {
            continue;
        };
        let (Some(hex), Ok(cost)) = (address.strip_prefix("0x"), cost.parse::<u64>()) else {
            continue;
        };
        if let Ok(address) = u64::from_str_radix(hex, 16) {
            *counts
                .entry(object.clone())
                .or_default()
                .entry(address)
                .or_insert(0) += cost;
        }
    }
    counts
}

#[cfg(test)]
mod tests {
    use super::parse_callgrind;

    #[test]
    fn reads_self_costs_and_skips_inclusive_call_costs() {
        let text = "ob=/bin/a\nfn=(1) main\n0x401000 10 5\n0x401004 10 7\ncalls=2 0x402000 20\n\
                    0x401008 11 900\n0x40100c 12 3\nfn=(2) f\n0x401000 30 1\n\
                    ob=/lib/m.so\nfn=(3) sin\n0x401000 1 4\n";
        let all = parse_callgrind(text);
        assert_eq!(all["/lib/m.so"].get(&0x401000), Some(&4));
        let counts = &all["/bin/a"];
        assert_eq!(counts.get(&0x401000), Some(&6));
        assert_eq!(counts.get(&0x401004), Some(&7));
        assert_eq!(counts.get(&0x401008), None);
        assert_eq!(counts.get(&0x40100c), Some(&3));
    }
}
