//! Diagnostics: where in which file something is wrong, in one plain sentence.
//!
//! Errors and warnings print as `file:line:column: error: message`, the form
//! editors and CI logs turn into links.

use std::fmt;
use std::path::{Path, PathBuf};

/// A position in a model file: 1-based line and column (in characters).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// The file, as it was named to the compiler.
    pub file: PathBuf,
    /// Line, from 1.
    pub line: u32,
    /// Column, from 1.
    pub column: u32,
}

/// The byte offsets at which the lines of a text start, for
/// [`Location::at_offset_indexed`].
#[derive(Clone, Debug)]
pub struct LineIndex {
    starts: Vec<usize>,
}

impl LineIndex {
    /// The index of `text`.
    #[must_use]
    pub fn new(text: &str) -> Self {
        let starts = core::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        Self { starts }
    }
}

impl Location {
    /// The position of byte `offset` in `text`, which is the content of `file`.
    #[must_use]
    pub fn at_offset(file: &Path, text: &str, offset: usize) -> Self {
        let before = &text[..offset.min(text.len())];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let column = before[line_start..].chars().count() + 1;
        Self {
            file: file.to_path_buf(),
            line: u32::try_from(line).unwrap_or(u32::MAX),
            column: u32::try_from(column).unwrap_or(u32::MAX),
        }
    }
    /// The position of byte `offset` in `text` through a [`LineIndex`] of
    /// it: a binary search for the line and a count within it, instead of
    /// a scan from the start (which made every link's location cost the
    /// whole file before it, and loading quadratic in the link count).
    #[must_use]
    pub fn at_offset_indexed(file: &Path, text: &str, lines: &LineIndex, offset: usize) -> Self {
        let offset = offset.min(text.len());
        let line = lines
            .starts
            .partition_point(|&start| start <= offset)
            .max(1);
        let line_start = lines.starts[line - 1];
        let column = text
            .get(line_start..offset)
            .map_or(offset - line_start, |s| s.chars().count())
            + 1;
        Self {
            file: file.to_path_buf(),
            line: u32::try_from(line).unwrap_or(u32::MAX),
            column: u32::try_from(column).unwrap_or(u32::MAX),
        }
    }
    /// The start of `file` (for problems that belong to no single place).
    #[must_use]
    pub fn start_of(file: &Path) -> Self {
        Self {
            file: file.to_path_buf(),
            line: 1,
            column: 1,
        }
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.file.display(), self.line, self.column)
    }
}

/// How serious a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Severity {
    /// The model cannot be built.
    Error,
    /// The model was built, but part of the file was ignored or adjusted.
    Warning,
}

/// One problem found in a model file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// Error or warning.
    pub severity: Severity,
    /// Where.
    pub location: Location,
    /// What, as a plain sentence.
    pub message: String,
}

impl Diagnostic {
    /// An error at `location`.
    #[must_use]
    pub fn error(location: Location, message: impl Into<String>) -> Self {
        Self {
            severity: Severity::Error,
            location,
            message: message.into(),
        }
    }
    /// A warning at `location`.
    #[must_use]
    pub fn warning(location: Location, message: impl Into<String>) -> Self {
        Self {
            severity: Severity::Warning,
            location,
            message: message.into(),
        }
    }
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let kind = match self.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        write!(f, "{}: {kind}: {}", self.location, self.message)
    }
}

impl std::error::Error for Diagnostic {}

/// The result of every step that reads a model file.
pub type Result<T> = std::result::Result<T, Diagnostic>;
