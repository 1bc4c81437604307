//! A contact's `slip_velocity` reaches the generated `GroundContact`, and a
//! file without it keeps the documented default.

use rodyn_model::codegen::generate;
use rodyn_model::description::Contact;
use rodyn_model::{load, LoadOptions};
use std::path::Path;

const SLIDING_FOOT: &str = r#"
[model]
name = "sliding_foot"

[[body]]
name = "leg"
parent = "world"
joint = "slide"
type = "prismatic"
axis = [0.0, 0.0, 1.0]
mass = 1.0
com = [0.0, 0.0, 0.0]
inertia = [0.01, 0.01, 0.01]

[[endpoint]]
name = "foot"
body = "leg"
position = [0.0, 0.0, -0.1]

[[contact]]
name = "foot_contact"
endpoint = "foot"
stiffness = 5000.0
damping = 50.0
friction = 0.8
slip_velocity = 0.05
"#;

#[test]
fn the_file_slip_velocity_is_emitted_per_contact() {
    let path = std::env::temp_dir().join(format!("rodyn_slip_{}.toml", std::process::id()));
    std::fs::write(&path, SLIDING_FOOT).unwrap();
    let model = load(&path, LoadOptions::default());
    std::fs::remove_file(&path).unwrap();
    let model = model.unwrap();
    assert_eq!(model.contacts[0].slip_velocity, 0.05);
    let rust = generate(&model, "sliding_foot", "sliding_foot.toml").unwrap();
    assert!(
        rust.contains("friction: 0.8, slip_scale: 0.05 }"),
        "generated contact:\n{}",
        rust.lines()
            .filter(|l| l.contains("GroundContact::<"))
            .collect::<String>()
    );
}

#[test]
fn a_contact_without_slip_velocity_gets_the_default() {
    let aibo = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../models/aibo.toml");
    let model = load(&aibo, LoadOptions::default()).unwrap();
    assert_eq!(model.contacts.len(), 4);
    for contact in &model.contacts {
        assert_eq!(contact.slip_velocity, Contact::DEFAULT_SLIP_VELOCITY);
    }
    assert_eq!(Contact::DEFAULT_SLIP_VELOCITY, 0.2);
}
