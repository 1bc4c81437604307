//! rodyn's project commands, run as `cargo xtask <command>` from anywhere in
//! the repository (the alias lives in `.cargo/config.toml`).
//!
//! | command                  | does                                                              |
//! |--------------------------|-------------------------------------------------------------------|
//! | `run [example]`          | builds the firmware, runs `example` (default: the arm controller) in QEMU, prints the decoded defmt log |
//! | `test`                   | host tests (the core's and `rodyn-host-tests`' also in the in-order tuning profile), the no_std core for thumbv7em, every firmware example in QEMU against its expected output, sizes, panic sites, stack bounds, the board images (sizes, fit, panic sites), the viewer's pages in Chromium, the Python bindings against Pinocchio's, the firmware template run from a copy outside the repository, lint |
//! | `lint`                   | the core's layers (`layers`); rustfmt, clippy and rustdoc, warnings as errors, host, firmware and boards; the core without float features stops at one error; `cargo package` of every crate, the published libraries built from their packages; their public API against `xtask/public-api/`; the core's unit tests under Miri (nightly), which stops at undefined behaviour |
//! | `host-lints`              | clippy (host, in-order profile) and rustdoc, warnings as errors: the part of `lint` that `test` runs in the background, in `target/lint` |
//! | `viewer`                 | the viewer's pages in headless Chromium (also a step of `test`): every model's page draws without an error, the Panda against its reference image, the trot moves when scrubbed |
//! | `docs [--check]`         | regenerates every figure and table of the docs that a command draws the same on every run (`--check`: fails naming each committed file that differs) |
//! | `costs`                  | runs the cost probe, measures sizes and bounds the stack, rewrites the tables in `docs/sections/firmware.md` and `firmware/expected/sizes.txt`; builds and runs the probes on QEMU's Cortex-M3, M7 (f32 and f64) and M33 for `docs/sections/cortex_m_family.md` |
//! | `boards [--bless]`       | builds the board images of `boards/` (nRF52840-DK, Nucleo-H743ZI, Pico 2) and checks their sizes against `boards/expected/sizes.txt`, their fit and their panic sites (a step of `test`; `--bless` records the sizes) |
//! | `family`                 | builds the cost probes for QEMU's Cortex-M3, M7 (f32 and f64) and M33 and runs them (the step of `test`; `costs` writes their tables) |
//! | `stack [image] [words]`  | worst-case stack per image and per cost-table row from a static call graph, checked against the painted figures (`--check-frames`: the frame reading against LLVM's `-Z emit-stack-sizes`) |
//! | `panic-sites [image]`    | the panic call sites of one image (default: all) by source, function and line |
//! | `layers`                 | the core's files import no file that imports them back, and each module only from its layer and those below (`xtask/src/layers.rs`) |
//! | `public-api [--bless]`   | the public items of `rodyn` and `rodyn-model` (rustdoc JSON, nightly) against `xtask/public-api/*.txt`: a removed item fails; `--bless` rewrites the lists |
//! | `python`                 | the Python bindings (also a step of `test`): `pip install ./crates/rodyn-py` into the venv of `python-env`, then their pytest suite against Pinocchio's bindings |
//! | `python-env`             | makes or updates the test command's Python venv (Pinocchio 4.1, example-robot-data, numpy, pytest, matplotlib, maturin) under `target/python-venv` and prints its paths |
//! | `bless`                  | rewrites `firmware/expected/*.log` from fresh runs, keeping `*` wildcards |
//! | `profile [words]`        | one call of each algorithm on each model in QEMU with an instruction trace; prints where its instructions go, line by line (calls whose label contains every word) |
//! | `host-profile <algorithm> <model> [--pinocchio]` | the same on the host: callgrind's count per instruction of one call of the `profile` binary (or of Pinocchio's timing program), charged line by line, and its floating-point operations |
//!
//! Each command installs what it needs when it is missing: the
//! `thumbv7em-none-eabihf` target through rustup, QEMU and (for `test` and
//! `lint`, which build `rodyn-optimal-control`) IPOPT's development files
//! through apt-get when running as root (otherwise it stops with the
//! command to run). `lint` adds Miri to an installed nightly toolchain
//! through rustup; without a nightly toolchain it skips Miri and says so.

