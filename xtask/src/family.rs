//! The Cortex-M family's cost tables (`docs/sections/cortex_m_family.md`).
//!
//! The cost probes of the Cortex-M4F table, built from the same source for
//! QEMU's other Cortex-M machines ([`CORES`]) and run there under the same
//! `-icount`: instructions per call, painted and static stack bytes per
//! call, and the code bytes each call reaches. `cargo xtask costs` writes
//! the tables beside the Cortex-M4F's; `cargo xtask test` runs every
//! core's probes ([`run_probes`]) and its docs check compares the tables
//! from those runs with the committed page.

use crate::costs::{self, Cost, ProbeRuns};
use crate::firmware;
use crate::setup;
use crate::shell;
use crate::stack_bound::{self, Analysed, Graph};
use anyhow::{bail, Context, Result};
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::PathBuf;
use std::time::Instant;

/// One core of the family, other than the Cortex-M4F of the main build.
pub struct Core {
    /// Short name: the build's folder and the logs'.
    pub id: &'static str,
    /// The column's heading.
    pub title: &'static str,
    /// Rust target.
    pub target: &'static str,
    /// rustflags beyond the firmware's own (`firmware/.cargo/config.toml`).
    pub rustflags: &'static [&'static str],
    /// Features of the firmware crate.
    pub features: &'static [&'static str],
    /// QEMU machine and CPU.
    pub machine: (&'static str, &'static str),
    /// The cost probes built and run ([`costs::PROBES`] or a part).
    pub probes: &'static [&'static str],
}

/// The cores beside the Cortex-M4F, in the tables' order after it.
pub const CORES: [Core; 4] = [
    Core {
        id: "m3",
        title: "Cortex-M3, f32 soft-float (mps2-an385)",
        target: "thumbv7m-none-eabi",
        rustflags: &["-C", "target-cpu=cortex-m3"],
        features: &[],
        machine: ("mps2-an385", "cortex-m3"),
        probes: &costs::PROBES,
    },
    Core {
        id: "m7-f32",
        title: "Cortex-M7, f32 (mps2-an500)",
        target: "thumbv7em-none-eabihf",
        rustflags: &["-C", "target-cpu=cortex-m7"],
        features: &[],
        machine: ("mps2-an500", "cortex-m7"),
        probes: &costs::PROBES,
    },
    Core {
        id: "m7-f64",
        title: "Cortex-M7, f64 (mps2-an500)",
        target: "thumbv7em-none-eabihf",
        rustflags: &["-C", "target-cpu=cortex-m7"],
        features: &["f64"],
        machine: ("mps2-an500", "cortex-m7"),
        probes: &["cost_probe"],
    },
    Core {
        id: "m33",
        title: "Cortex-M33, f32 (mps2-an505)",
        target: "thumbv8m.main-none-eabihf",
        rustflags: &["-C", "target-cpu=cortex-m33"],
        features: &[],
        machine: ("mps2-an505", "cortex-m33"),
        probes: &costs::PROBES,
    },
];

/// The Cortex-M4F column's heading (the main build, `crate::costs`).
const M4F_TITLE: &str = "Cortex-M4F, f32 (mps2-an386)";

/// The page the tables go to, and its markers.
pub const PAGE: &str = "docs/sections/cortex_m_family.md";

impl Core {
    /// The core's own target directory: the Cortex-M7's builds share the
    /// Cortex-M4F's target with other flags, and would overwrite its
    /// artefacts in a shared one.
    fn target_dir(&self) -> PathBuf {
        shell::target_dir().join("family").join(self.id)
    }

    fn elf(&self, probe: &str) -> PathBuf {
        self.target_dir()
            .join(self.target)
            .join("release")
            .join(probe)
    }

    fn log_path(&self, probe: &str) -> PathBuf {
        shell::target_dir()
            .join("firmware-logs")
            .join("family")
            .join(self.id)
            .join(format!("{probe}.log"))
    }

    /// Builds the core's probes in release mode.
    fn build(&self) -> Result<()> {
        let mut command = firmware::cargo_command_for(self.target, self.rustflags);
        command.args([
            "build",
            "--release",
            "--target",
            self.target,
            "--target-dir",
        ]);
        command.arg(self.target_dir());
        for probe in self.probes {
            command.args(["--bin", probe]);
        }
        if !self.features.is_empty() {
            command.args(["--features", &self.features.join(",")]);
        }
        shell::run(&mut command)
    }

