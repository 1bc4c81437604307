//! numpy arrays in and out.
//!
//! A C-contiguous float64 vector is read in place, as a slice of its own
//! memory; a Python sequence of numbers or a strided float64 vector is
//! copied once. Every other array (another dtype, more dimensions) is
//! refused with a `ValueError` naming the argument, as are wrong lengths and
//! non-finite entries. Outputs are new arrays, or the caller's `out=`
//! buffers after their dtype, shape, layout and writability are checked.
//!
//! Slices into numpy memory are formed only after every conversion that can
//! run Python code (a sequence's `__float__`, a new array's allocation,
//! which may run the garbage collector) is done, and used only until the
//! method returns, while the GIL is held: no Python code can change or free
//! that memory in between. An `out=` buffer that shares memory with an
//! input is refused, so a mutable slice never aliases a shared one.

use crate::errors::value_error;
use numpy::ndarray::Dimension;
use numpy::npyffi::flags::NPY_ARRAY_WRITEABLE;
use numpy::npyffi::objects::_PyArray_GET_ITEM_DATA;
use numpy::{PyArray, PyArray1, PyArray2, PyArrayMethods, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;

/// A vector argument (`q`, `v`, `tau`, ...) before it is read.
pub enum Vector<'a, 'py> {
    /// A C-contiguous float64 array, read in place.
    InPlace(&'a Bound<'py, PyArray1<f64>>),
    /// A copy of a sequence or of a strided array.
    Copied(Vec<f64>),
}

impl<'a, 'py> Vector<'a, 'py> {
    /// Takes `object` as the vector argument `name` of length `len`.
    ///
    /// # Errors
    /// `ValueError` naming `name`: not a vector of numbers, not float64,
    /// not of length `len`.
    pub fn extract(name: &str, object: &'a Bound<'py, PyAny>, len: usize) -> PyResult<Self> {
        let vector = if let Ok(array) = object.cast::<PyArray1<f64>>() {
            if array.is_c_contiguous() {
                Self::InPlace(array)
            } else {
                Self::Copied(array.to_owned_array().iter().copied().collect())
            }
        } else if let Ok(array) = object.cast::<PyUntypedArray>() {
            return Err(wrong_array(name, array, "a 1-D"));
        } else if object.is_instance_of::<pyo3::types::PyString>() {
            return Err(not_numbers(name, object));
        } else {
            Self::Copied(
                object
                    .extract::<Vec<f64>>()
                    .map_err(|_| not_numbers(name, object))?,
            )
        };
        let found = vector.len();
        if found != len {
            return Err(value_error(format!(
                "{name} has {found} entries; this model's {name} has {len}"
            )));
        }
        Ok(vector)
    }

    fn len(&self) -> usize {
        match self {
            Self::InPlace(array) => array.len(),
            Self::Copied(values) => values.len(),
        }
    }

    /// The entries.
    ///
    /// # Safety
    /// No Python code may run while the slice lives (see the module).
    pub unsafe fn slice(&self) -> &[f64] {
        match self {
            // SAFETY: checked C-contiguous and float64 in `extract`; the
            // caller runs no Python code while the slice lives.
            Self::InPlace(array) => unsafe { array.as_slice() }.unwrap_or(&[]),
            Self::Copied(values) => values,
        }
    }

    /// The memory the vector reads, for the aliasing check of `out=`.
    fn memory(&self) -> Option<(usize, usize)> {
        match self {
            Self::InPlace(array) => Some(span(array.data() as usize, array.len())),
            Self::Copied(_) => None,
        }
    }
}

fn span(address: usize, len: usize) -> (usize, usize) {
    (address, address + len * size_of::<f64>())
}

fn dtype_name(array: &Bound<'_, PyUntypedArray>) -> String {
    array
        .dtype()
        .as_any()
        .str()
        .map_or_else(|_| "?".to_owned(), |s| s.to_string())
}

fn not_numbers(name: &str, object: &Bound<'_, PyAny>) -> PyErr {
    value_error(format!(
        "{name} must be a float64 numpy array or a sequence of numbers, not {}",
        type_name(object)
    ))
}

/// A shape as Python writes it: `(9, 9)`, `(9,)`.
fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

fn type_name(object: &Bound<'_, PyAny>) -> String {
    object
        .get_type()
        .name()
        .map_or_else(|_| "?".to_owned(), |n| n.to_string())
}

fn wrong_array(name: &str, array: &Bound<'_, PyUntypedArray>, wanted: &str) -> PyErr {
    let dtype = dtype_name(array);
    if dtype == "float64" {
        value_error(format!(
            "{name} must be {wanted} float64 array; it has {} dimensions (shape {})",
            array.ndim(),
            shape_text(array.shape())
        ))
    } else {
        value_error(format!(
            "{name} must be {wanted} float64 array, not {dtype} (convert with {name}.astype(float))"
        ))
    }
}

/// A 1-D result: a new array, or the caller's `out` after its checks.
pub fn output_vector<'py>(
    py: Python<'py>,
    out: Option<&Bound<'py, PyAny>>,
    len: usize,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    match out {
        None => Ok(PyArray1::zeros(py, len, false)),
        Some(object) => checked_out(object, &[len]),
    }
}

