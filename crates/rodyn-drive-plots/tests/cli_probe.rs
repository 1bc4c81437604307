//! `rodyn-drive-plots` takes `--out DIR` only: it refuses anything else
//! rather than ignore it, and an output it cannot write before it works
//! (run without arguments, it rewrites the documentation's figures, so
//! that run is left to its users and to `cargo xtask docs`).

use rodyn_cli::probe::{assert_calm_when_stdout_closes, assert_refused};
use std::path::Path;

const USAGE: &str = "usage: rodyn-drive-plots [--out DIR]";

#[test]
fn other_arguments_and_unwritable_outputs_are_refused() {
    let exe = Path::new(env!("CARGO_BIN_EXE_rodyn-drive-plots"));
    for args in [
        &["--duration", "10"][..],
        &["out/"],
        &["--help"],
        &["--out"],
    ] {
        assert_refused(exe, args, USAGE);
    }
    let dir = std::env::temp_dir().join(format!("rodyn-drive-plots-probe-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let plain = dir.join("a-file");
    std::fs::write(&plain, "not a directory").unwrap();
    let unwritable = plain.join("out");
    let outcome = assert_refused(exe, &["--out", unwritable.to_str().unwrap()], "a-file");
    assert!(!outcome.stderr.contains("panicked"), "{}", outcome.stderr);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `rodyn-drive-plots --out DIR | head -1`: the figures are written and
/// the closing summary goes to a closed pipe without a panic.
#[test]
fn a_reader_that_stops_early_is_no_panic() {
    let exe = Path::new(env!("CARGO_BIN_EXE_rodyn-drive-plots"));
    let dir = std::env::temp_dir().join(format!(
        "rodyn-drive-plots-closed-stdout-{}",
        std::process::id()
    ));
    assert_calm_when_stdout_closes(exe, &["--out", dir.to_str().unwrap()]);
    assert!(dir.join("muscle_robot_trajectory.svg").is_file());
    let _ = std::fs::remove_dir_all(&dir);
}
