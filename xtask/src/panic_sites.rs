//! Panic call sites in the firmware images, attributed to their source.
//!
//! The core promises no panics on a valid model, but bounds checks the
//! optimiser cannot prove (slices indexed through the topology tables)
//! link calls to `core::panicking` into the images. This finds the calls
//! to the panic entry points in each image's disassembly and charges each
//! to the code it came from: the innermost frame of its inlined call chain
//! (from the ELF's debug information) that is not the standard library's,
//! so a bounds check `core::slice::index` reports for `a[i]` in
//! `rnea.rs` counts as `rodyn`'s. `cargo xtask test` fails when any image
//! has a site of `rodyn`'s, and when an image's count for another source
//! grows above `firmware/expected/panic_sites.txt`;
//! `cargo xtask costs` rewrites the file when a change removes some, and
//! `cargo xtask panic-sites [image]` lists the sites by function and line.

use crate::firmware::{self, EXAMPLES};
use crate::profile::short_function;
use crate::setup;
use anyhow::{anyhow, bail, Context, Result};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The symbols a panic enters through (demangled prefixes).
pub const PANIC_ENTRIES: [&str; 6] = [
    "<core::panicking::",
    "<core::slice::index::",
    "<core::option::unwrap_failed",
    "<core::option::expect_failed",
    "<core::result::unwrap_failed",
    "<core::panic",
];

/// Where the code of a panic call site comes from.
pub const SOURCES: [&str; 4] = ["rodyn", "scenarios", "firmware", "other"];

fn expected_path() -> PathBuf {
    firmware::dir().join("expected/panic_sites.txt")
}

/// One call to a panic entry point.
#[derive(Debug)]
pub struct Site {
    /// One of [`SOURCES`].
    pub source: &'static str,
    /// The function whose code makes the call (innermost outside the
    /// standard library), without generic arguments.
    pub function: String,
    /// Its `file:line`, the path from the crate's `src/` on.
    pub line: String,
    /// The entry point called (`panic_bounds_check`, `slice_end_index_len_fail`, ...).
    pub entry: String,
}

/// One call to a panic entry point, as the disassembly shows it.
struct Call {
    /// The call instruction's address.
    address: u64,
    /// The entry point called, short.
    entry: String,
    /// The address the call's block loads into a register with a
    /// `movw`/`movt` pair just before it, when it does: the panic's
    /// `core::panic::Location` (a bounds check's file and line), or
    /// nothing of use.
    loaded: Vec<u64>,
}

/// Instructions that end a block: the scan for a location stops there.
fn ends_block(op: &str) -> bool {
    op.starts_with('b') && !op.starts_with("bic") || matches!(op, "trap" | "udf" | "pop" | "pop.w")
}

/// The calls (`bl`, `b`, `b.w`) to a panic entry point in one image.
fn calls(elf: &Path) -> Result<Vec<Call>> {
    let objdump = setup::llvm_tool("llvm-objdump")?;
    let output = Command::new(objdump)
        .args(["-d", "--no-show-raw-insn", "--demangle"])
        .arg(elf)
        .output()
        .context("running llvm-objdump")?;
    if !output.status.success() {
        bail!("llvm-objdump failed on {}", elf.display());
    }
    let text = String::from_utf8_lossy(&output.stdout);
    // (op, operands) of the instructions since the last block end.
    let mut block: Vec<(String, String)> = Vec::new();
    let mut found = Vec::new();
    for line in text.lines() {
        let mut words = line.split_whitespace();
        let (Some(address), Some(op)) = (words.next(), words.next()) else {
            continue;
        };
        let Ok(address) = u64::from_str_radix(address.trim_end_matches(':'), 16) else {
            block.clear();
            continue;
        };
        let operands: String = words.collect::<Vec<_>>().join(" ");
        if matches!(op, "bl" | "b" | "b.w") {
            if let Some(entry) = PANIC_ENTRIES.iter().find(|entry| line.contains(*entry)) {
                let callee = line[line.find(entry).unwrap_or(0) + 1..]
                    .split('>')
                    .next()
                    .unwrap_or("")
                    .to_string();
                found.push(Call {
                    address,
                    entry: short_function(&callee),
                    loaded: loaded_addresses(&block),
                });
            }
        }
        if ends_block(op) {
            block.clear();
        } else {
            block.push((op.to_string(), operands));
        }
    }
    Ok(found)
}

/// The 32-bit constants `movw`/`movt` pairs put in registers in `block`.
fn loaded_addresses(block: &[(String, String)]) -> Vec<u64> {
    let immediate = |operands: &str| -> Option<(String, u64)> {
        let (register, value) = operands.split_once(", #")?;
        let value = value.split_whitespace().next()?;
        let value = match value.strip_prefix("0x") {
            Some(hex) => u64::from_str_radix(hex, 16).ok()?,
            None => value.parse().ok()?,
        };
        Some((register.to_string(), value))
    };
    let mut low: BTreeMap<String, u64> = BTreeMap::new();
    let mut found = Vec::new();
    for (op, operands) in block {
        match op.as_str() {
            "movw" => {
                if let Some((r, v)) = immediate(operands) {
                    low.insert(r, v);
                }
            }
            "movt" => {
                if let Some((r, v)) = immediate(operands) {
                    if let Some(l) = low.get(&r) {
                        found.push(v << 16 | l);
                    }
                }
            }
            _ => {}
        }
    }
    found
}

