//! `rodyn.Model`: a model file's run-time model with numpy arrays in and
//! out, in Pinocchio's layout (see `layout.rs`).
//!
//! Every call reads its inputs in place (`arrays.rs`), runs the
//! [`RuntimeModel`] call into the output's memory and returns the output:
//! one array allocation per result, none with `out=`.

use crate::arrays::{check_no_alias, output_matrix, output_vector, Vector};
use crate::contacts::contact_specs;
use crate::errors::{model_error, runtime_error, value_error};
use crate::frame_names::FrameNames;
use crate::layout::ConfigurationLayout;
use numpy::{PyArray1, PyArray2, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use rodyn_model::description::JointType;
use rodyn_model::runtime::{Reference, RuntimeModel, Workspace};
use std::path::PathBuf;

/// A robot model loaded from a URDF or rodyn TOML file, with every
/// algorithm on numpy arrays in Pinocchio's conventions.
#[pyclass(name = "Model", module = "rodyn")]
pub struct Model {
    runtime: RuntimeModel,
    workspace: Workspace,
    layout: ConfigurationLayout,
    /// rodyn's `q` when Pinocchio's differs (continuous joints).
    q_rodyn: Vec<f64>,
    /// The seed of the next `random_configuration()` without one.
    next_seed: u64,
    /// The frame names last passed, with their text.
    names: FrameNames,
}

impl Model {
    fn new(runtime: RuntimeModel) -> Self {
        let layout = ConfigurationLayout::new(runtime.description().bodies.iter().map(|b| {
            let nq = match b.joint {
                // Run as a free-flyer (the run-time model's 3-D equivalent).
                JointType::FreeFlyer | JointType::PlanarFloating => 7,
                JointType::Revolute { .. } | JointType::Prismatic { .. } => 1,
            };
            (nq, b.continuous)
        }));
        let q_rodyn = vec![0.0; layout.rodyn_nq()];
        let workspace = runtime.workspace();
        Self {
            runtime,
            workspace,
            layout,
            q_rodyn,
            next_seed: 0,
            names: FrameNames::default(),
        }
    }

    fn nv(&self) -> usize {
        self.runtime.nv()
    }

    fn q<'a, 'py>(&self, q: &'a Bound<'py, PyAny>) -> PyResult<Vector<'a, 'py>> {
        Vector::extract("q", q, self.layout.pinocchio_nq())
    }

    fn vector<'a, 'py>(&self, name: &str, x: &'a Bound<'py, PyAny>) -> PyResult<Vector<'a, 'py>> {
        Vector::extract(name, x, self.nv())
    }
}

/// rodyn's `q` for Pinocchio's `q`: the same slice without continuous
/// joints, else converted into `scratch`.
fn rodyn_q<'s>(
    layout: &ConfigurationLayout,
    scratch: &'s mut [f64],
    q: &'s [f64],
) -> PyResult<&'s [f64]> {
    if layout.is_identity() {
        return Ok(q);
    }
    if let Some(k) = q.iter().position(|x| !x.is_finite()) {
        return Err(value_error(format!(
            "q[{k}] is {}",
            if q[k].is_nan() { "NaN" } else { "infinite" }
        )));
    }
    layout.to_rodyn(q, scratch).map_err(|bad| {
        value_error(format!(
            "q[{}:{}] is a continuous joint's (cos θ, sin θ), but cos² + sin² = {} is not 1",
            bad.index,
            bad.index + 2,
            bad.norm_squared
        ))
    })?;
    Ok(scratch)
}

/// A 4×4 homogeneous placement (any float array or nested sequence).
fn placement(object: &Bound<'_, PyAny>) -> PyResult<[f64; 16]> {
    let rows: Vec<Vec<f64>> = object.extract().map_err(|_| {
        value_error("target must be a 4×4 array of numbers (a homogeneous placement)")
    })?;
    if rows.len() != 4 || rows.iter().any(|r| r.len() != 4) {
        return Err(value_error(format!(
            "target must be 4×4; it has {} rows of lengths {:?}",
            rows.len(),
            rows.iter().map(Vec::len).collect::<Vec<_>>()
        )));
    }
    let mut flat = [0.0; 16];
    for (out, x) in flat.iter_mut().zip(rows.iter().flatten()) {
        *out = *x;
    }
    if let Some(k) = flat.iter().position(|x| !x.is_finite()) {
        return Err(value_error(format!(
            "target[{}, {}] is {}",
            k / 4,
            k % 4,
            flat[k]
        )));
    }
    Ok(flat)
}

