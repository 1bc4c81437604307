//! What the model compiler says about files that load but would not run
//! as meant: a mass matrix singular at the neutral configuration (a
//! warning naming the joint), and `rodyn-model check` running the same
//! validation as code generation.

use rodyn_model::{load, LoadOptions, Severity};
use std::path::{Path, PathBuf};
use std::process::Command;

fn write(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rodyn-model-warnings-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// Two joints about the same axis through the same point with only a
/// point mass on that axis between them: the second moves nothing the first does not, so the
/// mass matrix at q = 0 is singular, though every joint moves mass.
const COAXIAL: &str = r#"
[model]
name = "coaxial"
gravity = [0.0, 0.0, -9.81]

[[body]]
name = "hub"
parent = "world"
joint = "outer"
type = "revolute"
axis = [0.0, 0.0, 1.0]
mass = 0.1
com = [0.0, 0.0, 0.0]
inertia = [0.0, 0.0, 0.0]

[[body]]
name = "arm"
parent = "hub"
joint = "inner"
type = "revolute"
axis = [0.0, 0.0, 1.0]
mass = 1.0
com = [0.5, 0.0, 0.0]
inertia = [0.01, 0.01, 0.01]
"#;

#[test]
fn a_mass_matrix_singular_at_q_zero_is_a_warning_naming_the_joint() {
    let model = load(&write("coaxial.toml", COAXIAL), LoadOptions::default()).unwrap();
    let singular: Vec<_> = model
        .warnings
        .iter()
        .filter(|w| w.message.contains("singular at the neutral configuration"))
        .collect();
    assert_eq!(singular.len(), 1, "{:?}", model.warnings);
    assert_eq!(singular[0].severity, Severity::Warning);
    assert!(
        singular[0].message.contains("joint `inner`"),
        "{}",
        singular[0]
    );
    // The same file with inertia on the hub: no warning.
    let fine = COAXIAL.replacen(
        "inertia = [0.0, 0.0, 0.0]",
        "inertia = [0.01, 0.01, 0.01]",
        1,
    );
    let model = load(&write("coaxial_hub.toml", &fine), LoadOptions::default()).unwrap();
    assert!(
        model
            .warnings
            .iter()
            .all(|w| !w.message.contains("singular")),
        "{:?}",
        model.warnings
    );
}

#[test]
fn the_shipped_models_are_not_singular_at_q_zero() {
    let models = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../models");
    for name in ["panda.toml", "solo12.toml", "aibo.toml", "pendulum.toml"] {
        let model = load(&models.join(name), LoadOptions::default()).unwrap();
        assert!(
            model
                .warnings
                .iter()
                .all(|w| !w.message.contains("singular")),
            "{name}: {:?}",
            model.warnings
        );
    }
}

/// Two joints whose names become the same Rust constant: code generation
/// refuses the file, and so must `check`.
#[test]
fn check_refuses_what_code_generation_refuses() {
    let clash = COAXIAL
        .replacen(
            "inertia = [0.0, 0.0, 0.0]",
            "inertia = [0.01, 0.01, 0.01]",
            1,
        )
        .replacen("joint = \"outer\"", "joint = \"el-bow\"", 1)
        .replacen("joint = \"inner\"", "joint = \"el_bow\"", 1);
    let path = write("clash.toml", &clash);
    if let Err(e) = load(&path, LoadOptions::default()) {
        panic!("{e}");
    }
    let bin = env!("CARGO_BIN_EXE_rodyn-model");
    let rust = Command::new(bin).arg("rust").arg(&path).output().unwrap();
    assert!(!rust.status.success());
    let check = Command::new(bin).arg("check").arg(&path).output().unwrap();
    let stderr = String::from_utf8_lossy(&check.stderr);
    assert!(!check.status.success(), "check passed: {stderr}");
    assert!(!String::from_utf8_lossy(&check.stdout).contains(": ok"));
    assert!(
        stderr.contains("el_bow") || stderr.contains("el-bow"),
        "{stderr}"
    );
}

/// A frame of a planar model placed off its plane is left out of the
/// generated frames, with a warning naming it; a frame in the plane is
/// kept without one.
#[test]
fn a_planar_models_frame_off_its_plane_is_named() {
    let text = r#"
[model]
name = "flat"
planar = true
gravity = [0.0, -9.81]

[[body]]
name = "link"
parent = "world"
joint = "hinge"
type = "revolute"
axis = [0.0, 0.0, 1.0]
mass = 1.0
com = [0.0, -0.5]
inertia = [0.1, 0.1, 0.1]

[[frame]]
name = "tip"
body = "link"
position = [0.0, -1.0]

[[frame]]
name = "marker"
body = "link"
position = [0.0, -1.0, 0.05]
"#;
    let model = load(&write("flat.toml", text), LoadOptions::default()).unwrap();
    let off: Vec<_> = model
        .warnings
        .iter()
        .filter(|w| w.message.contains("leaves the x-y plane"))
        .collect();
    assert_eq!(off.len(), 1, "{:?}", model.warnings);
    assert!(off[0].message.contains("frame `marker`"), "{}", off[0]);
}
