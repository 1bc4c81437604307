//! Every argument of `rodyn-sim` tried with hostile values: each must be
//! refused at once with a message naming the argument, without a panic or
//! a hang. The tables below must list every option the help shows; a new
//! option fails `every_option_is_probed` until it is added here.

use rodyn_cli::probe::NumericOption;
use rodyn_cli::probe::{
    assert_calm_when_stdout_closes, assert_listed, assert_refused, assert_refuses_hostile_values,
    run,
};
use std::path::{Path, PathBuf};

fn exe() -> &'static Path {
    Path::new(env!("CARGO_BIN_EXE_rodyn-sim"))
}

/// A scratch directory of this test process, removed when dropped.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Self {
        let dir =
            std::env::temp_dir().join(format!("rodyn-sim-probe-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        Self(dir)
    }
    fn path(&self) -> &str {
        self.0.to_str().unwrap()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A path in `scratch` that cannot be a directory: it goes through a
/// plain file.
fn unwritable(scratch: &Scratch) -> PathBuf {
    let file = scratch.0.join("a-file");
    std::fs::write(&file, "not a directory").unwrap();
    file.join("out")
}

const SUBCOMMANDS: [&str; 3] = ["run", "chart", "failures"];

/// The numeric options of each subcommand.
fn numeric(subcommand: &str) -> &'static [&'static str] {
    match subcommand {
        "run" => &[
            "--duration",
            "--dt",
            "--friction",
            "--restitution",
            "--drop-height",
        ],
        _ => &[],
    }
}

/// The other value-taking options, each with a probe below.
fn other(subcommand: &str) -> &'static [&'static str] {
    match subcommand {
        "run" => &[
            "[SCENARIO]",
            "--model",
            "--contact",
            "--method",
            "--integrator",
            "--scalar",
            "--out",
            "--html",
        ],
        "failures" => &["[EXPERIMENT]", "--out"],
        "chart" => &["--out", "--scenario"],
        _ => &["--out"],
    }
}

#[test]
fn every_option_is_probed() {
    let top = run(exe(), &["--help"]);
    assert_listed(&top.stdout, &[], &[]);
    for subcommand in SUBCOMMANDS {
        let help = run(exe(), &[subcommand, "--help"]);
        assert!(
            help.status.success(),
            "{subcommand} --help: {}",
            help.stderr
        );
        assert_listed(&help.stdout, numeric(subcommand), other(subcommand));
    }
}

#[test]
fn numeric_options_refuse_hostile_values() {
    let scratch = Scratch::new("numeric");
    let out = scratch.path();
    for option in ["--duration", "--dt"] {
        assert_refuses_hostile_values(
            exe(),
            &NumericOption {
                option,
                before: &["run", "arm-swing", "-o", out],
                after: &[],
                accepts: &[],
            },
        );
    }
}

/// The ground's numbers, on a short run of the Panda on the ground: zero
/// is a frictionless floor, a dead bounce and a drop from the ground.
#[test]
fn ground_options_refuse_hostile_values() {
    let scratch = Scratch::new("ground");
    let out = scratch.path();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let panda = root.join("models/urdf/panda.urdf");
    let panda = panda.to_str().unwrap();
    let before = [
        "run",
        "--model",
        panda,
        "--floating-base",
        "--ground",
        "--duration",
        "0.002",
        "-o",
        out,
    ];
    for option in ["--friction", "--restitution", "--drop-height"] {
        assert_refuses_hostile_values(
            exe(),
            &NumericOption {
                option,
                before: &before,
                after: &[],
                accepts: &["0", "5e-324"],
            },
        );
    }
    let refused = |args: &[&str], naming: &str, words: &str| {
        let mut all = before.to_vec();
        all.extend(args);
        let outcome = assert_refused(exe(), &all, naming);
        assert!(
            outcome.stderr.contains(words),
            "{args:?}: {}",
            outcome.stderr
        );
    };
    refused(&["--restitution", "1.5"], "--restitution", "above 1");
    refused(&["--friction", "11"], "--friction", "above 10");
    refused(
        &["--contact", "no_such_frame"],
        "--contact no_such_frame",
        "panda_link7",
    );
    refused(
        &["--contact", "panda_link7", "--contact", "panda_link7"],
        "--contact panda_link7",
        "twice",
    );
    // The ground's options need the ground, and a drop needs a floating base.
    assert_refused(
        exe(),
        &["run", "--model", panda, "--friction", "0.5", "-o", out],
        "--ground",
    );
    assert_refused(
        exe(),
        &[
            "run",
            "--model",
            panda,
            "--ground",
            "--drop-height",
            "0.1",
            "-o",
            out,
        ],
        "--drop-height",
    );
}

#[test]
fn runs_without_end_or_without_a_step_are_refused_with_the_limit() {
    let scratch = Scratch::new("limits");
    let out = scratch.path();
    let refused = |args: &[&str], words: &[&str]| {
        let mut all = vec!["run", "arm-swing", "-o", out];
        all.extend(args);
        let outcome = assert_refused(exe(), &all, "--duration");
        for w in words {
            assert!(outcome.stderr.contains(w), "{args:?}: {}", outcome.stderr);
        }
    };
    refused(&["--duration", "1001"], &["limit of 1000 s"]);
    refused(&["--dt", "1e-9"], &["--dt", "limit of 10000000"]);
    refused(
        &["--duration", "1000", "--dt", "1e-5"],
        &["limit of 10000000"],
    );
    refused(
        &["--duration", "0.001", "--dt", "0.01"],
        &["--dt", "no step"],
    );
}

