//! Panic call sites in the firmware images, attributed to their source.
//!
//! The core promises no panics on a valid model, but bounds checks the
//! optimiser cannot prove (slices indexed through the topology tables)
//! link calls to `core::panicking` into the images. This finds the calls
//! to the panic entry points in each image's disassembly and charges each
//! to the code it came from: the innermost frame of its inlined call chain
//! (from the ELF's debug information) that is not the standard library's,
//! so a bounds check `core::slice::index` reports for `a[i]` in
//! `rnea.rs` counts as `rodyn`'s. `cargo xtask test` fails when an image's
//! count for any source grows above `firmware/expected/panic_sites.txt`;
//! `cargo xtask costs` rewrites the file when a change removes some, and
//! `cargo xtask panic-sites [image]` lists the sites by function and line.

use crate::firmware::{self, EXAMPLES};
use crate::setup;
use anyhow::{anyhow, bail, Context, Result};
use std::collections::BTreeMap;
use std::path::PathBuf;
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

/// Addresses and callees of the calls (`bl`, `b`, `b.w`) to a panic entry point in one image.
fn calls(name: &str) -> Result<Vec<(u64, String)>> {
    let objdump = setup::llvm_tool("llvm-objdump")?;
    let output = Command::new(objdump)
        .args(["-d", "--no-show-raw-insn", "--demangle"])
        .arg(firmware::elf_of(name))
        .output()
        .context("running llvm-objdump")?;
    if !output.status.success() {
        bail!("llvm-objdump failed on {name}");
    }
    let text = String::from_utf8_lossy(&output.stdout);
    let mut found = Vec::new();
    for line in text.lines() {
        let mut words = line.split_whitespace();
        let (Some(address), Some(op)) = (words.next(), words.next()) else {
            continue;
        };
        if !matches!(op, "bl" | "b" | "b.w") {
            continue;
        }
        let Some(entry) = PANIC_ENTRIES.iter().find(|entry| line.contains(*entry)) else {
            continue;
        };
        let address = u64::from_str_radix(address.trim_end_matches(':'), 16)
            .with_context(|| format!("an address in `{line}`"))?;
        let callee = line[line.find(entry).unwrap_or(0) + 1..]
            .trim_end_matches('>')
            .to_string();
        found.push((address, short_function(&callee)));
    }
    Ok(found)
}

/// Every panic call site in one image.
pub fn sites(name: &str) -> Result<Vec<Site>> {
    let elf = firmware::elf_of(name);
    let loader = addr2line::Loader::new(&elf)
        .map_err(|e| anyhow!("{}: debug information: {e}", elf.display()))?;
    calls(name)?
        .into_iter()
        .map(|(address, entry)| {
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
                // The standard library's frames (`/rustc/<hash>/library/...`) are how
                // the check is made, not where it comes from.
                if file.contains("/library/") || file.is_empty() {
                    outermost.get_or_insert((function, String::new(), "other"));
                    continue;
                }
                let source = source_of(file);
                return Ok(Site {
                    source,
                    function,
                    line: format!("{}:{line}", short_file(file)),
                    entry,
                });
            }
            let (function, line, source) =
                outermost.unwrap_or_else(|| (format!("{address:#x}"), String::new(), "other"));
            Ok(Site {
                source,
                function,
                line,
                entry,
            })
        })
        .collect()
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

/// A function's path without generic arguments and hash, last two segments.
fn short_function(name: &str) -> String {
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
    let segments: Vec<&str> = plain
        .split("::")
        .filter(|s| !(s.is_empty() || s.len() == 17 && s.starts_with('h')))
        .collect();
    segments[segments.len().saturating_sub(2)..].join("::")
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

/// Fails when an image has more panic call sites from any source than recorded.
pub fn check() -> Result<()> {
    let recorded = recorded()?;
    let mut grew = Vec::new();
    for (name, now) in measure()? {
        println!("panic call sites {name}: {}", describe(&now));
        for (source, n) in &now {
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
    if !grew.is_empty() {
        bail!(
            "panic call sites grew in {} (a new bounds check or unwrap the optimiser cannot remove; \
             `cargo xtask panic-sites <image>` lists them; `cargo xtask costs` records an intended change)",
            grew.join(", ")
        );
    }
    Ok(())
}

/// Rewrites the recorded counts.
pub fn record() -> Result<()> {
    let mut text = String::from(
        "# Calls to core's panic entry points in each firmware image, by the source of the code that makes them\n\
         # (cargo xtask test fails when one grows; cargo xtask costs rewrites this file).\n",
    );
    for (name, counts) in measure()? {
        for (source, n) in counts {
            text.push_str(&format!("{name} {source} {n}\n"));
        }
    }
    std::fs::write(expected_path(), text)?;
    println!("wrote {}", expected_path().display());
    Ok(())
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
