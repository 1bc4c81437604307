//! The Python bindings' step (also a step of `test`): the venv of
//! [`python_env`], `pip install ./crates/rodyn-py` (maturin's build of the
//! `rodyn` module through pip, as a user installs it), then pytest against
//! Pinocchio's bindings (`crates/rodyn-py/tests/`).
//!
//! The module is built in cargo's dev profile: the same code as a user's
//! release wheel, compiled minutes faster (the run-time model's size
//! classes are most of the optimiser's work), and the tests check results,
//! not speed. `RODYN_PY_PROFILE=release` builds what a user gets.

use crate::{python_env, shell};
use anyhow::Result;
use std::time::Instant;

/// Installs the bindings into the test venv and runs their tests.
pub fn check() -> Result<()> {
    let started = Instant::now();
    let venv = python_env::ensure()?;
    let root = shell::root();
    let profile = std::env::var("RODYN_PY_PROFILE").unwrap_or_else(|_| "dev".into());
    // The venv's maturin builds the wheel: no second download of the
    // build backend into an isolated environment. maturin's PEP 517
    // backend passes MATURIN_PEP517_ARGS on to its build.
    shell::run(
        venv.command()
            .current_dir(&root)
            .env("MATURIN_PEP517_ARGS", format!("--profile {profile}"))
            .args([
                "-m",
                "pip",
                "install",
                "--quiet",
                "--disable-pip-version-check",
            ])
            .args(["--no-build-isolation", "--force-reinstall", "--no-deps"])
            .arg("./crates/rodyn-py"),
    )?;
    shell::run(venv.command().current_dir(&root).args([
        "-m",
        "pytest",
        "-q",
        "-p",
        "no:cacheprovider",
        "crates/rodyn-py/tests",
    ]))?;
    println!(
        "xtask python: the bindings ({profile} profile) built and passed their tests in {:.0} s",
        started.elapsed().as_secs_f64()
    );
    Ok(())
}