    /// Runs one probe in QEMU, keeps its log and requires exit code 0.
    fn run(&self, probe: &str) -> Result<Vec<String>> {
        let outcome = firmware::run_on_machine(&self.elf(probe), self.machine, &[], |_| {})?;
        let path = self.log_path(probe);
        std::fs::create_dir_all(path.parent().expect("a log directory"))?;
        std::fs::write(&path, outcome.lines.join("\n") + "\n")?;
        if outcome.exit_code != 0 {
            for line in &outcome.lines {
                println!("  | {line}");
            }
            bail!(
                "{probe} on {} exited with code {} (log: {})",
                self.title,
                outcome.exit_code,
                path.display()
            );
        }
        Ok(outcome.lines)
    }

    fn last_log(&self, probe: &str) -> Result<Vec<String>> {
        let path = self.log_path(probe);
        Ok(std::fs::read_to_string(&path)
            .with_context(|| {
                format!(
                    "cannot read {} (`cargo xtask test` writes it)",
                    path.display()
                )
            })?
            .lines()
            .map(str::to_string)
            .collect())
    }
}

/// Builds every core's probes and runs them in QEMU, keeping their logs:
/// the step of `cargo xtask test` whose logs its docs check turns into the
/// tables. Fails on a probe that does not exit with 0, on an image whose
/// stack the static analysis cannot bound, on a painted stack figure above
/// its static bound, and on an f64 image that computes in software.
pub fn run_probes() -> Result<()> {
    setup::ensure_family_targets()?;
    for core in &CORES {
        let started = Instant::now();
        core.build()?;
        let built = started.elapsed().as_secs_f64();
        let mut rows = Vec::new();
        for probe in core.probes {
            rows.extend(costs::parse_costs(&core.run(probe)?)?);
        }
        let images = analyse(core)?;
        stack_bound::check_images(&images)?;
        stack_bound::check_rows(&images, &costs::stack_rows(&rows))?;
        println!(
            "family {}: {} probes ran ({} rows; built in {built:.0} s, ran in {:.0} s)",
            core.title,
            core.probes.len(),
            rows.len(),
            started.elapsed().as_secs_f64() - built
        );
    }
    double_precision_in_hardware()?;
    Ok(())
}

/// The call graphs of one core's probe images.
fn analyse(core: &Core) -> Result<BTreeMap<&'static str, Analysed>> {
    core.probes
        .iter()
        .map(|&probe| {
            let graph = Graph::of_elf(&core.elf(probe))?;
            let bounds = graph.bounds();
            let without_panics = graph.bounds_without(&graph.panic_entries());
            Ok((
                probe,
                Analysed {
                    graph,
                    bounds,
                    without_panics,
                },
            ))
        })
        .collect()
}

/// Floating-point instructions of the f64 cost probe's image, by mnemonic
/// (`vadd.f64` …), and the soft-float double routines it links
/// (`__aeabi_dadd` …, which would mean f64 arithmetic in software).
fn f64_instructions() -> Result<(BTreeMap<String, usize>, Vec<String>)> {
    let core = CORES
        .iter()
        .find(|c| c.features.contains(&"f64"))
        .context("no f64 core")?;
    let elf = core.elf("cost_probe");
    let objdump = setup::llvm_tool("llvm-objdump")?;
    let text = setup::output(
        std::process::Command::new(objdump)
            .args(["-d", "--no-show-raw-insn"])
            .arg(&elf),
    )?;
    let mut counts = BTreeMap::new();
    let mut soft = std::collections::BTreeSet::new();
    for line in text.lines() {
        let mut fields = line.split_whitespace().skip(1);
        if let Some(mnemonic) = fields.next() {
            if mnemonic.starts_with('v') && mnemonic.ends_with(".f64") {
                *counts.entry(mnemonic.to_string()).or_insert(0) += 1;
            }
        }
        // A label line: `00001234 <__aeabi_dadd>:`.
        if let Some(name) = line
            .split_once('<')
            .and_then(|(_, rest)| rest.strip_suffix(">:"))
        {
            if name.starts_with("__aeabi_d") || name.starts_with("__adddf3") {
                soft.insert(name.to_string());
            }
        }
    }
    Ok((counts, soft.into_iter().collect()))
}

