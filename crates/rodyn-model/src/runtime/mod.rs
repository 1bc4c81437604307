//! A model file's model built at run time: every algorithm of the compiled
//! (const-generic) path on a URDF or TOML file read by the running program,
//! with slices in and slices out.
//!
//! rodyn's sizes are const parameters. A [`RuntimeModel`] picks, when it
//! loads a file, the smallest of a fixed set of monomorphized capacities
//! (its *size class*, see `classes.rs`) and fills what the file does not
//! use with massless padding bodies hanging from the world; each call
//! copies the caller's slices into the class's arrays, runs the same code
//! the compiled model runs, and copies the file's entries back. The padding
//! never moves and exchanges no force with the file's bodies, so results
//! equal the compiled model's; the cost is a few copies and the padding
//! bodies (the design and its measured cost: `docs/sections/runtime.md`).
//!
//! **Speed needs the `size-classes` feature** of `rodyn-model`
//! (`rodyn-model = { ..., features = ["size-classes"] }`): without it each
//! call runs in the largest class (128 bodies), with the same results.
//!
//! # API notes (issue 41's contract)
//!
//! The names are the contract's. Beyond it: [`RuntimeError::kind`] tells
//! bad input ([`RuntimeErrorKind::InvalidInput`], a `ValueError`) from a
//! numerical failure; contacts are [`ContactSpec::point`] and
//! [`ContactSpec::frame`] by frame name, `λ` has [`contact_rows`] entries;
//! also [`forward_dynamics_crba`](RuntimeModel::forward_dynamics_crba),
//! [`kinetic_energy`](RuntimeModel::kinetic_energy),
//! [`potential_energy`](RuntimeModel::potential_energy),
//! [`frame_jacobian_time_variation`](RuntimeModel::frame_jacobian_time_variation),
//! [`impulse_dynamics`](RuntimeModel::impulse_dynamics),
//! [`inverse_kinematics`](RuntimeModel::inverse_kinematics),
//! [`integrate`](RuntimeModel::integrate) and
//! [`set_gravity`](RuntimeModel::set_gravity) (a URDF has no gravity).
//! The file's drives (springs, dampers, muscles, motors) run at run time
//! too: [`aba_with_drives`](RuntimeModel::aba_with_drives),
//! [`drive_generalized_forces`](RuntimeModel::drive_generalized_forces),
//! their inputs [`drive_input_names`](RuntimeModel::drive_input_names) and
//! the [`motors`](RuntimeModel::motors).
//!
//! # Conventions (the same as the compiled model's)
//!
//! **Free-flyer `q` and `v`, matrix rows and Jacobian rows are already
//! Pinocchio's: no copy or reordering is needed**, except for continuous
//! joints (below).
//!
//! * `q` and `v` list the joints in the file's body order
//!   ([`joint_names`](RuntimeModel::joint_names)), each joint's coordinates
//!   together.
//! * **A free-flyer is Pinocchio's layout**: `q = [x y z qx qy qz qw]`
//!   (position of the base in the world, then the unit quaternion, scalar
//!   **last**), `v = [vx vy vz wx wy wz]`, **linear first, in the base's
//!   own (local) frame**. Nothing to convert for Pinocchio's
//!   `JointModelFreeFlyer`.
//! * A revolute joint, `continuous` or not, has **one** coordinate, its
//!   angle (rad). Pinocchio's continuous joints (`JointModelRUBX` …) have
//!   two, `(cos θ, sin θ)`; that is the only difference from Pinocchio's
//!   `q` (and none in `v`). Prismatic joints: one coordinate (m).
//! * A planar model runs as its 3-D equivalent: joints about z, and a
//!   planar floating base as a free-flyer (`nq` 7, `nv` 6 for it).
//! * Matrices are row-major slices: `M` is `nv × nv` (both triangles);
//!   Jacobians and the centroidal map are `6 × nv` **with the linear rows
//!   first** (Pinocchio's order); `∂τ/∂q` and `∂q̈/∂q` take `q`'s variation
//!   in the tangent space (`nv` columns, a free-flyer's in its local
//!   frame, as Pinocchio's).
//! * Placements are `4 × 4` homogeneous matrices, row-major (`ᵒMf`, world
//!   from frame).
//! * Jacobian references: [`Reference::Local`] (the frame's axes at its
//!   origin), [`Reference::World`] (world axes at the world origin),
//!   [`Reference::LocalWorldAligned`] (world axes at the frame's origin):
//!   Pinocchio's `LOCAL`, `WORLD`, `LOCAL_WORLD_ALIGNED`.
//!
//! Frames are the generated module's: every link fixed to a moving body
//! (its `FRAME_NAMES`); links welded to the world are not frames.
//!
//! # Example
//!
//! ```
//! use rodyn_model::runtime::{Reference, RuntimeModel};
//! # let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
//! let panda = RuntimeModel::from_urdf(&root.join("models/urdf/panda.urdf"), false)?;
//! let mut ws = panda.workspace();
//! let q = panda.neutral();
//! let (v, mut tau) = (vec![0.0; panda.nv()], vec![0.0; panda.nv()]);
//! // The torques that hold the arm still at q: gravity's.
//! panda.rnea(&mut ws, &q, &v, &v, &mut tau)?;
//! let mut g = vec![0.0; panda.nv()];
//! panda.gravity(&mut ws, &q, &mut g)?;
//! assert!(tau.iter().zip(&g).all(|(a, b)| (a - b).abs() < 1e-12));
//! // And ABA gives back a zero acceleration under them.
//! let mut a = vec![1.0; panda.nv()];
//! panda.aba(&mut ws, &q, &v, &tau, &mut a)?;
//! assert!(a.iter().all(|x| x.abs() < 1e-9));
//! let frame = panda.frame_names().last().unwrap().clone();
//! let mut j = vec![0.0; 6 * panda.nv()];
//! panda.frame_jacobian(&mut ws, &q, &frame, Reference::LocalWorldAligned, &mut j)?;
//! // Bad input is an error that names it, never a panic.
//! let err = panda.rnea(&mut ws, &q[..6], &v, &v, &mut tau).unwrap_err();
//! assert_eq!(err.to_string(), "q has 6 entries, the model has nq = 7");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#[macro_use]
mod classes;
#[macro_use]
mod call;
mod check;
mod configuration;
mod contacts;
mod derivatives;
mod drives;
mod dynamics;
mod error;
mod inverse_kinematics;
mod kinematics;
pub mod legacy;
mod padded;
mod skeleton;

