//! Every argument of the measuring binaries tried with hostile values:
//! each must be refused before any timing, with a message naming it, and
//! without a panic or a hang. The table must list every argument the
//! binaries' help shows; a new one fails `every_argument_is_probed`.

use rodyn_cli::probe::{
    assert_calm_when_stdout_closes, assert_listed, assert_refused, assert_refuses_hostile_values,
    example, run, NumericOption, HOSTILE,
};
use std::path::Path;

/// Each binary, its numeric arguments and its others.
const BINARIES: [(&str, &str, &[&str], &[&str]); 4] = [
    (
        "compare",
        env!("CARGO_BIN_EXE_compare"),
        &["--rounds", "--ms"],
        &["--pinocchio"],
    ),
    (
        "crossover",
        env!("CARGO_BIN_EXE_crossover"),
        &["--rounds", "--ms"],
        &["--out"],
    ),
    (
        "derivatives_timing",
        env!("CARGO_BIN_EXE_derivatives_timing"),
        &["--ms", "--only"],
        &[],
    ),
    (
        "profile",
        env!("CARGO_BIN_EXE_profile"),
        &["[CALLS]"],
        &["<ALGORITHM>", "<MODEL>"],
    ),
];

/// An existing file that stands for Pinocchio's timing program: the
/// refusals come before it would be run.
fn stand_in_program() -> &'static str {
    env!("CARGO_BIN_EXE_profile")
}

#[test]
fn every_argument_is_probed() {
    for (name, exe, numeric, other) in BINARIES {
        let help = run(Path::new(exe), &["--help"]);
        assert!(help.status.success(), "{name}: {}", help.stderr);
        assert_listed(&help.stdout, numeric, other);
    }
}

/// The contact and kinematics benchmarks, examples of this crate (their
/// robots come from the unpublished test fixtures, a dev-dependency).
#[test]
fn the_benchmark_examples_refuse_hostile_values() {
    for (name, numeric) in [
        ("contacts_timing", &["--ms"][..]),
        ("kinematics_timing", &["--ms", "--only"][..]),
    ] {
        let exe = example("rodyn-bench", name);
        let help = run(&exe, &["--help"]);
        assert!(help.status.success(), "{name}: {}", help.stderr);
        assert_listed(&help.stdout, numeric, &[]);
        assert_refuses_hostile_values(
            &exe,
            &NumericOption {
                option: "--ms",
                before: &[],
                after: &[],
                accepts: &[],
            },
        );
        if name == "kinematics_timing" {
            for value in HOSTILE {
                assert_refused(&exe, &["--only", "ur5", "ccrba", value], "--only");
            }
        }
    }
}

#[test]
fn numeric_arguments_refuse_hostile_values() {
    for (name, exe, numeric, _) in BINARIES {
        let exe = Path::new(exe);
        let before: &[&str] = if name == "compare" {
            &["--pinocchio", stand_in_program()]
        } else {
            &[]
        };
        for &option in numeric.iter() {
            match option {
                // The count of calls is `--only`'s third value.
                "--only" => {
                    for value in HOSTILE {
                        assert_refused(exe, &["--only", "ur5", "ccrba", value], "--only");
                    }
                }
                "[CALLS]" => {
                    for value in HOSTILE {
                        assert_refused(exe, &["aba", "panda", value], "CALLS");
                    }
                }
                _ => assert_refuses_hostile_values(
                    exe,
                    &NumericOption {
                        option,
                        before,
                        after: &[],
                        accepts: &[],
                    },
                ),
            }
        }
    }
    for exe in [
        env!("CARGO_BIN_EXE_crossover"),
        env!("CARGO_BIN_EXE_compare"),
    ] {
        let exe = Path::new(exe);
        let pinocchio = ["--pinocchio", stand_in_program()];
        let compare = exe.ends_with("compare");
        let with = |args: &[&'static str]| -> Vec<&'static str> {
            let mut all = args.to_vec();
            if compare {
                all.extend(pinocchio);
            }
            all
        };
        let outcome = assert_refused(exe, &with(&["--ms", "10001"]), "--ms");
        assert!(
            outcome.stderr.contains("limit of 10000 ms"),
            "{}",
            outcome.stderr
        );
        let outcome = assert_refused(exe, &with(&["--rounds", "101"]), "--rounds");
        assert!(
            outcome.stderr.contains("from 1 to 100"),
            "{}",
            outcome.stderr
        );
    }
}

#[test]
fn names_paths_and_choices_are_checked_before_any_timing() {
    let derivatives = Path::new(env!("CARGO_BIN_EXE_derivatives_timing"));
    let kinematics = example("rodyn-bench", "kinematics_timing");
    for exe in [derivatives, kinematics.as_path()] {
        let outcome = assert_refused(exe, &["--only", "hexapod", "aba", "1"], "--only");
        assert!(
            outcome.stderr.contains("unknown model `hexapod`"),
            "{}",
            outcome.stderr
        );
        let outcome = assert_refused(exe, &["--only", "ur5", "nonsense", "1"], "--only");
        assert!(
            outcome.stderr.contains("unknown algorithm `nonsense`"),
            "{}",
            outcome.stderr
        );
        assert_refused(exe, &["--only", "ur5"], "--only");
        assert_refused(exe, &["stray"], "stray");
    }
    // A known model and algorithm run their calls and print nothing.
    let outcome = run(derivatives, &["--only", "ur5", "aba_derivatives", "3"]);
    assert!(
        outcome.status.success() && outcome.stdout.is_empty(),
        "{outcome:?}"
    );

    let profile = Path::new(env!("CARGO_BIN_EXE_profile"));
    assert_refused(profile, &["nonsense", "panda"], "nonsense");
    assert_refused(profile, &["aba", "hexapod"], "unknown model hexapod");
    let outcome = run(profile, &["aba", "panda", "10"]);
    assert!(outcome.status.success(), "{}", outcome.stderr);
    assert!(
        outcome.stdout.contains("over 10 calls"),
        "{}",
        outcome.stdout
    );

    let compare = Path::new(env!("CARGO_BIN_EXE_compare"));
    assert_refused(compare, &[], "--pinocchio");
    assert_refused(compare, &["--pinocchio", "/no/such/program"], "--pinocchio");

    let dir = std::env::temp_dir().join(format!("rodyn-bench-probe-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let plain = dir.join("a-file");
    std::fs::write(&plain, "not a directory").unwrap();
    let unwritable = plain.join("crossover.svg");
    let crossover = Path::new(env!("CARGO_BIN_EXE_crossover"));
    assert_refused(crossover, &["--out", unwritable.to_str().unwrap()], "--out");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `profile aba panda 1 | head -1` and the like: the measuring programs
/// print to a closed pipe without a panic and end with status 0 (short
/// runs of each; `compare` needs Pinocchio's program and `crossover`
/// minutes, and they print through the same macro).
#[test]
fn a_reader_that_stops_early_is_no_panic() {
    let short = ["--ms", "1"];
    assert_calm_when_stdout_closes(
        Path::new(env!("CARGO_BIN_EXE_profile")),
        &["aba", "panda", "1"],
    );
    assert_calm_when_stdout_closes(Path::new(env!("CARGO_BIN_EXE_derivatives_timing")), &short);
    assert_calm_when_stdout_closes(&example("rodyn-bench", "kinematics_timing"), &short);
}
