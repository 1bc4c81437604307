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
//! On a host, [`runtime::RuntimeModel`] builds the same model at run time for
//! the `rodyn-model tree` and `rodyn-model render` commands.
#![warn(missing_docs)]

pub mod build;
pub mod codegen;
pub mod description;
pub mod diagnostic;
pub mod geometry;
pub mod names;
pub mod physics;
pub mod render;
pub mod rodyn_file;
pub mod runtime;
pub mod tree;
pub mod urdf;

pub use description::ModelDescription;
pub use diagnostic::{Diagnostic, Location, Severity};

use std::path::Path;

/// How to read a model file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LoadOptions {
    /// For a URDF: put a free-flyer between the world and the root link.
    /// (A rodyn file says this itself with `floating_base = true`.)
    pub floating_base: bool,
}

/// Reads a model file: URDF (`.urdf`, `.xml`) or rodyn's own (`.toml`).
///
/// # Errors
/// The first problem, with its file, line and column.
pub fn load(path: &Path, options: LoadOptions) -> diagnostic::Result<ModelDescription> {
    let text = std::fs::read_to_string(path).map_err(|e| {
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
            },
        ),
        Some("toml") => rodyn_file::read_rodyn_file(path, &text),
        other => Err(Diagnostic::error(
            Location::start_of(path),
            format!(
                "unknown model file type `{}`; rodyn reads .urdf (or .xml) and .toml files",
                other.unwrap_or("")
            ),
        )),
    }
}
