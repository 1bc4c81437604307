//! The file's drives at run time: its springs, dampers, muscles and motors
//! as `rodyn::drive`'s elements, the same values the model compiler writes
//! into the generated module.
//!
//! A path element's type carries its number of points, and its forces are
//! generic over the model's capacities. Monomorphizing every element for
//! every size class would multiply the classes' code; instead the class
//! runs forward kinematics, the file's body poses and velocities are copied
//! into one drive workspace of the largest capacities, and the elements run
//! there once, on a single instantiation. The copy is a few numbers per
//! body, small against the dynamics that follow.

use super::check::Input;
use super::padded::{Padded, Scratch};
use super::{RuntimeError, RuntimeModel, Workspace};
use crate::description::{ForceLaw, JointType, ModelDescription};
use rodyn::algorithm::aba::aba;
use rodyn::algorithm::kinematics::forward_kinematics_velocity;
use rodyn::algorithm::rnea::rnea;
use rodyn::drive::{
    DriveForces, DriveState, ForceElement, JointMotor, LinearDamper, LinearSpring, NonlinearSpring,
    Path, ThelenMuscle, ThelenParameters,
};
use rodyn::error::Quantity;
use rodyn::space::VectorOps;
use rodyn::spatial::{Force, Spatial, Vec3};
use rodyn::{Data, Endpoint};

/// Bodies of the drive workspace: the most of any size class.
const DRIVE_NB: usize = 128;
/// Velocity coordinates of the drive workspace: the most of any size class.
const DRIVE_NV: usize = 129;
/// Most points on one drive's path.
pub const MAX_PATH_POINTS: usize = 6;

/// One force law on a path of `K` points.
#[derive(Clone, Copy, Debug)]
enum PathElement<const K: usize> {
    Spring(LinearSpring<f64, Spatial, K>),
    CubicSpring(NonlinearSpring<f64, Spatial, K>),
    Damper(LinearDamper<f64, Spatial, K>),
    Muscle(ThelenMuscle<f64, Spatial, K>),
}

impl<const K: usize> ForceElement<f64, Spatial, DRIVE_NB, DRIVE_NV> for PathElement<K> {
    fn add_forces(
        &self,
        state: &DriveState<'_, f64, Spatial, DRIVE_NB, DRIVE_NV>,
        w: &[f64],
        out: &mut DriveForces<f64, Spatial, DRIVE_NB, DRIVE_NV>,
    ) -> rodyn::Result<()> {
        match self {
            Self::Spring(e) => e.add_forces(state, w, out),
            Self::CubicSpring(e) => e.add_forces(state, w, out),
            Self::Damper(e) => e.add_forces(state, w, out),
            Self::Muscle(e) => e.add_forces(state, w, out),
        }
    }
}

/// A drive of any kind, its path length chosen at load time.
#[derive(Clone, Copy, Debug)]
enum Element {
    Path2(PathElement<2>),
    Path3(PathElement<3>),
    Path4(PathElement<4>),
    Path5(PathElement<5>),
    Path6(PathElement<6>),
    Motor(JointMotor<f64>),
}

impl Element {
    fn add_forces(
        &self,
        state: &DriveState<'_, f64, Spatial, DRIVE_NB, DRIVE_NV>,
        w: &[f64],
        out: &mut DriveForces<f64, Spatial, DRIVE_NB, DRIVE_NV>,
    ) -> rodyn::Result<()> {
        match self {
            Self::Path2(e) => e.add_forces(state, w, out),
            Self::Path3(e) => e.add_forces(state, w, out),
            Self::Path4(e) => e.add_forces(state, w, out),
            Self::Path5(e) => e.add_forces(state, w, out),
            Self::Path6(e) => e.add_forces(state, w, out),
            Self::Motor(e) => e.add_forces(state, w, out),
        }
    }
}

