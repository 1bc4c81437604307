//! Compiles the robot's model file into Rust constants and hands `memory.x`
//! to the linker.

use std::{env, fs, path::PathBuf};

fn main() {
    // `$OUT_DIR/arm.rs`: the model as `const` values, `include!`d by
    // src/main.rs. A mistake in the file stops the build with its
    // `file:line:column`.
    let _ = rodyn_model::build::compile("models/arm.toml", "arm");

    // cortex-m-rt's link.x includes memory.x from the linker's search path.
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    fs::copy("memory.x", out.join("memory.x")).expect("copy memory.x to OUT_DIR");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=build.rs");
}
