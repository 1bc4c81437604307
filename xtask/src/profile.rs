//! `cargo xtask profile [model] [algorithm]`: where a call's instructions go
//! on the Cortex-M4F, line by line.
//!
//! The `profile` firmware calls every algorithm once on every model, each
//! call between `rodyn_profile_begin` and `rodyn_profile_end`. QEMU runs it
//! one instruction per translation block and logs the address of every
//! instruction executed (`-d exec,nochain`). Each marked stretch of the log
//! is one call: its addresses are counted and mapped through the ELF's
//! debug information to their inlined call chains, and each instruction is
//! charged to the innermost line of `rodyn`'s algorithms it was inlined into
//! (outside any algorithm: its innermost `rodyn` line, else its function). The totals agree with the
//! cost probe's counts to within the state and the call overhead.

use crate::{firmware, setup, shell};
use anyhow::{bail, Context, Result};
use std::collections::{BTreeMap, HashMap};
use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::Command;

/// Rows printed per profiled call.
const ROWS: usize = 25;

/// One profiled call: its label from the firmware's log and the number of
/// times each address ran.
struct Stretch {
    label: String,
    counts: HashMap<u64, u64>,
}

/// Profiles the calls whose label contains every word of `filter`.
pub fn run(filter: &[String]) -> Result<()> {
    setup::ensure_target()?;
    setup::ensure_qemu()?;
    firmware::build()?;
    let elf = firmware::elf_of("profile");
    let trace = shell::target_dir()
        .join("firmware-logs")
        .join("profile.trace");
    std::fs::create_dir_all(trace.parent().expect("a log directory"))?;
    let trace_arg = trace.to_string_lossy().into_owned();
    let mut qemu_args = one_instruction_per_block()?;
    qemu_args.extend(["-d", "exec,nochain", "-D"]);
    qemu_args.push(&trace_arg);
    eprintln!(
        "running the profile firmware in QEMU with an instruction trace ({})",
        trace.display()
    );
    let outcome = firmware::run_elf(&elf, &qemu_args, |_| {})?;
    if outcome.exit_code != 0 {
        bail!(
            "the profile firmware failed (exit code {})",
            outcome.exit_code
        );
    }
    let mut labels: Vec<String> = Vec::new();
    for line in &outcome.lines {
        if let Some(label) = line.strip_prefix("profile ") {
            labels.push(label.to_owned());
        } else if line.trim() == "refused" {
            if let Some(last) = labels.last_mut() {
                last.push_str(" (returned an error: not a full call)");
            }
        }
    }
    let stretches = read_stretches(&elf, &trace, labels)?;
    let lines = Lines::new(&elf)?;
    let mut shown = 0;
    for stretch in stretches
        .iter()
        .filter(|s| filter.iter().all(|w| s.label.contains(w.as_str())))
    {
        print_stretch(stretch, &lines)?;
        shown += 1;
    }
    if shown == 0 {
        bail!("no profiled call matches {filter:?}");
    }
    std::fs::remove_file(&trace).ok();
    Ok(())
}

/// QEMU's option for one instruction per translation block, which makes its
/// execution log list every instruction: `-singlestep` up to 8.0, an
/// accelerator property from 8.1 on.
fn one_instruction_per_block() -> Result<Vec<&'static str>> {
    let output = Command::new("qemu-system-arm")
        .arg("--version")
        .output()
        .context("running qemu-system-arm --version")?;
    let text = String::from_utf8_lossy(&output.stdout);
    let version = text
        .split_whitespace()
        .skip_while(|w| *w != "version")
        .nth(1)
        .context("no version in qemu-system-arm --version")?;
    let mut parts = version.split('.').map(|p| p.parse::<u32>().unwrap_or(0));
    let (major, minor) = (parts.next().unwrap_or(0), parts.next().unwrap_or(0));
    Ok(if (major, minor) >= (8, 1) {
        vec!["-accel", "tcg,one-insn-per-tb=on"]
    } else {
        vec!["-singlestep"]
    })
}