/// `law` on the path through `points`, reading input `input` (a muscle).
fn path_element<const K: usize>(
    points: &[Endpoint<f64>],
    law: &ForceLaw,
    input: usize,
) -> PathElement<K> {
    let path = Path::new(core::array::from_fn(|k| points[k]));
    match *law {
        ForceLaw::Spring {
            stiffness,
            rest_length,
            cubic_stiffness: 0.0,
        } => PathElement::Spring(LinearSpring::new(path, stiffness, rest_length)),
        ForceLaw::Spring {
            stiffness,
            rest_length,
            cubic_stiffness,
        } => PathElement::CubicSpring(NonlinearSpring::new(
            path,
            stiffness,
            cubic_stiffness,
            rest_length,
        )),
        ForceLaw::Damper { damping } => PathElement::Damper(LinearDamper::new(path, damping)),
        ForceLaw::Muscle {
            max_isometric_force,
            optimal_fiber_length,
            tendon_slack_length,
            pennation_angle,
            max_contraction_velocity,
            activation_time_constant,
            deactivation_time_constant,
        } => PathElement::Muscle(ThelenMuscle::new(
            path,
            ThelenParameters {
                max_contraction_velocity,
                activation_time_constant,
                deactivation_time_constant,
                ..ThelenParameters::<f64>::thelen_2003(
                    max_isometric_force,
                    optimal_fiber_length,
                    tendon_slack_length,
                    pennation_angle,
                )
            },
            input,
        )),
    }
}

/// The file's drives, in the order of the generated module: force elements
/// first, then motors.
pub(super) struct Drives {
    names: Vec<String>,
    elements: Vec<Element>,
    /// The drive inputs' names: muscle activations, then motor currents.
    inputs: Vec<String>,
    motors: Vec<(String, JointMotor<f64>)>,
}

impl Drives {
    /// The drives of `description`, whose bodies start at velocity
    /// coordinates `idx_v` in the run-time layout.
    ///
    /// # Errors
    /// A path longer than [`MAX_PATH_POINTS`], named.
    pub fn new(description: &ModelDescription) -> Result<Self, String> {
        let mut idx_v = Vec::with_capacity(description.bodies.len());
        let mut next = 0;
        for b in &description.bodies {
            idx_v.push(next);
            next += match b.joint {
                JointType::FreeFlyer | JointType::PlanarFloating => 6,
                _ => 1,
            };
        }
        let inputs: Vec<String> = description
            .force_elements
            .iter()
            .filter(|f| matches!(f.law, ForceLaw::Muscle { .. }))
            .map(|f| f.name.clone())
            .chain(description.motors.iter().map(|m| m.name.clone()))
            .collect();
        let input_of = |name: &str| inputs.iter().position(|n| n == name).unwrap_or(0);
        let mut drives = Self {
            names: Vec::new(),
            elements: Vec::new(),
            inputs: Vec::new(),
            motors: Vec::new(),
        };
        for f in &description.force_elements {
            let points: Vec<Endpoint<f64>> = f
                .path
                .iter()
                .map(|&e| {
                    let e = &description.endpoints[e];
                    let p = Vec3::new(e.position[0], e.position[1], e.position[2]);
                    match e.body {
                        Some(b) => Endpoint::on_body(b, p),
                        None => Endpoint::in_world(p),
                    }
                })
                .collect();
            let input = input_of(&f.name);
            let element = match points.len() {
                2 => Element::Path2(path_element(&points, &f.law, input)),
                3 => Element::Path3(path_element(&points, &f.law, input)),
                4 => Element::Path4(path_element(&points, &f.law, input)),
                5 => Element::Path5(path_element(&points, &f.law, input)),
                6 => Element::Path6(path_element(&points, &f.law, input)),
                n => {
                    return Err(format!(
                        "{} '{}' has a path of {n} points; a run-time model takes 2 to {MAX_PATH_POINTS}",
                        f.law.kind(),
                        f.name
                    ))
                }
            };
            drives.names.push(f.name.clone());
            drives.elements.push(element);
        }
        for m in &description.motors {
            let motor = JointMotor::new(
                idx_v[m.body],
                input_of(&m.name),
                m.gear_ratio,
                m.torque_constant,
                m.rotor_inertia,
            );
            drives.names.push(m.name.clone());
            drives.elements.push(Element::Motor(motor));
            drives.motors.push((m.name.clone(), motor));
        }
        drives.inputs = inputs;
        Ok(drives)
    }

    /// The first drive whose own forces are not finite at `state`.
    fn culprit(&self, state: &DriveState<'_, f64, Spatial, DRIVE_NB, DRIVE_NV>, w: &[f64]) -> &str {
        let mut scratch = DriveForces::new();
        self.elements
            .iter()
            .zip(&self.names)
            .find(|(e, _)| {
                scratch.clear();
                e.add_forces(state, w, &mut scratch).is_err()
                    || scratch.f_ext.iter().any(|f| !f.is_finite())
            })
            .map_or("a drive", |(_, n)| n.as_str())
    }
}