fn reference(name: &str) -> PyResult<Reference> {
    match name {
        "local_world_aligned" => Ok(Reference::LocalWorldAligned),
        "local" => Ok(Reference::Local),
        "world" => Ok(Reference::World),
        other => Err(value_error(format!(
            "reference '{other}' is none of 'local_world_aligned', 'local', 'world'"
        ))),
    }
}

/// The mutable slice of a result array made or checked by `arrays.rs`.
///
/// # Safety
/// As [`Vector::slice`]: no Python code runs while it lives, and no input
/// slice shares its memory (checked by `check_no_alias`).
// A mutable slice from a shared reference, as numpy's own `as_slice_mut`:
// the array object is shared, its memory is what the caller owns.
#[allow(clippy::mut_from_ref)]
unsafe fn result_slice<'a, D: numpy::ndarray::Dimension>(
    array: &'a Bound<'_, numpy::PyArray<f64, D>>,
) -> &'a mut [f64] {
    // SAFETY: a C-contiguous float64 array (made here or checked), no
    // other reference to its memory while the call runs.
    unsafe { array.as_slice_mut() }.unwrap_or(&mut [])
}

#[pymethods]
impl Model {
    /// Loads a URDF; `floating_base=True` puts a free-flyer named
    /// `root_joint` between the world and the root link (Pinocchio's
    /// `buildModelFromUrdf(path, JointModelFreeFlyer())`).
    ///
    /// Raises `rodyn.ModelError` (a `ValueError`) with `file`, `line` and
    /// `column` when the file cannot be read or built.
    #[staticmethod]
    #[pyo3(signature = (path, floating_base = false))]
    fn from_urdf(py: Python<'_>, path: PathBuf, floating_base: bool) -> PyResult<Self> {
        RuntimeModel::from_urdf(&path, floating_base)
            .map(Self::new)
            .map_err(|d| model_error(py, &d))
    }

    /// Loads a model file: rodyn's TOML (`.toml`), or a URDF with a fixed
    /// base (`.urdf`, `.xml`).
    ///
    /// Raises `rodyn.ModelError` as `from_urdf` does.
    #[staticmethod]
    fn from_file(py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        RuntimeModel::from_file(&path)
            .map(Self::new)
            .map_err(|d| model_error(py, &d))
    }

    /// Length of `q` (Pinocchio's: two per continuous joint).
    #[getter]
    fn nq(&self) -> usize {
        self.layout.pinocchio_nq()
    }

    /// Length of `v`, `a` and `tau`.
    #[getter(nv)]
    fn nv_py(&self) -> usize {
        self.nv()
    }

    /// The joints' names in `q`'s and `v`'s order (Pinocchio's
    /// `model.names[1:]`).
    #[getter]
    fn joint_names(&self) -> Vec<String> {
        self.runtime.joint_names()
    }

    /// The frames' names: every link fixed to a moving body.
    #[getter]
    fn frame_names(&self) -> Vec<String> {
        self.runtime.frame_names()
    }