mod background;
mod boards;
mod costs;
mod defmt_log;
mod docs;
mod expected;
mod family;
mod firmware;
mod fp_ops;
mod host_profile;
mod layers;
mod miri;
mod panic_sites;
mod profile;
mod public_api;
mod python;
mod python_env;
mod replay;
mod setup;
mod shell;
mod stack_bound;
mod template;
mod viewer;

use anyhow::{bail, Context, Result};
use std::process::{Command, ExitCode};
use std::time::Instant;

const USAGE: &str =
    "usage: cargo xtask <run [example] [--html page.html] | test | lint | host-lints | layers | docs [--check] | costs | family | boards [--bless] | stack [image [words]] | stack --frames <image> | stack --check-frames | panic-sites [image] | viewer | python | python-env | public-api [--bless] | bless | profile [model] [algorithm] | host-profile <algorithm> <model> [--pinocchio]>";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = match args.first().map(String::as_str) {
        Some("run") => run(&args[1..]),
        Some("test") => test(),
        Some("lint") => lint(),
        Some("host-lints") => host_lints(),
        Some("docs") => docs::run(&args[1..]),
        Some("costs") => costs::regenerate(),
        Some("family") => family::run_probes(),
        Some("boards") => boards::run(&args[1..]),
        Some("viewer") => viewer::check(),
        Some("bless") => bless(),
        Some("python") => python::check(),
        Some("python-env") => python_env::ensure().and_then(|venv| {
            println!("python: {}", venv.python().display());
            println!("example-robot-data robots: {}", venv.robots()?.display());
            Ok(())
        }),
        Some("layers") => layers::run(),
        Some("public-api") => public_api::run(args.get(1).map(String::as_str) == Some("--bless")),
        Some("stack") => stack_bound::run(&args[1..]),
        Some("panic-sites") => panic_sites::run(&args[1..]),
        Some("profile") => profile::run(&args[1..]),
        Some("host-profile") => host_profile::run(&args[1..]),
        _ => {
            eprintln!("{USAGE}");
            return ExitCode::from(2);
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("xtask: error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

/// Builds the firmware and runs one example in QEMU with a live log;
/// with `--html PAGE`, also writes its run as a viewer page.
fn run(args: &[String]) -> Result<()> {
    let mut name = None;
    let mut html = None;
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--html" => {
                let page = it
                    .next()
                    .context("--html needs a page to write, such as run.html")?;
                html = Some(std::path::PathBuf::from(page));
            }
            other if other.starts_with('-') => bail!("run: unknown option {other}\n{USAGE}"),
            other if name.is_none() => name = Some(other),
            other => bail!(
                "run: two examples, {} and {other}: give one",
                name.unwrap_or("")
            ),
        }
    }
    let example = firmware::example(name.unwrap_or(firmware::FLAGSHIP))?;
    setup::ensure_target()?;
    setup::ensure_qemu()?;
    if let Some(html) = html {
        replay::model_of(example)?;
        // Checked before the minutes of building: the page can be written.
        std::fs::write(&html, "")
            .with_context(|| format!("--html: cannot write {}", html.display()))?;
        let rodyn_model = replay::build_rodyn_model()?;
        println!(
            "running {} in QEMU (mps2-an386, Cortex-M4F) with its pose log: {}",
            example.name, example.about
        );
        return replay::write_page(example, &html, &rodyn_model, |line| println!("{line}"));
    }
    firmware::build()?;
    println!(
        "running {} in QEMU (mps2-an386, Cortex-M4F): {}",
        example.name, example.about
    );
    let outcome = firmware::run(example, |line| println!("{line}"))?;
    if outcome.exit_code != 0 {
        bail!("{} exited with code {}", example.name, outcome.exit_code);
    }
    Ok(())
}

