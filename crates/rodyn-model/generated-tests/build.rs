//! Compiles every shipped model into `$OUT_DIR/models.rs` exactly as a
//! firmware build script would, so the tests exercise the generated code.

use rodyn_model::{build::compile_with, LoadOptions};
use std::fmt::Write;
use std::path::Path;

/// `(file under models/, module name, floating base)`: the URDFs with the
/// root joints of the Pinocchio fixtures in `host-tests/fixtures/`, then
/// every rodyn model file shipped in `models/`.
const MODELS: &[(&str, &str, bool)] = &[
    ("urdf/panda.urdf", "panda", false),
    ("urdf/ur5.urdf", "ur5", false),
    ("urdf/solo12.urdf", "solo12", true),
    ("urdf/branched_tree.urdf", "branched_tree", false),
    ("urdf/planar_chain_5.urdf", "planar_chain_5", false),
    ("urdf/spatial_chain_12.urdf", "spatial_chain_12", false),
    ("pendulum.toml", "pendulum", false),
    ("two_link_muscles.toml", "two_link_muscles", false),
    ("gait_planar.toml", "gait_planar", false),
    ("aibo.toml", "aibo", false),
    ("panda.toml", "panda_with_motors", false),
    ("solo12.toml", "solo12_with_contacts", false),
];

fn main() {
    let models = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../models");
    let mut all = String::new();
    for (file, module, floating_base) in MODELS {
        let options = LoadOptions::new().with_floating_base(*floating_base);
        let out = compile_with(models.join(file), module, options);
        writeln!(all, "include!({:?});", out.display().to_string()).unwrap();
    }
    // Odd but valid names: the generated module must compile.
    let odd = Path::new(env!("CARGO_MANIFEST_DIR")).join("odd/odd_names.toml");
    let out = compile_with(odd, "odd_names", LoadOptions::default());
    writeln!(all, "include!({:?});", out.display().to_string()).unwrap();
    // Continuous joints on a free-flyer, against Pinocchio's layout.
    let urdf = Path::new(env!("CARGO_MANIFEST_DIR")).join("urdf/wheeled_arm.urdf");
    let options = LoadOptions::floating_base();
    let out = compile_with(urdf, "wheeled_arm", options);
    writeln!(all, "include!({:?});", out.display().to_string()).unwrap();
    // Mimic joints, against Pinocchio's mimic=True model.
    let urdf = Path::new(env!("CARGO_MANIFEST_DIR")).join("urdf/gripper.urdf");
    let out = compile_with(urdf, "gripper", LoadOptions::default());
    writeln!(all, "include!({:?});", out.display().to_string()).unwrap();
    // Frames named in a rodyn file on top of the URDF's.
    let toml = Path::new(env!("CARGO_MANIFEST_DIR")).join("urdf/wheeled_arm_tool.toml");
    let out = compile_with(toml, "wheeled_arm_tool", LoadOptions::default());
    writeln!(all, "include!({:?});", out.display().to_string()).unwrap();
    // Link names that become the same constant: the frames stay distinct.
    let odd = Path::new(env!("CARGO_MANIFEST_DIR")).join("odd/frame_names.urdf");
    let out = compile_with(odd, "frame_names", LoadOptions::default());
    writeln!(all, "include!({:?});", out.display().to_string()).unwrap();
    let out_dir = std::env::var("OUT_DIR").unwrap();
    std::fs::write(Path::new(&out_dir).join("models.rs"), all).unwrap();
}
