//! Gait input files written by the tests themselves: the columns of
//! `inverse_dynamics_inputs_60hz.csv` with chosen times and zeros.

use rodyn_host_tests::subject_gait::COORDINATES;
use std::path::{Path, PathBuf};

/// The header of `inverse_dynamics_inputs_60hz.csv`.
fn header() -> Vec<String> {
    let translation = |c: &str| c.ends_with("_tx") || c.ends_with("_ty");
    let mut columns = vec!["time_s".to_owned()];
    for (prefix, linear, angular) in [
        ("q", "m", "rad"),
        ("qd", "m_per_s", "rad_per_s"),
        ("qdd", "m_per_s2", "rad_per_s2"),
    ] {
        for c in COORDINATES {
            let unit = if translation(c) { linear } else { angular };
            columns.push(format!("{prefix}_{c}_{unit}"));
        }
    }
    for side in ["r", "l"] {
        for name in ["Fx_N", "Fy_N", "CoPx_m", "CoPy_m", "Tz_Nm"] {
            columns.push(format!("{side}_{name}"));
        }
    }
    columns
}

/// Writes `path` (and its directory) with one row at each of `times`,
/// every other field zero: a file `read_inputs` accepts.
pub fn write_inputs(path: &Path, times: &[f64]) -> PathBuf {
    let header = header();
    let mut text = header.join(",");
    for t in times {
        text.push('\n');
        text.push_str(&format!("{t:.8}"));
        text.push_str(&",0".repeat(header.len() - 1));
    }
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(path, text).unwrap();
    path.to_path_buf()
}

/// 60 Hz frames from `start` to `end` s.
pub fn frames(start: f64, end: f64) -> Vec<f64> {
    let n = ((end - start) * 60.0).round() as usize;
    (0..=n).map(|k| start + k as f64 / 60.0).collect()
}
