//! Panic call sites in the firmware images, held to a ratchet.
//!
//! The core promises no panics on a valid model, but bounds checks the
//! optimiser cannot prove (slices indexed through the topology tables)
//! still link calls to `core::panicking` into the images. This counts the
//! calls to the panic entry points in each image's disassembly and fails
//! when an image has more than `firmware/expected/panic_sites.txt`
//! records, so that no change adds one unnoticed; `cargo xtask costs`
//! rewrites the file when a change removes some.

use crate::firmware::{self, EXAMPLES};
use crate::setup;
use anyhow::{bail, Context, Result};
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

fn expected_path() -> PathBuf {
    firmware::dir().join("expected/panic_sites.txt")
}

/// Calls (`bl`, `b`, `b.w`) to a panic entry point in one image.
fn count(name: &str) -> Result<usize> {
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
    Ok(text
        .lines()
        .filter(|line| {
            let mut words = line.split_whitespace();
            let branch = words
                .nth(1)
                .is_some_and(|op| matches!(op, "bl" | "b" | "b.w"));
            branch && PANIC_ENTRIES.iter().any(|entry| line.contains(entry))
        })
        .count())
}

/// Every image's count.
pub fn measure() -> Result<BTreeMap<String, usize>> {
    EXAMPLES
        .iter()
        .map(|e| Ok((e.name.to_string(), count(e.name)?)))
        .collect()
}

fn recorded() -> Result<BTreeMap<String, usize>> {
    let text = std::fs::read_to_string(expected_path())
        .with_context(|| format!("reading {}", expected_path().display()))?;
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let (name, n) = l
                .split_once(char::is_whitespace)
                .context("a line `name count`")?;
            Ok((name.to_string(), n.trim().parse()?))
        })
        .collect()
}

/// Fails when an image has more panic call sites than recorded.
pub fn check() -> Result<()> {
    let recorded = recorded()?;
    let mut grew = Vec::new();
    for (name, now) in measure()? {
        let before = recorded.get(&name).copied();
        println!(
            "panic call sites {name}: {now} (recorded {})",
            before.map_or("-".into(), |b| b.to_string())
        );
        if before.is_some_and(|b| now > b) {
            grew.push(format!("{name}: {} -> {now}", before.unwrap_or(0)));
        }
    }
    if !grew.is_empty() {
        bail!(
            "panic call sites grew in {} (a new bounds check or unwrap the optimiser cannot remove; \
             `cargo xtask costs` records an intended change)",
            grew.join(", ")
        );
    }
    Ok(())
}

/// Rewrites the recorded counts.
pub fn record() -> Result<()> {
    let mut text = String::from(
        "# Calls to core's panic entry points in each firmware image (cargo xtask test fails when one grows;\n# cargo xtask costs rewrites this file).\n",
    );
    for (name, n) in measure()? {
        text.push_str(&format!("{name} {n}\n"));
    }
    std::fs::write(expected_path(), text)?;
    println!("wrote {}", expected_path().display());
    Ok(())
}
