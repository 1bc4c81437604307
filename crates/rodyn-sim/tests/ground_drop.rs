//! `rodyn-sim run --model FILE --floating-base --ground`: the Solo-12 URDF,
//! unpowered, dropped from 5 cm onto the compliant ground under every one
//! of its frames, must come to rest on it: still, its weight carried by
//! the ground's springs, and no point sunk further than the whole weight on
//! one spring would sink it.

use rodyn_model::runtime::RuntimeModel;
use std::path::Path;
use std::process::Command;

/// The default ground sinks an even share of the weight by 1 mm
/// (`ground.rs`'s `DEFAULT_SINK`): `k = M g / (n · 1 mm)`.
const DEFAULT_SINK: f64 = 1e-3;

/// The last and first samples of the run's CSV, as numbers.
fn samples(csv: &str) -> (Vec<f64>, Vec<f64>) {
    let parse = |line: &str| -> Vec<f64> { line.split(',').map(|x| x.parse().unwrap()).collect() };
    let mut lines = csv.lines().skip(1);
    let first = parse(lines.next().unwrap());
    let last = parse(lines.last().unwrap());
    (first, last)
}

#[test]
fn solo12_dropped_on_the_ground_comes_to_rest_on_it() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let urdf = root.join("models/urdf/solo12.urdf");
    let out = std::env::temp_dir().join(format!("rodyn-sim-ground-{}", std::process::id()));
    let output = Command::new(env!("CARGO_BIN_EXE_rodyn-sim"))
        .args(["run", "--model"])
        .arg(&urdf)
        .args(["--floating-base", "--ground", "--duration", "2", "-o"])
        .arg(&out)
        .output()
        .expect("rodyn-sim runs");
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let csv = std::fs::read_to_string(out.join("solo.csv")).unwrap();
    let _ = std::fs::remove_dir_all(&out);

    let model = RuntimeModel::from_urdf(&urdf, true).unwrap();
    let (nq, nv) = (model.nq(), model.nv());
    let (first, last) = samples(&csv);
    assert_eq!(last.len(), 1 + nq + nv, "t, q, v");
    assert!(
        (last[0] - 2.0).abs() < 1e-9,
        "the run reached 2 s: {}",
        last[0]
    );
    // The CSV's ten digits leave the quaternion off unit length by 1e-11:
    // normalised before the model reads it.
    let heights = |q: &[f64]| -> Vec<f64> {
        let mut q = q.to_vec();
        let norm = q[3..7].iter().map(|x| x * x).sum::<f64>().sqrt();
        q[3..7].iter_mut().for_each(|x| *x /= norm);
        let mut ws = model.workspace();
        let mut placement = [0.0; 16];
        model
            .frame_names()
            .iter()
            .map(|f| {
                model
                    .frame_placement(&mut ws, &q, f, &mut placement)
                    .unwrap();
                placement[11]
            })
            .collect()
    };

    // The drop starts with the lowest point 5 cm up (the CSV's ten digits).
    let start = heights(&first[1..=nq]);
    let lowest = start.iter().copied().fold(f64::INFINITY, f64::min);
    assert!((lowest - 0.05).abs() < 1e-9, "lowest point at {lowest} m");

    // At rest: every velocity below 1 µm/s (or µrad/s).
    let speed = last[1 + nq..].iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    assert!(speed < 1e-6, "still moving at {speed:e}");

    // The ground's springs carry the weight: Σ k·depth = M g to 1e-6
    // (damping and friction vanish at rest).
    let g = model.gravity_vector();
    let g = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
    let weight = model.description().total_mass() * g;
    let points = model.frame_names().len();
    let stiffness = weight / (points as f64 * DEFAULT_SINK);
    let rest = heights(&last[1..=nq]);
    let carried: f64 = rest.iter().map(|z| stiffness * (-z).max(0.0)).sum();
    assert!(
        (carried - weight).abs() <= 1e-6 * weight,
        "the ground carries {carried} N of {weight} N"
    );
    // No point sinks further than the whole weight on its spring alone,
    // and the base's origin (one of the points) rests within that reach.
    let deepest = rest.iter().copied().fold(f64::INFINITY, f64::min);
    assert!(
        deepest >= -weight / stiffness,
        "a point sank to {deepest} m"
    );
    let base = last[3];
    assert!(
        (-weight / stiffness..=0.0).contains(&base),
        "base at z = {base} m"
    );
}
