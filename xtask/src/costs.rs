//! The cost and size tables of `docs/sections/firmware.md` and `README.md`.
//!
//! `cargo xtask costs` runs the `cost_probe`, `control_cost_probe` and
//! `contact_cost_probe` firmware
//! (instructions per call counted with QEMU's `-icount` and SysTick, stack
//! bytes from a painted stack) and measures each example's image with `llvm-size`, then rewrites
//! the tables between the `<!-- …:begin -->` / `<!-- …:end -->` markers of
//! the section and `firmware/expected/sizes.txt`. `cargo xtask test` compares
//! the pendulum image with that file: a scene pays only for what it models,
//! so the pendulum must not grow when the library gains contacts, muscles or
//! floating bases it does not use.

use crate::firmware::{self, Example, EXAMPLES};
use crate::{family, setup, shell, stack_bound};
use anyhow::{bail, Context, Result};
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::PathBuf;
use std::process::Command;

/// The images whose `cost` lines make the cost table, in its order: the
/// control-level rows (task space, derivatives) and the rigid-contact rows
/// have images of their own (see `control_cost_probe.rs`), so that adding
/// rows does not change how the optimiser inlines the others.
pub const PROBES: [&str; 4] = [
    "cost_probe",
    "control_cost_probe",
    "contact_cost_probe",
    "update_cost_probe",
];
/// The Cortex-M4 goals the README states, as (model, algorithm, most
/// instructions per call): checked against the cost probe's `fast` lines,
/// the calls with every joint angle in the f32 sine's fast range (the
/// wound states, whose exact argument reduction the goals leave out, are
/// in the table's max).
pub const GOALS: [(&str, &str, u64); 2] =
    [("panda-7dof", "RNEA", 4_000), ("panda-7dof", "ABA", 8_000)];
/// The example whose size must not grow.
const SIZE_GUARDED: &str = "pendulum";
/// Growth of its flash image accepted without failing (fraction): room for
/// changes to the algorithms it does use, none for features it does not.
const SIZE_TOLERANCE: f64 = 0.01;

/// One image's sections as `llvm-size` (Berkeley format) reports them.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Size {
    /// Code, read-only data and the vector table (bytes).
    text: u64,
    /// Initialised statics: in flash and in RAM (bytes).
    data: u64,
    /// Zeroed statics (bytes).
    bss: u64,
}

impl Size {
    fn flash(self) -> u64 {
        self.text + self.data
    }
    fn ram(self) -> u64 {
        self.data + self.bss
    }
}

fn measure(example: &Example) -> Result<Size> {
    let llvm_size = setup::llvm_size()?;
    let out = setup::output(
        Command::new(llvm_size)
            .arg("-B")
            .arg(firmware::elf(example)),
    )?;
    let numbers: Vec<u64> = out
        .lines()
        .nth(1)
        .context("llvm-size printed no sizes")?
        .split_whitespace()
        .take(3)
        .map(str::parse)
        .collect::<Result<_, _>>()
        .context("llvm-size output")?;
    Ok(Size {
        text: numbers[0],
        data: numbers[1],
        bss: numbers[2],
    })
}

fn sizes_path() -> PathBuf {
    shell::root().join("firmware/expected/sizes.txt")
}

fn read_sizes() -> Result<BTreeMap<String, Size>> {
    let text = std::fs::read_to_string(sizes_path())
        .with_context(|| format!("cannot read {}", sizes_path().display()))?;
    let mut sizes = BTreeMap::new();
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let fields: Vec<&str> = line.split_whitespace().collect();
        let value = |key: &str| -> Result<u64> {
            fields
                .iter()
                .find_map(|f| f.strip_prefix(key)?.strip_prefix('='))
                .with_context(|| format!("sizes.txt: no {key} in `{line}`"))?
                .parse()
                .with_context(|| format!("sizes.txt: bad {key} in `{line}`"))
        };
        let size = Size {
            text: value("text")?,
            data: value("data")?,
            bss: value("bss")?,
        };
        sizes.insert(fields[0].to_string(), size);
    }
    Ok(sizes)
}

/// Compares every image with `firmware/expected/sizes.txt`; fails when the
/// guarded pendulum's flash grew beyond the tolerance.
pub fn check_sizes() -> Result<()> {
    let recorded = read_sizes()?;
    let mut failure = None;
    for example in EXAMPLES {
        let now = measure(example)?;
        let Some(before) = recorded.get(example.name) else {
            println!(
                "size {}: flash {} B (not recorded)",
                example.name,
                now.flash()
            );
            continue;
        };
        let growth = now.flash() as f64 / before.flash() as f64 - 1.0;
        println!(
            "size {}: flash {} B (recorded {} B, {:+.1} %), RAM {} B",
            example.name,
            now.flash(),
            before.flash(),
            100.0 * growth,
            now.ram()
        );
        if example.name == SIZE_GUARDED && growth > SIZE_TOLERANCE {
            failure = Some(format!(
                "the {SIZE_GUARDED} image grew from {} to {} B of flash (more than {} %): \
                 it pays for something it does not model (`cargo xtask costs` records \
                 an intended change)",
                before.flash(),
                now.flash(),
                100.0 * SIZE_TOLERANCE
            ));
        }
    }
    match failure {
        Some(message) => bail!(message),
        None => Ok(()),
    }
}

