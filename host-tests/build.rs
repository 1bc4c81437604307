//! Compiles the planar gait model into `$OUT_DIR/gait_planar.rs` and the
//! measured subject's into `$OUT_DIR/gait_subject01.rs`, the way a
//! firmware build script would, for the gait examples and tests; and the
//! models the docs' snippets include (`src/doc_snippets.rs`).

fn main() {
    let models = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../models");
    let _ = rodyn_model::build::compile(models.join("gait_planar.toml"), "gait_planar");
    let _ = rodyn_model::build::compile(models.join("gait_subject01.toml"), "gait_subject01");
    for model in ["pendulum", "panda", "two_link_muscles", "aibo", "solo12"] {
        let _ = rodyn_model::build::compile(models.join(format!("{model}.toml")), model);
    }
    // Continuous joints on a free flyer, for the configuration conversion.
    let wheeled_arm = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../crates/rodyn-model/generated-tests/urdf/wheeled_arm.urdf");
    let options = rodyn_model::LoadOptions::floating_base();
    let _ = rodyn_model::build::compile_with(wheeled_arm, "wheeled_arm", options);
}
