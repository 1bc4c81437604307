//! The measured gait example (`models/gait_subject01.toml`, OpenSim's
//! subject01 walk in `data/gait/`): rodyn's inverse dynamics
//! against Pinocchio 4.1 on the same model and inputs, a statics check by
//! hand, f32 against f64, and bad input files.

use rodyn::Data;
use rodyn_host_tests::subject_gait::{
    data_dir, model_torques, opensim_loads, read_inputs, Reaction, Sample, GRAVITY, MODEL,
};
use serde::Deserialize;
use std::path::{Path, PathBuf};

#[derive(Deserialize)]
struct Fixture {
    frames: Vec<FixtureFrame>,
}

#[derive(Deserialize)]
struct FixtureFrame {
    row: usize,
    time: f64,
    tau: Vec<f64>,
}

fn samples() -> Vec<Sample> {
    read_inputs(&data_dir().join("inverse_dynamics_inputs_60hz.csv")).unwrap()
}

/// Pinocchio's RNEA on its own build of the model from `segments.csv`
/// (`tools/pinocchio/make_gait_fixtures.py`, every 5th frame) against
/// rodyn's, in the model's coordinates: 1e-9 relative.
#[test]
fn inverse_dynamics_matches_pinocchio() {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/gait/subject01_rnea.json"),
    )
    .unwrap();
    let fixture: Fixture = serde_json::from_str(&text).unwrap();
    assert_eq!(fixture.frames.len(), 31);
    let samples = samples();
    let (model, _) = MODEL;
    let mut data = Data::new();
    let mut worst = 0.0_f64;
    for frame in &fixture.frames {
        let sample = &samples[frame.row];
        assert!((sample.time - frame.time).abs() < 1e-6);
        let tau = model_torques(&model, &mut data, sample).unwrap();
        for (a, b) in tau.iter().zip(&frame.tau) {
            let error = (a - b).abs() / b.abs().max(1.0);
            worst = worst.max(error);
        }
    }
    eprintln!("rodyn against Pinocchio: largest relative difference {worst:.1e}");
    assert!(worst < 1e-9, "largest relative difference {worst:e}");
}

/// The subject held still in frame 75's pose with no ground contact: the
/// pelvis must carry the whole weight, and each joint the moment of the
/// weight below it about its centre, computed here by hand from the
/// segment table (planar kinematics written out, not rodyn's).
#[test]
fn statics_by_hand() {
    let samples = samples();
    let still = Sample {
        qd: [0.0; 10],
        qdd: [0.0; 10],
        right: Reaction::default(),
        left: Reaction::default(),
        ..samples[75]
    };
    let (model, _) = MODEL;
    let mut data = Data::new();
    let tau = model_torques(&model, &mut data, &still).unwrap();
    let loads = opensim_loads(&tau, still.q[0]);

    // Segment table (segments.csv): mass, centre of mass in the body frame,
    // and each joint's position in its parent's frame.
    let rot = |a: f64, p: [f64; 2]| {
        [
            a.cos() * p[0] - a.sin() * p[1],
            a.sin() * p[0] + a.cos() * p[1],
        ]
    };
    let add = |a: [f64; 2], b: [f64; 2]| [a[0] + b[0], a[1] + b[1]];
    let q = &still.q;
    let (tilt, pelvis) = (q[0], [q[1], q[2]]);
    let pelvis_mass = (11.37517129, [-0.0724378, 0.0]);
    let torso = (33.06845457, [-0.0323916, 0.34551]);
    let (femur, tibia, foot) = (
        (8.984038231, [0.0, -0.195031]),
        (3.581000897, [0.0, -0.184557]),
        (1.513147945, [0.06139445507, -0.01859508221]),
    );
    let hip_offset = [-0.0724378, -0.0677247];
    let knee_offset = [-0.005162415391, -0.4541013358];
    let ankle_offset = [0.0, -0.425065];
    let lumbar = add(pelvis, rot(tilt, [-0.103175, 0.0835033]));
    let mut bodies = vec![
        (pelvis_mass.0, add(pelvis, rot(tilt, pelvis_mass.1))),
        (torso.0, add(lumbar, rot(tilt + q[9], torso.1))),
    ];
    let mut leg = |hip_angle: f64, knee_angle: f64, ankle_angle: f64| {
        let hip = add(pelvis, rot(tilt, hip_offset));
        let (a_femur, a_tibia) = (tilt + hip_angle, tilt + hip_angle + knee_angle);
        let knee = add(hip, rot(a_femur, knee_offset));
        let ankle = add(knee, rot(a_tibia, ankle_offset));
        let parts = [
            (femur.0, add(hip, rot(a_femur, femur.1))),
            (tibia.0, add(knee, rot(a_tibia, tibia.1))),
            (foot.0, add(ankle, rot(a_tibia + ankle_angle, foot.1))),
        ];
        bodies.extend(parts);
        (hip, parts)
    };
    let (hip_r, right) = leg(q[3], q[4], q[5]);
    let (_, _left) = leg(q[6], q[7], q[8]);
    let total: f64 = bodies.iter().map(|b| b.0).sum();
    // Moment of the weights about a point, turning counter-clockwise.
    let weight_moment = |parts: &[(f64, [f64; 2])], about: [f64; 2]| -> f64 {
        parts
            .iter()
            .map(|(m, c)| -(c[0] - about[0]) * m * GRAVITY)
            .sum()
    };
    let expect = [
        (loads[2], total * GRAVITY, "pelvis ty"),
        (loads[1], 0.0, "pelvis tx"),
        (loads[0], -weight_moment(&bodies, pelvis), "pelvis tilt"),
        (loads[3], -weight_moment(&right, hip_r), "right hip"),
    ];
    for (got, want, what) in expect {
        assert!(
            (got - want).abs() <= 1e-9 * want.abs().max(1.0),
            "{what}: {got} against {want}"
        );
    }
    assert!((total - 72.6).abs() < 1e-6, "segment masses sum to {total}");
}