pub use contacts::{contact_rows, ContactSpec};
pub use drives::MAX_PATH_POINTS;
pub use error::{RuntimeError, RuntimeErrorKind};
pub use kinematics::Reference;
pub use legacy::{PaddedModel, PaddedRuntimeModel, MAX_BODIES, MAX_FREE_FLYERS, MAX_NQ, MAX_NV};
pub use padded::MAX_CONTACT_ROWS;

use crate::description::ModelDescription;
use crate::diagnostic::{Diagnostic, Location};
use crate::LoadOptions;
use check::Input;
use classes::{ClassModel, ClassScratch};
use rodyn::Frame;
use std::path::Path;

/// A model file's model, built at run time (see the [module](self) for
/// the conventions). One model serves any number of [`Workspace`]s: share
/// it between threads, give each thread its own workspace.
pub struct RuntimeModel {
    class: ClassModel,
    description: ModelDescription,
    joint_names: Vec<String>,
    frames: Vec<(String, Frame<f64>)>,
    nq: usize,
    nv: usize,
    neutral: Vec<f64>,
    gravity: [f64; 3],
    drives: drives::Drives,
}

/// A [`RuntimeModel`]'s scratch memory (rodyn's `Data` and the algorithms'
/// workspaces in the model's size class), made by
/// [`RuntimeModel::workspace`]: one per thread.
pub struct Workspace {
    class: ClassScratch,
    /// The drives' scratch, made by the first drive call.
    drive: Option<drives::DriveScratch>,
}

