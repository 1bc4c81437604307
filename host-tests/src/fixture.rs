//! Pinocchio reference fixtures: loading them and building rodyn models from them.
//!
//! `tools/pinocchio/make_fixtures.py` loads each URDF of `models/urdf/` with
//! Pinocchio and writes `host-tests/fixtures/<name>.json`: the model as
//! Pinocchio built it (fixed joints merged into their parents) and Pinocchio's
//! results on seeded random states. This module reads such a file, builds the
//! equivalent [`Model`] at run time for given const sizes, and converts a
//! state into fixed-size arrays in any [`Scalar`].
//!
//! Pinocchio's conventions map onto rodyn's one to one: body `i` is
//! Pinocchio's joint `i + 1`, `jointPlacements` are rodyn placements, an
//! inertia's `lever` is the centre of mass and its `inertia` the rotational
//! inertia about it, all in the joint's frame. Pinocchio stores spatial
//! vectors linear part first; rodyn's constructors take the angular part
//! first, so [`State::arrays`] reorders them.
//!
//! ```no_run
//! use rodyn_host_tests::fixture::Fixture;
//! let fixture = Fixture::load_named("ur5")?;
//! let model = fixture.model::<6, 6, 6>()?;
//! let state = fixture.states[0].arrays::<f64, 6, 6, 6>()?;
//! # Ok::<(), rodyn_host_tests::fixture::FixtureError>(())
//! ```

pub mod catalog;
pub mod compare;

use rodyn::joint::{Axis, Joint};
use rodyn::spatial::{Force, Inertia, Mat3, Motion, Sym3, Transform, Vec3};
use rodyn::topology::Topology;
use rodyn::{Model, Scalar};
use serde::Deserialize;
use std::fmt;
use std::path::{Path, PathBuf};

/// How far from symmetric (relative to its largest entry) a fixture's
/// rotational inertia may be. Pinocchio writes exactly symmetric matrices;
/// anything visibly asymmetric means a corrupted or hand-edited file.
const INERTIA_SYMMETRY_TOLERANCE: f64 = 1e-12;

/// One fixture file: a model and Pinocchio's results on several states.
#[derive(Clone, Debug, Deserialize)]
pub struct Fixture {
    /// The Pinocchio version that wrote the file.
    pub pinocchio_version: String,
    /// The model as Pinocchio built it.
    pub model: ModelDescription,
    /// Random states with Pinocchio's results.
    pub states: Vec<State>,
}

/// A model in Pinocchio's terms, after fixed joints were merged.
#[derive(Clone, Debug, Deserialize)]
pub struct ModelDescription {
    /// The model's name (the URDF file's stem).
    pub name: String,
    /// Number of configuration coordinates.
    pub nq: usize,
    /// Number of velocity coordinates.
    pub nv: usize,
    /// Gravitational acceleration in the world frame (m/s²).
    pub gravity: [f64; 3],
    /// Mass of the links welded to the world (kg); it enters no result.
    pub world_fixed_mass: f64,
    /// The fixed joints Pinocchio merged into their parents.
    pub merged_fixed_joints: Vec<String>,
    /// One entry per moving body, parents first.
    pub joints: Vec<JointDescription>,
}

/// One Pinocchio joint and the body it moves.
#[derive(Clone, Debug, Deserialize)]
pub struct JointDescription {
    /// The URDF joint's name.
    pub name: String,
    /// Parent body index (`None`: the world).
    pub parent: Option<usize>,
    /// Pinocchio's joint type without its `JointModel` prefix: `RX`, `RY`,
    /// `RZ`, `RevoluteUnaligned`, `PX`, `PY`, `PZ`, `PrismaticUnaligned`,
    /// `FreeFlyer`.
    #[serde(rename = "type")]
    pub kind: String,
    /// Configuration coordinates of the joint.
    pub nq: usize,
    /// Velocity coordinates of the joint.
    pub nv: usize,
    /// First configuration coordinate.
    pub idx_q: usize,
    /// First velocity coordinate.
    pub idx_v: usize,
    /// The unit axis of an unaligned revolute or prismatic joint (joint frame).
    pub axis: Option<[f64; 3]>,
    /// The joint frame at `q = 0` in the parent's joint frame.
    pub placement: PlacementDescription,
    /// The body's inertia in the joint frame.
    pub inertia: InertiaDescription,
}

