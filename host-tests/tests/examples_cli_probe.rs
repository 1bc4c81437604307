//! The host-tests examples run with hostile arguments and inputs: each
//! must refuse with a message naming the argument or the file, without a
//! panic or a hang. `every_option_is_probed` fails on an option of the
//! gait example's usage that the tables below do not list.

mod gait_inputs;

use gait_inputs::{frames, write_inputs};
use rodyn_cli::probe::{
    assert_calm_when_stdout_closes, assert_listed, assert_refused, example, run,
};
use std::path::PathBuf;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "rodyn-examples-probe-{}-{name}",
        std::process::id()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A path that cannot be created: it goes through a plain file.
fn unwritable(dir: &std::path::Path) -> String {
    let plain = dir.join("a-file");
    std::fs::write(&plain, "not a directory").unwrap();
    plain.join("out").to_str().unwrap().to_owned()
}

const INPUT: &str = "inverse_dynamics_inputs_60hz.csv";

#[test]
fn every_option_is_probed() {
    let gait = example("rodyn-host-tests", "gait_subject01");
    let help = run(&gait, &["--help"]);
    assert!(help.status.success(), "{}", help.stderr);
    // No numeric options; both paths are probed below.
    assert_listed(&help.stdout, &[], &["--out", "--data"]);
}

#[test]
fn the_gait_example_refuses_short_or_missing_data_and_unwritable_outputs() {
    let gait = example("rodyn-host-tests", "gait_subject01");
    let dir = scratch("gait");
    let out = dir.join("out");
    let out = out.to_str().unwrap();
    for (name, rows) in [("one_row", 1), ("ten_rows", 10)] {
        let data = dir.join(name);
        let times: Vec<f64> = (0..rows).map(|k| 0.6 + k as f64 / 60.0).collect();
        let file = write_inputs(&data.join(INPUT), &times);
        let outcome = assert_refused(
            &gait,
            &["--out", out, "--data", data.to_str().unwrap()],
            file.to_str().unwrap(),
        );
        assert!(
            outcome
                .stderr
                .contains(&format!("{rows} data rows, too few")),
            "{}",
            outcome.stderr
        );
    }
    let missing = dir.join("missing");
    assert_refused(
        &gait,
        &["--out", out, "--data", missing.to_str().unwrap()],
        missing.join(INPUT).to_str().unwrap(),
    );

    // Data that cover the gait cycle: an unwritable --out is refused, a
    // writable one gets the table and a summary without NaN.
    let full = dir.join("full");
    write_inputs(&full.join(INPUT), &frames(0.0, 2.5));
    let full = full.to_str().unwrap();
    assert_refused(
        &gait,
        &["--out", &unwritable(&dir), "--data", full],
        "--out",
    );
    let outcome = run(&gait, &["--out", out, "--data", full]);
    assert!(outcome.status.success(), "{}", outcome.stderr);
    let summary = std::fs::read_to_string(dir.join("out/summary.txt")).unwrap();
    assert!(summary.starts_with("subject01: 151 frames"), "{summary}");
    assert!(
        !summary.contains("NaN") && !summary.contains("inf"),
        "{summary}"
    );

    assert_refused(&gait, &[], "--out");
    assert_refused(&gait, &["--out"], "--out");
    assert_refused(&gait, &["--out", out, "--data"], "--data");
    assert_refused(&gait, &["--out", out, "--frobnicate"], "--frobnicate");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_sweep_refuses_missing_empty_or_unwritable_files() {
    let sweep = example("rodyn-host-tests", "model_sweep");
    let dir = scratch("sweep");
    let output = dir.join("out.json");
    let output = output.to_str().unwrap();
    let missing = dir.join("missing.json");
    let missing = missing.to_str().unwrap();
    assert_refused(&sweep, &[missing, output], missing);
    let empty = dir.join("empty.json");
    std::fs::write(&empty, "[]").unwrap();
    let empty = empty.to_str().unwrap();
    assert_refused(&sweep, &[empty, output], "no robots");
    let truncated = dir.join("truncated.json");
    std::fs::write(&truncated, r#"[{"urdf": "#).unwrap();
    let truncated = truncated.to_str().unwrap();
    assert_refused(&sweep, &[truncated, output], truncated);
    let no_urdf = dir.join("no_urdf.json");
    std::fs::write(&no_urdf, r#"[{"states": []}]"#).unwrap();
    assert_refused(&sweep, &[no_urdf.to_str().unwrap(), output], "urdf");
    let bad_output = format!("{}.json", unwritable(&dir));
    assert_refused(
        &sweep,
        &[no_urdf.to_str().unwrap(), &bad_output],
        &bad_output,
    );
    assert_refused(&sweep, &[empty], "usage");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn examples_without_options_refuse_arguments() {
    for name in ["gait_data", "f32_error_table"] {
        let exe = example("rodyn-host-tests", name);
        assert_refused(&exe, &["--duration", "10"], "takes no arguments");
    }
    // `gait_prosthesis` takes `--out DIR` only.
    let exe = example("rodyn-host-tests", "gait_prosthesis");
    assert_refused(
        &exe,
        &["--duration", "10"],
        "usage: gait_prosthesis [--out DIR]",
    );
    assert_refused(&exe, &["--out"], "usage: gait_prosthesis [--out DIR]");
}

/// The examples that print, with the reader of their output gone (`| head
/// -1`): no panic, status 0. The README's first program
/// (`crates/rodyn/examples/quickstart.rs`) keeps the plain `println!` a
/// first program shows.
#[test]
fn a_reader_that_stops_early_is_no_panic() {
    let gait = example("rodyn-host-tests", "gait_subject01");
    assert_calm_when_stdout_closes(&gait, &["--help"]);
    assert_calm_when_stdout_closes(&example("rodyn-host-tests", "f32_error_table"), &[]);
    assert_calm_when_stdout_closes(&example("rodyn", "pendulum_spring"), &[]);
    let dir = scratch("closed-stdout");
    assert_calm_when_stdout_closes(
        &example("rodyn-host-tests", "gait_prosthesis"),
        &["--out", dir.to_str().unwrap()],
    );
}