/// Everything CI checks.
fn test() -> Result<()> {
    let mut steps = Steps::new("test");
    steps.run("set-up (target, QEMU, IPOPT)", || {
        setup::ensure_target()?;
        setup::ensure_qemu()?;
        setup::ensure_ipopt()
    })?;
    // Miri interprets on one core for minutes: beside the other steps it
    // takes the time the second core would idle (crate::background).
    let miri = miri::start_in_background()?;
    steps.run("host tests", || shell::cargo(&["test", "--workspace"]))?;
    // So do clippy and rustdoc, in a target folder of their own so that
    // neither waits for the other's build lock.
    let host_lints = start_host_lints()?;
    steps.run("host tests, in-order profile", test_in_order_profile)?;
    steps.run("no_std core for thumbv7em", || {
        shell::cargo(&[
            "build",
            "-p",
            "rodyn",
            "-p",
            "rodyn-scenarios",
            "--no-default-features",
            "--features",
            "libm",
            "--target",
            "thumbv7em-none-eabihf",
        ])?;
        // The interop features stay no_std.
        shell::cargo(&[
            "build",
            "-p",
            "rodyn",
            "--no-default-features",
            "--features",
            "libm,nalgebra",
            "--target",
            "thumbv7em-none-eabihf",
        ])
    })?;

    let mut failures = Vec::new();
    steps.run("firmware in QEMU", || {
        firmware::build()?;
        for example in firmware::EXAMPLES {
            firmware::check_no_allocator(example)?;
            match firmware::run_and_compare(example) {
                Ok(()) => println!("firmware {}: ok", example.name),
                Err(e) => {
                    println!("firmware {}: FAILED: {e:#}", example.name);
                    failures.push(example.name);
                }
            }
        }
        firmware::agreement_against_fresh_run()?;
        firmware::check_panic_reentry()?;
        costs::check_sizes()?;
        costs::check_goals_of_last_run()
    })?;
    // The Cortex-M family's probes, whose logs the docs check reads.
    steps.run("Cortex-M family probes", family::run_probes)?;
    steps.run("docs check", docs::check_after_test)?;
    steps.run("board images", boards::check)?;
    steps.run("panic sites", panic_sites::check)?;
    steps.run("stack bounds", stack_bound::check)?;
    steps.run("viewer in Chromium", viewer::check)?;
    steps.run("Python bindings", python::check)?;
    steps.run("firmware template", template::check)?;
    steps.run("lint", || {
        lint_with(Started {
            miri: Some(miri),
            host_lints: Some(host_lints),
        })
    })?;

    if !failures.is_empty() {
        bail!("firmware examples failed: {}", failures.join(", "));
    }
    steps.finish();
    Ok(())
}

/// Runs a command's steps one after another and says how long each took,
/// so that a user (or CI's time budget) sees where the minutes go; the
/// table is printed when the last step passes and when one fails.
struct Steps {
    command: &'static str,
    started: Instant,
    done: Vec<(&'static str, f64)>,
}

impl Steps {
    fn new(command: &'static str) -> Self {
        Steps {
            command,
            started: Instant::now(),
            done: Vec::new(),
        }
    }

    fn run<T>(&mut self, name: &'static str, step: impl FnOnce() -> Result<T>) -> Result<T> {
        println!("xtask {}: {name} ...", self.command);
        let started = Instant::now();
        let outcome = step();
        let seconds = started.elapsed().as_secs_f64();
        self.done.push((name, seconds));
        match &outcome {
            Ok(_) => println!("xtask {}: {name}: passed in {seconds:.0} s", self.command),
            Err(_) => {
                println!(
                    "xtask {}: {name}: FAILED after {seconds:.0} s",
                    self.command
                );
                self.print_table();
            }
        }
        outcome
    }