/// The drive workspace: the file's kinematics in the largest capacities,
/// and the forces the drives add there.
pub(super) struct DriveScratch {
    data: Box<Data<f64, DRIVE_NB, DRIVE_NV>>,
    v: Box<[f64; DRIVE_NV]>,
    forces: Box<DriveForces<f64, Spatial, DRIVE_NB, DRIVE_NV>>,
}

impl DriveScratch {
    pub fn new() -> Self {
        Self {
            data: Box::default(),
            v: Box::new([0.0; DRIVE_NV]),
            forces: Box::default(),
        }
    }
}

/// One class's forward kinematics with velocities, the file's body poses
/// and velocities copied out to the drive workspace.
#[inline(never)]
fn class_kinematics<const NB: usize, const NQ: usize, const NV: usize>(
    m: &Padded<NB, NQ, NV>,
    s: &mut Scratch<NB, NQ, NV>,
    q: &[f64],
    v: &[f64],
    nb: usize,
    drive: &mut DriveScratch,
) -> rodyn::Result<()> {
    s.set_q(q);
    s.set_v(v);
    forward_kinematics_velocity(&m.model, &mut s.data, &s.q, &s.v)?;
    drive.data.o_m_i[..nb].copy_from_slice(&s.data.o_m_i[..nb]);
    drive.data.v[..nb].copy_from_slice(&s.data.v[..nb]);
    drive.v[..v.len()].copy_from_slice(v);
    Ok(())
}

/// What a drive evaluation computes after the forces: the forward
/// dynamics under them, or their generalized forces.
#[derive(Clone, Copy)]
enum After {
    Aba,
    GeneralizedForces,
}

/// One class's pass after the drive forces: `tau + τ_drive` and the drive's
/// body forces into ABA, or `τ_drive + Σ Jᵀ f` as `g(q) − RNEA(q, 0, 0, f)`.
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn class_after_drives<const NB: usize, const NQ: usize, const NV: usize>(
    m: &Padded<NB, NQ, NV>,
    s: &mut Scratch<NB, NQ, NV>,
    nb: usize,
    tau: &[f64],
    forces: &DriveForces<f64, Spatial, DRIVE_NB, DRIVE_NV>,
    after: After,
    out: &mut [f64],
) -> rodyn::Result<()> {
    s.f_ext[..nb].copy_from_slice(&forces.f_ext[..nb]);
    let nv = out.len();
    match after {
        After::Aba => {
            for (k, a) in s.a[..nv].iter_mut().enumerate() {
                *a = forces.tau[k] + tau[k];
            }
            let ddq = aba(&m.model, &mut s.data, &s.q, &s.v, &s.a, Some(&s.f_ext))?;
            out.copy_from_slice(&ddq[..nv]);
        }
        After::GeneralizedForces => {
            s.v[..nv].fill(0.0);
            s.a[..nv].fill(0.0);
            let held = rnea(&m.model, &mut s.data, &s.q, &s.v, &s.a, None)?;
            out.copy_from_slice(&held[..nv]);
            let pulled = rnea(&m.model, &mut s.data, &s.q, &s.v, &s.a, Some(&s.f_ext))?;
            for (k, o) in out.iter_mut().enumerate() {
                *o = forces.tau[k] + (*o - pulled[k]);
            }
        }
    }
    s.f_ext[..nb].fill(Force::ZERO);
    Ok(())
}

impl RuntimeModel {
    /// The drives' names (springs, dampers, muscles, then motors), in the
    /// file's order.
    #[must_use]
    pub fn drive_names(&self) -> Vec<String> {
        self.drives.names.clone()
    }

    /// Drive inputs: the length of `w`.
    #[must_use]
    pub fn nu(&self) -> usize {
        self.drives.inputs.len()
    }

    /// What each entry of `w` is: the muscles' activations (0 to 1), then
    /// the motors' currents (A), by drive name (the generated module's
    /// `input` constants).
    #[must_use]
    pub fn drive_input_names(&self) -> Vec<String> {
        self.drives.inputs.clone()
    }

