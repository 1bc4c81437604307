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
pub mod neutral;
pub mod physics;
pub mod render;
pub mod rodyn_file;
pub mod runtime;
pub mod tree;
pub mod urdf;

pub use description::ModelDescription;
pub use diagnostic::{Diagnostic, Location, Severity, WarningKind, WarningKinds};

use std::path::Path;

/// How to read a model file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LoadOptions {
    /// For a URDF: put a free-flyer between the world and the root link.
    /// (A rodyn file says this itself with `floating_base = true`.)
    pub floating_base: bool,
    /// Turn the warnings about what cannot harm the dynamics (a link's
    /// tensor that only a merge makes physical, a triangle-inequality
    /// violation, a massless link with a tensor, a robot without a name)
    /// into errors. A rodyn file can ask for it with `strict = true` in
    /// its `[model]` table; the CLI with `--strict`.
    pub strict: bool,
    /// Round placements within 1e-10 of a quarter turn to exact quarter
    /// turns, which CRBA exploits (π/2 written to 12 digits, as the UR
    /// descriptions do, then counts as one). Off by default: the compiled
    /// model keeps the file's rotations. A rodyn file asks with
    /// `round_quarter_turns = true` in `[model]`; the CLI with
    /// `--round-quarter-turns`.
    pub round_quarter_turns: bool,
    /// Kinds of warning not to report, nor to refuse in strict mode
    /// (`WarningKinds::NONE.with(WarningKind::Limit)`). The others are
    /// reported once per kind and file, with a count. A rodyn file adds
    /// its own with `silence = ["limit", "geometry"]` in `[model]`; the
    /// CLI with `--silence limit,geometry` (or `all`).
    pub silence: WarningKinds,
}

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