    fn print_table(&self) {
        println!("xtask {}: time per step", self.command);
        for (name, seconds) in &self.done {
            println!("  {seconds:>6.0} s  {name}");
        }
        println!("  {:>6.0} s  in all", self.started.elapsed().as_secs_f64());
    }

    fn finish(&self) {
        self.print_table();
        println!(
            "xtask {}: all checks passed in {:.0} s",
            self.command,
            self.started.elapsed().as_secs_f64()
        );
    }
}

/// The tuning profile that hosts do not compile by default
/// (`crates/rodyn/src/tuning.rs`): `RODYN_TUNING=in-order`.
const IN_ORDER: (&str, &str) = ("RODYN_TUNING", "in-order");

/// Where the in-order profile builds: a target directory of its own, so
/// that switching profiles does not rebuild the core and everything above
/// it in the default one.
fn in_order_target_dir() -> String {
    shell::target_dir()
        .join("in-order")
        .to_string_lossy()
        .into_owned()
}

/// The core's tests and `rodyn-host-tests` (the Pinocchio fixtures, the
/// identities, f32 accuracy, the firmware agreement) again in the in-order
/// profile, whose forms hosts otherwise never run. The compile-fail test is
/// skipped: it checks the type-level model, which no profile changes.
fn test_in_order_profile() -> Result<()> {
    let started = Instant::now();
    let dir = in_order_target_dir();
    shell::cargo_env(
        &[
            "test",
            "-p",
            "rodyn",
            "-p",
            "rodyn-host-tests",
            "--",
            "--skip",
            "inconsistent_models_fail_to_compile",
        ],
        &[IN_ORDER, ("CARGO_TARGET_DIR", &dir)],
    )?;
    println!(
        "xtask test: in-order profile passed in {:.0} s",
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// The steps of `lint` that `test` started in the background; `None` runs
/// them in turn.
#[derive(Default)]
struct Started {
    /// `Some(None)`: Miri skipped, and said so.
    miri: Option<Option<background::Background>>,
    host_lints: Option<background::Background>,
}

/// Formatting, clippy and rustdoc with warnings as errors; Miri.
fn lint() -> Result<()> {
    lint_with(Started::default())
}

fn lint_with(started: Started) -> Result<()> {
    let mut steps = Steps::new("lint");
    steps.run("IPOPT", setup::ensure_ipopt)?;
    steps.run("layers", layers::run)?;
    steps.run("rustfmt", || {
        shell::cargo(&["fmt", "--all", "--check"])?;
        shell::cargo_in(firmware::dir(), &["fmt", "--check"])
    })?;
    steps.run("boards: rustfmt and clippy", boards::lint)?;
    steps.run("clippy: firmware", || {
        shell::cargo_in(
            firmware::dir(),
            &["clippy", "--release", "--", "-D", "warnings"],
        )
    })?;
    match started.host_lints {
        None => steps.run("clippy and rustdoc: host", host_lints)?,
        Some(run) => steps.run(
            "clippy and rustdoc: host (collected from the background)",
            || run.finish(),
        )?,
    }
    steps.run(
        "core without float features",
        no_float_features_is_one_error,
    )?;
    steps.run("packages", packages)?;
    steps.run("public API", || public_api::run(false))?;
    match started.miri {
        None => steps.run("Miri", miri::run)?,
        Some(Some(run)) => steps.run("Miri (collected from the background)", || run.finish())?,
        Some(None) => {}
    }
    steps.print_table();
    println!(
        "xtask lint: clean in {:.0} s",
        steps.started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// Clippy on the host's crates (the workspace, and the core in the
/// in-order profile; the firmware's clippy covers it without `std`) and
/// rustdoc, warnings as errors.
fn host_lints() -> Result<()> {
    shell::cargo(&[
        "clippy",
        "--workspace",
        "--all-targets",
        "--",
        "-D",
        "warnings",
    ])?;
    let in_order_dir = in_order_target_dir();
    shell::cargo_env(
        &[
            "clippy",
            "-p",
            "rodyn",
            "--all-targets",
            "--",
            "-D",
            "warnings",
        ],
        &[IN_ORDER, ("CARGO_TARGET_DIR", &in_order_dir)],
    )?;
    shell::cargo_env(
        &["doc", "--workspace", "--no-deps"],
        &[("RUSTDOCFLAGS", "-D warnings")],
    )
}

/// `cargo xtask host-lints` in the background, building in `target/lint`.
fn start_host_lints() -> Result<background::Background> {
    let mut command = Command::new(std::env::current_exe()?);
    command
        .arg("host-lints")
        .current_dir(shell::root())
        .env("CARGO_TARGET_DIR", shell::target_dir().join("lint"));
    background::Background::start("clippy and rustdoc", command, "host-lints.log")
}

/// The crates as crates.io would get them. Every member is packaged with
/// `--no-verify`: the manifests, the `include` lists and the versions on
/// path dependencies are checked, nothing is compiled. Then the published
/// libraries are packaged again and each compiled from its own tarball,
/// which proves it holds what its build reads (the scenes' model files
/// through rodyn-scenarios' build script). rodyn-sim, published too, is
/// left at the first step: it has no build script and reads no file at
/// build time, so its tarball's build would prove only what the workspace
/// build does, for minutes of plotting and image crates in the package
/// target folder. The internal crates are never published. Each command
/// packages its crates together, so that a dependency on a crate not yet
/// on crates.io resolves to the one packaged beside it.
///
/// The verifying builds go to a target folder emptied first: cargo takes a
/// registry crate's source as fixed by its version, so a `rodyn 0.1.0`
/// compiled from an earlier package would otherwise stand in for today's.
fn packages() -> Result<()> {
    shell::cargo(&["package", "--workspace", "--no-verify", "--allow-dirty"])?;
    let dir = shell::target_dir().join("package-verify");
    if dir.exists() {
        std::fs::remove_dir_all(&dir).with_context(|| format!("cannot empty {}", dir.display()))?;
    }
    let mut verified = vec!["package", "--allow-dirty"];
    for name in VERIFIED_FROM_PACKAGE {
        verified.extend(["-p", name]);
    }
    shell::cargo_env(&verified, &[("CARGO_TARGET_DIR", &dir.to_string_lossy())])
}

/// The published libraries, in dependency order, built from their
/// packages by `lint` (`rodyn-cli`, the tools' argument types, because the
/// model compiler's and the scenes' tests use it). The other published
/// crate is the `rodyn-sim` tool; every other member has `publish = false`.
const VERIFIED_FROM_PACKAGE: [&str; 5] = [
    "rodyn",
    "rodyn-cli",
    "rodyn-viewer",
    "rodyn-model",
    "rodyn-scenarios",
];

/// Building the core with neither `std` nor `libm` must stop at the one
/// `compile_error!` naming both features, not bury it in type errors.
fn no_float_features_is_one_error() -> Result<()> {
    let mut command = shell::cargo_command(&shell::root());
    command.args([
        "check",
        "-p",
        "rodyn",
        "--no-default-features",
        "--message-format=short",
    ]);
    println!("$ {}", shell::describe(&command));
    let output = command.output()?;
    let stderr = String::from_utf8_lossy(&output.stderr);
    let errors: Vec<&str> = stderr
        .lines()
        .filter(|line| line.contains("error") && !line.contains("could not compile"))
        .collect();
    let names_both = |line: &&str| line.contains("`std`") && line.contains("`libm`");
    if output.status.success() || errors.len() != 1 || !errors.iter().all(names_both) {
        bail!(
            "rodyn without `std` and `libm` should fail with one error naming both features; got:\n{}",
            errors.join("\n")
        );
    }
    Ok(())
}

/// Rewrites the expected logs from fresh runs.
fn bless() -> Result<()> {
    setup::ensure_target()?;
    setup::ensure_qemu()?;
    firmware::build()?;
    for example in firmware::EXAMPLES {
        firmware::bless(example)?;
    }
    Ok(())
}
