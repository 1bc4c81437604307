//! Building the firmware, running its examples in QEMU, checking their logs.

use crate::defmt_log::LogDecoder;
use crate::setup::TARGET;
use crate::{expected, shell};
use anyhow::{bail, Context, Result};
use object::{Object, ObjectSymbol};
use std::io::Read;
use std::path::PathBuf;
use std::process::{Command, Stdio};

/// One firmware example (a binary in `firmware/src/bin/`).
#[derive(Debug)]
pub struct Example {
    /// Binary name.
    pub name: &'static str,
    /// What it shows.
    pub about: &'static str,
}

/// What `cargo xtask run` runs without an argument.
pub const FLAGSHIP: &str = "arm_control";

/// Every example, each checked by `cargo xtask test`.
pub const EXAMPLES: &[Example] = &[
    Example {
        name: "arm_control",
        about: "computed-torque control of a 7-DoF arm through embedded-hal drivers",
    },
    Example {
        name: "task_space",
        about: "task-space impedance control of the 7-DoF arm's flange along a pose trajectory",
    },
    Example {
        name: "payload_update",
        about: "the 7-DoF arm identifies an unknown payload while it moves and swaps the updated model in between two ticks",
    },
    Example {
        name: "mpc_pendulum",
        about: "model-predictive control of the pendulum by iLQR on rodyn's analytic derivatives",
    },
    Example {
        name: "pendulum",
        about: "the seed pendulum with its return spring, simulated in real time",
    },
    Example {
        name: "quadruped",
        about: "the Aibo-size quadruped lands, stands and trots, with ground contact, in f32",
    },
    Example {
        name: "quadruped_rigid",
        about: "the quadruped trots with rigid feet while inverse dynamics with contacts holds its trunk, in f32 at 1 kHz",
    },
    Example {
        name: "cost_probe",
        about: "instructions and stack bytes per call, per model and algorithm",
    },
    Example {
        name: "control_cost_probe",
        about: "instructions and stack bytes of the flange's Jacobian, J̇v, an IK step, a task-space tick, the derivatives and an MPC tick",
    },
    Example {
        name: "contact_cost_probe",
        about: "instructions and stack bytes of the quadruped's constrained dynamics, impact, rigid-contact step and trunk-control tick",
    },
    Example {
        name: "update_cost_probe",
        about: "instructions and stack bytes of staging and publishing a payload update, and of the tick's read of the model",
    },
    Example {
        name: "agreement",
        about: "RNEA, ABA, CRBA and CRBA forward dynamics on seeded random states, for the host to recompute in f64",
    },
];

/// Longest a run may take before QEMU is stopped (s).
const QEMU_TIMEOUT_S: u32 = 300;

/// The firmware directory (its `.cargo/config.toml` selects the target).
pub fn dir() -> PathBuf {
    shell::root().join("firmware")
}

/// The example by name.
pub fn example(name: &str) -> Result<&'static Example> {
    EXAMPLES.iter().find(|e| e.name == name).with_context(|| {
        let names: Vec<_> = EXAMPLES.iter().map(|e| e.name).collect();
        format!(
            "no firmware example `{name}`; examples: {}",
            names.join(", ")
        )
    })
}

/// The example's ELF after [`build`].
pub fn elf(example: &Example) -> PathBuf {
    elf_of(example.name)
}

/// The ELF of the firmware binary `name` after [`build`].
pub fn elf_of(name: &str) -> PathBuf {
    shell::target_dir().join(TARGET).join("release").join(name)
}

/// Builds every example in release mode.
pub fn build() -> Result<()> {
    shell::run(cargo_command().args(["build", "--release", "--bins"]))
}

/// Cargo in the firmware directory, with the source paths that reach the
/// images rewritten to fixed names.
///
/// Panic locations (`core::panic::Location`, `file!()`) carry the path of
/// their source file into flash: for the registry's crates and for files
/// generated into the target directory, an absolute path that names cargo's
/// home or the clone's directory. Remapped, the images, their sizes and the
/// cost tables are the same in every clone (rodyn's own crates are named
/// relative to `firmware/`, see its `Cargo.toml`). Only that scope is
/// remapped (`--remap-path-scope=macro`): the debug information keeps the
/// real paths, for debuggers and `cargo xtask profile`.
pub fn cargo_command() -> Command {
    cargo_command_for(TARGET, &[])
}

/// [`cargo_command`] for another `target`, with `extra_rustflags` after the
/// path remaps (the Cortex-M family's builds, `crate::family`).
pub fn cargo_command_for(target: &str, extra_rustflags: &[&str]) -> Command {
    cargo_command_in(&dir(), target, extra_rustflags)
}