/// An image's read-only data, to read panic locations from.
struct Image {
    /// (address, bytes) of each allocated section.
    sections: Vec<(u64, Vec<u8>)>,
}

impl Image {
    fn read(elf: &std::path::Path) -> Result<Self> {
        use object::{Object, ObjectSection};
        let data = std::fs::read(elf).with_context(|| format!("reading {}", elf.display()))?;
        let file = object::File::parse(&*data)?;
        let sections = file
            .sections()
            .filter(|s| s.address() != 0)
            .filter_map(|s| Some((s.address(), s.data().ok()?.to_vec())))
            .collect();
        Ok(Self { sections })
    }

    fn bytes(&self, address: u64, n: u64) -> Option<&[u8]> {
        self.sections.iter().find_map(|(start, bytes)| {
            let at = usize::try_from(address.checked_sub(*start)?).ok()?;
            bytes.get(at..at + usize::try_from(n).ok()?)
        })
    }

    fn word(&self, address: u64) -> Option<u64> {
        let b = self.bytes(address, 4)?;
        Some(u64::from(u32::from_le_bytes([b[0], b[1], b[2], b[3]])))
    }

    /// The `core::panic::Location` at `address` (on this 32-bit target:
    /// file pointer, file length, line, column), when one is there.
    fn location(&self, address: u64) -> Option<(String, u32)> {
        let (file, len, line) = (
            self.word(address)?,
            self.word(address + 4)?,
            self.word(address + 8)?,
        );
        if len == 0 || len > 400 || line == 0 || line > 1_000_000 {
            return None;
        }
        let file = std::str::from_utf8(self.bytes(file, len)?).ok()?;
        let line = u32::try_from(line).ok()?;
        file.ends_with(".rs").then(|| (file.to_string(), line))
    }
}

/// Every panic call site in one image. The location a call passes (its
/// `Location`, which names the line of the index or `unwrap`) says where it
/// comes from when the call's block loads one; otherwise the innermost
/// frame outside the standard library of its inlined call chain does.
pub fn sites(name: &str) -> Result<Vec<Site>> {
    sites_in(&firmware::elf_of(name))
}

/// [`sites`] of any firmware ELF (the boards', `crate::boards`).
pub fn sites_in(elf: &Path) -> Result<Vec<Site>> {
    let image = Image::read(elf)?;
    let loader = addr2line::Loader::new(elf)
        .map_err(|e| anyhow!("{}: debug information: {e}", elf.display()))?;
    calls(elf)?
        .into_iter()
        .map(|call| {
            let (function, frame_line) = frame_of(&loader, call.address)?;
            let passed = call.loaded.iter().find_map(|a| image.location(*a));
            let (source, line) = match (passed, frame_line) {
                (Some((file, line)), _) => {
                    (source_of(&file), format!("{}:{line}", short_file(&file)))
                }
                (None, Some((file, line))) => {
                    (source_of(&file), format!("{}:{line}", short_file(&file)))
                }
                (None, None) => ("other", String::new()),
            };
            Ok(Site {
                source,
                function,
                line,
                entry: call.entry,
            })
        })
        .collect()
}

/// The innermost function of `address`'s inlined call chain outside the
/// standard library (`/rustc/<hash>/library/...`: how a check is made, not
/// where it comes from), with its file and line when known.
fn frame_of(loader: &addr2line::Loader, address: u64) -> Result<(String, Option<(String, u32)>)> {
    let mut frames = loader
        .find_frames(address)
        .map_err(|e| anyhow!("address {address:#x}: {e}"))?;
    let mut outermost = None;
    while let Some(frame) = frames.next()? {
        let function = frame
            .function
            .as_ref()
            .and_then(|f| f.demangle().ok())
            .map(|f| short_function(&f))
            .unwrap_or_else(|| format!("{address:#x}"));
        let file = frame.location.as_ref().and_then(|l| l.file).unwrap_or("");
        let line = frame.location.as_ref().and_then(|l| l.line).unwrap_or(0);
        if file.contains("/library/") || file.is_empty() {
            outermost = Some(function);
            continue;
        }
        return Ok((function, Some((file.to_string(), line))));
    }
    Ok((outermost.unwrap_or_else(|| format!("{address:#x}")), None))
}

/// Which of [`SOURCES`] a source file belongs to.
fn source_of(file: &str) -> &'static str {
    if file.contains("crates/rodyn/src/") {
        "rodyn"
    } else if file.contains("crates/rodyn-scenarios/") {
        "scenarios"
    } else if file.contains("firmware/src/") {
        "firmware"
    } else {
        "other"
    }
}

