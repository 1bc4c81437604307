//! Frame names as Python passes them.
//!
//! A caller usually passes the same few name objects again and again (a
//! literal, a variable in a loop), so the last few are kept with their
//! text and recognised by identity: a `str` never changes, and a kept
//! reference keeps its address from being reused. Under the 3.9 stable
//! ABI this saves a new `bytes` object per call (a `str`'s UTF-8 view
//! joined the stable ABI in 3.10); under 3.10's it saves little, and it
//! still makes a name of another type a `ValueError` naming the argument.

use crate::errors::value_error;
use pyo3::prelude::*;
use pyo3::types::PyString;

/// How many name objects are kept: a robot's feet or hands in a loop.
const KEPT: usize = 8;

/// The last name objects seen, with their text.
#[derive(Default)]
pub struct FrameNames {
    kept: Vec<(Py<PyString>, String)>,
    /// The slot the next new name replaces once all are taken.
    next: usize,
}

impl FrameNames {
    /// The text of `object`, the argument `argument` (a frame's name).
    ///
    /// # Errors
    /// `ValueError` when `object` is not a `str`.
    pub fn text<'s>(&'s mut self, argument: &str, object: &Bound<'_, PyAny>) -> PyResult<&'s str> {
        if let Some(k) = self
            .kept
            .iter()
            .position(|(kept, _)| kept.as_ptr() == object.as_ptr())
        {
            return Ok(&self.kept[k].1);
        }
        let name = object.cast::<PyString>().map_err(|_| {
            value_error(format!(
                "{argument} must be a frame's name (str), not {}",
                object
                    .get_type()
                    .name()
                    .map_or_else(|_| "?".to_owned(), |n| n.to_string())
            ))
        })?;
        let entry = (name.clone().unbind(), name.to_cow()?.into_owned());
        let slot = if self.kept.len() < KEPT {
            self.kept.push(entry);
            self.kept.len() - 1
        } else {
            let slot = self.next;
            self.kept[slot] = entry;
            self.next = (slot + 1) % KEPT;
            slot
        };
        Ok(&self.kept[slot].1)
    }
}