/// Fails unless the f64 image computes on the FPU: double-precision
/// additions, multiplications and divisions in its code, and no soft-float
/// double routine linked.
fn double_precision_in_hardware() -> Result<()> {
    let (counts, soft) = f64_instructions()?;
    let missing: Vec<&str> = ["vadd.f64", "vmul.f64", "vdiv.f64"]
        .into_iter()
        .filter(|m| !counts.contains_key(*m))
        .collect();
    if !missing.is_empty() || !soft.is_empty() {
        bail!(
            "the Cortex-M7 f64 cost probe does not compute on the double-precision FPU: \
             no {} in its code; soft-float routines linked: {}",
            missing.join(", "),
            soft.join(", ")
        );
    }
    println!(
        "family Cortex-M7 f64: {} double-precision FPU instructions, no soft-float double routine",
        counts.values().sum::<usize>()
    );
    Ok(())
}

/// One column of the tables: a core's cost rows and call graphs.
struct Column {
    title: &'static str,
    costs: Vec<Cost>,
    images: BTreeMap<&'static str, Analysed>,
    /// Flash (text + data) of each probe image.
    flash: BTreeMap<&'static str, u64>,
}

impl Column {
    /// The row of (`model`, algorithm key), if this core measured it.
    fn row(&self, model: &str, key: &str) -> Option<&Cost> {
        self.costs
            .iter()
            .find(|c| c.model == model && algorithm_key(&c.algorithm) == key)
    }
}

/// The algorithm's name without the scalar prefix of the `scalar` rows
/// (`f32-sin_cos` and `f64-sin_cos` are one row of the tables).
fn algorithm_key(algorithm: &str) -> &str {
    algorithm
        .strip_prefix("f32-")
        .or_else(|| algorithm.strip_prefix("f64-"))
        .unwrap_or(algorithm)
}

/// Flash bytes (text + data, `llvm-size -B`) of an ELF.
fn flash_bytes(elf: &std::path::Path) -> Result<u64> {
    let out = setup::output(
        std::process::Command::new(setup::llvm_size()?)
            .arg("-B")
            .arg(elf),
    )?;
    let numbers: Vec<u64> = out
        .lines()
        .nth(1)
        .context("llvm-size printed no sizes")?
        .split_whitespace()
        .take(2)
        .map(str::parse)
        .collect::<Result<_, _>>()
        .context("llvm-size output")?;
    Ok(numbers[0] + numbers[1])
}

/// The page with its tables regenerated: the Cortex-M4F column from the
/// main build's rows and images (`m4_costs`, `m4_images`), the other
/// cores' from fresh builds and runs or from `cargo xtask test`'s logs.
pub fn page(
    runs: ProbeRuns,
    m4_costs: Vec<Cost>,
    m4_images: BTreeMap<&'static str, Analysed>,
) -> Result<String> {
    if runs == ProbeRuns::Fresh {
        run_probes()?;
    }
    let mut m4_flash = BTreeMap::new();
    for probe in costs::PROBES {
        m4_flash.insert(probe, flash_bytes(&firmware::elf_of(probe))?);
    }
    let mut columns = vec![Column {
        title: M4F_TITLE,
        costs: m4_costs,
        images: m4_images,
        flash: m4_flash,
    }];
    for core in &CORES {
        let mut rows = Vec::new();
        let mut flash = BTreeMap::new();
        for &probe in core.probes {
            rows.extend(costs::parse_costs(&core.last_log(probe)?)?);
            flash.insert(probe, flash_bytes(&core.elf(probe))?);
        }
        columns.push(Column {
            title: core.title,
            costs: rows,
            images: analyse(core)?,
            flash,
        });
    }
    // The M3 first, as the cheapest core: the order of CORES with the
    // Cortex-M4F after it.
    columns.swap(0, 1);

    let path = shell::root().join(PAGE);
    let text = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    let text = costs::replace_between(&text, "family-instructions", &instructions(&columns)?)?;
    let text = costs::replace_between(&text, "family-stack", &stack(&columns)?)?;
    let text = costs::replace_between(&text, "family-flash", &flash(&columns)?)?;
    costs::replace_between(&text, "family-f64", &f64_table()?)
}

