//! [`LoadOptions`]: how to read a model file.
//!
//! The struct is `#[non_exhaustive]` so that a later option is not a
//! breaking change: build it from [`LoadOptions::new`] (or `default()`) or
//! [`LoadOptions::floating_base`] and the `with_…` methods.

use crate::WarningKinds;

/// How to read a model file.
///
/// ```
/// use rodyn_model::{LoadOptions, WarningKind, WarningKinds};
///
/// // A URDF whose root link is free to move, strict about every warning
/// // except the joint limits.
/// let options = LoadOptions::floating_base()
///     .with_strict(true)
///     .with_silence(WarningKinds::NONE.with(WarningKind::Limit));
/// assert!(options.floating_base && options.strict && !options.round_quarter_turns);
/// assert_eq!(LoadOptions::new(), LoadOptions::default());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
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

impl LoadOptions {
    /// The defaults: a fixed root, warnings reported but not refused, the
    /// file's rotations kept, nothing silenced. The same as `default()`,
    /// usable in a `const`.
    ///
    /// ```
    /// use rodyn_model::LoadOptions;
    ///
    /// const OPTIONS: LoadOptions = LoadOptions::new().with_round_quarter_turns(true);
    /// assert!(OPTIONS.round_quarter_turns && !OPTIONS.floating_base);
    /// ```
    #[must_use]
    pub const fn new() -> Self {
        Self {
            floating_base: false,
            strict: false,
            round_quarter_turns: false,
            silence: WarningKinds::NONE,
        }
    }

    /// The defaults with a free-flyer between the world and a URDF's root
    /// link (what `--floating-base` asks on the command line).
    ///
    /// ```no_run
    /// // build.rs: a legged robot's URDF, its trunk free in space.
    /// use rodyn_model::{build::compile_with, LoadOptions};
    ///
    /// let _ = compile_with("models/urdf/solo12.urdf", "solo12", LoadOptions::floating_base());
    /// ```
    #[must_use]
    pub const fn floating_base() -> Self {
        Self::new().with_floating_base(true)
    }

    /// These options with a free-flyer under a URDF's root link, or not.
    ///
    /// ```
    /// use rodyn_model::LoadOptions;
    ///
    /// assert!(LoadOptions::new().with_floating_base(true).floating_base);
    /// ```
    #[must_use]
    pub const fn with_floating_base(mut self, floating_base: bool) -> Self {
        self.floating_base = floating_base;
        self
    }

    /// These options with strict mode on or off (see [`LoadOptions::strict`]).
    ///
    /// ```
    /// use rodyn_model::LoadOptions;
    ///
    /// assert!(LoadOptions::new().with_strict(true).strict);
    /// ```
    #[must_use]
    pub const fn with_strict(mut self, strict: bool) -> Self {
        self.strict = strict;
        self
    }

    /// These options with near quarter turns rounded, or not (see
    /// [`LoadOptions::round_quarter_turns`]).
    ///
    /// ```
    /// use rodyn_model::LoadOptions;
    ///
    /// assert!(LoadOptions::new().with_round_quarter_turns(true).round_quarter_turns);
    /// ```
    #[must_use]
    pub const fn with_round_quarter_turns(mut self, round_quarter_turns: bool) -> Self {
        self.round_quarter_turns = round_quarter_turns;
        self
    }

    /// These options silencing `silence`'s kinds of warning, in place of
    /// the ones silenced so far.
    ///
    /// ```
    /// use rodyn_model::{LoadOptions, WarningKind, WarningKinds};
    ///
    /// let options = LoadOptions::new().with_silence(WarningKinds::NONE.with(WarningKind::Limit));
    /// assert!(options.silence.contains(WarningKind::Limit));
    /// ```
    #[must_use]
    pub const fn with_silence(mut self, silence: WarningKinds) -> Self {
        self.silence = silence;
        self
    }
}
