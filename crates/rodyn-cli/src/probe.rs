//! The probe: runs a tool with hostile values of each argument and
//! requires a clean refusal: a non-zero exit, a message that names the
//! argument, no panic, and no hang.
//!
//! A tool's probe test lists its value-taking options in two tables, the
//! numeric ones (tried with every value of [`HOSTILE`]) and the others
//! (paths, names, choices, with probes of their own); [`assert_listed`]
//! reads the tool's help and fails on an option in neither, so a new
//! argument cannot skip the probe.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// How long one run of a tool may take before the probe calls it a hang.
pub const TIMEOUT: Duration = Duration::from_secs(20);

/// The values every numeric argument is tried with: not-a-number, the
/// infinities, a huge number, the smallest subnormal, zero, a negative,
/// and counts beyond any memory (one of them beyond 64 bits).
pub const HOSTILE: [&str; 10] = [
    "NaN",
    "inf",
    "-inf",
    "1e300",
    "5e-324",
    "0",
    "-1",
    "-0.5",
    "1000000000000000000",
    "18446744073709551616",
];

/// What a run of a tool did.
#[derive(Debug)]
pub struct Outcome {
    /// How it ended.
    pub status: ExitStatus,
    /// What it printed.
    pub stdout: String,
    /// What it printed as diagnostics.
    pub stderr: String,
}

/// Runs `exe` with `args`, killing it after [`TIMEOUT`].
///
/// # Panics
/// If the tool cannot be started, or runs past the timeout (a hang is a
/// failure of the probe), naming the arguments.
#[must_use]
pub fn run(exe: &Path, args: &[&str]) -> Outcome {
    run_reading(exe, args, true)
}

/// Runs `exe` with `args` as `exe args | head -0` would: the reader of its
/// standard output is gone before it writes. The tool must finish calmly
/// (see [`emit`](crate::emit)): exit 0 without a panic.
///
/// # Panics
/// If the tool cannot be started, hangs, panics, dies by a signal or
/// exits with an error, naming the arguments and showing its diagnostics.
pub fn assert_calm_when_stdout_closes(exe: &Path, args: &[&str]) {
    let outcome = run_reading(exe, args, false);
    assert_no_panic(&outcome, args);
    assert!(
        outcome.status.success(),
        "{} {args:?} with its standard output closed: {}\n{}",
        exe.display(),
        outcome.status,
        outcome.stderr
    );
}

/// [`run`], reading the tool's standard output or (`read_stdout` false)
/// closing it at once.
fn run_reading(exe: &Path, args: &[&str], read_stdout: bool) -> Outcome {
    let mut child = Command::new(exe)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start {}: {e}", exe.display()));
    // Read both pipes while the tool runs: a tool that prints more than a
    // pipe holds would otherwise block and look like a hang.
    let drain = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut text = Vec::new();
            if let Some(mut pipe) = pipe {
                let _ = pipe.read_to_end(&mut text);
            }
            String::from_utf8_lossy(&text).into_owned()
        })
    };
    let stdout = child.stdout.take();
    let stdout = drain(if read_stdout {
        stdout.map(|p| Box::new(p) as Box<dyn Read + Send>)
    } else {
        // The pipe's only reader, dropped: every write now fails.
        drop(stdout);
        None
    });
    let stderr = drain(
        child
            .stderr
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("the tool's status") {
            break status;
        }
        if started.elapsed() > TIMEOUT {
            let _ = child.kill();
            let _ = child.wait();
            panic!(
                "{} {args:?} still ran after {} s: a hang",
                exe.display(),
                TIMEOUT.as_secs()
            );
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    Outcome {
        status,
        stdout: stdout.join().expect("stdout reader"),
        stderr: stderr.join().expect("stderr reader"),
    }
}

/// Runs `exe` with `args` and requires a refusal whose message contains
/// `naming` (the argument's name, or the file's).
///
/// # Panics
/// On a success, a panic, a hang, or a message without `naming`.
pub fn assert_refused(exe: &Path, args: &[&str], naming: &str) -> Outcome {
    let outcome = run(exe, args);
    assert_no_panic(&outcome, args);
    assert!(
        !outcome.status.success(),
        "{args:?} was accepted (exit 0); stdout:\n{}\nstderr:\n{}",
        outcome.stdout,
        outcome.stderr
    );
    assert!(
        outcome.stderr.contains(naming),
        "{args:?}: the message does not name `{naming}`:\n{}",
        outcome.stderr
    );
    outcome
}

/// Requires that the run did not panic.
///
/// # Panics
/// When it did, with its diagnostics.
pub fn assert_no_panic(outcome: &Outcome, args: &[&str]) {
    assert!(
        !outcome.stderr.contains("panicked at"),
        "{args:?} panicked:\n{}",
        outcome.stderr
    );
    // A signal (abort, out-of-memory kill) leaves no exit code.
    assert!(
        outcome.status.code().is_some(),
        "{args:?} died by a signal:\n{}",
        outcome.stderr
    );
}

/// The path of example `name` of `package`, built first (quick when it is
/// up to date) in the profile of the running test. Cargo gives tests the
/// paths of binaries (`CARGO_BIN_EXE_…`) but not of examples; `cargo
/// test` builds the examples anyway, and `cargo test --test …` does not,
/// hence the build here.
///
/// # Panics
/// When the build fails, with cargo's status.
#[must_use]
pub fn example(package: &str, name: &str) -> PathBuf {
    // target/<profile>/deps/<test binary>
    let exe = std::env::current_exe().expect("the test's own path");
    let profile_dir = exe
        .parent()
        .and_then(Path::parent)
        .expect("the test runs from target/<profile>/deps")
        .to_path_buf();
    // The directory is named after the profile, but for `dev` (and
    // `test`, which builds into `dev`'s directory).
    let profile = match profile_dir.file_name().and_then(|n| n.to_str()) {
        Some("debug") | None => "dev",
        Some(other) => other,
    };
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let status = Command::new(cargo)
        .args(["build", "--quiet", "--profile", profile, "-p", package])
        .args(["--example", name])
        .status()
        .expect("cargo runs");
    assert!(status.success(), "cargo build --example {name}: {status}");
    profile_dir.join("examples").join(name)
}

/// A numeric option and how to reach it.
#[derive(Clone, Copy, Debug)]
pub struct NumericOption<'a> {
    /// The option as the help spells it, such as `--dt`.
    pub option: &'a str,
    /// The arguments of an otherwise valid invocation, before the option.
    pub before: &'a [&'a str],
    /// The arguments after the option's value.
    pub after: &'a [&'a str],
    /// The values of [`HOSTILE`] the option rightly accepts (a joint angle
    /// may be zero or negative): for these the probe requires only no
    /// panic and no hang.
    pub accepts: &'a [&'a str],
}