/// The rows of the tables: the Cortex-M4F's, in its order (every core
/// probes a part of them).
fn row_keys(columns: &[Column]) -> Vec<(String, String)> {
    let m4 = columns
        .iter()
        .find(|c| c.title == M4F_TITLE)
        .expect("the Cortex-M4F column");
    m4.costs
        .iter()
        .map(|c| (c.model.clone(), algorithm_key(&c.algorithm).to_string()))
        .collect()
}

fn header(columns: &[Column], first: &str) -> String {
    let mut text = format!("| {first} |");
    for c in columns {
        write!(text, " {} |", c.title).expect("writing to a String");
    }
    text.push_str("\n|---|---|");
    text.push_str(&"---:|".repeat(columns.len()));
    text.push('\n');
    text
}

/// Instructions per call (min – max over the states) per core, and each
/// core's maximum over the Cortex-M4F's.
fn instructions(columns: &[Column]) -> Result<String> {
    let mut table = header(columns, "model | algorithm");
    for (model, key) in row_keys(columns) {
        write!(table, "| {model} | {key} |")?;
        let m4_max = columns
            .iter()
            .find(|c| c.title == M4F_TITLE)
            .and_then(|c| c.row(&model, &key))
            .map(|c| c.max);
        for column in columns {
            match column.row(&model, &key) {
                Some(c) if column.title == M4F_TITLE => write!(table, " {} – {} |", c.min, c.max)?,
                Some(c) => match m4_max {
                    Some(m4) if m4 > 0 => write!(
                        table,
                        " {} – {} (×{:.2}) |",
                        c.min,
                        c.max,
                        c.max as f64 / m4 as f64
                    )?,
                    _ => write!(table, " {} – {} |", c.min, c.max)?,
                },
                None => table.push_str(" - |"),
            }
        }
        table.push('\n');
    }
    Ok(table)
}

/// Stack bytes per call: painted / static bound, per core.
fn stack(columns: &[Column]) -> Result<String> {
    let mut table = header(columns, "model | algorithm");
    for (model, key) in row_keys(columns) {
        write!(table, "| {model} | {key} |")?;
        for column in columns {
            match column.row(&model, &key) {
                Some(c) if c.stack != "-" => {
                    let bound = stack_bound::row_bound(&column.images, &c.model, &c.algorithm)?;
                    write!(table, " {} / {} |", c.stack, bound.bytes)?;
                }
                _ => table.push_str(" - |"),
            }
        }
        table.push('\n');
    }
    Ok(table)
}

/// Code bytes each call reaches, per core, and each probe image's flash.
fn flash(columns: &[Column]) -> Result<String> {
    let mut table = header(columns, "model | algorithm");
    for (model, key) in row_keys(columns) {
        write!(table, "| {model} | {key} |")?;
        for column in columns {
            match column.row(&model, &key) {
                Some(c) if c.stack != "-" => {
                    let bytes =
                        stack_bound::row_code_bytes(&column.images, &c.model, &c.algorithm)?;
                    write!(table, " {bytes} |")?;
                }
                _ => table.push_str(" - |"),
            }
        }
        table.push('\n');
    }
    for probe in costs::PROBES {
        write!(table, "| whole image | `{probe}` (text + data) |")?;
        for column in columns {
            match column.flash.get(probe) {
                Some(bytes) => write!(table, " {bytes} |")?,
                None => table.push_str(" - |"),
            }
        }
        table.push('\n');
    }
    Ok(table)
}

/// The double-precision instructions of the Cortex-M7's f64 image.
fn f64_table() -> Result<String> {
    let (counts, soft) = f64_instructions()?;
    let mut table =
        String::from("| instruction (f64 `cost_probe`, Cortex-M7) | in the code |\n|---|---:|\n");
    for (mnemonic, count) in &counts {
        writeln!(table, "| `{mnemonic}` | {count} |")?;
    }
    writeln!(
        table,
        "| soft-float double routines (`__aeabi_d…`) linked | {} |",
        soft.len()
    )?;
    Ok(table)
}