/// [`cargo_command_for`] in another firmware workspace `workspace` whose
/// `repo` links to the root (the boards', `crate::boards`).
pub fn cargo_command_in(
    workspace: &std::path::Path,
    target: &str,
    extra_rustflags: &[&str],
) -> Command {
    let flags: Vec<String> = path_remaps(workspace)
        .into_iter()
        .map(|(from, to)| format!("--remap-path-prefix={}={to}", from.display()))
        .chain(["--remap-path-scope=macro".to_string()])
        .chain(extra_rustflags.iter().map(|f| f.to_string()))
        .collect();
    // `--config` joins these to the rustflags of `firmware/.cargo/config.toml`
    // (a `RUSTFLAGS` variable would replace them).
    let list: Vec<String> = flags.iter().map(|f| toml_string(f)).collect();
    let mut command = shell::cargo_command(workspace);
    command
        .arg("--config")
        .arg(format!("target.{target}.rustflags = [{}]", list.join(", ")));
    command
}

/// (directory, fixed name) pairs; rustc applies the last that matches, so
/// a directory inside another comes after it.
fn path_remaps(workspace: &std::path::Path) -> Vec<(PathBuf, &'static str)> {
    let root = shell::root();
    // The firmware reaches rodyn's crates through `firmware/repo`, a link
    // to the root (see firmware/Cargo.toml); the boards' workspace the same.
    let mut remaps = vec![(root.clone(), "rodyn"), (workspace.join("repo"), "rodyn")];
    let target = shell::target_dir();
    if !target.starts_with(&root) {
        // Sources generated into OUT_DIR (the compiled model files).
        remaps.push((target, "target"));
    }
    let cargo_home = std::env::var_os("CARGO_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|home| PathBuf::from(home).join(".cargo")));
    if let Some(cargo_home) = cargo_home {
        remaps.push((cargo_home, "cargo-home"));
    }
    remaps
}

/// `text` as a TOML basic string.
pub fn toml_string(text: &str) -> String {
    format!("\"{}\"", text.replace('\\', "\\\\").replace('"', "\\\""))
}

/// How a run ended.
pub struct Outcome {
    /// QEMU's exit code: the firmware's semihosting exit code.
    pub exit_code: i32,
    /// The decoded log.
    pub lines: Vec<String>,
}

/// Runs `example` in QEMU (mps2-an386, Cortex-M4F) and decodes its log,
/// passing each line to `on_line` as it arrives.
///
/// `-icount shift=6` makes the emulation deterministic: every instruction
/// advances virtual time by 64 ns, so SysTick-based timings and the
/// real-time pacing of the examples do not depend on the host's load.
pub fn run(example: &Example, on_line: impl FnMut(&str)) -> Result<Outcome> {
    run_elf(&elf(example), &[], on_line)
}

/// [`run`] for any firmware ELF, with extra QEMU arguments.
pub fn run_elf(
    elf_path: &std::path::Path,
    qemu_args: &[&str],
    on_line: impl FnMut(&str),
) -> Result<Outcome> {
    run_on_machine(elf_path, ("mps2-an386", "cortex-m4"), qemu_args, on_line)
}

/// [`run_elf`] on another QEMU (machine, CPU), such as the Cortex-M
/// family's (`crate::family`).
pub fn run_on_machine(
    elf_path: &std::path::Path,
    (machine, cpu): (&str, &str),
    qemu_args: &[&str],
    mut on_line: impl FnMut(&str),
) -> Result<Outcome> {
    let elf = std::fs::read(elf_path)
        .with_context(|| format!("cannot read {} (was it built?)", elf_path.display()))?;
    let decoder = LogDecoder::from_elf(&elf)?;
    let mut stream = decoder.stream();
    let mut command = Command::new("timeout");
    command
        .arg(QEMU_TIMEOUT_S.to_string())
        .args(["qemu-system-arm", "-machine", machine, "-cpu", cpu])
        .args(["-nographic", "-monitor", "none", "-serial", "none"])
        .args(["-icount", "shift=6"])
        .args(qemu_args)
        .args(["-semihosting-config", "enable=on,target=native", "-kernel"])
        .arg(elf_path)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit());
    let mut child = command
        .spawn()
        .with_context(|| format!("cannot start {}", shell::describe(&command)))?;
    let mut stdout = child.stdout.take().context("QEMU's stdout")?;
    let mut lines = Vec::new();
    let mut buffer = [0u8; 4096];
    loop {
        let n = stdout.read(&mut buffer).context("reading QEMU's output")?;
        if n == 0 {
            break;
        }
        stream.feed(&buffer[..n], &mut |line| {
            on_line(&line);
            lines.push(line);
        });
    }
    let status = child.wait()?;
    let exit_code = status.code().unwrap_or(-1);
    if exit_code == 124 {
        bail!(
            "{} did not finish within {QEMU_TIMEOUT_S} s",
            elf_path.display()
        );
    }
    Ok(Outcome { exit_code, lines })
}