/// Splits the trace at the markers into one address histogram per call.
fn read_stretches(elf: &Path, trace: &Path, labels: Vec<String>) -> Result<Vec<Stretch>> {
    let begin = symbol_address(elf, "rodyn_profile_begin")?;
    let end = symbol_address(elf, "rodyn_profile_end")?;
    let file = std::fs::File::open(trace)
        .with_context(|| format!("cannot read the trace {}", trace.display()))?;
    let mut stretches = Vec::new();
    let mut current: Option<HashMap<u64, u64>> = None;
    let mut labels = labels.into_iter();
    for line in BufReader::new(file).lines() {
        let Some(pc) = trace_address(&line?) else {
            continue;
        };
        if pc == begin {
            current = Some(HashMap::new());
        } else if pc == end {
            if let Some(counts) = current.take() {
                let label = labels
                    .next()
                    .context("more marked calls in the trace than labels in the log")?;
                stretches.push(Stretch { label, counts });
            }
        } else if let Some(counts) = current.as_mut() {
            *counts.entry(pc).or_insert(0) += 1;
        }
    }
    if stretches.is_empty() {
        bail!("no marked call in the trace {}", trace.display());
    }
    Ok(stretches)
}

/// The guest address of a QEMU `-d exec` line:
/// `Trace 0: 0x7f.. [00800408/00000400/00000110/ff000201] symbol`.
fn trace_address(line: &str) -> Option<u64> {
    let fields = line.strip_prefix("Trace ")?.split_once('[')?.1;
    let pc = fields.split('/').nth(1)?;
    u64::from_str_radix(pc, 16).ok()
}

/// The address of a function symbol, without the Thumb bit.
fn symbol_address(elf: &Path, name: &str) -> Result<u64> {
    use object::{Object, ObjectSymbol};
    let data = std::fs::read(elf)?;
    let file = object::File::parse(&*data)?;
    file.symbols()
        .find(|s| s.name() == Ok(name))
        .map(|s| s.address() & !1)
        .with_context(|| format!("no symbol {name} in {}", elf.display()))
}

/// Source attribution of addresses, cached.
pub(crate) struct Lines {
    loader: addr2line::Loader,
}

impl Lines {
    pub(crate) fn new(elf: &Path) -> Result<Self> {
        let loader = addr2line::Loader::new(elf)
            .map_err(|e| anyhow::anyhow!("cannot read the debug information: {e}"))?;
        Ok(Self { loader })
    }

    /// The line an address is charged to: the innermost line of `rodyn`'s
    /// algorithms in its inlined call chain (`algorithm/aba.rs:145`), else
    /// the innermost line of `rodyn` (`spatial/articulated.rs:200`), else its
    /// function. Pinocchio's headers are read the same way
    /// (`algorithm/crba.hxx:60`, `spatial/inertia.hpp:300`).
    fn charge(&self, pc: u64) -> Result<String> {
        let mut frames = self
            .loader
            .find_frames(pc)
            .map_err(|e| anyhow::anyhow!("address {pc:#x}: {e}"))?;
        let mut in_algorithm = None;
        let mut in_rodyn = None;
        let mut function = None;
        while let Some(frame) = frames.next()? {
            if function.is_none() {
                function = frame
                    .function
                    .as_ref()
                    .and_then(|f| f.demangle().ok())
                    .map(|name| short_function(&name));
            }
            let Some(location) = &frame.location else {
                continue;
            };
            let (Some(file), Some(line)) = (location.file, location.line) else {
                continue;
            };
            // rodyn's sources, or Pinocchio's headers for its timing program.
            let Some((at, marker)) = ["rodyn/src/", "include/pinocchio/"]
                .into_iter()
                .find_map(|marker| file.find(marker).map(|at| (at, marker)))
            else {
                continue;
            };
            let key = format!("{}:{line}", &file[at + marker.len()..]);
            if in_algorithm.is_none() && key.starts_with("algorithm/") {
                in_algorithm = Some(key.clone());
            }
            in_rodyn.get_or_insert(key);
        }
        Ok(in_algorithm
            .or(in_rodyn)
            .or(function)
            .unwrap_or_else(|| format!("{pc:#x}")))
    }
}

