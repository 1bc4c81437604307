//! What a model file can put into the generated Rust: names and paths from
//! the file reach comments only, escaped, and never become code; names
//! that Rust cannot take as they are still give valid, distinct constants.

use rodyn_model::codegen::generate;
use rodyn_model::names::{constant_name, module_name};
use rodyn_model::{load, LoadOptions};
use std::path::PathBuf;

const PAYLOAD: &str = "pub static INJECTED: &str = \"x\"; //";

fn write(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rodyn-model-generated-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

fn xml(text: &str) -> String {
    text.replace('&', "&amp;").replace('"', "&quot;")
}

/// Every line that carries the payload is a comment or holds it inside an
/// escaped string literal (constants made from the name carry it as one
/// identifier, `..._INJECTED___STR_...`).
fn assert_payload_only_in_comments(source: &str) {
    let mut seen = 0;
    for line in source.lines() {
        if line.contains("static INJECTED:") {
            seen += 1;
            // In a comment, or inside a string literal with its quotes
            // escaped (the names at run time): never as code.
            let escaped = line.contains(r#"static INJECTED: &str = \"x\""#);
            assert!(
                line.trim_start().starts_with("//") || escaped,
                "code line carries the name: {line}"
            );
        }
        assert!(
            !line.contains('\r'),
            "a bare CR reached the source: {line:?}"
        );
    }
    assert!(seen > 0, "the name should still be documented");
}

#[test]
fn a_newline_in_a_toml_model_name_stays_in_the_comment() {
    let text = format!(
        "[model]\nname = \"arm\\n{}\\rrest\"\ngravity = [0.0, -9.81, 0.0]\n\n[[body]]\nname = \"link\\u2028{}\"\nparent = \"world\"\njoint = \"hinge\"\ntype = \"revolute\"\naxis = [0.0, 0.0, 1.0]\nmass = 1.0\ncom = [0.0, -0.5, 0.0]\ninertia = [0.1, 0.1, 0.1]\n",
        PAYLOAD.replace('"', "\\\""),
        PAYLOAD.replace('"', "\\\""),
    );
    let path = write("injection.toml", &text);
    let model = load(&path, LoadOptions::default()).unwrap();
    let source = generate(&model, &model.name, "injection.toml").unwrap();
    assert_payload_only_in_comments(&source);
}

#[test]
fn a_newline_entity_in_a_urdf_robot_name_stays_in_the_comment() {
    let text = format!(
        "<robot name=\"arm&#10;{}\">\n  <link name=\"base\"/>\n  <link name=\"arm&#13;{}\">\n    <inertial><mass value=\"1\"/><inertia ixx=\"0.1\" iyy=\"0.1\" izz=\"0.1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>\n  </link>\n  <joint name=\"j\" type=\"continuous\"><parent link=\"base\"/><child link=\"arm&#13;{}\"/><axis xyz=\"0 0 1\"/></joint>\n</robot>\n",
        xml(PAYLOAD),
        xml(PAYLOAD),
        xml(PAYLOAD),
    );
    let path = write("injection.urdf", &text);
    let model = load(&path, LoadOptions::default()).unwrap();
    let source = generate(&model, &model.name, "injection.urdf\nnot code").unwrap();
    assert_payload_only_in_comments(&source);
    assert!(
        source.lines().all(|l| l != "not code"),
        "the source path broke its comment"
    );
}

#[test]
fn names_without_ascii_letters_become_distinct_identifiers() {
    assert_eq!(constant_name("é"), "_U_E9");
    assert_eq!(constant_name("腕"), "_U_8155");
    assert_eq!(constant_name(""), "_EMPTY");
    assert_ne!(constant_name("é"), constant_name("è"));
    assert_eq!(module_name("é"), "_u_e9");
    assert_eq!(constant_name("1st"), "_1ST");
    assert_eq!(module_name("fn"), "fn_");
}
