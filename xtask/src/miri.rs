//! The core's unit tests under Miri, which stops at undefined behaviour.
//!
//! The core tells the optimiser what its topology guarantees through
//! `core::hint::assert_unchecked` (`Topology::velocity_range`,
//! `Model::configuration_range`, ...): a promise that does not hold is
//! undefined behaviour, not a panic. Miri checks every such promise each
//! time a test reaches it, and every index and pointer besides.
//!
//! Miri interprets each operation, so the tests' long sweeps take fewer
//! points under `cfg(miri)`; tests that need what Miri's isolation
//! withholds (files, processes, threads' timing) are ignored there.
//!
//! Miri runs only on a nightly toolchain. Its component is added when the
//! nightly toolchain lacks it; a machine without a nightly toolchain skips
//! the step and says so (the pinned stable toolchain cannot run Miri, and
//! nothing here downloads a whole toolchain).

use anyhow::{bail, Context, Result};
use std::process::Command;

use crate::background::Background;
use crate::shell;

/// Miri's options: sine, cosine and the other float functions give the
/// host's results, without the error Miri otherwise adds to show that they
/// are not exact (the core's tests compare against them within an ulp).
const MIRIFLAGS: &str = "-Zmiri-deterministic-floats";

/// Runs the core's unit tests under Miri, in a target folder of their own
/// (`target/miri`) so the normal build is left as it is.
pub fn run() -> Result<()> {
    if !ready()? {
        return Ok(());
    }
    shell::run(&mut command()).context("the core's tests under Miri")
}

/// Starts [`run`]'s command in the background (`target/miri.log`): it
/// interprets on one core for minutes. `None` (and a message) without a
/// nightly toolchain.
pub fn start_in_background() -> Result<Option<Background>> {
    if !ready()? {
        return Ok(None);
    }
    Background::start("miri", command(), "miri.log").map(Some)
}

/// Whether Miri can run here (adding its components to an installed
/// nightly toolchain); says so when it cannot.
fn ready() -> Result<bool> {
    if !nightly_installed() {
        println!(
            "miri: skipped, no nightly toolchain (Miri needs one: \
             `rustup toolchain install nightly`, then run this command again)"
        );
        return Ok(false);
    }
    ensure_components()?;
    Ok(true)
}

fn command() -> Command {
    let mut command = Command::new("rustup");
    command
        .current_dir(shell::root())
        .args([
            "run", "nightly", "cargo", "miri", "test", "-p", "rodyn", "--lib",
        ])
        .env("MIRIFLAGS", MIRIFLAGS)
        .env("CARGO_TARGET_DIR", shell::target_dir().join("miri"));
    command
}

/// Whether rustup has a nightly toolchain (nothing is downloaded).
fn nightly_installed() -> bool {
    Command::new("rustup")
        .args(["run", "nightly", "rustc", "--version"])
        .output()
        .is_ok_and(|out| out.status.success())
}

/// Adds Miri and the standard library's source (which Miri builds its own
/// standard library from) to the nightly toolchain unless it has them.
fn ensure_components() -> Result<()> {
    let installed = crate::setup::output(Command::new("rustup").args([
        "component",
        "list",
        "--installed",
        "--toolchain",
        "nightly",
    ]))?;
    let has = |name: &str| {
        installed
            .lines()
            .any(|l| l.trim() == name || l.trim().starts_with(&format!("{name}-")))
    };
    if has("miri") && has("rust-src") {
        return Ok(());
    }
    println!(
        "set-up: adding the rustup components miri and rust-src to the nightly toolchain \
         (Miri checks the core's tests for undefined behaviour)"
    );
    let status = Command::new("rustup")
        .args([
            "component",
            "add",
            "--toolchain",
            "nightly",
            "miri",
            "rust-src",
        ])
        .status()
        .context("cannot start rustup")?;
    if !status.success() {
        bail!(
            "rustup could not add miri and rust-src to the nightly toolchain; add them with \
             `rustup component add --toolchain nightly miri rust-src`, then run this command again"
        );
    }
    Ok(())
}