/// A 2-D result (row-major): a new array, or the caller's `out`.
pub fn output_matrix<'py>(
    py: Python<'py>,
    out: Option<&Bound<'py, PyAny>>,
    rows: usize,
    columns: usize,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    match out {
        None => Ok(PyArray2::zeros(py, [rows, columns], false)),
        Some(object) => checked_out(object, &[rows, columns]),
    }
}

/// `object` as a writable C-contiguous float64 array of `shape`; the
/// reasons it is not are looked up only when it is not.
fn checked_out<'py, D: Dimension>(
    object: &Bound<'py, PyAny>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyArray<f64, D>>> {
    let Ok(array) = object.cast::<PyArray<f64, D>>() else {
        return Err(out_of_wrong_type(object, shape));
    };
    if array.shape() != shape {
        return Err(value_error(format!(
            "out has shape {}; this result has shape {}",
            shape_text(array.shape()),
            shape_text(shape)
        )));
    }
    if !array.is_c_contiguous() {
        return Err(value_error(
            "out must be C-contiguous (row-major without gaps), as np.empty makes it",
        ));
    }
    // SAFETY: a live array's fields, read under the GIL.
    let flags = unsafe { (*_PyArray_GET_ITEM_DATA(array.as_array_ptr())).flags };
    if flags & NPY_ARRAY_WRITEABLE == 0 {
        return Err(value_error("out is read-only; pass a writable array"));
    }
    Ok(array.clone())
}

fn out_of_wrong_type(object: &Bound<'_, PyAny>, shape: &[usize]) -> PyErr {
    let Ok(array) = object.cast::<PyUntypedArray>() else {
        return value_error(format!(
            "out must be a float64 numpy array of shape {}, not {}",
            shape_text(shape),
            type_name(object)
        ));
    };
    let dtype = dtype_name(array);
    if dtype == "float64" {
        value_error(format!(
            "out has shape {}; this result has shape {}",
            shape_text(array.shape()),
            shape_text(shape)
        ))
    } else {
        value_error(format!("out must be a float64 array, not {dtype}"))
    }
}

/// Refuses an `out` buffer (`len` floats at `data`) that shares memory
/// with one of the inputs.
pub fn check_no_alias(
    data: *const f64,
    len: usize,
    inputs: &[(&str, &Vector<'_, '_>)],
) -> PyResult<()> {
    let (out_start, out_end) = span(data as usize, len);
    for (name, vector) in inputs {
        if let Some((start, end)) = vector.memory() {
            if start < out_end && out_start < end {
                return Err(value_error(format!(
                    "out shares memory with {name}; pass a separate array"
                )));
            }
        }
    }
    Ok(())
}
