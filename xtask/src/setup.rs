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
    println!("set-up: adding the Rust target {TARGET} (rustup), which the firmware is built for");
    shell::run(Command::new("rustup").args(["target", "add", TARGET]))
}

/// The targets of the Cortex-M family's cost tables beyond [`TARGET`]
/// (`crate::family`): the Cortex-M3 and the Cortex-M33.
pub const FAMILY_TARGETS: [&str; 2] = ["thumbv7m-none-eabi", "thumbv8m.main-none-eabihf"];

/// Adds [`FAMILY_TARGETS`] through rustup unless they are installed.
pub fn ensure_family_targets() -> Result<()> {
    ensure_target()?;
    let installed = output(Command::new("rustup").args(["target", "list", "--installed"]))
        .context("rustup is needed to add the Cortex-M family's targets")?;
    let missing: Vec<&str> = FAMILY_TARGETS
        .into_iter()
        .filter(|t| !installed.lines().any(|l| l.trim() == *t))
        .collect();
    if missing.is_empty() {
        return Ok(());
    }
    println!(
        "set-up: adding the Rust targets {} (rustup), which the Cortex-M family's cost probes are built for",
        missing.join(", ")
    );
    shell::run(
        Command::new("rustup")
            .args(["target", "add"])
            .args(&missing),
    )
}

/// The QEMU machine every firmware example runs on.
const QEMU_MACHINE: &str = "mps2-an386";

/// Makes sure `qemu-system-arm` runs and knows [`QEMU_MACHINE`]; installs
/// it through apt-get when running as root, never removing a package, and
/// otherwise stops with the command to run.
///
/// Debian's `qemu-system-arm` must match the version of an installed
/// `qemu-utils` (their common package says so). A machine whose
/// `qemu-utils` came from the backports suite therefore cannot take the
/// release's QEMU without losing it: then the same version comes from
/// backports, through a package list kept in the target directory, so the
/// machine's own apt sources stay as they are.
pub fn ensure_qemu() -> Result<()> {
    if qemu_has_machine() {
        return Ok(());
    }
    let what = "QEMU (qemu-system-arm, which runs the firmware examples)";
    require_root(what, &["qemu-system-arm"])?;
    println!("set-up: installing {what} through apt-get (nothing is removed)");
    apt_update(None)?;
    if apt_install(None, &["qemu-system-arm"]).is_ok() && qemu_has_machine() {
        return Ok(());
    }
    let utils = installed_version("qemu-utils");
    match (&utils, backports_suite()) {
        (Some(version), Some(suite)) if version.contains("~bpo") => {
            println!(
                "set-up: the installed qemu-utils {version} is from {suite}; \
                 installing qemu-system-arm of the same version from there"
            );
            let lists = backports_lists(&suite)?;
            apt_update(Some(&lists))?;
            apt_install(
                Some(&lists),
                &["-t", &suite, &format!("qemu-system-arm={version}")],
            )?;
        }
        _ => bail!(
            "apt-get cannot install qemu-system-arm without removing another package \
             (installed qemu-utils: {}). Nothing was removed. Install a qemu-system-arm \
             that matches your QEMU packages yourself, or put one with the machine \
             {QEMU_MACHINE} on PATH, then run this command again.",
            utils.as_deref().unwrap_or("none")
        ),
    }
    if !qemu_has_machine() {
        bail!("qemu-system-arm was installed but does not offer the machine {QEMU_MACHINE}");
    }
    Ok(())
}