impl RuntimeModel {
    /// Loads a URDF, with a free-flyer root when `floating_base` is set.
    ///
    /// # Errors
    /// The model compiler's diagnostic (file, line, column): what
    /// `rodyn-model check` reports.
    pub fn from_urdf(path: &Path, floating_base: bool) -> Result<Self, Diagnostic> {
        let options = LoadOptions::new().with_floating_base(floating_base);
        Self::new(crate::load(path, options)?)
    }

    /// Loads a rodyn TOML file (or a URDF, by its extension, with a fixed
    /// base).
    ///
    /// # Errors
    /// As [`from_urdf`](Self::from_urdf).
    pub fn from_file(path: &Path) -> Result<Self, Diagnostic> {
        Self::new(crate::load(path, LoadOptions::default())?)
    }

    /// The model of a description already read.
    ///
    /// # Errors
    /// A model larger than the largest size class (the message gives it).
    pub fn new(description: ModelDescription) -> Result<Self, Diagnostic> {
        let skeleton = skeleton::Skeleton::new(&description);
        let Some(class) = ClassModel::new(&skeleton) else {
            let largest = classes::LARGEST
                .iter()
                .filter(|(f, _)| *f == skeleton.free_flyers)
                .map(|(_, nb)| *nb)
                .max();
            let location = description
                .bodies
                .first()
                .map_or_else(|| Location::start_of(Path::new("")), |b| b.location.clone());
            let message = match largest {
                Some(nb) => format!(
                    "the model has {} bodies, more than the {nb} a run-time model with {} floating base(s) holds",
                    skeleton.nb(),
                    skeleton.free_flyers
                ),
                None => format!(
                    "the model has {} floating bases; a run-time model holds at most 2",
                    skeleton.free_flyers
                ),
            };
            return Err(Diagnostic::error(location, message));
        };
        let class = class.map_err(|e| {
            let body = match e {
                rodyn::Error::InvalidModel { body, .. } => body,
                _ => 0,
            };
            let location = description
                .bodies
                .get(body)
                .or(description.bodies.first())
                .map_or_else(|| Location::start_of(Path::new("")), |b| b.location.clone());
            Diagnostic::error(location, format!("rodyn refuses the model's tree: {e}"))
        })?;
        let nv = skeleton.one_dof + 6 * skeleton.free_flyers;
        let nq = nv + skeleton.free_flyers;
        let joint_names = description
            .bodies
            .iter()
            .map(|b| b.joint_name.clone())
            .collect();
        let gravity = description.gravity;
        let drives = drives::Drives::new(&description).map_err(|message| {
            let location = description
                .bodies
                .first()
                .map_or_else(|| Location::start_of(Path::new("")), |b| b.location.clone());
            Diagnostic::error(location, message)
        })?;
        let mut model = Self {
            class,
            description,
            joint_names,
            frames: skeleton.frames,
            nq,
            nv,
            neutral: Vec::new(),
            gravity,
            drives,
        };
        model.neutral = model.compute_neutral();
        Ok(model)
    }

    /// Configuration coordinates.
    #[must_use]
    pub fn nq(&self) -> usize {
        self.nq
    }

    /// Velocity coordinates.
    #[must_use]
    pub fn nv(&self) -> usize {
        self.nv
    }

    /// Bodies (one per joint).
    #[must_use]
    pub fn nb(&self) -> usize {
        self.joint_names.len()
    }

    /// The joints' names, in `q`'s and `v`'s order (one per body).
    #[must_use]
    pub fn joint_names(&self) -> Vec<String> {
        self.joint_names.clone()
    }