/// A function's path without generic arguments and hash, last two segments.
pub(crate) fn short_function(name: &str) -> String {
    let mut depth = 0;
    let plain: String = name
        .chars()
        .filter(|c| {
            match c {
                '<' => depth += 1,
                '>' => depth -= 1,
                _ => return depth == 0,
            }
            false
        })
        .collect();
    // A symbol's hash segment (`h` and 16 hex digits) is dropped too.
    let segments: Vec<&str> = plain
        .split("::")
        .filter(|s| !(s.is_empty() || s.len() == 17 && s.starts_with('h')))
        .collect();
    segments[segments.len().saturating_sub(2)..].join("::")
}

fn print_stretch(stretch: &Stretch, lines: &Lines) -> Result<()> {
    print_table(&stretch.label, &stretch.counts, lines, 1, None)
}

/// Prints where `counts` (address → instructions over `calls` calls) go,
/// charged line by line, as instructions per call; with `fp_ops` (address
/// → floating-point operations per execution), their arithmetic too.
pub(crate) fn print_table(
    label: &str,
    counts: &HashMap<u64, u64>,
    lines: &Lines,
    calls: u64,
    fp_ops: Option<&HashMap<u64, u64>>,
) -> Result<()> {
    let total: u64 = counts.values().sum();
    let mut by_line: BTreeMap<String, (u64, u64)> = BTreeMap::new();
    for (pc, n) in counts {
        let ops = fp_ops.and_then(|f| f.get(pc)).copied().unwrap_or(0);
        let entry = by_line.entry(lines.charge(*pc)?).or_insert((0, 0));
        entry.0 += n;
        entry.1 += n * ops;
    }
    let mut rows: Vec<(String, (u64, u64))> = by_line.into_iter().collect();
    rows.sort_by(|a, b| b.1 .0.cmp(&a.1 .0).then(a.0.cmp(&b.0)));
    let per_call = |n: u64| (n + calls / 2) / calls;
    let row = |n: u64, ops: u64, what: &str| match fp_ops {
        Some(_) => println!(
            "| {} | {:.1} % | {} | {what} |",
            per_call(n),
            100.0 * n as f64 / total as f64,
            per_call(ops)
        ),
        None => println!(
            "| {} | {:.1} % | {what} |",
            per_call(n),
            100.0 * n as f64 / total as f64
        ),
    };
    println!("\n{label}: {} instructions", per_call(total));
    if fp_ops.is_some() {
        println!("| instructions | share | fp ops | charged to |");
        println!("|---:|---:|---:|---|");
    } else {
        println!("| instructions | share | charged to |");
        println!("|---:|---:|---|");
    }
    for (key, (n, ops)) in rows.iter().take(ROWS) {
        row(*n, *ops, &format!("`{key}`"));
    }
    if rows.len() > ROWS {
        let rest = rows[ROWS..]
            .iter()
            .fold((0, 0), |acc, r| (acc.0 + r.1 .0, acc.1 + r.1 .1));
        row(rest.0, rest.1, &format!("({} more)", rows.len() - ROWS));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::{short_function, trace_address};

    #[test]
    fn reads_the_guest_address_of_a_trace_line() {
        let line = "Trace 0: 0x7fa5a4000240 [00800408/00011426/00000110/ff000201] DefaultPreInit";
        assert_eq!(trace_address(line), Some(0x11426));
        assert_eq!(trace_address("IN: something else"), None);
    }

    #[test]
    fn shortens_function_paths() {
        assert_eq!(
            short_function("<rodyn::spatial::articulated::ArticulatedInertia6<S> as rodyn::space::ArticulatedInertia<S>>::add_act"),
            "add_act"
        );
        assert_eq!(
            short_function("rodyn::algorithm::kinematics::body_transform"),
            "kinematics::body_transform"
        );
    }
}
