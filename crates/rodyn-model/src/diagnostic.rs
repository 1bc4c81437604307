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

/// The kinds of warning a user can silence ([`LoadOptions::silence`](crate::LoadOptions::silence),
/// `silence = ["limit", ...]` in a rodyn file's `[model]` table, the CLI's
/// `--silence limit,...`). Each prints its [`name`](Self::name) after its
/// message, and at most once per file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum WarningKind {
    /// `<limit>`: rodyn does not enforce joint limits.
    Limit,
    /// `<dynamics>` damping and friction.
    Dynamics,
    /// `<mimic>`: the follower becomes an independent joint.
    Mimic,
    /// `<visual>` and `<collision>` geometry.
    Geometry,
    /// `<transmission>`.
    Transmission,
    /// `<gazebo>`.
    Gazebo,
    /// `<calibration>` and `<safety_controller>`.
    Calibration,
    /// An element rodyn does not know, where URDF allows extensions.
    UnknownElement,
    /// A `<robot>` without a name (the model takes the file's).
    UnnamedRobot,
    /// A fixed root link's inertia, which never moves and is dropped.
    FixedRootInertia,
    /// A link of mass 0 with a non-zero tensor.
    MasslessTensor,
    /// A link's own tensor that is not physical before fixed joints merge it.
    LinkTensor,
    /// A merged body's tensor off by rounding (triangle inequality, tiny
    /// negative eigenvalue).
    BodyTensor,
}

impl WarningKind {
    /// Every kind.
    pub const ALL: [Self; 13] = [
        Self::Limit,
        Self::Dynamics,
        Self::Mimic,
        Self::Geometry,
        Self::Transmission,
        Self::Gazebo,
        Self::Calibration,
        Self::UnknownElement,
        Self::UnnamedRobot,
        Self::FixedRootInertia,
        Self::MasslessTensor,
        Self::LinkTensor,
        Self::BodyTensor,
    ];

    /// The name users write to silence it: `limit`, `geometry`,
    /// `fixed-root-inertia`, ...
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Limit => "limit",
            Self::Dynamics => "dynamics",
            Self::Mimic => "mimic",
            Self::Geometry => "geometry",
            Self::Transmission => "transmission",
            Self::Gazebo => "gazebo",
            Self::Calibration => "calibration",
            Self::UnknownElement => "unknown-element",
            Self::UnnamedRobot => "unnamed-robot",
            Self::FixedRootInertia => "fixed-root-inertia",
            Self::MasslessTensor => "massless-tensor",
            Self::LinkTensor => "link-tensor",
            Self::BodyTensor => "body-tensor",
        }
    }

    /// The kind named `name` ([`name`](Self::name)).
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|k| k.name() == name)
    }

    /// Every kind's name, for messages: `limit, dynamics, ...`.
    #[must_use]
    pub fn names() -> String {
        Self::ALL.map(Self::name).join(", ")
    }
}

/// A set of [`WarningKind`]s (the silenced ones).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WarningKinds(u32);

impl WarningKinds {
    /// No kind.
    pub const NONE: Self = Self(0);
    /// Every kind.
    pub const ALL: Self = Self((1 << WarningKind::ALL.len()) - 1);

    /// This set with `kind` added.
    #[must_use]
    pub const fn with(self, kind: WarningKind) -> Self {
        Self(self.0 | 1 << kind as u32)
    }
    /// The union of two sets.
    #[must_use]
    pub const fn union(self, other: Self) -> Self {
        Self(self.0 | other.0)
    }
    /// Whether `kind` is in the set.
    #[must_use]
    pub const fn contains(self, kind: WarningKind) -> bool {
        self.0 & (1 << kind as u32) != 0
    }
    /// The set of a comma-separated list of names (`limit,geometry`), or
    /// `all`.
    ///
    /// # Errors
    /// The first name that is no kind, in a sentence that lists the kinds.
    pub fn parse(list: &str) -> std::result::Result<Self, String> {
        let mut set = Self::NONE;
        for name in list.split(',').map(str::trim).filter(|n| !n.is_empty()) {
            set = set.union(Self::parse_one(name)?);
        }
        Ok(set)
    }
    /// The set of one name, or of every kind for `all`.
    ///
    /// # Errors
    /// As [`parse`](Self::parse).
    pub fn parse_one(name: &str) -> std::result::Result<Self, String> {
        if name == "all" {
            return Ok(Self::ALL);
        }
        WarningKind::from_name(name)
            .map(|k| Self::NONE.with(k))
            .ok_or_else(|| {
                format!(
                    "`{name}` is no kind of warning; the kinds are {} (or `all`)",
                    WarningKind::names()
                )
            })
    }
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
    /// For a warning a user can silence, its kind.
    pub kind: Option<WarningKind>,
}

impl Diagnostic {
    /// An error at `location`.
    #[must_use]
    pub fn error(location: Location, message: impl Into<String>) -> Self {
        Self {
            severity: Severity::Error,
            location,
            message: message.into(),
            kind: None,
        }
    }
    /// A warning at `location`.
    #[must_use]
    pub fn warning(location: Location, message: impl Into<String>) -> Self {
        Self {
            severity: Severity::Warning,
            location,
            message: message.into(),
            kind: None,
        }
    }
    /// A warning of `kind` at `location`.
    #[must_use]
    pub fn warning_of(kind: WarningKind, location: Location, message: impl Into<String>) -> Self {
        Self {
            kind: Some(kind),
            ..Self::warning(location, message)
        }
    }
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let severity = match self.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        write!(f, "{}: {severity}: {}", self.location, self.message)?;
        match (self.severity, self.kind) {
            (Severity::Warning, Some(kind)) => write!(f, " [{}]", kind.name()),
            _ => Ok(()),
        }
    }
}

/// The warnings a user sees: those of a silenced kind dropped, and of the
/// others only the first of each kind in each file, which says how many
/// more there are. Warnings without a kind are kept as they are.
#[must_use]
pub fn settle_warnings(warnings: Vec<Diagnostic>, silenced: WarningKinds) -> Vec<Diagnostic> {
    let mut out: Vec<Diagnostic> = Vec::with_capacity(warnings.len());
    let mut first: std::collections::HashMap<(WarningKind, PathBuf), (usize, usize)> =
        std::collections::HashMap::new();
    for w in warnings {
        let Some(kind) = w.kind else {
            out.push(w);
            continue;
        };
        if silenced.contains(kind) {
            continue;
        }
        match first.entry((kind, w.location.file.clone())) {
            std::collections::hash_map::Entry::Occupied(mut e) => e.get_mut().1 += 1,
            std::collections::hash_map::Entry::Vacant(e) => {
                e.insert((out.len(), 0));
                out.push(w);
            }
        }
    }
    for (index, more) in first.into_values() {
        if more > 0 {
            let w = &mut out[index];
            w.message = format!(
                "{}; {more} more warning{} of this kind in this file",
                w.message,
                if more == 1 { "" } else { "s" }
            );
        }
    }
    out
}

impl std::error::Error for Diagnostic {}

/// The result of every step that reads a model file.
pub type Result<T> = std::result::Result<T, Diagnostic>;
