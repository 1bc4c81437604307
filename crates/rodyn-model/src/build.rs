//! The build-script interface: compile a model file into `$OUT_DIR/<module>.rs`.
//!
//! ```no_run
//! // build.rs of a firmware crate, inside `fn main()`:
//! let _ = rodyn_model::build::compile("../models/panda.toml", "panda");
//! // src/main.rs
//! // include!(concat!(env!("OUT_DIR"), "/panda.rs"));
//! // use panda::{MODEL_F32, body, joint};
//! ```

use crate::diagnostic::{Diagnostic, Location, Result, Severity};
use crate::{codegen, load, LoadOptions};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// Compiles `model_file` into `$OUT_DIR/<module>.rs` and returns that path;
/// on a bad file, prints `file:line:column: error: message` and ends the
/// build script with exit code 1.
#[must_use = "the generated file is usually `include!`d; the path is returned for logging"]
pub fn compile(model_file: impl AsRef<Path>, module: &str) -> PathBuf {
    compile_with(model_file, module, LoadOptions::default())
}

/// [`compile`] with options (e.g. a floating base under a URDF).
#[must_use = "the generated file is usually `include!`d; the path is returned for logging"]
pub fn compile_with(model_file: impl AsRef<Path>, module: &str, options: LoadOptions) -> PathBuf {
    match compile_file_with(model_file.as_ref(), module, options) {
        Ok(path) => path,
        Err(diagnostic) => {
            eprintln!("{diagnostic}");
            println!("cargo:warning={diagnostic}");
            std::process::exit(1);
        }
    }
}

/// Compiles `model_file` into `$OUT_DIR/<module>.rs`, printing
/// `cargo:rerun-if-changed` for every file read and `cargo:warning` for
/// every warning.
///
/// # Errors
/// The first problem in the model file, or a failure to write the output.
pub fn compile_file(model_file: impl AsRef<Path>, module: &str) -> Result<PathBuf> {
    compile_file_with(model_file.as_ref(), module, LoadOptions::default())
}

/// [`compile_file`] with options.
///
/// # Errors
/// As [`compile_file`].
pub fn compile_file_with(model_file: &Path, module: &str, options: LoadOptions) -> Result<PathBuf> {
    let out_dir = std::env::var_os("OUT_DIR")
        .map(PathBuf::from)
        .ok_or_else(|| {
            Diagnostic::error(
                Location::start_of(model_file),
                "OUT_DIR is not set; call rodyn_model::build from a build script",
            )
        })?;
    println!("cargo:rerun-if-changed={}", model_file.display());
    let (source, model) = generate_source(model_file, module, options)?;
    for file in &model.included_files {
        println!("cargo:rerun-if-changed={}", file.display());
    }
    for w in model
        .warnings
        .iter()
        .filter(|d| d.severity == Severity::Warning)
    {
        println!("cargo:warning={w}");
    }
    let out = out_dir.join(format!("{}.rs", crate::names::module_name(module)));
    std::fs::write(&out, source).map_err(|e| {
        Diagnostic::error(
            Location::start_of(model_file),
            format!("cannot write {}: {e}", out.display()),
        )
    })?;
    Ok(out)
}

/// Reads, checks and writes a model as formatted Rust source (formatted by
/// `rustfmt` when it is installed, which the generated text already nearly is).
///
/// # Errors
/// The first problem in the model file.
pub fn generate_source(
    model_file: &Path,
    module: &str,
    options: LoadOptions,
) -> Result<(String, crate::ModelDescription)> {
    let model = load(model_file, options)?;
    let raw = codegen::generate(&model, module, &model_file.display().to_string())?;
    Ok((rustfmt(&raw).unwrap_or(raw), model))
}

/// `text` formatted by rustfmt (`$RUSTFMT` or the one on `PATH`), if it runs.
fn rustfmt(text: &str) -> Option<String> {
    let program = std::env::var_os("RUSTFMT").unwrap_or_else(|| "rustfmt".into());
    let mut child = Command::new(program)
        .args(["--edition", "2021", "--emit", "stdout", "--quiet"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    child.stdin.take()?.write_all(text.as_bytes()).ok()?;
    let output = child.wait_with_output().ok()?;
    if output.status.success() {
        String::from_utf8(output.stdout).ok()
    } else {
        None
    }
}
