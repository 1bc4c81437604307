//! The optimal-control example run with hostile arguments: each must be
//! refused before any solve, with a message naming the argument, without
//! a panic or a hang. `every_option_is_probed` fails on an option of its
//! help that the tables below do not list.

use rodyn_cli::probe::{
    assert_listed, assert_refused, assert_refuses_hostile_values, example, run, NumericOption,
};

const NAME: &str = "muscle_robot_optimal_control";
const NUMERIC: [&str; 2] = ["--nodes", "--duration"];

#[test]
fn every_option_is_probed() {
    let help = run(&example("rodyn-optimal-control", NAME), &["--help"]);
    assert!(help.status.success(), "{}", help.stderr);
    assert_listed(&help.stdout, &NUMERIC, &["--out"]);
}

#[test]
fn numbers_sizes_and_outputs_are_refused_before_any_solve() {
    let exe = example("rodyn-optimal-control", NAME);
    let dir = std::env::temp_dir().join(format!("rodyn-oc-probe-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("out");
    let out = out.to_str().unwrap();
    for option in NUMERIC {
        assert_refuses_hostile_values(
            &exe,
            &NumericOption {
                option,
                before: &["--out", out],
                after: &[],
                accepts: &[],
            },
        );
    }
    let outcome = assert_refused(&exe, &["--out", out, "--nodes", "1002"], "--nodes");
    assert!(
        outcome.stderr.contains("from 3 to 1001"),
        "{}",
        outcome.stderr
    );
    assert_refused(&exe, &["--out", out, "--nodes", "2"], "--nodes");
    let outcome = assert_refused(&exe, &["--out", out, "--duration", "20.5"], "--duration");
    assert!(
        outcome.stderr.contains("limit of 20 s"),
        "{}",
        outcome.stderr
    );

    let plain = dir.join("a-file");
    std::fs::write(&plain, "not a directory").unwrap();
    let unwritable = plain.join("out");
    assert_refused(&exe, &["--out", unwritable.to_str().unwrap()], "--out");
    assert_refused(&exe, &[], "--out");
    let _ = std::fs::remove_dir_all(&dir);
}