#[test]
fn other_options_refuse_unknown_choices_and_unwritable_outputs() {
    let scratch = Scratch::new("choices");
    let out = scratch.path();
    for option in ["--method", "--integrator", "--scalar"] {
        assert_refused(
            exe(),
            &["run", "arm-swing", "-o", out, option, "nonsense"],
            option,
        );
    }
    assert_refused(exe(), &["run", "no-such-scenario"], "no-such-scenario");
    // A scenario without a chart, and one that is not a scenario.
    assert_refused(
        exe(),
        &[
            "chart",
            "--replot",
            "-o",
            out,
            "--scenario",
            "quadruped-trot",
        ],
        "quadruped-trot has no chart",
    );
    assert_refused(
        exe(),
        &["chart", "-o", out, "--scenario", "nonsense"],
        "--scenario",
    );
    assert_refused(
        exe(),
        &["failures", "no-such-experiment"],
        "no-such-experiment",
    );
    let bad = unwritable(&scratch);
    let bad = bad.to_str().unwrap();
    for args in [
        vec!["run", "arm-swing", "--duration", "0.01", "-o", bad],
        vec!["chart", "-o", bad],
        vec!["failures", "all", "-o", bad],
    ] {
        let outcome = assert_refused(exe(), &args, "--out");
        assert!(outcome.stderr.contains(bad), "{}", outcome.stderr);
    }
    let good = scratch.path();
    let args = [
        "run",
        "arm-swing",
        "--duration",
        "0.01",
        "-o",
        good,
        "--html",
        bad,
    ];
    let outcome = assert_refused(exe(), &args, "--html");
    assert!(outcome.stderr.contains(bad), "{}", outcome.stderr);
    assert_refused(exe(), &["--no-such-option"], "--no-such-option");
    assert_refused(exe(), &[], "Usage");
}

#[test]
fn a_short_valid_run_still_succeeds_and_writes_its_files() {
    let scratch = Scratch::new("valid");
    let out = &scratch.0;
    let outcome = run(
        exe(),
        &[
            "run",
            "arm-swing",
            "--duration",
            "0.05",
            "-o",
            scratch.path(),
        ],
    );
    assert!(outcome.status.success(), "{}", outcome.stderr);
    // 0.05 s at the default 1 ms: 50 steps, samples every 10 ms and the start.
    let csv = std::fs::read_to_string(out.join("arm-swing.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 6, "{csv}");
    assert!(out.join("arm-swing.svg").is_file() && out.join("arm-swing.gif").is_file());
}

/// `rodyn-sim run … | head -1`: the summary's lines go to a closed pipe;
/// the run still ends with status 0 and its files, without a panic.
#[test]
fn a_reader_that_stops_early_is_no_panic() {
    let scratch = Scratch::new("closed-stdout");
    let args = [
        "run",
        "arm-swing",
        "--duration",
        "0.05",
        "-o",
        scratch.path(),
    ];
    assert_calm_when_stdout_closes(exe(), &args);
    assert!(scratch.0.join("arm-swing.csv").is_file());
}

#[test]
fn a_model_file_runs_and_bad_ones_are_refused_by_name() {
    let scratch = Scratch::new("model-file");
    let out = scratch.path();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let panda = root.join("models/urdf/panda.urdf");
    let panda = panda.to_str().unwrap();
    let ok = run(
        exe(),
        &[
            "run",
            "--model",
            panda,
            "--duration",
            "0.05",
            "--integrator",
            "rk4",
            "-o",
            out,
        ],
    );
    assert!(ok.status.success(), "{}", ok.stderr);
    let csv = std::fs::read_to_string(Path::new(out).join("panda.csv")).unwrap();
    assert!(csv.starts_with("t,q_panda_joint1,"), "{csv}");
    assert_eq!(csv.lines().count(), 7, "a header and six samples");
    assert_refused(
        exe(),
        &["run", "--model", "no/such.urdf", "-o", out],
        "--model",
    );
    assert_refused(
        exe(),
        &[
            "run",
            "--model",
            panda,
            "--integrator",
            "implicit-euler",
            "-o",
            out,
        ],
        "--integrator implicit-euler",
    );
    assert_refused(
        exe(),
        &["run", "--model", panda, "--scalar", "f32", "-o", out],
        "--scalar",
    );
    assert_refused(
        exe(),
        &["run", "arm-swing", "--model", panda, "-o", out],
        "--model",
    );
    let broken = Path::new(out).join("broken.urdf");
    std::fs::write(&broken, "<robot name=\"x\"><link name=\"a\"/>\n<joint name=\"j\" type=\"revolute\"></joint></robot>").unwrap();
    assert_refused(
        exe(),
        &["run", "--model", broken.to_str().unwrap(), "-o", out],
        "broken.urdf:2:",
    );
}
