//! Puts the machine's memory layout where the linker finds it as
//! `memory.x`, and relinks when it changes.
//!
//! The layouts live in `memory/`, none in the crate's root: cortex-m-rt's
//! `INCLUDE memory.x` would find one there (the linker's working directory)
//! before the copy in `OUT_DIR`. `mps2-an386.x` (Cortex-M4F) is shared by
//! the Cortex-M3 of mps2-an385 and the Cortex-M7 of mps2-an500; the
//! Cortex-M33 of mps2-an505 (thumbv8m.main) has its own, and a slower
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
        "memory/mps2-an386.x"
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
