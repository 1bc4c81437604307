//! What a run-time call reports when its input or its result is wrong.

use std::fmt;

/// Whether the caller gave something wrong or the dynamics could not be
/// computed at a valid input (bindings map the first to `ValueError`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RuntimeErrorKind {
    /// A wrong length, a NaN or infinity, an unknown frame, a bad setting,
    /// a workspace of another model.
    InvalidInput,
    /// The algorithm refused a valid-looking input: a singular mass matrix,
    /// redundant contacts, an IK target not reached, a non-finite result.
    Numerical,
}

/// The error of a [`RuntimeModel`](super::RuntimeModel) call: a sentence
/// that names the input (`"q has 8 entries, the model has nq = 9"`,
/// `"unknown frame 'foo'"`, `"v[3] is NaN"`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RuntimeError {
    kind: RuntimeErrorKind,
    message: String,
}

impl RuntimeError {
    /// An error in the caller's input.
    #[must_use]
    pub fn invalid_input(message: impl Into<String>) -> Self {
        Self {
            kind: RuntimeErrorKind::InvalidInput,
            message: message.into(),
        }
    }

    /// A numerical failure at a valid input.
    #[must_use]
    pub fn numerical(message: impl Into<String>) -> Self {
        Self {
            kind: RuntimeErrorKind::Numerical,
            message: message.into(),
        }
    }

    /// Which of the two it is.
    #[must_use]
    pub const fn kind(&self) -> RuntimeErrorKind {
        self.kind
    }

    /// The sentence, as [`Display`](fmt::Display) prints it.
    #[must_use]
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for RuntimeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for RuntimeError {}
