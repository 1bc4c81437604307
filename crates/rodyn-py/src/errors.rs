//! Python exceptions: the model compiler's diagnostics as `rodyn.ModelError`
//! (a `ValueError` carrying `file`, `line` and `column`), everything else a
//! caller can get wrong as `ValueError` naming the argument.

use pyo3::create_exception;
use pyo3::exceptions::{PyArithmeticError, PyValueError};
use pyo3::prelude::*;
use rodyn_model::runtime::{RuntimeError, RuntimeErrorKind};
use rodyn_model::Diagnostic;

create_exception!(
    rodyn,
    ModelError,
    PyValueError,
    "A model file rodyn cannot build a model from. `file`, `line` and \
     `column` (1-based) say where, and the message says what, as \
     `file:line:column: error: sentence`."
);

/// The exception for a diagnostic of the model compiler.
pub fn model_error(py: Python<'_>, diagnostic: &Diagnostic) -> PyErr {
    let error = ModelError::new_err(diagnostic.to_string());
    let value = error.value(py);
    let location = &diagnostic.location;
    // Setting attributes on a fresh exception instance cannot fail short
    // of memory exhaustion, which then surfaces as that error instead.
    let set = || -> PyResult<()> {
        value.setattr("file", location.file.to_string_lossy().into_owned())?;
        value.setattr("line", location.line)?;
        value.setattr("column", location.column)?;
        value.setattr("message", diagnostic.message.as_str())
    };
    if let Err(e) = set() {
        return e;
    }
    error
}

/// A `ValueError` with `message`.
pub fn value_error(message: impl Into<String>) -> PyErr {
    PyValueError::new_err(message.into())
}

/// The exception for a failed call: `ValueError` for the caller's input
/// (a wrong length, a NaN, an unknown frame, a quaternion off the unit
/// sphere), `ArithmeticError` for dynamics that cannot be computed at a
/// valid input (redundant contacts, a singular mass matrix).
pub fn runtime_error(error: RuntimeError) -> PyErr {
    match error.kind() {
        RuntimeErrorKind::InvalidInput => PyValueError::new_err(error.message().to_owned()),
        RuntimeErrorKind::Numerical => PyArithmeticError::new_err(error.message().to_owned()),
    }
}
