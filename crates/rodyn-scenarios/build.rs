//! Compiles the scenes' model files from `models/` into `$OUT_DIR/<module>.rs`
//! with rodyn's model compiler, exactly as a user's firmware would.
//!
//! `models` in this crate is a link to the workspace's `models/` folder, so
//! the files have one home in the repository and still travel inside the
//! published package (`cargo package` follows the link; see `include` in
//! Cargo.toml).

use rodyn_model::build::compile;
use std::path::Path;

/// `(file under models/, module name)`.
const MODELS: &[(&str, &str)] = &[
    ("pendulum.toml", "pendulum"),
    ("panda.toml", "panda"),
    ("aibo.toml", "aibo"),
    ("two_link_muscles.toml", "two_link_muscles"),
    ("gait_planar.toml", "gait_planar"),
];

fn main() {
    let models = Path::new(env!("CARGO_MANIFEST_DIR")).join("models");
    for (file, module) in MODELS {
        // The path is `include!`d by src/lib.rs through OUT_DIR.
        let _ = compile(models.join(file), module);
    }
    println!("cargo:rerun-if-changed=build.rs");
}