    /// The frames' names, in the generated module's `FRAME_NAMES` order.
    #[must_use]
    pub fn frame_names(&self) -> Vec<String> {
        self.frames.iter().map(|(name, _)| name.clone()).collect()
    }

    /// The description the model was built from.
    #[must_use]
    pub fn description(&self) -> &ModelDescription {
        &self.description
    }

    /// The gravitational acceleration in the world frame (m/s²).
    #[must_use]
    pub fn gravity_vector(&self) -> [f64; 3] {
        self.gravity
    }

    /// Sets the gravitational acceleration in the world frame (m/s²): a
    /// URDF has none, and the file's default is `[0, 0, -9.80665]`.
    ///
    /// # Errors
    /// A non-finite component.
    pub fn set_gravity(&mut self, gravity: [f64; 3]) -> Result<(), RuntimeError> {
        if let Some(k) = gravity.iter().position(|g| !g.is_finite()) {
            return Err(RuntimeError::invalid_input(format!(
                "gravity[{k}] is {}",
                gravity[k]
            )));
        }
        let motion = rodyn::spatial::Motion::new(
            rodyn::spatial::Vec3::ZERO,
            rodyn::spatial::Vec3::new(gravity[0], gravity[1], gravity[2]),
        );
        self.class
            .set_gravity(motion)
            .map_err(|e| RuntimeError::invalid_input(format!("gravity: {e}")))?;
        self.gravity = gravity;
        Ok(())
    }

    /// The size class's capacities `(NB, NQ, NV)`: the file's bodies and
    /// coordinates plus the padding's.
    #[must_use]
    pub fn capacity(&self) -> (usize, usize, usize) {
        self.class.capacity()
    }

    /// A workspace for this model's calls.
    #[must_use]
    pub fn workspace(&self) -> Workspace {
        Workspace {
            class: self.class.scratch(),
            drive: None,
        }
    }

    fn frame(&self, name: &str) -> Result<&Frame<f64>, RuntimeError> {
        self.frame_index(name).map(|k| &self.frames[k].1)
    }

    /// The index of frame `name` in [`frame_names`](Self::frame_names).
    fn frame_index(&self, name: &str) -> Result<usize, RuntimeError> {
        self.frames
            .iter()
            .position(|(n, _)| n == name)
            .ok_or_else(|| RuntimeError::invalid_input(format!("unknown frame '{name}'")))
    }

    fn check_q(&self, q: &[f64]) -> Result<(), RuntimeError> {
        check::length("q", q.len(), self.nq, "nq")
    }

    fn check_nv(&self, name: &str, x: &[f64]) -> Result<(), RuntimeError> {
        check::length(name, x.len(), self.nv, "nv")
    }

    fn check_matrix(&self, name: &str, x: &[f64], rows: usize) -> Result<(), RuntimeError> {
        let expected = rows * self.nv;
        if x.len() == expected {
            Ok(())
        } else {
            Err(RuntimeError::invalid_input(format!(
                "{name} has {} entries, it must have {rows} x nv = {expected}",
                x.len()
            )))
        }
    }

    fn explain(&self, algorithm: &str, error: &rodyn::Error, inputs: &[Input<'_>]) -> RuntimeError {
        check::explain(algorithm, error, inputs, &self.joint_names)
    }
}

/// `rows × nv` of a padded row-major matrix `m` (`NV` columns) into `out`.
fn copy_matrix<const NV: usize>(m: &[[f64; NV]], nv: usize, out: &mut [f64]) {
    // A file that fills its class (no padding coordinate) has rows as long
    // as the class's: one copy of the block instead of one per row.
    if nv == NV && out.len() == m.len() * NV {
        out.copy_from_slice(m.as_flattened());
        return;
    }
    for (row, out_row) in m.iter().zip(out.chunks_exact_mut(nv)) {
        out_row.copy_from_slice(&row[..nv]);
    }
}
