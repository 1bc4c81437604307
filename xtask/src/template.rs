//! The firmware template (`templates/firmware/`), built and run as a user
//! would: from a copy outside the repository, with `cargo run --release`.
//!
//! The template depends on `rodyn` and `rodyn-model` by version, as a
//! user's `Cargo.toml` does. The copy gets a `[patch.crates-io]` section
//! that points both at this repository, so what is tested is the code
//! here, through the manifest a user keeps. Its `Cargo.lock` starts from
//! the firmware's, so the template is tested with the dependency versions
//! the repository's firmware is tested with (cargo resolves what that lock
//! lacks). The runner prints raw defmt frames (`DEFMT_PRINT=""`), which
//! this decodes; the firmware's exit code must be 0 and its log must say
//! that RNEA, ABA and the 1 kHz loop passed their checks.

use crate::defmt_log::LogDecoder;
use crate::setup::TARGET;
use crate::{firmware, shell};
use anyhow::{bail, Context, Result};
use std::path::{Path, PathBuf};
use std::process::Stdio;

/// The template's binary (its package name).
const BINARY: &str = "my-firmware";

/// The lines the template's log must hold: each check's verdict.
const EXPECTED: [&str; 3] = ["rnea ok", "aba ok", "loop ok"];

/// The template in the repository.
fn source() -> PathBuf {
    shell::root().join("templates").join("firmware")
}

/// Where the copy builds: a directory of its own in the workspace's
/// target directory, kept between runs so a second run is incremental.
fn target_dir() -> PathBuf {
    shell::target_dir().join("template-firmware")
}

/// Copies the template outside the repository, checks its formatting and
/// lints, runs it in QEMU and checks its exit code and log.
pub fn check() -> Result<()> {
    let copy = std::env::temp_dir().join(format!("rodyn-firmware-template-{}", std::process::id()));
    if copy.starts_with(shell::root()) {
        bail!(
            "the temporary directory {} is inside the repository; the template must be tried outside it",
            copy.display()
        );
    }
    let result = copy_and_run(&copy);
    // Kept when it failed, to look at.
    if result.is_ok() {
        std::fs::remove_dir_all(&copy).with_context(|| format!("removing {}", copy.display()))?;
    }
    result.with_context(|| format!("the firmware template, copied to {}", copy.display()))
}

fn copy_and_run(copy: &Path) -> Result<()> {
    if copy.exists() {
        std::fs::remove_dir_all(copy)?;
    }
    copy_tree(&source(), copy)?;
    patch_to_this_repository(&copy.join("Cargo.toml"))?;
    std::fs::copy(firmware::dir().join("Cargo.lock"), copy.join("Cargo.lock"))
        .context("seeding the copy's Cargo.lock from the firmware's")?;

    let target = target_dir();
    shell::run(
        shell::cargo_command(copy)
            .args(["fmt", "--check"])
            .env("CARGO_TARGET_DIR", &target),
    )?;
    shell::run(
        shell::cargo_command(copy)
            .args(["clippy", "--release", "--", "-D", "warnings"])
            .env("CARGO_TARGET_DIR", &target),
    )?;

    let mut run = shell::cargo_command(copy);
    run.args(["run", "--release"])
        .env("CARGO_TARGET_DIR", &target)
        .env("DEFMT_PRINT", "")
        .stdin(Stdio::null())
        .stderr(Stdio::inherit());
    println!("$ {}", shell::describe(&run));
    let output = run
        .output()
        .with_context(|| format!("cannot start {}", shell::describe(&run)))?;

    let elf_path = target.join(TARGET).join("release").join(BINARY);
    let elf = std::fs::read(&elf_path)
        .with_context(|| format!("cannot read {} (did the build fail?)", elf_path.display()))?;
    let decoder = LogDecoder::from_elf(&elf)?;
    let mut lines = Vec::new();
    decoder
        .stream()
        .feed(&output.stdout, &mut |line| lines.push(line));
    for line in &lines {
        println!("  | {line}");
    }
    if !output.status.success() {
        bail!("`cargo run --release` failed with {}", output.status);
    }
    let missing: Vec<&str> = EXPECTED
        .into_iter()
        .filter(|expected| !lines.iter().any(|line| line.starts_with(expected)))
        .collect();
    if !missing.is_empty() {
        bail!("the log has no line starting with {}", missing.join(", "));
    }
    println!("firmware template: builds and runs outside the repository");
    Ok(())
}

/// Copies the directory `from` to `to`, without build output (`target/`)
/// or a lock file a local build left.
fn copy_tree(from: &Path, to: &Path) -> Result<()> {
    std::fs::create_dir_all(to)?;
    for entry in std::fs::read_dir(from).with_context(|| format!("reading {}", from.display()))? {
        let entry = entry?;
        let name = entry.file_name();
        if name == "target" || name == "Cargo.lock" {
            continue;
        }
        let (source, destination) = (entry.path(), to.join(&name));
        if entry.file_type()?.is_dir() {
            copy_tree(&source, &destination)?;
        } else {
            // Keeps the permissions: the runner script stays executable.
            std::fs::copy(&source, &destination)
                .with_context(|| format!("copying {}", source.display()))?;
        }
    }
    Ok(())
}

/// Appends the `[patch.crates-io]` section that resolves `rodyn` and
/// `rodyn-model` to this repository's crates.
fn patch_to_this_repository(manifest: &Path) -> Result<()> {
    let crates = shell::root().join("crates");
    let mut text = std::fs::read_to_string(manifest)?;
    text.push_str(
        "\n# Added by `cargo xtask test`: this repository's crates.\n[patch.crates-io]\n",
    );
    for name in ["rodyn", "rodyn-model"] {
        let path = crates.join(name);
        let path = path.to_str().with_context(|| {
            format!("{} is not UTF-8: a manifest cannot name it", path.display())
        })?;
        text.push_str(&format!(
            "{name} = {{ path = {} }}\n",
            firmware::toml_string(path)
        ));
    }
    std::fs::write(manifest, text)?;
    Ok(())
}
