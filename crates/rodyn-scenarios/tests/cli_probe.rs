//! The muscle robot example takes no arguments: it refuses any rather
//! than ignore them, and runs without.

use rodyn_cli::probe::{assert_calm_when_stdout_closes, assert_refused, example, run};

#[test]
fn the_example_refuses_arguments_and_runs_without() {
    let exe = example("rodyn-scenarios", "muscle_robot");
    assert_refused(&exe, &["--duration", "10"], "takes no arguments");
    let outcome = run(&exe, &[]);
    assert!(outcome.status.success(), "{}", outcome.stderr);
    // The header and a row every 0.2 s from 0 to 2 s.
    assert_eq!(outcome.stdout.lines().count(), 1 + 11, "{}", outcome.stdout);
}

/// `muscle_robot | head -1`: the table goes to a closed pipe without a
/// panic, and the run ends with status 0.
#[test]
fn a_reader_that_stops_early_is_no_panic() {
    assert_calm_when_stdout_closes(&example("rodyn-scenarios", "muscle_robot"), &[]);
}
