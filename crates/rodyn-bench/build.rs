//! Compiles the benchmark robots from `models/urdf/` with rodyn's model
//! compiler: the same files Pinocchio reads in the comparison.

use rodyn_model::build::compile_with;
use rodyn_model::LoadOptions;
use std::path::Path;

/// `(file under models/urdf/, module name, floating base)`.
const MODELS: &[(&str, &str, bool)] = &[
    ("panda.urdf", "panda", false),
    ("ur5.urdf", "ur5", false),
    ("solo12.urdf", "solo12", true),
];

fn main() {
    let urdf = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../models/urdf");
    for (file, module, floating_base) in MODELS {
        // Included by src/models/urdf_models.rs through OUT_DIR.
        let _ = compile_with(
            urdf.join(file),
            module,
            // The timed models take the UR5's quarter turns, written to 12
            // digits, as exact (an explicit opt-in since the model compiler
            // keeps files' rotations by default): the comparison's figures
            // were measured so, and the torques still agree with
            // Pinocchio's to 1e-9 (compare.sh checks).
            LoadOptions::new()
                .with_floating_base(*floating_base)
                .with_round_quarter_turns(true),
        );
    }
    println!("cargo:rerun-if-changed=build.rs");
}