    /// The file's motors as rodyn's [`JointMotor`], `dof` in this model's
    /// `v`: their torque per ampere
    /// ([`torque_per_current`](JointMotor::torque_per_current)) and the
    /// rotor inertia reflected at the joint
    /// ([`reflected_inertia`](JointMotor::reflected_inertia)), as the
    /// generated module's constants have them.
    #[must_use]
    pub fn motors(&self) -> &[(String, JointMotor<f64>)] {
        &self.drives.motors
    }

    /// Forward dynamics under the file's drives at inputs `w` and further
    /// joint forces `tau`: `q̈ = M⁻¹ (τ + τ_drive − h + Jᵀ f_drive)` into
    /// `a_out` (the compiled path's `forward_dynamics_with_drives` with ABA).
    ///
    /// # Errors
    /// As [`aba`](Self::aba); `w` not of [`nu`](Self::nu) entries or not
    /// finite (named); a drive whose force cannot be evaluated (named: a
    /// muscle stretched off its curves, a path of zero length).
    #[allow(clippy::too_many_arguments)]
    pub fn aba_with_drives(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        tau: &[f64],
        w: &[f64],
        a_out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        self.check_nv("tau", tau)?;
        self.check_nv("a_out", a_out)?;
        self.run_drives(ws, q, v, w, tau, After::Aba, a_out)
    }

    /// The generalized forces of the file's drives at `(q, v)` and inputs
    /// `w`: `Q = τ_drive + Σ Jᵀ f_drive` (the motors' torques and the
    /// springs', dampers' and muscles' pulls mapped to the joints) into
    /// `out`. `Q` is what the drives add to `τ` in `M q̈ + h = τ + Q`.
    ///
    /// # Errors
    /// As [`aba_with_drives`](Self::aba_with_drives).
    pub fn drive_generalized_forces(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        w: &[f64],
        out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        self.check_nv("out", out)?;
        self.run_drives(ws, q, v, w, &[], After::GeneralizedForces, out)
    }

    /// Kinematics in the class, the drives on the drive workspace, then
    /// `after` in the class.
    #[allow(clippy::too_many_arguments)]
    fn run_drives(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        w: &[f64],
        tau: &[f64],
        after: After,
        out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        self.check_q(q)?;
        self.check_nv("v", v)?;
        super::check::length("w", w.len(), self.nu(), "nu")?;
        let inputs = [
            Input {
                name: "q",
                values: q,
            },
            Input {
                name: "v",
                values: v,
            },
            Input {
                name: "tau",
                values: tau,
            },
            Input {
                name: "w",
                values: w,
            },
        ];
        if let Some(bad) = super::check::first_non_finite(&inputs) {
            return Err(bad);
        }
        let nb = self.nb();
        let drive = ws.drive.get_or_insert_with(DriveScratch::new);
        dispatch!(&self.class, &mut ws.class, |m, s| {
            class_kinematics(m, s, q, v, nb, drive)
                .map_err(|e| self.explain("drives (kinematics)", &e, &inputs))
        })?;
        // Only the file's entries are ever written: clearing them is enough
        // (the whole workspace is a few kilobytes).
        let forces = &mut *drive.forces;
        forces.f_ext[..nb].fill(Force::ZERO);
        forces.tau[..self.nv].fill(0.0);
        let state = DriveState {
            data: &drive.data,
            q,
            v: &drive.v,
        };
        for (element, name) in self.drives.elements.iter().zip(&self.drives.names) {
            element.add_forces(&state, w, forces).map_err(|e| {
                RuntimeError::invalid_input(format!("drive '{name}' at the given q, v, w: {e}"))
            })?;
        }
        if let Some(k) = forces.tau.iter().position(|t| !t.is_finite()) {
            return Err(RuntimeError::numerical(format!(
                "drives: {}",
                rodyn::Error::NonFiniteResult {
                    quantity: Quantity::Torque,
                    index: k
                }
            )));
        }
        if let Some(b) = forces.f_ext[..nb].iter().position(|f| !f.is_finite()) {
            let name = self.drives.culprit(&state, w);
            return Err(RuntimeError::numerical(format!(
                "drive '{name}': its force on body {b} is not finite at the given q, v, w"
            )));
        }
        let algorithm = match after {
            After::Aba => "aba with drives",
            After::GeneralizedForces => "drive generalized forces",
        };
        let forces = &*drive.forces;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            class_after_drives(m, s, nb, tau, forces, after, out)
                .map_err(|e| self.explain(algorithm, &e, &inputs))
        })
    }
}
