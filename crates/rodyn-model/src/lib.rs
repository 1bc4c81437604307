//! # rodyn-model
//!
//! Robot descriptions as files, compiled into `const` Rust for
//! [rodyn](https://docs.rs/rodyn): URDF for the skeleton, rodyn's own TOML
//! file for what URDF cannot say (endpoints, springs, dampers and muscles
//! along paths of endpoints, motors, contacts, planar models).
//!
//! From a build script:
//!
//! ```no_run
//! // build.rs
//! let path = rodyn_model::build::compile("models/pendulum.toml", "pendulum");
//! // src/lib.rs: include!(concat!(env!("OUT_DIR"), "/pendulum.rs"));
//! # let _ = path;
//! ```
//!
//! The generated module is `no_std` and names every body, joint,
//! coordinate, endpoint and drive (see [`codegen`]). A broken file fails the
//! build with `file:line:column: error: sentence`.
//!
//! On a host, [`runtime::RuntimeModel`] builds the same model at run time
//! and runs every algorithm of the compiled path on it, slices in and out
//! (for tools, notebooks and bindings that learn their robot when they
//! run; enable the `size-classes` feature for speed); it also serves the
//! `rodyn-model tree`, `rodyn-model render` and `rodyn-model view`
//! commands. [`view`] turns it, with the URDF's [`visual`] geometry, into
//! a self-contained HTML page.
#![warn(missing_docs)]

pub mod build;
pub mod codegen;
pub mod description;
pub mod diagnostic;
pub mod geometry;
pub mod joint_limits;
pub mod names;
pub mod neutral;
mod options;
pub mod physics;
pub mod render;
pub mod rodyn_file;
pub mod runtime;
pub mod tree;
pub mod urdf;
pub mod view;
pub mod visual;

pub use description::ModelDescription;
pub use diagnostic::{Diagnostic, Location, Severity, WarningKind, WarningKinds};
pub use options::LoadOptions;

use std::path::Path;

/// The largest model file read, bytes: far above any robot's (a 16,000-link
/// URDF is about 10 MB), far below what would exhaust a build machine.
pub const MAX_MODEL_FILE_BYTES: u64 = 64 << 20;

/// Reads a model file as text, only when it is a regular file of at most
/// [`MAX_MODEL_FILE_BYTES`]: `/dev/zero` would fill the memory and
/// `/dev/stdin` block the build.
///
/// # Errors
/// The I/O error, or `InvalidInput` naming what is wrong.
pub fn read_model_file(path: &Path) -> std::io::Result<String> {
    use std::io::{Error, ErrorKind, Read};
    let metadata = std::fs::metadata(path)?;
    if !metadata.is_file() {
        return Err(Error::new(
            ErrorKind::InvalidInput,
            "it is not a regular file (a device, a pipe or a directory)",
        ));
    }
    if metadata.len() > MAX_MODEL_FILE_BYTES {
        return Err(Error::new(
            ErrorKind::InvalidInput,
            format!(
                "it has {} bytes, more than the {MAX_MODEL_FILE_BYTES} a model file may have",
                metadata.len()
            ),
        ));
    }
    // The size can change between the check and the read: read no more.
    let mut text = String::new();
    std::fs::File::open(path)?
        .take(MAX_MODEL_FILE_BYTES)
        .read_to_string(&mut text)?;
    Ok(text)
}

/// Reads a model file: URDF (`.urdf`, `.xml`) or rodyn's own (`.toml`).
///
/// # Errors
/// The first problem, with its file, line and column.
pub fn load(path: &Path, options: LoadOptions) -> diagnostic::Result<ModelDescription> {
    let mut model = load_file(path, options)?;
    model.round_quarter_turns |= options.round_quarter_turns;
    let found = neutral::warnings(&model);
    model.warnings.extend(found);
    Ok(model)
}

fn load_file(path: &Path, options: LoadOptions) -> diagnostic::Result<ModelDescription> {
    let text = read_model_file(path).map_err(|e| {
        Diagnostic::error(
            Location::start_of(path),
            format!("cannot read the model file: {e}"),
        )
    })?;
    match path.extension().and_then(|e| e.to_str()) {
        Some("urdf" | "xml") => urdf::read_urdf(
            path,
            &text,
            urdf::UrdfOptions {
                floating_base: options.floating_base,
                strict: options.strict,
                silence: options.silence,
            },
        ),
        Some("toml") => rodyn_file::read_rodyn_file_with(path, &text, options),
        other => Err(Diagnostic::error(
            Location::start_of(path),
            format!(
                "unknown model file type `{}`; rodyn reads .urdf (or .xml) and .toml files",
                other.unwrap_or("")
            ),
        )),
    }
}
