//! The `contacts` argument of `constrained_dynamics`: frame names (point
//! contacts) or `(name, "point" | "frame")` pairs.

use crate::errors::value_error;
use pyo3::prelude::*;
use pyo3::types::{PyString, PyTuple};
use rodyn_model::runtime::ContactSpec;

/// The contacts named by `contacts`, a sequence.
pub fn contact_specs(contacts: &Bound<'_, PyAny>) -> PyResult<Vec<ContactSpec>> {
    if contacts.is_instance_of::<PyString>() {
        return Err(value_error(
            "contacts must be a list of frame names or (name, kind) pairs, not one string; write [name]",
        ));
    }
    let items = contacts
        .try_iter()
        .map_err(|_| value_error("contacts must be a list of frame names or (name, kind) pairs"))?;
    let mut specs = Vec::new();
    for (k, item) in items.enumerate() {
        specs.push(contact_spec(k, &item?)?);
    }
    Ok(specs)
}

fn contact_spec(k: usize, item: &Bound<'_, PyAny>) -> PyResult<ContactSpec> {
    if let Ok(name) = item.extract::<String>() {
        return Ok(ContactSpec::point(name));
    }
    let pair = item
        .cast::<PyTuple>()
        .ok()
        .and_then(|t| t.extract::<(String, String)>().ok());
    match pair {
        Some((name, kind)) if kind == "point" => Ok(ContactSpec::point(name)),
        Some((name, kind)) if kind == "frame" => Ok(ContactSpec::frame(name)),
        Some((name, kind)) => Err(value_error(format!(
            "contacts[{k}] ('{name}', '{kind}'): the kind is 'point' or 'frame'"
        ))),
        None => Err(value_error(format!(
            "contacts[{k}] must be a frame name or a (name, 'point' | 'frame') pair"
        ))),
    }
}
