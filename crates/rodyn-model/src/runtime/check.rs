//! Checks of the caller's slices, and the core's errors told in the
//! caller's terms (the input's name and index, the joint's name).

use super::error::RuntimeError;
use rodyn::error::Error;

/// A slice the caller passed, with the name it has in the API.
pub(super) struct Input<'a> {
    pub name: &'static str,
    pub values: &'a [f64],
}

/// `Ok` when `values` has `expected` entries; the error names both counts.
pub(super) fn length(
    name: &str,
    len: usize,
    expected: usize,
    dimension: &str,
) -> Result<(), RuntimeError> {
    if len == expected {
        Ok(())
    } else {
        Err(RuntimeError::invalid_input(format!(
            "{name} has {len} entries, the model has {dimension} = {expected}"
        )))
    }
}

/// The first non-finite entry among `inputs`, as `"v[3] is NaN"`.
pub(super) fn first_non_finite(inputs: &[Input<'_>]) -> Option<RuntimeError> {
    inputs.iter().find_map(|input| {
        let k = input.values.iter().position(|x| !x.is_finite())?;
        let what = if input.values[k].is_nan() {
            "NaN"
        } else {
            "infinite"
        };
        Some(RuntimeError::invalid_input(format!(
            "{}[{k}] is {what}",
            input.name
        )))
    })
}

/// The core's `error` in the caller's terms: a non-finite input by its name
/// and index, a configuration off its joint's manifold by the joint's name,
/// anything else as a numerical failure of `algorithm`.
pub(super) fn explain(
    algorithm: &str,
    error: &Error,
    inputs: &[Input<'_>],
    joint_names: &[String],
) -> RuntimeError {
    if let Some(bad) = first_non_finite(inputs) {
        return bad;
    }
    match error {
        Error::InvalidConfiguration { joint, .. } => {
            let name = joint_names
                .get(*joint)
                .map_or("a padding joint", String::as_str);
            RuntimeError::invalid_input(format!("q: joint '{name}': {error}"))
        }
        Error::NonFinite { .. }
        | Error::InvalidSetting { .. }
        | Error::TooManyConstraints { .. } => {
            RuntimeError::invalid_input(format!("{algorithm}: {error}"))
        }
        _ => RuntimeError::numerical(format!("{algorithm}: {error}")),
    }
}
