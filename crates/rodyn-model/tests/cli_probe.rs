//! Every argument of the `rodyn-model` command tried with hostile values:
//! each must be refused with a message naming it, without a panic or a
//! hang. The tables must list every option the usage shows; a new option
//! fails `every_option_is_probed` until it is added here.

use rodyn_cli::probe::{
    assert_calm_when_stdout_closes, assert_listed, assert_no_panic, assert_refused,
    assert_refuses_hostile_values, run, NumericOption,
};
use std::path::{Path, PathBuf};

fn exe() -> &'static Path {
    Path::new(env!("CARGO_BIN_EXE_rodyn-model"))
}

fn model(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../models")
        .join(name)
        .to_str()
        .unwrap()
        .to_owned()
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rodyn-model-probe-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const NUMERIC: [&str; 2] = ["--width", "--q"];
const OTHER: [&str; 6] = [
    "--module",
    "--view",
    "-o",
    "--silence",
    "--package-path",
    "--trajectory",
];

#[test]
fn every_option_is_probed() {
    let help = run(exe(), &["--help"]);
    assert!(help.status.success(), "{}", help.stderr);
    assert_listed(&help.stdout, &NUMERIC, &OTHER);
}

#[test]
fn numeric_options_refuse_hostile_values() {
    let pendulum = model("pendulum.toml");
    assert_refuses_hostile_values(
        exe(),
        &NumericOption {
            option: "--width",
            before: &["render", &pendulum],
            after: &[],
            accepts: &[],
        },
    );
    // A joint angle may be zero or negative; the rest must be refused.
    assert_refuses_hostile_values(
        exe(),
        &NumericOption {
            option: "--q",
            before: &["render", &pendulum],
            after: &[],
            accepts: &["0", "-1", "-0.5", "5e-324"],
        },
    );
    // One bad number in a list is enough.
    let panda = model("panda.toml");
    let outcome = assert_refused(exe(), &["render", &panda, "--q", "0,0,0,NaN,0,0,0"], "--q");
    assert!(outcome.stderr.contains("NaN"), "{}", outcome.stderr);
    assert_refused(exe(), &["render", &panda, "--q", "0,0"], "--q");
}

#[test]
fn accepted_values_draw_a_finite_picture() {
    let outcome = run(
        exe(),
        &[
            "render",
            &model("pendulum.toml"),
            "--q",
            "-0.5",
            "--width",
            "16",
        ],
    );
    assert!(outcome.status.success(), "{}", outcome.stderr);
    assert!(outcome.stdout.starts_with("<svg") && !outcome.stdout.contains("NaN"));
    assert!(
        outcome.stdout.contains(r#"width="16""#),
        "{}",
        outcome.stdout
    );
}

#[test]
fn other_options_refuse_bad_values_outputs_and_inputs() {
    let pendulum = model("pendulum.toml");
    assert_refused(
        exe(),
        &["render", &pendulum, "--view", "sideways"],
        "--view",
    );
    assert_refused(
        exe(),
        &["check", &pendulum, "--silence", "nonsense"],
        "--silence",
    );
    for option in [
        "--module",
        "--view",
        "-o",
        "--silence",
        "--q",
        "--width",
        "--package-path",
        "--trajectory",
    ] {
        // The value missing.
        assert_refused(exe(), &["render", &pendulum, option], option);
    }
    // A module name the generator would have to change.
    for name in ["a b", "", "9x", "fn", "Panda"] {
        assert_refused(exe(), &["rust", &pendulum, "--module", name], "--module");
    }
    let outcome = run(exe(), &["rust", &pendulum, "--module", "pendulum_model"]);
    assert!(
        outcome.status.success() && outcome.stdout.contains("pub mod pendulum_model {"),
        "{}",
        outcome.stderr
    );
    // An option of another command is refused, not ignored.
    assert_refused(exe(), &["check", &pendulum, "--module", "m"], "--module");
    assert_refused(exe(), &["tree", &pendulum, "--view", "xy"], "--view");
    assert_refused(
        exe(),
        &["render", &pendulum, "--package-path", "."],
        "--package-path",
    );
    assert_refused(
        exe(),
        &["render", &pendulum, "--trajectory", "run.csv"],
        "--trajectory",
    );

    let dir = scratch("files");
    let plain = dir.join("a-file");
    std::fs::write(&plain, "not a directory").unwrap();
    let unwritable = plain.join("out.svg");
    let unwritable = unwritable.to_str().unwrap();
    let outcome = assert_refused(exe(), &["render", &pendulum, "-o", unwritable], "-o");
    assert!(outcome.stderr.contains(unwritable), "{}", outcome.stderr);

    // Missing, empty and truncated model files, named in the message.
    let missing = dir.join("missing.toml");
    let empty = dir.join("empty.urdf");
    std::fs::write(&empty, "").unwrap();
    let truncated = dir.join("truncated.toml");
    let full = std::fs::read_to_string(model("pendulum.toml")).unwrap();
    std::fs::write(&truncated, &full[..full.len() / 2]).unwrap();
    for file in [&missing, &empty, &truncated] {
        let file = file.to_str().unwrap();
        for command in ["rust", "check", "tree", "render"] {
            assert_refused(exe(), &[command, file], file);
        }
    }
    assert_refused(exe(), &[], "usage");
    assert_refused(exe(), &["check"], "usage");
    assert_refused(exe(), &["frobnicate", &pendulum], "frobnicate");
    assert_refused(exe(), &["check", &pendulum, "--frobnicate"], "--frobnicate");
    let outcome = assert_refused(exe(), &["check", &pendulum, &pendulum], "two model files");
    assert_no_panic(&outcome, &[]);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `view --trajectory` replays a CSV file into the page, and refuses one
/// with a bad line, naming the file and the line.
#[test]
fn view_replays_a_trajectory_and_names_a_bad_line() {
    let pendulum = model("pendulum.toml");
    let dir = scratch("trajectory");
    let csv = dir.join("swing.csv");
    std::fs::write(&csv, "t,q0\n0,0.1\n0.5,0.6\n1,-0.2\n").unwrap();
    let page = dir.join("swing.html");
    let outcome = run(
        exe(),
        &[
            "view",
            &pendulum,
            "--trajectory",
            csv.to_str().unwrap(),
            "-o",
            page.to_str().unwrap(),
        ],
    );
    assert!(outcome.status.success(), "{}", outcome.stderr);
    let html = std::fs::read_to_string(&page).unwrap();
    // The scene's JSON carries the three sample times.
    assert!(
        html.contains("\"t\":[0.0,0.5,1.0]"),
        "no trajectory in the page"
    );

    let bad = dir.join("bad.csv");
    std::fs::write(&bad, "t,q0\n0,0.1\n0.5,NaN\n").unwrap();
    let outcome = assert_refused(
        exe(),
        &["view", &pendulum, "--trajectory", bad.to_str().unwrap()],
        "bad.csv:3",
    );
    assert!(outcome.stderr.contains("`NaN`"), "{}", outcome.stderr);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `rodyn-model rust FILE | head -1`, and the same for `tree`, `check` and
/// `render` to standard output: the reader's early close is no panic and
/// no error.
#[test]
fn a_reader_that_stops_early_is_no_panic() {
    let pendulum = model("pendulum.toml");
    for command in ["rust", "tree", "check", "render"] {
        assert_calm_when_stdout_closes(exe(), &[command, &pendulum]);
    }
}