/// The checked-in expected log of `example`.
pub fn expected_path(example: &Example) -> PathBuf {
    dir().join("expected").join(format!("{}.log", example.name))
}

/// Where the last run's log is kept, for the host tests and for reading.
pub fn last_log_path(example: &Example) -> PathBuf {
    shell::target_dir()
        .join("firmware-logs")
        .join(format!("{}.log", example.name))
}

/// Runs `example`, requires exit code 0 and a log that matches the expected one.
pub fn run_and_compare(example: &Example) -> Result<()> {
    let outcome = run(example, |_| {})?;
    let log_path = last_log_path(example);
    std::fs::create_dir_all(log_path.parent().expect("a log directory"))?;
    std::fs::write(&log_path, outcome.lines.join("\n") + "\n")?;
    if outcome.exit_code != 0 {
        for line in &outcome.lines {
            println!("  | {line}");
        }
        bail!("exit code {}", outcome.exit_code);
    }
    let expected_path = expected_path(example);
    let expected = std::fs::read_to_string(&expected_path)
        .with_context(|| format!("cannot read {}", expected_path.display()))?;
    expected::compare(&expected, &outcome.lines).map_err(|difference| {
        anyhow::anyhow!(
            "log differs from {}: {difference}\n  (full log: {}; `cargo xtask bless` accepts it)",
            expected_path.display(),
            log_path.display()
        )
    })
}

/// Rewrites the expected log of `example` from a fresh run.
pub fn bless(example: &Example) -> Result<()> {
    let outcome = run(example, |_| {})?;
    if outcome.exit_code != 0 {
        bail!(
            "{} exited with code {}: not blessed",
            example.name,
            outcome.exit_code
        );
    }
    let path = expected_path(example);
    let old = std::fs::read_to_string(&path).unwrap_or_default();
    std::fs::create_dir_all(dir().join("expected"))?;
    std::fs::write(&path, expected::bless(&old, &outcome.lines))?;
    println!("blessed {}", path.display());
    Ok(())
}

/// Fails when the image links a heap allocator: rodyn and its examples must
/// run without one.
pub fn check_no_allocator(example: &Example) -> Result<()> {
    let data = std::fs::read(elf(example))?;
    let file = object::File::parse(&*data)?;
    let allocator = file.symbols().find_map(|s| {
        let name = s.name().ok()?;
        (name.contains("__rust_alloc") || name.contains("__rg_alloc") || name == "malloc")
            .then(|| name.to_string())
    });
    if let Some(symbol) = allocator {
        bail!("{} links an allocator (symbol {symbol})", example.name);
    }
    Ok(())
}

/// The firmware that panics inside its panic handler's logging
/// (`firmware/src/bin/panic_reentry.rs`; not an example).
const PANIC_REENTRY: &str = "panic_reentry";

/// Runs the panic-reentry firmware and requires the panic exit code: the
/// handler, entered again by its own log line, must end the run instead of
/// recursing into a fault (which QEMU's timeout would report as a hang).
pub fn check_panic_reentry() -> Result<()> {
    const PANICKED: i32 = 101;
    let outcome = run_elf(&elf_of(PANIC_REENTRY), &[], |_| {})?;
    if outcome.exit_code != PANICKED {
        for line in &outcome.lines {
            println!("  | {line}");
        }
        bail!(
            "{PANIC_REENTRY} exited with code {} (expected {PANICKED}: a panic inside the panic handler's log line must end the run)",
            outcome.exit_code
        );
    }
    println!("firmware {PANIC_REENTRY}: a second panic in the handler exits with {PANICKED}");
    Ok(())
}

/// Runs the host's f64 recomputation against the log of this run of the
/// `agreement` example (plain `cargo test` checks the checked-in log).
pub fn agreement_against_fresh_run() -> Result<()> {
    let log = last_log_path(example("agreement")?);
    let log = log.to_string_lossy();
    shell::cargo_env(
        &[
            "test",
            "-p",
            "rodyn-host-tests",
            "--test",
            "firmware_agreement",
        ],
        &[("RODYN_AGREEMENT_LOG", log.as_ref())],
    )
}