/// A path from its crate's `src/` on, with the crate's directory name
/// (`rodyn/src/algorithm/aba.rs`, `defmt-1.0.1/src/lib.rs`).
fn short_file(file: &str) -> String {
    match file.rfind("/src/") {
        Some(at) => {
            let start = file[..at].rfind('/').map_or(0, |s| s + 1);
            file[start..].to_string()
        }
        None => file.to_string(),
    }
}

/// Every image's counts per source.
pub fn measure() -> Result<BTreeMap<String, BTreeMap<&'static str, usize>>> {
    EXAMPLES
        .iter()
        .map(|e| {
            let mut counts: BTreeMap<&'static str, usize> =
                SOURCES.iter().map(|s| (*s, 0)).collect();
            for site in sites(e.name)? {
                *counts.entry(site.source).or_default() += 1;
            }
            Ok((e.name.to_string(), counts))
        })
        .collect()
}

/// The recorded counts: image → source → count.
fn recorded() -> Result<BTreeMap<String, BTreeMap<String, usize>>> {
    let text = std::fs::read_to_string(expected_path())
        .with_context(|| format!("reading {}", expected_path().display()))?;
    let mut recorded: BTreeMap<String, BTreeMap<String, usize>> = BTreeMap::new();
    for l in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let words: Vec<&str> = l.split_whitespace().collect();
        let [name, source, n] = words[..] else {
            bail!("a line `image source count`, not `{l}`");
        };
        recorded
            .entry(name.to_string())
            .or_default()
            .insert(source.to_string(), n.parse()?);
    }
    Ok(recorded)
}

fn describe(counts: &BTreeMap<&'static str, usize>) -> String {
    counts
        .iter()
        .map(|(s, n)| format!("{s} {n}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The source whose images must have no panic call site at all (the
/// core's promise); the others are held to their recorded counts.
pub const NO_SITES: &str = "rodyn";

/// Fails when an image has any panic call site from [`NO_SITES`], or more
/// from another source than recorded.
pub fn check() -> Result<()> {
    let recorded = recorded()?;
    let mut grew = Vec::new();
    let mut forbidden = Vec::new();
    for (name, now) in measure()? {
        println!("panic call sites {name}: {}", describe(&now));
        for (source, n) in &now {
            if *source == NO_SITES {
                if *n > 0 {
                    forbidden.push(format!("{name}: {n}"));
                }
                continue;
            }
            let before = recorded
                .get(&name)
                .and_then(|r| r.get(*source))
                .copied()
                .unwrap_or(0);
            if *n > before {
                grew.push(format!("{name} {source}: {before} -> {n}"));
            }
        }
    }
    if !forbidden.is_empty() {
        bail!(
            "{NO_SITES} has panic call sites in {} (every image must have none: \
             `cargo xtask panic-sites <image>` lists them)",
            forbidden.join(", ")
        );
    }
    if !grew.is_empty() {
        bail!(
            "panic call sites grew in {} (a new bounds check or unwrap the optimiser cannot remove; \
             `cargo xtask panic-sites <image>` lists them; `cargo xtask costs` records an intended change)",
            grew.join(", ")
        );
    }
    Ok(())
}

/// The recorded counts' text (`cargo xtask costs` writes it to
/// `firmware/expected/panic_sites.txt`): each image's counts by source.
pub fn expected_text() -> Result<String> {
    let mut text = String::from(
        "# Calls to core's panic entry points in each firmware image, by the source of the code that makes them\n\
         # (cargo xtask test fails on any of rodyn's, and when another grows; cargo xtask costs rewrites this file).\n",
    );
    for (name, counts) in measure()? {
        for (source, n) in counts {
            text.push_str(&format!("{name} {source} {n}\n"));
        }
    }
    Ok(text)
}

/// `cargo xtask panic-sites [image]`: the sites of one image (or every
/// image) by source, function and line, most first.
pub fn run(args: &[String]) -> Result<()> {
    let names: Vec<&str> = match args.first() {
        Some(name) => vec![firmware::example(name)?.name],
        None => EXAMPLES.iter().map(|e| e.name).collect(),
    };
    setup::ensure_target()?;
    firmware::build()?;
    let mut by_function: BTreeMap<(String, &'static str), usize> = BTreeMap::new();
    let mut by_line: BTreeMap<(String, String, String), usize> = BTreeMap::new();
    for name in names {
        let sites = sites(name)?;
        let mut counts: BTreeMap<&'static str, usize> = SOURCES.iter().map(|s| (*s, 0)).collect();
        for site in sites {
            *counts.entry(site.source).or_default() += 1;
            *by_function
                .entry((site.function.clone(), site.source))
                .or_default() += 1;
            *by_line
                .entry((site.line, site.function, site.entry))
                .or_default() += 1;
        }
        println!("{name}: {}", describe(&counts));
    }
    let mut functions: Vec<_> = by_function.into_iter().collect();
    functions.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    println!("\nby function (sites summed over the images):");
    for ((function, source), n) in functions {
        println!("{n:6}  {source:9}  {function}");
    }
    let mut lines: Vec<_> = by_line.into_iter().collect();
    lines.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    println!("\nby line:");
    for ((line, function, entry), n) in lines {
        println!("{n:6}  {line}  ({function}, {entry})");
    }
    Ok(())
}