    /// The model compiler's warnings about the file (what it ignored:
    /// joint limits, meshes, ...), as `file:line:column: warning: ...`.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.runtime
            .description()
            .warnings
            .iter()
            .map(ToString::to_string)
            .collect()
    }

    fn __repr__(&self) -> String {
        format!(
            "<rodyn.Model '{}': nq={}, nv={}, {} joints, {} frames>",
            self.runtime.description().name,
            self.layout.pinocchio_nq(),
            self.nv(),
            self.runtime.nb(),
            self.runtime.frame_names().len()
        )
    }

    /// The neutral configuration (Pinocchio's `neutral`): every joint at
    /// zero, free-flyers at the origin with the quaternion `[0 0 0 1]`.
    fn neutral<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_vec(py, self.layout.to_pinocchio(&self.runtime.neutral()))
    }

    /// A random configuration: angles uniform in [-π, π), displacements and
    /// free-flyer positions in [-1, 1) m, orientations uniform. The same
    /// `seed` gives the same configuration on every machine; without one,
    /// each call gives the next of a sequence that starts anew with each
    /// model.
    #[pyo3(signature = (seed = None))]
    fn random_configuration<'py>(
        &mut self,
        py: Python<'py>,
        seed: Option<u64>,
    ) -> Bound<'py, PyArray1<f64>> {
        let seed = seed.unwrap_or_else(|| {
            self.next_seed = self.next_seed.wrapping_add(1);
            self.next_seed
        });
        PyArray1::from_vec(
            py,
            self.layout
                .to_pinocchio(&self.runtime.random_configuration(seed)),
        )
    }

    /// Inverse dynamics (RNEA): `tau = M(q) a + C(q, v) v + g(q)`.
    #[pyo3(signature = (q, v, a, out = None))]
    fn rnea<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        a: &Bound<'py, PyAny>,
        out: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let (q, v, a) = (self.q(q)?, self.vector("v", v)?, self.vector("a", a)?);
        let result = output_vector(py, out, self.nv())?;
        if out.is_some() {
            check_no_alias(
                result.data(),
                result.len(),
                &[("q", &q), ("v", &v), ("a", &a)],
            )?;
        }
        // SAFETY: no Python code runs from here to the return.
        let (q, v, a, tau) = unsafe { (q.slice(), v.slice(), a.slice(), result_slice(&result)) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .rnea(&mut self.workspace, q, v, a, tau)
            .map_err(runtime_error)?;
        Ok(result)
    }

    /// Forward dynamics (ABA): `ddq = M(q)⁻¹ (tau − C(q, v) v − g(q))`.
    #[pyo3(signature = (q, v, tau, out = None))]
    fn aba<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        tau: &Bound<'py, PyAny>,
        out: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let (q, v, tau) = (self.q(q)?, self.vector("v", v)?, self.vector("tau", tau)?);
        let result = output_vector(py, out, self.nv())?;
        if out.is_some() {
            check_no_alias(
                result.data(),
                result.len(),
                &[("q", &q), ("v", &v), ("tau", &tau)],
            )?;
        }
        // SAFETY: no Python code runs from here to the return.
        let (q, v, tau, ddq) =
            unsafe { (q.slice(), v.slice(), tau.slice(), result_slice(&result)) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .aba(&mut self.workspace, q, v, tau, ddq)
            .map_err(runtime_error)?;
        Ok(result)
    }

    /// The joint-space mass matrix `M(q)` (CRBA), both triangles.
    #[pyo3(signature = (q, out = None))]
    fn crba<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        out: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let q = self.q(q)?;
        let nv = self.nv();
        let result = output_matrix(py, out, nv, nv)?;
        if out.is_some() {
            check_no_alias(result.data(), result.len(), &[("q", &q)])?;
        }
        // SAFETY: no Python code runs from here to the return.
        let (q, mass) = unsafe { (q.slice(), result_slice(&result)) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .crba(&mut self.workspace, q, mass)
            .map_err(runtime_error)?;
        Ok(result)
    }

    /// The generalised gravity `g(q)` (Pinocchio's
    /// `computeGeneralizedGravity`).
    fn gravity<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let q = self.q(q)?;
        let result = output_vector(py, None, self.nv())?;
        // SAFETY: no Python code runs from here to the return.
        let (q, g) = unsafe { (q.slice(), result_slice(&result)) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .gravity(&mut self.workspace, q, g)
            .map_err(runtime_error)?;
        Ok(result)
    }

    /// The bias forces `C(q, v) v + g(q)` (Pinocchio's `nonLinearEffects`).
    fn nonlinear_effects<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let (q, v) = (self.q(q)?, self.vector("v", v)?);
        let result = output_vector(py, None, self.nv())?;
        // SAFETY: no Python code runs from here to the return.
        let (q, v, h) = unsafe { (q.slice(), v.slice(), result_slice(&result)) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .nonlinear_effects(&mut self.workspace, q, v, h)
            .map_err(runtime_error)?;
        Ok(result)
    }

    /// The world placement of frame `name` at `q`: a 4×4 homogeneous
    /// matrix (Pinocchio's `data.oMf[id].homogeneous`).
    fn frame_placement<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        name: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let q = self.q(q)?;
        let result = output_matrix(py, None, 4, 4)?;
        let name = self.names.text("name", name)?;
        let mut placement = [0.0; 16];
        // SAFETY: no Python code runs while `q` lives.
        let q = unsafe { q.slice() };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .frame_placement(&mut self.workspace, q, name, &mut placement)
            .map_err(runtime_error)?;
        // SAFETY: the new array, referenced nowhere else.
        unsafe { result_slice(&result) }.copy_from_slice(&placement);
        Ok(result)
    }

    /// The 6×nv Jacobian of frame `name` at `q`, linear rows first, in
    /// `reference`: "local_world_aligned" (default), "local" or "world"
    /// (Pinocchio's `computeFrameJacobian`).
    #[pyo3(signature = (q, name, reference = "local_world_aligned", out = None))]
    fn frame_jacobian<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        name: &Bound<'py, PyAny>,
        reference: &str,
        out: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let frame_reference = self::reference(reference)?;
        let q = self.q(q)?;
        let result = output_matrix(py, out, 6, self.nv())?;
        let name = self.names.text("name", name)?;
        if out.is_some() {
            check_no_alias(result.data(), result.len(), &[("q", &q)])?;
        }
        // SAFETY: no Python code runs from here to the return.
        let (q, jacobian) = unsafe { (q.slice(), result_slice(&result)) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .frame_jacobian(&mut self.workspace, q, name, frame_reference, jacobian)
            .map_err(runtime_error)?;
        Ok(result)
    }

    /// The centre of mass in the world (Pinocchio's `centerOfMass`).
    fn com<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let q = self.q(q)?;
        let mut com = [0.0; 3];
        // SAFETY: no Python code runs while `q` lives.
        let q = unsafe { q.slice() };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .com(&mut self.workspace, q, &mut com)
            .map_err(runtime_error)?;
        Ok(PyArray1::from_slice(py, &com))
    }

    /// The 6×nv centroidal momentum map, linear rows first (Pinocchio's
    /// `computeCentroidalMap`).
    fn centroidal_map<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let q = self.q(q)?;
        let result = output_matrix(py, None, 6, self.nv())?;
        // SAFETY: no Python code runs from here to the return.
        let (q, map) = unsafe { (q.slice(), result_slice(&result)) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .centroidal_map(&mut self.workspace, q, map)
            .map_err(runtime_error)?;
        Ok(result)
    }

    /// `(dtau_dq, dtau_dv, M)`: the derivatives of RNEA, `q`'s in the
    /// tangent space (Pinocchio's `computeRNEADerivatives`, `M` full).
    fn rnea_derivatives<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        a: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let (q, v, a) = (self.q(q)?, self.vector("v", v)?, self.vector("a", a)?);
        let nv = self.nv();
        let results = [(); 3].map(|()| PyArray2::<f64>::zeros(py, [nv, nv], false));
        // SAFETY: no Python code runs until the tuple is made.
        let (q, v, a) = unsafe { (q.slice(), v.slice(), a.slice()) };
        let [dq, dv, mass] = unsafe { [0, 1, 2].map(|k| result_slice(&results[k])) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .rnea_derivatives(&mut self.workspace, q, v, a, dq, dv, mass)
            .map_err(runtime_error)?;
        PyTuple::new(py, results)
    }

    /// `(dddq_dq, dddq_dv, Minv)`: the derivatives of forward dynamics,
    /// `q`'s in the tangent space (Pinocchio's `computeABADerivatives`,
    /// `M⁻¹` full).
    fn aba_derivatives<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        tau: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let (q, v, tau) = (self.q(q)?, self.vector("v", v)?, self.vector("tau", tau)?);
        let nv = self.nv();
        let results = [(); 3].map(|()| PyArray2::<f64>::zeros(py, [nv, nv], false));
        // SAFETY: no Python code runs until the tuple is made.
        let (q, v, tau) = unsafe { (q.slice(), v.slice(), tau.slice()) };
        let [dq, dv, minv] = unsafe { [0, 1, 2].map(|k| result_slice(&results[k])) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .aba_derivatives(&mut self.workspace, q, v, tau, dq, dv, minv)
            .map_err(runtime_error)?;
        PyTuple::new(py, results)
    }

    /// Forward dynamics with `contacts` held rigidly: `(ddq, lambda)`
    /// (Pinocchio's `constraintDynamics` without Baumgarte gains).
    ///
    /// `contacts` lists frame names, each a point contact (three rows,
    /// `lambda` a force in world axes: `CONTACT_3D`,
    /// `LOCAL_WORLD_ALIGNED`), or `(name, "point")` / `(name, "frame")`
    /// pairs, a frame contact holding the whole frame (six rows, `lambda`
    /// the force then the moment in the frame's axes: `CONTACT_6D`,
    /// `LOCAL`).
    fn constrained_dynamics<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        tau: &Bound<'py, PyAny>,
        contacts: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let contacts = contact_specs(contacts)?;
        let rows = rodyn_model::runtime::contact_rows(&contacts);
        let (q, v, tau) = (self.q(q)?, self.vector("v", v)?, self.vector("tau", tau)?);
        let ddq = PyArray1::<f64>::zeros(py, self.nv(), false);
        let lambda = PyArray1::<f64>::zeros(py, rows, false);
        // SAFETY: no Python code runs until the tuple is made.
        let (q, v, tau) = unsafe { (q.slice(), v.slice(), tau.slice()) };
        let (ddq_out, lambda_out) = unsafe { (result_slice(&ddq), result_slice(&lambda)) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .constrained_dynamics(
                &mut self.workspace,
                q,
                v,
                tau,
                &contacts,
                ddq_out,
                lambda_out,
            )
            .map_err(runtime_error)?;
        PyTuple::new(py, [ddq, lambda])
    }
    /// The kinetic energy `½ vᵀ M(q) v` (J; Pinocchio's
    /// `computeKineticEnergy`).
    fn kinetic_energy(&mut self, q: &Bound<'_, PyAny>, v: &Bound<'_, PyAny>) -> PyResult<f64> {
        let (q, v) = (self.q(q)?, self.vector("v", v)?);
        // SAFETY: no Python code runs from here to the return.
        let (q, v) = unsafe { (q.slice(), v.slice()) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .kinetic_energy(&mut self.workspace, q, v)
            .map_err(runtime_error)
    }

    /// The potential energy of gravity (J), zero at the world's origin
    /// (Pinocchio's `computePotentialEnergy`).
    fn potential_energy(&mut self, q: &Bound<'_, PyAny>) -> PyResult<f64> {
        let q = self.q(q)?;
        // SAFETY: no Python code runs from here to the return.
        let q = unsafe { q.slice() };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .potential_energy(&mut self.workspace, q)
            .map_err(runtime_error)
    }

    /// The time variation `dJ/dt` of frame `name`'s Jacobian at `(q, v)`:
    /// 6×nv, linear rows first, in `reference` as `frame_jacobian`
    /// (Pinocchio's `computeJointJacobiansTimeVariation` then
    /// `getFrameJacobianTimeVariation`).
    #[pyo3(signature = (q, v, name, reference = "local_world_aligned", out = None))]
    fn frame_jacobian_time_variation<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        name: &Bound<'py, PyAny>,
        reference: &str,
        out: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let frame_reference = self::reference(reference)?;
        let (q, v) = (self.q(q)?, self.vector("v", v)?);
        let result = output_matrix(py, out, 6, self.nv())?;
        let name = self.names.text("name", name)?;
        if out.is_some() {
            check_no_alias(result.data(), result.len(), &[("q", &q), ("v", &v)])?;
        }
        // SAFETY: no Python code runs from here to the return.
        let (q, v, dj) = unsafe { (q.slice(), v.slice(), result_slice(&result)) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .frame_jacobian_time_variation(&mut self.workspace, q, v, name, frame_reference, dj)
            .map_err(runtime_error)?;
        Ok(result)
    }

    /// The velocity just after an impact that brings `contacts` to rest,
    /// arriving at `q` with `v`: `(v_after, impulses)` (Pinocchio's
    /// `impulseDynamics` without proximal damping; `impulses` in the units
    /// and axes of `constrained_dynamics`' `lambda`, N s and N m s).
    /// `restitution` in [0, 1]: 0 stops the contacts, 1 reverses their
    /// velocity.
    #[pyo3(signature = (q, v, contacts, restitution = 0.0))]
    fn impulse_dynamics<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        contacts: &Bound<'py, PyAny>,
        restitution: f64,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let contacts = contact_specs(contacts)?;
        let rows = rodyn_model::runtime::contact_rows(&contacts);
        let (q, v) = (self.q(q)?, self.vector("v", v)?);
        let v_after = PyArray1::<f64>::zeros(py, self.nv(), false);
        let impulses = PyArray1::<f64>::zeros(py, rows, false);
        // SAFETY: no Python code runs until the tuple is made.
        let (q, v) = unsafe { (q.slice(), v.slice()) };
        let (v_out, impulses_out) = unsafe { (result_slice(&v_after), result_slice(&impulses)) };
        let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
        self.runtime
            .impulse_dynamics(
                &mut self.workspace,
                q,
                v,
                &contacts,
                restitution,
                v_out,
                impulses_out,
            )
            .map_err(runtime_error)?;
        PyTuple::new(py, [v_after, impulses])
    }

    /// `q ⊕ v`: `q` moved by the velocity `v` for one unit of time, each
    /// joint along its own manifold (Pinocchio's `integrate`: a
    /// free-flyer's `v` in its local frame, its quaternion kept unit).
    fn integrate<'py>(
        &mut self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let (q, v) = (self.q(q)?, self.vector("v", v)?);
        let mut next = vec![0.0; self.layout.rodyn_nq()];
        {
            // SAFETY: no Python code runs while the slices live.
            let (q, v) = unsafe { (q.slice(), v.slice()) };
            let q = rodyn_q(&self.layout, &mut self.q_rodyn, q)?;
            self.runtime
                .integrate(&mut self.workspace, q, v, 1.0, &mut next)
                .map_err(runtime_error)?;
        }
        Ok(PyArray1::from_vec(py, self.layout.to_pinocchio(&next)))
    }

    /// A configuration near `q0` at which frame `name` is at `target`
    /// (its world placement, 4×4 homogeneous), by damped least squares on
    /// the pose error: every component of the error (rad, m) within
    /// `tolerance` after at most `max_iterations` steps. Pinocchio has no
    /// such function; its documentation's inverse-kinematics example runs
    /// the same iteration.
    ///
    /// Raises `ArithmeticError` when the target is not reached within the
    /// budget (out of reach, or a singular start).
    #[pyo3(signature = (name, target, q0, tolerance = 1e-10, max_iterations = 100))]
    fn inverse_kinematics<'py>(
        &mut self,
        py: Python<'py>,
        name: &Bound<'py, PyAny>,
        target: &Bound<'py, PyAny>,
        q0: &Bound<'py, PyAny>,
        tolerance: f64,
        max_iterations: usize,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let target = placement(target)?;
        let q0 = Vector::extract("q0", q0, self.layout.pinocchio_nq())?;
        let name = self.names.text("name", name)?;
        let mut q = vec![0.0; self.layout.rodyn_nq()];
        {
            // SAFETY: no Python code runs while the slice lives.
            let q0 = unsafe { q0.slice() };
            q.copy_from_slice(rodyn_q(&self.layout, &mut self.q_rodyn, q0)?);
        }
        self.runtime
            .inverse_kinematics(
                &mut self.workspace,
                name,
                &target,
                tolerance,
                max_iterations,
                &mut q,
            )
            .map_err(runtime_error)?;
        Ok(PyArray1::from_vec(py, self.layout.to_pinocchio(&q)))
    }
}
