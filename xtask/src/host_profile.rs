//! `cargo xtask host-profile <algorithm> <model>`: where a call's
//! instructions go on the host (x86-64, `f64`), line by line.
//!
//! Runs `rodyn-bench`'s `profile` binary under callgrind twice, for
//! [`CALLS`] and twice as many calls, with a count per instruction address.
//! The difference of the two runs is what the extra calls executed, without
//! the set-up; divided by [`CALLS`], it is one call's instructions. Each
//! address is then charged through the binary's debug information to the
//! innermost line of `rodyn`'s algorithms it was inlined into, as
//! [`profile`](crate::profile) does for the firmware. Counts are exact for
//! the binary, inputs and environment: timings on a shared machine are not.

use crate::profile::{print_table, Lines};
use crate::{setup, shell};
use anyhow::{bail, Context, Result};
use std::collections::HashMap;
use std::path::Path;
use std::process::Command;

/// Calls in the first run (the second runs twice as many).
const CALLS: u64 = 500;

/// Profiles `args = [algorithm, model]` (as the `profile` binary names them).
pub fn run(args: &[String]) -> Result<()> {
    let [algorithm, model] = args else {
        bail!(
            "usage: cargo xtask host-profile <rnea|crba|crba_fd|aba> <model> \
             (panda, ur5, solo12, chainN, chainN_planar with N in 5, 10, 20, 60)"
        );
    };
    setup::ensure_valgrind()?;
    shell::cargo(&[
        "build",
        "-p",
        "rodyn-bench",
        "--release",
        "--bin",
        "profile",
    ])?;
    let binary = shell::target_dir().join("release").join("profile");
    let once = address_counts(&binary, algorithm, model, CALLS)?;
    let twice = address_counts(&binary, algorithm, model, 2 * CALLS)?;
    let extra: HashMap<u64, u64> = twice
        .iter()
        .filter_map(|(pc, n)| {
            let d = n.saturating_sub(once.get(pc).copied().unwrap_or(0));
            (d > 0).then_some((*pc, d))
        })
        .collect();
    let lines = Lines::new(&binary)?;
    print_table(
        &format!("{algorithm} {model} (host, f64, callgrind)"),
        &extra,
        &lines,
        CALLS,
    )
}

/// Instructions executed at each address in one run of `calls` calls.
fn address_counts(
    binary: &Path,
    algorithm: &str,
    model: &str,
    calls: u64,
) -> Result<HashMap<u64, u64>> {
    let out = shell::target_dir().join(format!("host-profile-{calls}.callgrind"));
    let status = Command::new("valgrind")
        .args([
            "--tool=callgrind",
            "--dump-instr=yes",
            "--compress-pos=no",
            "--compress-strings=no",
        ])
        .arg(format!("--callgrind-out-file={}", out.display()))
        .arg(binary)
        .args([algorithm, model, &calls.to_string()])
        .output()
        .context("running valgrind")?;
    if !status.status.success() {
        bail!(
            "the profile binary failed under callgrind: {}",
            String::from_utf8_lossy(&status.stdout).trim()
        );
    }
    let text =
        std::fs::read_to_string(&out).with_context(|| format!("reading {}", out.display()))?;
    std::fs::remove_file(&out).ok();
    Ok(parse_callgrind(&text))
}

/// The self cost of every address in a callgrind file written with
/// `--dump-instr=yes --compress-pos=no`: cost lines read `0xADDR LINE IR`;
/// the line after a `calls=` line is the call's inclusive cost and is skipped.
fn parse_callgrind(text: &str) -> HashMap<u64, u64> {
    let mut counts = HashMap::new();
    let mut after_call = false;
    for line in text.lines() {
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
            *counts.entry(address).or_insert(0) += cost;
        }
    }
    counts
}

#[cfg(test)]
mod tests {
    use super::parse_callgrind;

    #[test]
    fn reads_self_costs_and_skips_inclusive_call_costs() {
        let text = "fn=(1) main\n0x401000 10 5\n0x401004 10 7\ncalls=2 0x402000 20\n\
                    0x401008 11 900\n0x40100c 12 3\nfn=(2) f\n0x401000 30 1\n";
        let counts = parse_callgrind(text);
        assert_eq!(counts.get(&0x401000), Some(&6));
        assert_eq!(counts.get(&0x401004), Some(&7));
        assert_eq!(counts.get(&0x401008), None);
        assert_eq!(counts.get(&0x40100c), Some(&3));
    }
}
