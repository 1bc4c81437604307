//! What cannot harm the dynamics loads with a warning at its place, and is
//! an error in strict mode (`LoadOptions::strict`); what would break the
//! dynamics stays an error (`tests/bad/`).

use rodyn_model::{load, LoadOptions, Severity};
use std::path::{Path, PathBuf};

fn write(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rodyn-model-lenient-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

const STRICT: LoadOptions = LoadOptions::new().with_strict(true);

/// A link `name` with `mass` and the tensor entries `(ixx, iyy, izz, ixy)`.
fn link(name: &str, mass: f64, i: [f64; 4]) -> String {
    format!(
        "<link name=\"{name}\"><inertial><mass value=\"{mass}\"/><inertia ixx=\"{}\" iyy=\"{}\" izz=\"{}\" ixy=\"{}\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n",
        i[0], i[1], i[2], i[3]
    )
}

fn robot(name: Option<&str>, body: &str) -> String {
    let name = name.map_or(String::new(), |n| format!(" name=\"{n}\""));
    format!("<robot{name}>\n<link name=\"base\"/>\n{body}</robot>\n")
}

fn joint(name: &str, kind: &str, parent: &str, child: &str) -> String {
    format!("<joint name=\"{name}\" type=\"{kind}\"><parent link=\"{parent}\"/><child link=\"{child}\"/><axis xyz=\"0 0 1\"/></joint>\n")
}

fn assert_lenient(path: &Path, warning: &str) {
    let model = load(path, LoadOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        model
            .warnings
            .iter()
            .any(|w| w.severity == Severity::Warning && w.message.contains(warning)),
        "no warning `{warning}` in {:?}",
        model
            .warnings
            .iter()
            .map(|w| &w.message)
            .collect::<Vec<_>>()
    );
    let error = load(path, STRICT).unwrap_err();
    assert!(
        error.message.contains(warning) && error.message.ends_with("(strict mode)"),
        "{error}"
    );
}

#[test]
fn a_triangle_violation_is_a_warning() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/lenient/inertia_triangle.urdf");
    assert_lenient(&path, "break the triangle inequality");
    let model = load(&path, LoadOptions::default()).unwrap();
    let at = model
        .warnings
        .iter()
        .find(|w| w.message.starts_with("link `a`"))
        .unwrap();
    assert_eq!((at.location.line, at.location.column), (4, 45));
}

#[test]
fn rounding_noise_in_a_tensor_is_accepted_silently() {
    // Go1's base: principal moments -1.2e-22, 0, 3e-6 from a rotated disk.
    let text = robot(
        Some("noise"),
        &(link("a", 1.0, [0.1, 0.1, 0.1 + 1e-9, -1e-22]) + &joint("j", "continuous", "base", "a")),
    );
    let model = load(&write("noise.urdf", &text), STRICT).unwrap();
    assert_eq!(model.bodies.len(), 1);
}

#[test]
fn a_placeholder_tensor_merged_into_a_heavier_body_is_a_warning() {
    // TIAGo's antenna: a link whose own tensor is not positive
    // semi-definite, fixed to a heavy body that makes the sum physical.
    let text = robot(
        Some("merged"),
        &(link("a", 5.0, [0.5, 0.5, 0.5, 0.0])
            + &link("antenna", 0.01, [3.5e-8, 3.5e-8, 9.1e-8, 6e-8])
            + &joint("j", "continuous", "base", "a")
            + &joint("fix", "fixed", "a", "antenna")),
    );
    assert_lenient(&write("merged.urdf", &text), "not positive semi-definite");
}

#[test]
fn a_massless_link_with_a_tensor_is_a_warning_and_keeps_the_tensor() {
    // Bolt's FL_FOOT.
    let text = robot(
        Some("foot"),
        &(link("a", 1.0, [0.1, 0.1, 0.1, 0.0])
            + &link("foot", 0.0, [1e-5, 1e-5, 1e-5, 0.0])
            + &joint("j", "continuous", "base", "a")
            + &joint("k", "continuous", "a", "foot")),
    );
    let path = write("foot.urdf", &text);
    assert_lenient(&path, "has mass 0 but a non-zero inertia tensor");
    let model = load(&path, LoadOptions::default()).unwrap();
    assert_eq!(model.bodies[1].inertia.inertia[2][2], 1e-5);
}

#[test]
fn a_robot_without_a_name_takes_the_file_name() {
    let text = robot(
        None,
        &(link("a", 1.0, [0.1, 0.1, 0.1, 0.0]) + &joint("j", "continuous", "base", "a")),
    );
    let path = write("anonymous_arm.urdf", &text);
    assert_lenient(&path, "no `name` attribute");
    assert_eq!(
        load(&path, LoadOptions::default()).unwrap().name,
        "anonymous_arm"
    );
}

#[test]
fn a_merged_body_that_is_not_positive_semi_definite_is_an_error() {
    let text = robot(
        Some("bad"),
        &(link("a", 1.0, [1.0, 1.0, 3.0, 2.0]) + &joint("j", "continuous", "base", "a")),
    );
    let error = load(&write("bad.urdf", &text), LoadOptions::default()).unwrap_err();
    assert_eq!(error.severity, Severity::Error);
    assert!(
        error.message.contains("body `a`") && error.message.contains("not positive semi-definite"),
        "{error}"
    );
}