/// Whether `qemu-system-arm` runs and lists [`QEMU_MACHINE`].
fn qemu_has_machine() -> bool {
    Command::new("qemu-system-arm")
        .args(["-machine", "help"])
        .output()
        .is_ok_and(|o| {
            o.status.success()
                && String::from_utf8_lossy(&o.stdout)
                    .lines()
                    .any(|l| l.split_whitespace().next() == Some(QEMU_MACHINE))
        })
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
        "IPOPT (coinor-libipopt-dev, for the optional crate rodyn-optimal-control)",
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

/// Installs `packages` through apt-get when running as root, never
/// removing a package; otherwise stops with the command that would,
/// naming `what` is missing.
fn install_debian_packages(what: &str, packages: &[&str]) -> Result<()> {
    require_root(what, packages)?;
    println!("set-up: installing {what} through apt-get (nothing is removed)");
    apt_update(None)?;
    apt_install(None, packages).with_context(|| {
        format!(
            "apt-get could not install {} without removing a package; nothing was \
             removed. Install it yourself, then run this command again",
            packages.join(" ")
        )
    })
}

/// Stops with the command to run unless this process is root.
fn require_root(what: &str, packages: &[&str]) -> Result<()> {
    let is_root = output(Command::new("id").arg("-u")).is_ok_and(|uid| uid.trim() == "0");
    if !is_root {
        bail!(
            "{what} is missing; install it with:\n    \
             sudo apt-get update && sudo apt-get install --no-remove -y {}",
            packages.join(" ")
        );
    }
    Ok(())
}

/// Package lists of the machine's own sources plus a backports suite:
/// apt options that point apt-get at them (see [`ensure_qemu`]).
struct AptLists {
    options: Vec<String>,
}

/// `apt-get update`, with the extra package lists when given.
fn apt_update(lists: Option<&AptLists>) -> Result<()> {
    let mut command = apt_get(lists);
    command.arg("update");
    shell::run(&mut command)
}

/// `apt-get install --no-remove`: fails rather than remove a package.
fn apt_install(lists: Option<&AptLists>, args: &[&str]) -> Result<()> {
    let mut command = apt_get(lists);
    command
        .args(["install", "-y", "--no-install-recommends", "--no-remove"])
        .args(args);
    shell::run(&mut command)
}

fn apt_get(lists: Option<&AptLists>) -> Command {
    let mut command = Command::new("apt-get");
    if let Some(lists) = lists {
        command.args(&lists.options);
    }
    command.env("DEBIAN_FRONTEND", "noninteractive");
    command
}

/// The installed version of a Debian package, if it is installed.
fn installed_version(package: &str) -> Option<String> {
    let out = Command::new("dpkg-query")
        .args(["-W", "-f=${Status} ${Version}", package])
        .output()
        .ok()?;
    let text = String::from_utf8_lossy(&out.stdout);
    let version = text.strip_prefix("install ok installed ")?;
    Some(version.trim().to_owned())
}

/// `<codename>-backports` of a Debian machine (from `/etc/os-release`).
fn backports_suite() -> Option<String> {
    let release = std::fs::read_to_string("/etc/os-release").ok()?;
    let codename = release
        .lines()
        .find_map(|l| l.strip_prefix("VERSION_CODENAME="))?
        .trim_matches('"');
    (!codename.is_empty()).then(|| format!("{codename}-backports"))
}

/// Writes a source folder holding the machine's own sources and Debian's
/// `suite`, with package lists of their own, under the target directory.
fn backports_lists(suite: &str) -> Result<AptLists> {
    let dir = shell::target_dir().join("apt");
    let parts = dir.join("sources.list.d");
    let lists = dir.join("lists");
    std::fs::create_dir_all(lists.join("partial"))?;
    std::fs::create_dir_all(&parts)?;
    for entry in std::fs::read_dir("/etc/apt/sources.list.d")? {
        let path = entry?.path();
        let ends_right = path
            .extension()
            .is_some_and(|e| e == "list" || e == "sources");
        if ends_right {
            std::fs::copy(&path, parts.join(path.file_name().unwrap_or_default()))?;
        }
    }
    std::fs::write(
        parts.join("rodyn-backports.sources"),
        format!(
            "Types: deb\nURIs: http://deb.debian.org/debian\nSuites: {suite}\n\
             Components: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n"
        ),
    )?;
    Ok(AptLists {
        options: vec![
            "-o".into(),
            format!("Dir::Etc::sourceparts={}", parts.display()),
            "-o".into(),
            format!("Dir::State::Lists={}", lists.display()),
        ],
    })
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
        println!("set-up: adding the rustup component llvm-tools ({name} measures the firmware)");
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