/// Tries `option` with every value of [`HOSTILE`].
///
/// # Panics
/// On a hostile value accepted that the option does not list, a message
/// that does not name the option, a panic or a hang.
pub fn assert_refuses_hostile_values(exe: &Path, option: &NumericOption<'_>) {
    for value in HOSTILE {
        let mut args: Vec<&str> = option.before.to_vec();
        args.extend([option.option, value]);
        args.extend(option.after);
        if option.accepts.contains(&value) {
            let outcome = run(exe, &args);
            assert_no_panic(&outcome, &args);
        } else {
            assert_refused(exe, &args, option.option);
        }
    }
}

/// The value-taking arguments of a help or usage text: each `--name`
/// (or `-n`) followed by a `<VALUE>` placeholder, the convention of
/// clap's help and of rodyn's hand-written usage lines, then the
/// positional arguments of clap's `Arguments:` section as it writes them
/// (`<SCENARIO>`, `[CALLS]`).
#[must_use]
pub fn value_options(help: &str) -> Vec<String> {
    let tokens: Vec<&str> = help
        .split(|c: char| c.is_whitespace() || c == '[' || c == ']' || c == '=')
        .filter(|t| !t.is_empty())
        .collect();
    let mut options = Vec::new();
    let mut add = |name: String| {
        if !options.contains(&name) {
            options.push(name);
        }
    };
    for pair in tokens.windows(2) {
        let (name, value) = (pair[0].trim_end_matches(','), pair[1]);
        if name.starts_with('-') && name.len() > 1 && value.starts_with('<') {
            add(name.to_owned());
        }
    }
    let mut in_arguments = false;
    for line in help.lines() {
        if !line.starts_with(' ') && !line.is_empty() {
            in_arguments = line.trim_end() == "Arguments:";
            continue;
        }
        let text = line.trim_start();
        let indent = line.len() - text.len();
        if in_arguments && indent == 2 && (text.starts_with('<') || text.starts_with('[')) {
            if let Some(name) = text.split_whitespace().next() {
                add(name.to_owned());
            }
        }
    }
    options
}

/// Requires that every value-taking option of `help` be in `numeric` or
/// `other`, and that everything listed be in `help` (a renamed option
/// must not leave a stale row behind).
///
/// # Panics
/// Naming the unlisted option or the stale row.
pub fn assert_listed(help: &str, numeric: &[&str], other: &[&str]) {
    let found = value_options(help);
    for option in &found {
        assert!(
            numeric.contains(&option.as_str()) || other.contains(&option.as_str()),
            "{option} takes a value but is in neither probe table; add it to the numeric \
             table (and make it refuse the hostile values) or to the others with a probe:\n{help}"
        );
    }
    for listed in numeric.iter().chain(other) {
        assert!(
            found.iter().any(|f| f == listed),
            "{listed} is in a probe table but not in the help:\n{help}"
        );
    }
}

#[cfg(test)]
mod tests {
    use super::value_options;

    #[test]
    fn finds_the_options_that_take_values_in_clap_help_and_usage_lines() {
        let clap_help =
            "Options:\n      --duration <DURATION>  Simulated time (s) [default: 5]\n  \
                         -o, --out <OUT>  Output directory\n  -h, --help  Print help\n";
        assert_eq!(value_options(clap_help), ["--duration", "--out"]);
        let usage =
            "rodyn-model render <file> [--strict] [--q <a,b,...>] [--width <PX>] [-o <out.svg>]\n\
                     options: --round-quarter-turns, --silence <KINDS>";
        assert_eq!(value_options(usage), ["--q", "--width", "-o", "--silence"]);
    }
}