/// A rigid placement `parentMjoint`.
#[derive(Clone, Debug, Deserialize)]
pub struct PlacementDescription {
    /// Rotation, row-major; columns are the joint frame's axes in the parent frame.
    pub rotation: [[f64; 3]; 3],
    /// Origin of the joint frame in the parent frame (m).
    pub translation: [f64; 3],
}

/// Pinocchio's `Inertia`: mass, centre of mass, rotational inertia about it.
#[derive(Clone, Debug, Deserialize)]
pub struct InertiaDescription {
    /// Mass (kg).
    pub mass: f64,
    /// Centre of mass in the joint frame (m).
    pub lever: [f64; 3],
    /// Rotational inertia about the centre of mass (kg m²), row-major.
    pub inertia: [[f64; 3]; 3],
}

/// One state and Pinocchio's results for it, as stored (variable length).
#[derive(Clone, Debug, Deserialize)]
pub struct State {
    /// Configuration (NQ).
    pub q: Vec<f64>,
    /// Velocity (NV).
    pub v: Vec<f64>,
    /// Acceleration given to RNEA (NV).
    pub a: Vec<f64>,
    /// Torque given to ABA (NV).
    pub tau: Vec<f64>,
    /// One external force per body, in its frame, `[linear (N); angular (N m)]`.
    pub fext: Vec<[f64; 6]>,
    /// `rnea(q, v, a)`.
    pub rnea: Vec<f64>,
    /// `rnea(q, v, a, fext)`.
    pub rnea_fext: Vec<f64>,
    /// `crba(q)`, both triangles.
    pub mass_matrix: Vec<Vec<f64>>,
    /// `aba(q, v, tau)`.
    pub aba: Vec<f64>,
    /// `aba(q, v, tau, fext)`.
    pub aba_fext: Vec<f64>,
    /// `nonLinearEffects(q, v)`.
    pub nonlinear_effects: Vec<f64>,
    /// `computeGeneralizedGravity(q)`.
    pub gravity_torques: Vec<f64>,
    /// `computeKineticEnergy(q, v)` (J).
    pub kinetic_energy: f64,
    /// `computePotentialEnergy(q)` (J).
    pub potential_energy: f64,
    /// `centerOfMass(q)` in the world frame (m).
    pub center_of_mass: [f64; 3],
}

/// A state as fixed-size arrays in scalar `S`, ready for rodyn's algorithms.
///
/// The inputs (`q`, `v`, `a`, `tau`, `fext`) are rounded to `S`; the
/// reference results stay `f64`, so that an `f32` run is measured against
/// the exact reference.
#[derive(Clone, Debug)]
pub struct StateArrays<S: Scalar, const NB: usize, const NQ: usize, const NV: usize> {
    /// Configuration.
    pub q: [S; NQ],
    /// Velocity.
    pub v: [S; NV],
    /// Acceleration given to RNEA.
    pub a: [S; NV],
    /// Torque given to forward dynamics.
    pub tau: [S; NV],
    /// External force on each body, in its own frame.
    pub fext: [Force<S>; NB],
    /// Pinocchio's results.
    pub reference: Reference<NB, NV>,
}

