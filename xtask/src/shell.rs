//! Running commands, echoing them first so a log shows what ran.

use anyhow::{bail, Context, Result};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The repository root (the parent of this crate).
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("xtask lives one level below the root")
        .to_path_buf()
}

/// Cargo's target directory: `CARGO_TARGET_DIR` when set, else `target/`.
pub fn target_dir() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| root().join("target"), PathBuf::from)
}

/// Runs `command`, inheriting stdout and stderr; fails on a non-zero status.
pub fn run(command: &mut Command) -> Result<()> {
    println!("$ {}", describe(command));
    let status = command
        .status()
        .with_context(|| format!("cannot start {}", describe(command)))?;
    if !status.success() {
        bail!("`{}` failed with {status}", describe(command));
    }
    Ok(())
}

/// Runs cargo with `args` at the repository root.
pub fn cargo(args: &[&str]) -> Result<()> {
    cargo_env(args, &[])
}

/// Runs cargo with `args` and extra environment variables at the root.
pub fn cargo_env(args: &[&str], env: &[(&str, &str)]) -> Result<()> {
    let mut command = cargo_command(&root());
    command.args(args).envs(env.iter().copied());
    run(&mut command)
}

/// Runs cargo with `args` in `dir`, where that directory's
/// `.cargo/config.toml` applies.
pub fn cargo_in(dir: PathBuf, args: &[&str]) -> Result<()> {
    let mut command = cargo_command(&dir);
    command.args(args);
    run(&mut command)
}

/// A cargo command in `dir`, using the cargo that runs this xtask.
pub fn cargo_command(dir: &Path) -> Command {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(cargo);
    command.current_dir(dir);
    command
}

/// Makes a `cargo build` lint the workspace's own crates as `cargo clippy
/// -- -D warnings` would, while it compiles them: clippy's driver stands in
/// for rustc on the members (cargo's `RUSTC_WORKSPACE_WRAPPER`, as `cargo
/// clippy` sets it), so one build gives the image and the lints instead of
/// a second, check-only compile of every dependency.
pub fn lint_while_building(command: &mut Command) -> Result<()> {
    let cargo = PathBuf::from(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    let driver = cargo
        .parent()
        .map(|bin| bin.join("clippy-driver"))
        .filter(|driver| driver.is_file())
        .context("clippy-driver is not beside cargo: `rustup component add clippy` installs it")?;
    // How cargo-clippy hands its arguments to the driver.
    command.env("RUSTC_WORKSPACE_WRAPPER", driver).env(
        "CLIPPY_ARGS",
        "-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__",
    );
    Ok(())
}

/// `[VAR=value ...] program arg arg ...` for messages (the variables set
/// for this command, such as the tuning profile's).
pub fn describe(command: &Command) -> String {
    let mut text = String::new();
    for (name, value) in command.get_envs() {
        if let Some(value) = value {
            text.push_str(&format!(
                "{}={} ",
                name.to_string_lossy(),
                value.to_string_lossy()
            ));
        }
    }
    text.push_str(&command.get_program().to_string_lossy());
    for arg in command.get_args() {
        text.push(' ');
        text.push_str(&arg.to_string_lossy());
    }
    text
}