/// One row of the cost probe's output.
pub struct Cost {
    pub model: String,
    pub algorithm: String,
    /// Fewest instructions of a call.
    pub min: u64,
    /// Most instructions of a call.
    pub max: u64,
    /// Painted stack bytes: a number, `>16384` (the window overflowed) or
    /// `-` (not measured).
    pub stack: String,
}

/// Reads `cost model=… algorithm=… min=… max=… stack=…` lines.
pub fn parse_costs(lines: &[String]) -> Result<Vec<Cost>> {
    let mut costs = Vec::new();
    for line in lines.iter().filter(|l| l.starts_with("cost ")) {
        let field = |key: &str| -> Result<&str> {
            line.split_whitespace()
                .find_map(|f| f.strip_prefix(key)?.strip_prefix('='))
                .with_context(|| format!("cost line without {key}: `{line}`"))
        };
        costs.push(Cost {
            model: field("model")?.to_string(),
            algorithm: field("algorithm")?.to_string(),
            min: field("min")?.parse()?,
            max: field("max")?.parse()?,
            stack: field("stack")?.to_string(),
        });
    }
    if costs.is_empty() {
        bail!("the cost probe printed no cost lines");
    }
    Ok(costs)
}

/// The goals ([`GOALS`]) against the `fast model=… algorithm=… min=… max=…`
/// lines of the cost probe: a Markdown table, and a line for every goal
/// missed or not measured.
fn goals(lines: &[String]) -> Result<(String, Vec<String>)> {
    let fast: Vec<(String, String, u64, u64)> = lines
        .iter()
        .filter(|l| l.starts_with("fast "))
        .map(|line| {
            let field = |key: &str| -> Result<&str> {
                line.split_whitespace()
                    .find_map(|f| f.strip_prefix(key)?.strip_prefix('='))
                    .with_context(|| format!("fast line without {key}: `{line}`"))
            };
            Ok((
                field("model")?.to_string(),
                field("algorithm")?.to_string(),
                field("min")?.parse()?,
                field("max")?.parse()?,
            ))
        })
        .collect::<Result<_>>()?;
    let mut table = String::from(
        "| model | algorithm | goal (instructions per call) | measured, angles within ±8,192 rad (min – max) | met |\n\
         |---|---|---:|---:|---|\n",
    );
    let mut missed = Vec::new();
    for (model, algorithm, limit) in GOALS {
        let Some((_, _, min, max)) = fast
            .iter()
            .find(|(m, a, _, _)| m == model && a == algorithm)
        else {
            missed.push(format!("{model} {algorithm}: not measured"));
            continue;
        };
        let met = *max <= limit;
        if !met {
            missed.push(format!(
                "{model} {algorithm}: {max} instructions, goal {limit}"
            ));
        }
        writeln!(
            table,
            "| {model} | {algorithm} | ≤ {limit} | {min} – {max} | {} |",
            if met { "yes" } else { "**no**" }
        )?;
    }
    Ok((table, missed))
}

/// The goals on the cost probe's last log (`cargo xtask test` runs
/// the probe before).
pub fn check_goals_of_last_run() -> Result<()> {
    let path = firmware::last_log_path(firmware::example("cost_probe")?);
    let log = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    let lines: Vec<String> = log.lines().map(str::to_string).collect();
    let (_, missed) = goals(&lines)?;
    if !missed.is_empty() {
        bail!("Cortex-M4 goals missed: {}", missed.join("; "));
    }
    println!("Cortex-M4 goals: met");
    Ok(())
}

/// Where the cost probes' output comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProbeRuns {
    /// Build the firmware and run each probe in QEMU now.
    Fresh,
    /// The logs `cargo xtask test` kept of its runs of the images it has
    /// just built (`target/firmware-logs/`), so that checking the tables
    /// costs no second emulation.
    LastLogs,
}

/// The docs holding the tables, and which marked tables each holds.
const TABLE_DOCS: [(&str, &[&str]); 2] = [
    (
        "docs/sections/firmware.md",
        &["costs", "sizes", "goals", "stack"],
    ),
    ("README.md", &["goals"]),
];

/// Runs the probe and the size measurements and rewrites the tables.
pub fn regenerate() -> Result<()> {
    let root = shell::root();
    for (path, text) in generated_files(ProbeRuns::Fresh)? {
        let path = root.join(path);
        std::fs::write(&path, text).with_context(|| format!("cannot write {}", path.display()))?;
        println!("wrote {}", path.display());
    }
    Ok(())
}

