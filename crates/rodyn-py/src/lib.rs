//! Python bindings of rodyn: the module `rodyn` (built by maturin from
//! `pyproject.toml`; `pip install ./crates/rodyn-py`).
//!
//! `rodyn.Model.from_urdf(path)` loads any URDF (or rodyn TOML file with
//! `from_file`) at run time and runs every algorithm of the run-time model
//! ([`rodyn_model::runtime::RuntimeModel`]) on numpy arrays laid out as
//! Pinocchio's, so results compare with Pinocchio's bindings directly.
//! The user's guide is `docs/sections/python.md`.

mod arrays;
mod contacts;
mod errors;
mod frame_names;
mod layout;
mod model;

use pyo3::prelude::*;

/// rodyn's rigid-body dynamics on numpy arrays, in Pinocchio's conventions.
#[pymodule]
fn rodyn(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<model::Model>()?;
    m.add("ModelError", m.py().get_type::<errors::ModelError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
