//! The Python bindings' step (also a step of `test`): the venv of
//! [`python_env`], `pip install ./crates/rodyn-py` (maturin's release build
//! of the `rodyn` module, as a user installs it), then pytest against
//! Pinocchio's bindings (`crates/rodyn-py/tests/`).

use crate::{python_env, shell};
use anyhow::Result;
use std::time::Instant;

/// Installs the bindings into the test venv and runs their tests.
pub fn check() -> Result<()> {
    let started = Instant::now();
    let venv = python_env::ensure()?;
    let root = shell::root();
    // The venv's maturin builds the wheel: no second download of the
    // build backend into an isolated environment.
    shell::run(
        venv.command()
            .current_dir(&root)
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
        "xtask python: the bindings built and passed their tests in {:.0} s",
        started.elapsed().as_secs_f64()
    );
    Ok(())
}