/// Every file `cargo xtask costs` writes, as (path from the repository
/// root, its new text), computed without writing any: the tables of
/// [`TABLE_DOCS`] put into the committed docs, `firmware/expected/sizes.txt`,
/// `firmware/expected/panic_sites.txt` and the Cortex-M family's page
/// ([`family::PAGE`]).
pub fn generated_files(runs: ProbeRuns) -> Result<Vec<(String, String)>> {
    setup::ensure_target()?;
    if runs == ProbeRuns::Fresh {
        setup::ensure_qemu()?;
        firmware::build()?;
    }
    let mut costs = Vec::new();
    let mut goal_table = String::new();
    for name in PROBES {
        let probe = firmware::example(name)?;
        let lines = match runs {
            ProbeRuns::Fresh => {
                let outcome = firmware::run(probe, |line| println!("{line}"))?;
                if outcome.exit_code != 0 {
                    bail!("{name} exited with code {}", outcome.exit_code);
                }
                outcome.lines
            }
            ProbeRuns::LastLogs => {
                let path = firmware::last_log_path(probe);
                std::fs::read_to_string(&path)
                    .with_context(|| {
                        format!(
                            "cannot read {} (`cargo xtask test` writes it)",
                            path.display()
                        )
                    })?
                    .lines()
                    .map(str::to_string)
                    .collect()
            }
        };
        costs.extend(parse_costs(&lines)?);
        if name == "cost_probe" {
            // A missed goal is printed and the tables still written, so
            // that the README shows it; `cargo xtask test` fails on it.
            let (table, missed) = goals(&lines)?;
            for goal in missed {
                println!("Cortex-M4 goal missed: {goal}");
            }
            goal_table = table;
        }
    }

    // The static bounds, checked against the painted figures before any
    // table is written.
    let images = stack_bound::analyse()?;
    stack_bound::check_rows(&images, &stack_rows(&costs))?;
    stack_bound::check_images(&images)?;
    let image_stack = stack_bound::image_totals(&images)?;

    let mut cost_table = String::from(
        "| model | algorithm | instructions per call (min – max) | stack bytes per call (painted) | worst-case stack bytes (static) |\n\
         |---|---|---:|---:|---:|\n",
    );
    for c in &costs {
        let bound = if c.stack == "-" {
            "-".to_string()
        } else {
            stack_bound::row_bound(&images, &c.model, &c.algorithm)?
                .bytes
                .to_string()
        };
        writeln!(
            cost_table,
            "| {} | {} | {} – {} | {} | {} |",
            c.model, c.algorithm, c.min, c.max, c.stack, bound
        )?;
    }

    let mut size_table = String::from(
        "| example | flash: text + data (bytes) | RAM: data + bss + worst-case stack (bytes) | text | data | bss | stack (static bound) |\n\
         |---|---:|---:|---:|---:|---:|---:|\n",
    );
    let mut sizes_file = String::from(
        "# Image sizes (bytes, llvm-size -B) recorded by `cargo xtask costs`.\n\
         # `cargo xtask test` fails when the pendulum's flash grows by more than 1 %.\n",
    );
    for example in EXAMPLES {
        let s = measure(example)?;
        let stack = image_stack[example.name];
        writeln!(
            size_table,
            "| `{}` | {} | {} | {} | {} | {} | {} |",
            example.name,
            s.flash(),
            s.ram() + stack,
            s.text,
            s.data,
            s.bss,
            stack
        )?;
        writeln!(
            sizes_file,
            "{} text={} data={} bss={}",
            example.name, s.text, s.data, s.bss
        )?;
    }
    let stack_tables = stack_bound::tables(&images, &stack_rows(&costs))?;

    let mut files = Vec::new();
    for (doc, markers) in TABLE_DOCS {
        let doc_path = shell::root().join(doc);
        let mut text = std::fs::read_to_string(&doc_path)
            .with_context(|| format!("cannot read {}", doc_path.display()))?;
        for marker in markers {
            let table = match *marker {
                "costs" => &cost_table,
                "sizes" => &size_table,
                "goals" => &goal_table,
                _ => &stack_tables,
            };
            text = replace_between(&text, marker, table).with_context(|| format!("in {doc}"))?;
        }
        files.push((doc.to_string(), text));
    }
    files.push(("firmware/expected/sizes.txt".to_string(), sizes_file));
    files.push((
        "firmware/expected/panic_sites.txt".to_string(),
        crate::panic_sites::expected_text()?,
    ));
    files.push((family::PAGE.to_string(), family::page(runs, costs, images)?));
    Ok(files)
}

/// (model, algorithm, painted stack) of each cost line, for
/// [`stack_bound::check_rows`].
pub fn stack_rows(costs: &[Cost]) -> Vec<(String, String, String)> {
    costs
        .iter()
        .map(|c| (c.model.clone(), c.algorithm.clone(), c.stack.clone()))
        .collect()
}

/// Replaces the text between `<!-- name:begin -->` and `<!-- name:end -->`.
pub fn replace_between(doc: &str, name: &str, content: &str) -> Result<String> {
    let (begin, end) = (
        format!("<!-- {name}:begin -->"),
        format!("<!-- {name}:end -->"),
    );
    let start = doc
        .find(&begin)
        .with_context(|| format!("no `{begin}` marker"))?
        + begin.len();
    let stop = doc[start..]
        .find(&end)
        .with_context(|| format!("no `{end}` marker"))?
        + start;
    Ok(format!("{}\n{}{}", &doc[..start], content, &doc[stop..]))
}
