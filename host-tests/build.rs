//! Compiles the seed's planar gait model into `$OUT_DIR/gait_planar.rs`, the
//! way a firmware build script would, for the gait examples and tests.

fn main() {
    let model = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/gait_planar.toml");
    let _ = rodyn_model::build::compile(model, "gait_planar");
}