/// Pinocchio's results for one state, fixed-size.
#[derive(Clone, Debug)]
pub struct Reference<const NB: usize, const NV: usize> {
    /// `rnea(q, v, a)`.
    pub rnea: [f64; NV],
    /// `rnea(q, v, a, fext)`.
    pub rnea_fext: [f64; NV],
    /// The mass matrix, both triangles.
    pub mass_matrix: [[f64; NV]; NV],
    /// `aba(q, v, tau)`.
    pub aba: [f64; NV],
    /// `aba(q, v, tau, fext)`.
    pub aba_fext: [f64; NV],
    /// `nonLinearEffects(q, v)`.
    pub nonlinear_effects: [f64; NV],
    /// Generalised gravity.
    pub gravity_torques: [f64; NV],
    /// Kinetic energy (J).
    pub kinetic_energy: f64,
    /// Potential energy (J).
    pub potential_energy: f64,
    /// Centre of mass, world frame (m).
    pub center_of_mass: [f64; 3],
}

/// What went wrong reading a fixture or building its model.
#[derive(Debug)]
pub enum FixtureError {
    /// The file could not be read.
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The file is not valid JSON of the fixture's shape.
    Json {
        /// The file.
        path: PathBuf,
        /// The cause, with line and column.
        source: serde_json::Error,
    },
    /// A count in the file disagrees with the sizes asked for or with itself.
    SizeMismatch {
        /// What was counted (e.g. `"state 3: q"`).
        what: String,
        /// The size expected.
        expected: usize,
        /// The size found.
        found: usize,
    },
    /// A joint type rodyn does not map.
    UnsupportedJoint {
        /// Body index.
        body: usize,
        /// The joint's name.
        name: String,
        /// Pinocchio's type.
        kind: String,
    },
    /// A value that cannot describe a model (bad parent order, missing axis, ...).
    Malformed {
        /// Body index.
        body: usize,
        /// The joint's name.
        name: String,
        /// What is wrong.
        problem: String,
    },
    /// The model was built but rodyn's physical checks reject it.
    InvalidModel(rodyn::Error),
}

impl fmt::Display for FixtureError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Io { path, source } => write!(f, "{}: {source}", path.display()),
            Self::Json { path, source } => write!(f, "{}: {source}", path.display()),
            Self::SizeMismatch {
                what,
                expected,
                found,
            } => write!(f, "{what}: expected {expected} entries, found {found}"),
            Self::UnsupportedJoint { body, name, kind } => write!(
                f,
                "body {body} (joint {name:?}): Pinocchio joint type {kind:?} has no rodyn equivalent"
            ),
            Self::Malformed {
                body,
                name,
                problem,
            } => write!(f, "body {body} (joint {name:?}): {problem}"),
            Self::InvalidModel(e) => write!(f, "the fixture's model is not physical: {e}"),
        }
    }
}

impl std::error::Error for FixtureError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Io { source, .. } => Some(source),
            Self::Json { source, .. } => Some(source),
            Self::InvalidModel(e) => Some(e),
            _ => None,
        }
    }
}

/// The folder that holds the committed fixtures.
#[must_use]
pub fn fixtures_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures")
}

impl Fixture {
    /// Reads a fixture file.
    ///
    /// # Errors
    /// [`FixtureError::Io`] or [`FixtureError::Json`].
    pub fn load(path: impl AsRef<Path>) -> Result<Self, FixtureError> {
        let path = path.as_ref();
        let text = std::fs::read_to_string(path).map_err(|source| FixtureError::Io {
            path: path.to_owned(),
            source,
        })?;
        Self::parse(&text).map_err(|source| FixtureError::Json {
            path: path.to_owned(),
            source,
        })
    }

    /// Reads `host-tests/fixtures/<name>.json`.
    ///
    /// # Errors
    /// As [`Fixture::load`].
    pub fn load_named(name: &str) -> Result<Self, FixtureError> {
        Self::load(fixtures_dir().join(format!("{name}.json")))
    }

    /// Parses a fixture from JSON text.
    ///
    /// # Errors
    /// The JSON error, with line and column.
    pub fn parse(text: &str) -> Result<Self, serde_json::Error> {
        serde_json::from_str(text)
    }

