//! Puts the machine's memory layout where the linker finds it as
//! `memory.x`, and relinks when it changes.
//!
//! `memory.x` is the layout of mps2-an386 (Cortex-M4F), which the Cortex-M3
//! of mps2-an385 and the Cortex-M7 of mps2-an500 share; the Cortex-M33 of
//! mps2-an505 (thumbv8m.main) has its own in `memory/`, and a slower
//! clock, which the cfg `mps2_an505` tells the instruction counter.

use std::{env, fs, path::PathBuf};

/// Whether the target is the Cortex-M33 of mps2-an505 (thumbv8m.main).
fn is_an505(target: &str) -> bool {
    target.starts_with("thumbv8m.main")
}

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let target = env::var("TARGET").expect("cargo sets TARGET");
    let source = if is_an505(&target) {
        "memory/mps2-an505.x"
    } else {
        "memory.x"
    };
    // The machine's clock differs too (`measure::instructions`).
    println!("cargo::rustc-check-cfg=cfg(mps2_an505)");
    if is_an505(&target) {
        println!("cargo::rustc-cfg=mps2_an505");
    }
    fs::copy(source, out.join("memory.x")).expect("copy the memory layout to OUT_DIR");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed={source}");
    println!("cargo:rerun-if-changed=build.rs");
}
