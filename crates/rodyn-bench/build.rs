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
        // The model compiler's default options, as a user gets them: the
        // published comparison is measured on what a user runs.
        let _ = compile_with(
            urdf.join(file),
            module,
            LoadOptions::new().with_floating_base(*floating_base),
        );
    }
    println!("cargo:rerun-if-changed=build.rs");
}
