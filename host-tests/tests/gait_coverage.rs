//! A gait data file that reads cleanly but is too short for the analysis
//! (one row, ten rows, or rows that stop before the gait cycle ends) is
//! refused with the file's name and what is missing, instead of giving an
//! index out of range or NaN averages. The files are written here, so the
//! test needs no measured data.

mod gait_inputs;

use gait_inputs::{frames, write_inputs};
use rodyn_host_tests::subject_gait::{check_coverage, read_inputs};
use std::path::PathBuf;

/// A file of rows at `times` in this test's scratch directory.
fn write_file(name: &str, times: &[f64]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rodyn-gait-coverage-{}", std::process::id()));
    write_inputs(&dir.join(name), times)
}

const CYCLE: (f64, f64) = (0.618, 1.852);
const WHY: &str = "edge frames at each end and one between";

#[test]
fn too_few_rows_are_refused_with_the_file_and_the_count() {
    for (name, rows) in [("one_row.csv", 1), ("ten_rows.csv", 10)] {
        let times: Vec<f64> = (0..rows).map(|k| 0.6 + k as f64 / 60.0).collect();
        let path = write_file(name, &times);
        let samples = read_inputs(&path).unwrap();
        assert_eq!(samples.len(), rows);
        let error = check_coverage(&path, &samples, 11, WHY, CYCLE).unwrap_err();
        let text = error.to_string();
        assert!(text.starts_with(&path.display().to_string()), "{text}");
        assert!(
            text.contains(&format!("{rows} data rows, too few: at least 11")) && text.contains(WHY),
            "{text}"
        );
    }
}

#[test]
fn rows_that_miss_the_cycle_are_refused_with_the_times_they_cover() {
    for (name, start, end) in [("late.csv", 0.7, 2.0), ("early_end.csv", 0.0, 1.5)] {
        let path = write_file(name, &frames(start, end));
        let samples = read_inputs(&path).unwrap();
        let error = check_coverage(&path, &samples, 11, WHY, CYCLE).unwrap_err();
        let text = error.to_string();
        assert!(text.contains(&path.display().to_string()), "{text}");
        assert!(
            text.contains(&format!("the rows cover {start:.3}-{end:.3} s"))
                && text.contains("0.618-1.852 s is needed"),
            "{text}"
        );
    }
}

#[test]
fn an_empty_file_is_refused_and_enough_rows_pass() {
    let empty = write_file("header_only.csv", &[]);
    let error = read_inputs(&empty).unwrap_err();
    assert!(error.to_string().contains("no data rows"), "{error}");

    // The measured file's span (0 to 2.5 s at 60 Hz) and the bare minimum
    // around the cycle both pass.
    for (name, start, end) in [("full.csv", 0.0, 2.5), ("cycle.csv", 0.6, 1.86)] {
        let path = write_file(name, &frames(start, end));
        let samples = read_inputs(&path).unwrap();
        check_coverage(&path, &samples, 11, WHY, CYCLE).unwrap();
    }
}