    /// Builds the fixture's model with `NB` bodies, `NQ` and `NV` coordinates.
    ///
    /// Every count and index in the file is checked against the layout
    /// rodyn computes, and the result passes [`Model::validate`].
    ///
    /// # Errors
    /// [`FixtureError::SizeMismatch`] when the const sizes do not fit the
    /// file, [`FixtureError::UnsupportedJoint`], [`FixtureError::Malformed`],
    /// [`FixtureError::InvalidModel`].
    pub fn model<const NB: usize, const NQ: usize, const NV: usize>(
        &self,
    ) -> Result<Model<f64, NB, NQ, NV>, FixtureError> {
        let m = &self.model;
        expect_len("bodies (joints)", NB, m.joints.len())?;
        expect_len("nq", NQ, m.nq)?;
        expect_len("nv", NV, m.nv)?;

        let mut parents = [None; NB];
        let mut nq = [0; NB];
        let mut nv = [0; NB];
        let mut joints = [Joint::Fixed; NB];
        let mut placements = [Transform::IDENTITY; NB];
        let mut inertias = [Inertia::point_mass(0.0, Vec3::ZERO); NB];
        let (mut next_q, mut next_v) = (0, 0);
        for (i, jd) in m.joints.iter().enumerate() {
            let malformed = |problem: String| FixtureError::Malformed {
                body: i,
                name: jd.name.clone(),
                problem,
            };
            if let Some(p) = jd.parent {
                if p >= i {
                    return Err(malformed(format!(
                        "parent {p} does not come before the body (parent[i] < i)"
                    )));
                }
            }
            let joint = joint_from(i, jd)?;
            let (jq, jv) = (joint.const_nq(), joint.const_nv());
            if (jd.nq, jd.nv, jd.idx_q, jd.idx_v) != (jq, jv, next_q, next_v) {
                return Err(malformed(format!(
                    "coordinates (nq {}, nv {}, idx_q {}, idx_v {}) do not match rodyn's layout \
                     (nq {jq}, nv {jv}, idx_q {next_q}, idx_v {next_v})",
                    jd.nq, jd.nv, jd.idx_q, jd.idx_v
                )));
            }
            parents[i] = jd.parent;
            nq[i] = jq;
            nv[i] = jv;
            joints[i] = joint;
            placements[i] = Transform::new(
                Mat3::from_rows(jd.placement.rotation),
                Vec3::from_array(jd.placement.translation),
            );
            inertias[i] = inertia_from(&jd.inertia).map_err(malformed)?;
            next_q += jq;
            next_v += jv;
        }
        // Topology::new panics on an inconsistent layout; the checks above
        // (parent order, per-joint counts, totals) rule every such case out.
        expect_len("sum of the joints' nq", NQ, next_q)?;
        expect_len("sum of the joints' nv", NV, next_v)?;
        let topology = Topology::new(parents, nq, nv, NQ);
        let gravity = Motion::new(Vec3::ZERO, Vec3::from_array(m.gravity));
        let model = Model::from_parts(topology, joints, placements, inertias, gravity);
        model.validate().map_err(FixtureError::InvalidModel)?;
        Ok(model)
    }
}

/// rodyn's joint for a Pinocchio joint type.
fn joint_from(body: usize, jd: &JointDescription) -> Result<Joint<f64>, FixtureError> {
    let unaligned = || {
        jd.axis
            .map(|a| Axis::Unit(Vec3::from_array(a)))
            .ok_or_else(|| FixtureError::Malformed {
                body,
                name: jd.name.clone(),
                problem: format!("joint type {} needs an \"axis\"", jd.kind),
            })
    };
    Ok(match jd.kind.as_str() {
        "RX" => Joint::revolute(Axis::X),
        "RY" => Joint::revolute(Axis::Y),
        "RZ" => Joint::revolute(Axis::Z),
        "RevoluteUnaligned" => Joint::revolute(unaligned()?),
        "PX" => Joint::prismatic(Axis::X),
        "PY" => Joint::prismatic(Axis::Y),
        "PZ" => Joint::prismatic(Axis::Z),
        "PrismaticUnaligned" => Joint::prismatic(unaligned()?),
        "FreeFlyer" => Joint::free_flyer(),
        _ => {
            return Err(FixtureError::UnsupportedJoint {
                body,
                name: jd.name.clone(),
                kind: jd.kind.clone(),
            })
        }
    })
}

