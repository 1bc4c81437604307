//! The generated modules carry the file's names at run time, and print an
//! algorithm's error with them.

use rodyn::algorithm::rnea::rnea;
use rodyn::Data;
use rodyn_model_generated_tests::{odd_names, solo12, two_link_muscles};

#[test]
fn names_are_the_files() {
    assert_eq!(two_link_muscles::BODY_NAMES, ["upper_link", "lower_link"]);
    assert_eq!(two_link_muscles::JOINT_NAMES, ["shoulder", "elbow"]);
    assert_eq!(two_link_muscles::V_NAMES, ["shoulder", "elbow"]);
    assert_eq!(two_link_muscles::ENDPOINT_NAMES[0], "hand");
    // A free-flyer's coordinates are named after its joint.
    assert_eq!(solo12::Q_NAMES.len(), solo12::NQ);
    assert!(solo12::Q_NAMES[..7]
        .iter()
        .zip(["x", "y", "z", "qx", "qy", "qz", "qw"])
        .all(|(n, s)| n.ends_with(&format!(":{s}"))));
    assert!(solo12::V_NAMES[3].ends_with(":wx"));
    // Names Rust cannot take as identifiers are kept as written, control
    // characters included.
    assert_eq!(odd_names::BODY_NAMES, ["é", "腕", "è"]);
    assert_eq!(odd_names::JOINT_NAMES, ["type", "1st", "self"]);
    assert_eq!(odd_names::ENDPOINT_NAMES, ["", "model_f64"]);
}

#[test]
fn errors_print_with_names() {
    let mut data = Data::new();
    let error = rnea(
        &two_link_muscles::MODEL_F64,
        &mut data,
        &[0.1, 0.2],
        &[0.0, f64::NAN],
        &[0.0, 0.0],
        None,
    )
    .unwrap_err();
    let text = two_link_muscles::Named(&error).to_string();
    assert!(text.starts_with("coordinate \"elbow\": "), "{text}");
    assert!(text.contains("entry 1"), "{text}");
    // The same subject for logs without core::fmt (defmt).
    assert_eq!(
        two_link_muscles::Named(&error).subject(),
        Some(("coordinate", "elbow"))
    );
    let body = rodyn::Error::BodyOutOfRange { body: 7 };
    assert_eq!(two_link_muscles::Named(&body).to_string(), body.to_string());
    assert_eq!(two_link_muscles::Named(&body).subject(), None);
}
