//! Installing what the commands need, when it is missing.

use crate::shell;
use anyhow::{bail, Context, Result};
use std::path::PathBuf;
use std::process::Command;

/// The firmware's target.
pub const TARGET: &str = "thumbv7em-none-eabihf";

/// Adds the thumbv7em target through rustup unless it is installed. The
/// toolchain file lists it, but rustup does not install targets on its own
/// when `RUSTUP_AUTO_INSTALL=0`.
pub fn ensure_target() -> Result<()> {
    let installed = output(Command::new("rustup").args(["target", "list", "--installed"]))
        .context("rustup is needed to add the firmware target")?;
    if installed.lines().any(|l| l.trim() == TARGET) {
        return Ok(());
    }
    shell::run(Command::new("rustup").args(["target", "add", TARGET]))
}

/// Installs `qemu-system-arm` through apt-get when running as root;
/// otherwise stops with the command to run.
pub fn ensure_qemu() -> Result<()> {
    ensure_debian_tool("qemu-system-arm", "qemu-system-arm")
}

/// Installs IPOPT's development files (`coinor-libipopt-dev`, found by
/// pkg-config), which `rodyn-optimal-control` links, the same way.
pub fn ensure_ipopt() -> Result<()> {
    let found = Command::new("pkg-config")
        .args(["--exists", "ipopt"])
        .status()
        .is_ok_and(|s| s.success());
    if found {
        return Ok(());
    }
    install_debian_packages(
        "IPOPT (for rodyn-optimal-control)",
        &["pkg-config", "coinor-libipopt-dev"],
    )
}

/// Installs valgrind (callgrind counts the host's instructions) the same way.
pub fn ensure_valgrind() -> Result<()> {
    ensure_debian_tool("valgrind", "valgrind")
}

/// objdump (binutils), which reads the mnemonics of the profiled code.
pub fn ensure_objdump() -> Result<()> {
    ensure_debian_tool("objdump", "binutils")
}

/// Runs `program --version`; when that fails, installs `package` through
/// apt-get as root, or stops with the command to run.
fn ensure_debian_tool(program: &str, package: &str) -> Result<()> {
    if Command::new(program)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
    {
        return Ok(());
    }
    install_debian_packages(program, &[package])
}

/// Installs `packages` through apt-get when running as root; otherwise
/// stops with the command that would, naming `what` is missing.
fn install_debian_packages(what: &str, packages: &[&str]) -> Result<()> {
    let is_root = output(Command::new("id").arg("-u")).is_ok_and(|uid| uid.trim() == "0");
    if !is_root {
        bail!(
            "{what} is missing; install it with:\n    \
             sudo apt-get update && sudo apt-get install -y {}",
            packages.join(" ")
        );
    }
    shell::run(
        Command::new("apt-get")
            .arg("update")
            .env("DEBIAN_FRONTEND", "noninteractive"),
    )?;
    shell::run(
        Command::new("apt-get")
            .args(["install", "-y", "--no-install-recommends"])
            .args(packages)
            .env("DEBIAN_FRONTEND", "noninteractive"),
    )
}

/// `llvm-size` from the toolchain's llvm-tools component, added when missing.
pub fn llvm_size() -> Result<PathBuf> {
    llvm_tool("llvm-size")
}

/// A tool of the toolchain's llvm-tools component, added when missing.
pub fn llvm_tool(name: &str) -> Result<PathBuf> {
    let sysroot = output(Command::new("rustc").args(["--print", "sysroot"]))?;
    let host = output(Command::new("rustc").args(["--print", "host-tuple"]))?;
    let path = PathBuf::from(sysroot.trim())
        .join("lib/rustlib")
        .join(host.trim())
        .join("bin")
        .join(name);
    if !path.exists() {
        shell::run(Command::new("rustup").args(["component", "add", "llvm-tools"]))?;
    }
    Ok(path)
}

/// A command's stdout, failing on a non-zero status.
pub fn output(command: &mut Command) -> Result<String> {
    let out = command
        .output()
        .with_context(|| format!("cannot start {}", shell::describe(command)))?;
    if !out.status.success() {
        bail!(
            "`{}` failed: {}",
            shell::describe(command),
            String::from_utf8_lossy(&out.stderr)
        );
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}