/// f32 inverse dynamics stays within 1e-3 N (N m) of f64 on every frame
/// (measured: 2.4e-4).
#[test]
fn f32_against_f64() {
    let (model, model32) = MODEL;
    let (mut data, mut data32) = (Data::new(), Data::new());
    let mut worst = 0.0_f64;
    for s in &samples() {
        let tau = model_torques(&model, &mut data, s).unwrap();
        let tau32 = model_torques(&model32, &mut data32, s).unwrap();
        for (a, b) in tau.iter().zip(&tau32) {
            worst = worst.max((a - f64::from(*b)).abs());
        }
    }
    assert!(worst < 1e-3, "{worst}");
}

/// A copy of the input file with `edit` applied to its text.
fn edited(name: &str, edit: impl Fn(String) -> String) -> PathBuf {
    let text =
        std::fs::read_to_string(data_dir().join("inverse_dynamics_inputs_60hz.csv")).unwrap();
    let dir = std::env::temp_dir().join(format!("rodyn-gait-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, edit(text)).unwrap();
    path
}

/// Replaces field `column` of data line `line` (1-based file line).
fn replace_field(text: &str, line: usize, column: &str, value: &str) -> String {
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let k = header.iter().position(|h| *h == column).unwrap();
    text.lines()
        .enumerate()
        .map(|(n, l)| {
            if n + 1 == line {
                let mut fields: Vec<&str> = l.split(',').collect();
                fields[k] = value;
                fields.join(",")
            } else {
                l.to_owned()
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn bad_input_names_file_line_and_column() {
    let cases = [
        (
            "malformed.csv",
            replace_field_owned(7, "q_knee_angle_r_rad", "1.2.3"),
            "`1.2.3` is not a number",
            Some("q_knee_angle_r_rad"),
        ),
        (
            "nan.csv",
            replace_field_owned(9, "qdd_hip_flexion_l_rad_per_s2", "NaN"),
            "not a finite number",
            Some("qdd_hip_flexion_l_rad_per_s2"),
        ),
        (
            "no_cop.csv",
            replace_field_owned(3, "r_CoPx_m", ""),
            "needs a centre of pressure",
            Some("r_CoPx_m"),
        ),
    ];
    for (name, edit, message, column) in cases {
        let path = edited(name, edit);
        let error = read_inputs(&path).unwrap_err();
        let text = error.to_string();
        assert!(text.contains(message), "{name}: {text}");
        assert_eq!(error.column.as_deref(), column, "{name}: {text}");
        assert!(text.starts_with(&format!("{}:", path.display())), "{text}");
        assert!(error.line > 1, "{name}: {text}");
    }
    // The line number is the file's.
    let path = edited(
        "line.csv",
        replace_field_owned(7, "q_knee_angle_r_rad", "x"),
    );
    assert_eq!(read_inputs(&path).unwrap_err().line, 7);

    let short = edited("short.csv", |t| {
        let mut lines: Vec<String> = t.lines().map(str::to_owned).collect();
        lines[4] = lines[4].split(',').take(5).collect::<Vec<_>>().join(",");
        lines.join("\n")
    });
    let error = read_inputs(&short).unwrap_err();
    assert_eq!(error.line, 5, "{error}");

    let missing = edited("missing.csv", |t| t.replacen("r_Tz_Nm", "r_Tz", 1));
    let error = read_inputs(&missing).unwrap_err();
    assert_eq!(error.column.as_deref(), Some("r_Tz_Nm"), "{error}");
    assert!(error.to_string().contains("missing column"), "{error}");
}

fn replace_field_owned(
    line: usize,
    column: &'static str,
    value: &'static str,
) -> impl Fn(String) -> String {
    move |t| replace_field(&t, line, column, value)
}