/// rodyn's inertia for Pinocchio's (the same three quantities).
fn inertia_from(d: &InertiaDescription) -> Result<Inertia<f64>, String> {
    let i = &d.inertia;
    let scale = i.iter().flatten().fold(0.0_f64, |m, x| m.max(x.abs()));
    for (r, c) in [(0, 1), (0, 2), (1, 2)] {
        if (i[r][c] - i[c][r]).abs() > INERTIA_SYMMETRY_TOLERANCE * scale {
            return Err(format!(
                "rotational inertia is not symmetric: entry ({r}, {c}) = {} but ({c}, {r}) = {}",
                i[r][c], i[c][r]
            ));
        }
    }
    let rot_inertia = Sym3::new(i[0][0], i[0][1], i[0][2], i[1][1], i[1][2], i[2][2]);
    Ok(Inertia::new(d.mass, Vec3::from_array(d.lever), rot_inertia))
}

fn expect_len(what: &str, expected: usize, found: usize) -> Result<(), FixtureError> {
    if expected == found {
        Ok(())
    } else {
        Err(FixtureError::SizeMismatch {
            what: what.to_owned(),
            expected,
            found,
        })
    }
}

fn to_array<const N: usize>(what: &str, x: &[f64]) -> Result<[f64; N], FixtureError> {
    expect_len(what, N, x.len())?;
    let mut out = [0.0; N];
    out.copy_from_slice(x);
    Ok(out)
}

fn rounded<S: Scalar, const N: usize>(x: &[f64; N]) -> [S; N] {
    x.map(S::from_f64)
}

/// Pinocchio's `[linear; angular]` force as rodyn's `Force`, rounded to `S`.
fn force_from<S: Scalar>(f: &[f64; 6]) -> Force<S> {
    let v = |k: usize| {
        Vec3::new(
            S::from_f64(f[k]),
            S::from_f64(f[k + 1]),
            S::from_f64(f[k + 2]),
        )
    };
    Force::new(v(3), v(0))
}

impl State {
    /// The state as fixed-size arrays, inputs rounded to `S`.
    ///
    /// # Errors
    /// [`FixtureError::SizeMismatch`] naming the first vector whose length
    /// does not fit the const sizes.
    pub fn arrays<S: Scalar, const NB: usize, const NQ: usize, const NV: usize>(
        &self,
    ) -> Result<StateArrays<S, NB, NQ, NV>, FixtureError> {
        expect_len("fext (one per body)", NB, self.fext.len())?;
        expect_len("mass_matrix rows", NV, self.mass_matrix.len())?;
        let mut mass_matrix = [[0.0; NV]; NV];
        for (row, stored) in mass_matrix.iter_mut().zip(&self.mass_matrix) {
            *row = to_array("mass_matrix row", stored)?;
        }
        Ok(StateArrays {
            q: rounded(&to_array::<NQ>("q", &self.q)?),
            v: rounded(&to_array::<NV>("v", &self.v)?),
            a: rounded(&to_array::<NV>("a", &self.a)?),
            tau: rounded(&to_array::<NV>("tau", &self.tau)?),
            fext: core::array::from_fn(|i| force_from(&self.fext[i])),
            reference: Reference {
                rnea: to_array("rnea", &self.rnea)?,
                rnea_fext: to_array("rnea_fext", &self.rnea_fext)?,
                mass_matrix,
                aba: to_array("aba", &self.aba)?,
                aba_fext: to_array("aba_fext", &self.aba_fext)?,
                nonlinear_effects: to_array("nonlinear_effects", &self.nonlinear_effects)?,
                gravity_torques: to_array("gravity_torques", &self.gravity_torques)?,
                kinetic_energy: self.kinetic_energy,
                potential_energy: self.potential_energy,
                center_of_mass: self.center_of_mass,
            },
        })
    }
}
