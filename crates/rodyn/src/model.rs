//! The model: the constant description of a multibody tree.
//!
//! A [`Model`] holds the topology (fixed at compile time through its const
//! parameters) and the physical parameters (changeable at run time through
//! the `set_*` methods). Algorithms read it and never change it, so one model
//! can serve many [`Data`](crate::Data) workspaces and can be a `const` or a
//! `static`.
//!
//! Frames: body i's frame is its joint's moving frame. `placement(i)` is the
//! joint frame at `q = 0` seen from the parent body's frame (Pinocchio's
//! `jointPlacements`), `inertia(i)` is expressed in body i's frame, and
//! `gravity()` is a motion in the world frame whose linear part is the
//! gravitational acceleration (m/s²).
//!
//! The model holds physics and topology only. What an algorithm derives
//! from it once to run faster (CRBA's turned frames) lives in that
//! algorithm's own plan
//! ([`CrbaPlan`](crate::algorithm::crba::CrbaPlan)), never here.

use crate::error::{Error, ModelProblem, Quantity, Result};
use crate::joint::{Joint, JointModel};
use crate::planar::{Planar, PlanarInertia, PlanarJoint, PlanarMotion, PlanarTransform};
use crate::space::{BodyInertia, Space, VectorOps};
use crate::spatial::{Inertia, Motion, Spatial, Transform};
use crate::topology::Topology;
use crate::tuning::FINITE_JOINT_CHECKS;
use crate::Scalar;

/// A multibody tree with `NB` bodies, `NQ` configuration and `NV` velocity
/// coordinates, in geometry `G` ([`Spatial`] or [`Planar`]).
#[derive(Clone, Copy, Debug)]
pub struct Model<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space = Spatial> {
    topology: Topology<NB, NV>,
    /// Invariant: `joints[i]`'s `nq`/`nv` are the topology's `nq[i]`/`nv[i]`
    /// (the algorithms hand each joint the coordinates of its range):
    /// `new`, `try_new` and `new_planar` read the counts from the joints,
    /// `try_from_parts` compares them, `cast` keeps each joint's kind.
    joints: [G::Joint<S>; NB],
    placements: [G::Transform<S>; NB],
    inertias: [G::Inertia<S>; NB],
    gravity: G::Motion<S>,
    armature: [S; NV],
    /// `false` when no joint restricts a finite configuration (no
    /// quaternion, no custom rule), so that a finite `q` needs no further
    /// check. Set by the constructors that know their joints at compile time.
    constrained_configuration: bool,
}

/// Standard gravity, 9.80665 m/s².
pub const STANDARD_GRAVITY: f64 = 9.806_65;

impl<S: Scalar, const NB: usize, const NQ: usize, const NV: usize> Model<S, NB, NQ, NV, Spatial> {
    /// A 3-D model, checked at compile time when evaluated in a `const`.
    ///
    /// `parents[i]` is body i's parent (`None`: attached to the world),
    /// `joints[i]` the joint that moves body i, `placements[i]` that joint's
    /// frame in the parent's frame, `inertias[i]` body i's inertia in its own
    /// frame, `gravity` the world's gravity as a motion (linear part, m/s²).
    ///
    /// # Panics
    /// When the topology is inconsistent (see [`Topology::new`]); in a `const`
    /// this is a compile error. For a tree read at run time, use
    /// [`Model::try_new`], which returns the error instead.
    ///
    /// ```
    /// use rodyn::{Model, joint::{Axis, Joint}, spatial::*};
    /// // A one-link pendulum about z, 1 kg at 0.5 m along x.
    /// const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
    ///     [None],
    ///     [Joint::revolute(Axis::Z)],
    ///     [Transform::IDENTITY],
    ///     [Inertia::point_mass(1.0, Vec3::new(0.5, 0.0, 0.0))],
    ///     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
    /// );
    /// assert_eq!(PENDULUM.topology().idx_v, [0]);
    /// ```
    #[must_use]
    pub const fn new(
        parents: [Option<usize>; NB],
        joints: [Joint<S>; NB],
        placements: [Transform<S>; NB],
        inertias: [Inertia<S>; NB],
        gravity: Motion<S>,
    ) -> Self {
        let mut nq = [0; NB];
        let mut nv = [0; NB];
        let mut constrained_configuration = false;
        let mut i = 0;
        while i < NB {
            nq[i] = joints[i].const_nq();
            nv[i] = joints[i].const_nv();
            constrained_configuration |= joints[i].const_constrains_configuration();
            i += 1;
        }
        // The topology's counts are the joints' own: no mismatch possible.
        Self {
            topology: Topology::new(parents, nq, nv, NQ),
            joints,
            placements,
            inertias,
            gravity,
            armature: [S::ZERO; NV],
            constrained_configuration,
        }
    }

    /// [`Model::new`] for a tree known only at run time (read from a file):
    /// the same checks, reported instead of panicking.
    ///
    /// # Errors
    /// [`Error::InvalidModel`] with [`ModelProblem::Topology`] naming what
    /// is inconsistent (a parent after its child, counts that do not add up
    /// to `NQ`/`NV`, a joint with too many degrees of freedom); `body` is
    /// the body the topology error names, or 0 for a count.
    pub fn try_new(
        parents: [Option<usize>; NB],
        joints: [Joint<S>; NB],
        placements: [Transform<S>; NB],
        inertias: [Inertia<S>; NB],
        gravity: Motion<S>,
    ) -> Result<Self> {
        let topology = Self::try_topology(parents, &joints)?;
        let constrained_configuration = joints.iter().any(|j| j.const_constrains_configuration());
        Ok(Self {
            topology,
            joints,
            placements,
            inertias,
            gravity,
            armature: [S::ZERO; NV],
            constrained_configuration,
        })
    }
}

/// A topology error as the model's, naming its body when it has one.
#[cold]
fn topology_error(error: crate::topology::TopologyError) -> Error {
    use crate::topology::TopologyError as E;
    let body = match error {
        E::ParentAfterChild { body } | E::TooManyJointDofs { body } => body,
        E::ConfigurationCount { .. } | E::VelocityCount { .. } => 0,
    };
    Error::InvalidModel {
        body,
        problem: ModelProblem::Topology(error.problem()),
    }
}

impl<S: Scalar, const NB: usize, const NQ: usize, const NV: usize> Model<S, NB, NQ, NV, Planar> {
    /// A planar model, checked at compile time when evaluated in a `const`;
    /// arguments as for the 3-D [`Model::new`](crate::Model::new).
    ///
    /// # Panics
    /// When the topology is inconsistent; in a `const` a compile error. For
    /// a tree read at run time, use [`Model::try_new_planar`].
    #[must_use]
    pub const fn new_planar(
        parents: [Option<usize>; NB],
        joints: [PlanarJoint<S>; NB],
        placements: [PlanarTransform<S>; NB],
        inertias: [PlanarInertia<S>; NB],
        gravity: PlanarMotion<S>,
    ) -> Self {
        let mut nq = [0; NB];
        let mut nv = [0; NB];
        let mut i = 0;
        while i < NB {
            nq[i] = joints[i].const_nq();
            nv[i] = joints[i].const_nv();
            i += 1;
        }
        // Planar joints are angles and displacements: any finite q is valid.
        // The topology's counts are the joints' own (the loop above).
        Self::assemble(
            Topology::new(parents, nq, nv, NQ),
            joints,
            placements,
            inertias,
            gravity,
        )
        .with_unconstrained_configuration()
    }

    /// [`Model::new_planar`] for a tree known only at run time: the same
    /// checks, reported instead of panicking.
    ///
    /// # Errors
    /// As [`Model::try_new`].
    pub fn try_new_planar(
        parents: [Option<usize>; NB],
        joints: [PlanarJoint<S>; NB],
        placements: [PlanarTransform<S>; NB],
        inertias: [PlanarInertia<S>; NB],
        gravity: PlanarMotion<S>,
    ) -> Result<Self> {
        let topology = Self::try_topology(parents, &joints)?;
        Ok(
            Self::assemble(topology, joints, placements, inertias, gravity)
                .with_unconstrained_configuration(),
        )
    }
}

impl<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>
    Model<S, NB, NQ, NV, G>
{
    /// The tree of `joints` under `parents` laid out for `NQ`, checked:
    /// the run-time constructors' ([`Model::try_new`],
    /// [`Model::try_new_planar`]) shared first step.
    fn try_topology(
        parents: [Option<usize>; NB],
        joints: &[G::Joint<S>; NB],
    ) -> Result<Topology<NB, NV>> {
        Topology::try_new(parents, joints.map(|j| j.nq()), joints.map(|j| j.nv()), NQ)
            .map_err(topology_error)
    }

    /// Assembles a model from a checked topology and the joints it was laid
    /// out for, panicking where [`Self::try_from_parts`] returns an error.
    ///
    /// # Panics
    /// When the topology was laid out for another `NQ` than the model's, or
    /// when a joint's `nq`/`nv` differ from the topology's for its body.
    #[must_use]
    pub fn from_parts(
        topology: Topology<NB, NV>,
        joints: [G::Joint<S>; NB],
        placements: [G::Transform<S>; NB],
        inertias: [G::Inertia<S>; NB],
        gravity: G::Motion<S>,
    ) -> Self {
        match Self::try_from_parts(topology, joints, placements, inertias, gravity) {
            Ok(model) => model,
            Err(error) => panic!("rodyn model: {}", error),
        }
    }

    /// Assembles a model from a checked topology and its joints, for trees
    /// built at run time.
    ///
    /// The algorithms index `q: &[S; NQ]` and `v: &[S; NV]` by the
    /// topology's ranges and hand each joint the coordinates there, so the
    /// topology must be laid out for `NQ` and for these joints' counts.
    ///
    /// # Errors
    /// [`Error::InvalidModel`] with [`ModelProblem::Topology`]
    /// ([`TopologyError::ConfigurationCount`](crate::topology::TopologyError::ConfigurationCount))
    /// when the topology was laid out for another `NQ`, or with
    /// [`ModelProblem::JointCoordinateMismatch`] naming the first body whose
    /// joint's `nq` or `nv` differ from the topology's.
    pub fn try_from_parts(
        topology: Topology<NB, NV>,
        joints: [G::Joint<S>; NB],
        placements: [G::Transform<S>; NB],
        inertias: [G::Inertia<S>; NB],
        gravity: G::Motion<S>,
    ) -> Result<Self> {
        let nq_total = topology.tables().nq_total;
        if nq_total != NQ {
            return Err(topology_error(
                crate::topology::TopologyError::ConfigurationCount {
                    declared: NQ,
                    found: nq_total,
                },
            ));
        }
        if let Some(body) = (0..NB).find(|&i| {
            joints[i].nq() != topology.tables().nq[i] || joints[i].nv() != topology.tables().nv[i]
        }) {
            return Err(Error::InvalidModel {
                body,
                problem: ModelProblem::JointCoordinateMismatch,
            });
        }
        Ok(Self::assemble(
            topology, joints, placements, inertias, gravity,
        ))
    }

    /// Assembles a model whose topology the caller laid out for `NQ` and
    /// for these joints' counts (the geometry constructors, which read the
    /// counts from the joints themselves).
    const fn assemble(
        topology: Topology<NB, NV>,
        joints: [G::Joint<S>; NB],
        placements: [G::Transform<S>; NB],
        inertias: [G::Inertia<S>; NB],
        gravity: G::Motion<S>,
    ) -> Self {
        // `Topology::new` lays the tree out for the `nq_total` it is given;
        // the callers give `NQ` (a compile error in a `const` otherwise).
        assert!(
            topology.tables().nq_total == NQ,
            "rodyn model: the topology's configuration coordinates do not add up to the model's NQ"
        );
        Self {
            topology,
            joints,
            placements,
            inertias,
            gravity,
            armature: [S::ZERO; NV],
            // Trait methods cannot run in a `const fn`: ask every joint.
            constrained_configuration: true,
        }
    }

    /// Declares that no joint restricts a finite configuration, for the
    /// geometry constructors that know it.
    pub(crate) const fn with_unconstrained_configuration(mut self) -> Self {
        self.constrained_configuration = false;
        self
    }

    /// Number of bodies.
    pub const NB: usize = NB;
    /// Number of configuration coordinates.
    pub const NQ: usize = NQ;
    /// Number of velocity coordinates.
    pub const NV: usize = NV;

    /// The tree and its coordinate layout.
    #[must_use]
    pub const fn topology(&self) -> &Topology<NB, NV> {
        &self.topology
    }
    /// Parent of body `i` (`None`: the world).
    #[must_use]
    pub const fn parent(&self, i: usize) -> Option<usize> {
        self.topology.parent(i)
    }

    /// Body `i`'s first configuration coordinate and their count, with
    /// `idx_q[i] + nq[i] <= NQ` known to the optimiser.
    #[must_use]
    #[inline(always)]
    pub const fn configuration_range(&self, i: usize) -> (usize, usize) {
        let (iq, nq) = self.topology.configuration_range(i);
        // SAFETY: every constructor makes the topology's `nq_total` equal
        // `NQ` (`new`, `try_new` and `new_planar` lay it out for `NQ`;
        // `try_from_parts`, `from_parts` and `assemble` refuse another;
        // `cast` copies it) and the model never replaces its topology.
        // Tested in host-tests/tests/model_invariants.rs.
        unsafe { core::hint::assert_unchecked(self.topology.tables().nq_total == NQ) };
        (iq, nq)
    }
    /// The joint that moves body `i`.
    #[must_use]
    pub const fn joint(&self, i: usize) -> &G::Joint<S> {
        &self.joints[i]
    }
    /// Joint `i`'s frame at `q = 0` in its parent's frame.
    #[must_use]
    pub const fn placement(&self, i: usize) -> &G::Transform<S> {
        &self.placements[i]
    }
    /// Body `i`'s inertia in its own frame.
    #[must_use]
    pub const fn inertia(&self, i: usize) -> &G::Inertia<S> {
        &self.inertias[i]
    }
    /// Every joint's placement ([`placement`](Self::placement)).
    #[must_use]
    pub const fn placements(&self) -> &[G::Transform<S>; NB] {
        &self.placements
    }
    /// Every body's inertia ([`inertia`](Self::inertia)).
    #[must_use]
    pub const fn inertias(&self) -> &[G::Inertia<S>; NB] {
        &self.inertias
    }
    /// Gravity in the world frame, as a motion (linear part in m/s²).
    #[must_use]
    pub const fn gravity(&self) -> &G::Motion<S> {
        &self.gravity
    }
    /// Total mass (kg).
    #[must_use]
    pub fn total_mass(&self) -> S {
        self.inertias.iter().fold(S::ZERO, |m, i| m + i.mass())
    }

    /// Changes body `i`'s inertia (a payload, an identified parameter).
    ///
    /// # Errors
    /// [`Error::BodyOutOfRange`] for `i ≥ NB`; [`Error::InvalidModel`] when
    /// the inertia is not physical (non-finite, negative mass, not positive
    /// semi-definite, breaking the triangle inequality, or overflowing
    /// `m |c|²`); the model is then unchanged.
    pub fn set_inertia(&mut self, i: usize, inertia: G::Inertia<S>) -> Result<()> {
        if i >= NB {
            return Err(Error::BodyOutOfRange { body: i });
        }
        G::validate_inertia(&inertia)
            .map_err(|problem| Error::InvalidModel { body: i, problem })?;
        self.inertias[i] = inertia;
        Ok(())
    }
    /// Changes joint `i`'s placement in its parent (a link length).
    ///
    /// # Errors
    /// [`Error::BodyOutOfRange`] for `i ≥ NB`; [`Error::InvalidModel`] for a
    /// non-finite placement, a translation whose `|p|⁴` overflows, a
    /// rotation that is not orthonormal, or a reflection; the model is then
    /// unchanged.
    pub fn set_placement(&mut self, i: usize, placement: G::Transform<S>) -> Result<()> {
        if i >= NB {
            return Err(Error::BodyOutOfRange { body: i });
        }
        G::validate_transform(&placement)
            .map_err(|problem| Error::InvalidModel { body: i, problem })?;
        self.placements[i] = placement;
        Ok(())
    }

    /// The armature of each velocity coordinate: an inertia (kg m² or kg)
    /// added to the diagonal of the mass matrix, such as a motor rotor's
    /// reflected inertia `N² J_r`
    /// ([`JointMotor::reflected_inertia`](crate::drive::JointMotor::reflected_inertia)).
    /// Zero unless set. CRBA adds it to `M`, ABA to each joint's `D`, RNEA
    /// adds `armature · q̈` to `τ`, and the kinetic energy counts it.
    #[must_use]
    pub const fn armature(&self) -> &[S; NV] {
        &self.armature
    }
    /// The model with the per-coordinate `armature` (usable in `const`).
    #[must_use]
    pub const fn with_armature(mut self, armature: [S; NV]) -> Self {
        self.armature = armature;
        self
    }
    /// Changes the armature of velocity coordinate `dof`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite value, [`Error::InvalidModel`]
    /// with [`ModelProblem::InvalidInertia`] for a negative one (the body
    /// index reported is the joint's), and
    /// [`Error::InvalidDrive`] for a `dof` out of range.
    ///
    /// # Example
    ///
    /// ```
    /// use rodyn::algorithm::rnea::rnea;
    /// use rodyn::drive::JointMotor;
    /// # use rodyn::prelude::*;
    /// # // A 1 kg point mass on a massless 1 m link, pivot about z, gravity -y.
    /// # const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
    /// #     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
    /// #     [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
    /// #     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
    /// # );
    /// let mut model = PENDULUM;
    /// // A 50:1 gearbox on a 2e-5 kg m² rotor adds N² J_r = 0.05 kg m² at the joint.
    /// let motor = JointMotor::new(0, 0, 50.0, 0.02, 2e-5);
    /// model.set_armature(0, motor.reflected_inertia()?)?;
    /// let mut data = Data::new();
    /// let tau = rnea(&model, &mut data, &[0.0], &[0.0], &[1.0], None)?;
    /// assert!((tau[0] - (1.0 + 0.05 + 9.81)).abs() < 1e-12);
    /// assert!(model.set_armature(1, 0.1).is_err()); // only one velocity coordinate
    /// assert!(model.set_armature(0, -0.1).is_err()); // not physical
    /// # Ok::<(), rodyn::Error>(())
    /// ```
    pub fn set_armature(&mut self, dof: usize, armature: S) -> Result<()> {
        if dof >= NV {
            return Err(Error::InvalidDrive {
                problem: crate::error::DriveProblem::DofOutOfRange { dof },
            });
        }
        if !armature.is_finite() {
            return Err(Error::NonFinite {
                quantity: Quantity::ModelParameter,
                index: dof,
            });
        }
        if armature.to_f64() < 0.0 {
            return Err(Error::InvalidModel {
                body: self.topology.body_of_v[dof],
                problem: ModelProblem::InvalidInertia,
            });
        }
        self.armature[dof] = armature;
        Ok(())
    }
    /// Changes gravity (world frame).
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a non-finite vector.
    ///
    /// # Example
    ///
    /// ```
    /// use rodyn::algorithm::rnea::gravity_torques;
    /// # use rodyn::prelude::*;
    /// # // A 1 kg point mass on a massless 1 m link, pivot about z, gravity -y.
    /// # const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
    /// #     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
    /// #     [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
    /// #     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
    /// # );
    /// let mut model = PENDULUM;
    /// let mut data = Data::new();
    /// // The same arm on the Moon.
    /// model.set_gravity(Motion::new(Vec3::ZERO, Vec3::new(0.0, -1.62, 0.0)))?;
    /// assert!((gravity_torques(&model, &mut data, &[0.0])?[0] - 1.62).abs() < 1e-12);
    /// // A NaN is refused and the model keeps its gravity.
    /// assert!(model.set_gravity(Motion::new(Vec3::ZERO, Vec3::new(0.0, f64::NAN, 0.0))).is_err());
    /// assert!((model.gravity().lin.y + 1.62).abs() < 1e-15);
    /// # Ok::<(), rodyn::Error>(())
    /// ```
    pub fn set_gravity(&mut self, gravity: G::Motion<S>) -> Result<()> {
        if !gravity.is_finite() {
            return Err(Error::NonFinite {
                quantity: Quantity::ModelParameter,
                index: 0,
            });
        }
        self.gravity = gravity;
        Ok(())
    }

    /// Checks every physical parameter: masses, inertias (positive
    /// semi-definite, triangle inequality), axes of unit length, orthonormal
    /// rotations. `const` construction checks only the topology.
    ///
    /// # Errors
    /// The first [`Error::InvalidModel`] found.
    pub fn validate(&self) -> Result<()> {
        for i in 0..NB {
            let err = |problem| Error::InvalidModel { body: i, problem };
            G::validate_inertia(&self.inertias[i]).map_err(err)?;
            G::validate_transform(&self.placements[i]).map_err(err)?;
            G::validate_joint(&self.joints[i]).map_err(err)?;
        }
        if !self.gravity.is_finite() {
            return Err(Error::NonFinite {
                quantity: Quantity::ModelParameter,
                index: 0,
            });
        }
        Ok(())
    }

    /// The same model in another scalar type (e.g. `f64` to `f32` or to
    /// [`Dual`](crate::Dual)).
    ///
    /// # Errors
    /// [`Error::UnsupportedCast`] for a model with a custom joint.
    pub fn cast<T: Scalar>(&self) -> Result<Model<T, NB, NQ, NV, G>> {
        let mut joints = [G::default_joint::<T>(); NB];
        for (i, j) in joints.iter_mut().enumerate() {
            *j = G::cast_joint(&self.joints[i]).ok_or(Error::UnsupportedCast { body: i })?;
        }
        Ok(Model {
            topology: self.topology,
            joints,
            placements: core::array::from_fn(|i| G::cast_transform(&self.placements[i])),
            inertias: core::array::from_fn(|i| G::cast_inertia(&self.inertias[i])),
            gravity: G::cast_motion(&self.gravity),
            armature: core::array::from_fn(|k| T::from_f64(self.armature[k].to_f64())),
            constrained_configuration: self.constrained_configuration,
        })
    }

    /// Checks a configuration: length, finiteness, unit quaternions.
    ///
    /// # Errors
    /// [`Error::InvalidConfiguration`] naming the first bad joint.
    pub fn check_configuration(&self, q: &[S; NQ]) -> Result<()> {
        // Every dynamics call starts here. One pass over `q` settles
        // finiteness for all joints; only joints with a further condition
        // (a unit quaternion, a user's rule) are then asked. Walking and
        // slicing every joint cost instructions on every joint on the
        // Cortex-M4 (docs/sections/performance_notebook.md, "Model
        // checks"). Out of order those are asked only their further
        // conditions (`check_finite_configuration`: a free flyer's
        // quaternion norm), finiteness being settled (`FINITE_JOINT_CHECKS`).
        // A non-finite `q` takes the joint-by-joint walk below, which names
        // the joint exactly as before.
        if sum_is_finite(q) {
            if !self.constrained_configuration {
                return Ok(());
            }
            for (i, joint) in self.joints.iter().enumerate() {
                if joint.constrains_configuration() {
                    // Two whole arms, not one call of a method chosen
                    // first: that form changed the Cortex-M4's inlining and
                    // cost its Jacobians stack.
                    if FINITE_JOINT_CHECKS {
                        joint
                            .check_finite_configuration(self.joint_q(i, q)?)
                            .map_err(|reason| Error::InvalidConfiguration { joint: i, reason })?;
                    } else {
                        joint
                            .check_configuration(self.joint_q(i, q)?)
                            .map_err(|reason| Error::InvalidConfiguration { joint: i, reason })?;
                    }
                }
            }
            return Ok(());
        }
        for i in 0..NB {
            self.joints[i]
                .check_configuration(self.joint_q(i, q)?)
                .map_err(|reason| Error::InvalidConfiguration { joint: i, reason })?;
        }
        Ok(())
    }

    /// Body `i`'s `nq[i]` coordinates of `q`, or the error of a topology
    /// that does not fit `q` (never one built by `Topology::try_new`):
    /// an early exit, not a panic path.
    #[inline(always)]
    fn joint_q<'q>(&self, i: usize, q: &'q [S; NQ]) -> Result<&'q [S]> {
        let iq = self.topology.idx_q[i];
        q.get(iq..iq + self.topology.nq[i])
            .ok_or_else(|| inconsistent_topology(i))
    }

    /// The neutral configuration (zero angles, identity quaternions).
    #[must_use]
    pub fn neutral_configuration(&self) -> [S; NQ] {
        let mut q = [S::ZERO; NQ];
        for i in 0..NB {
            let iq = self.topology.idx_q[i];
            // A valid topology keeps the range in `q` (`Topology::try_new`).
            if let Some(joint_q) = q.get_mut(iq..iq + self.topology.nq[i]) {
                self.joints[i].neutral(joint_q);
            }
        }
        q
    }

    /// `q ⊕ v dt` for every joint (quaternions through the exponential map).
    ///
    /// # Errors
    /// [`Error::NonFinite`] naming a non-finite entry of `q`
    /// ([`Quantity::Configuration`]), `v` ([`Quantity::Velocity`]) or `dt`
    /// ([`Quantity::Time`]); [`Error::NonFiniteResult`] with
    /// [`Quantity::Configuration`] when finite inputs overflow (a velocity
    /// of 1e308 over a second); [`Error::InvalidConfiguration`] naming the
    /// joint whose result is not on its manifold (a zero quaternion in `q`
    /// stays zero).
    ///
    /// # Example
    ///
    /// ```
    /// use rodyn::prelude::*;
    /// // One free-floating 1 kg ball; q = (x, y, z, qx, qy, qz, qw), v = (v, ω) in the body frame.
    /// const BALL: Model<f64, 1, 7, 6> = Model::new(
    ///     [None], [Joint::free_flyer()], [Transform::IDENTITY],
    ///     [Inertia::point_mass(1.0, Vec3::ZERO)], Motion::new(Vec3::ZERO, Vec3::ZERO),
    /// );
    /// let q0 = BALL.neutral_configuration();
    /// // Half a turn about z in one second, moving along x.
    /// let q1 = BALL.integrate(&q0, &[1.0, 0.0, 0.0, 0.0, 0.0, core::f64::consts::PI], 1.0)?;
    /// // The quaternion stays of unit length: (0, 0, sin(π/2), cos(π/2)).
    /// assert!((q1[5] - 1.0).abs() < 1e-12 && q1[6].abs() < 1e-12);
    /// // Pinocchio's SE(3) exponential: the body runs a half circle of radius 1/π.
    /// assert!(q1[0].abs() < 1e-12 && (q1[1] - 2.0 / core::f64::consts::PI).abs() < 1e-12);
    /// // A NaN step is named, not passed on.
    /// assert!(BALL.integrate(&q0, &[0.0; 6], f64::NAN).is_err());
    /// # Ok::<(), rodyn::Error>(())
    /// ```
    pub fn integrate(&self, q: &[S; NQ], v: &[S; NV], dt: S) -> Result<[S; NQ]> {
        let out = self.integrate_unvalidated(q, v, dt);
        // One check of the result on the way out; the inputs are only
        // looked at to name the cause when it fails.
        let Err(error) = self.check_configuration(&out) else {
            return Ok(out);
        };
        check_finite(q, Quantity::Configuration)?;
        check_finite(v, Quantity::Velocity)?;
        check_finite(&[dt], Quantity::Time)?;
        check_result(&out, Quantity::Configuration)?;
        Err(error)
    }

    /// [`integrate`](Self::integrate) without the checks, for the
    /// integrators, which check the whole next state once before they
    /// commit it.
    pub(crate) fn integrate_unvalidated(&self, q: &[S; NQ], v: &[S; NV], dt: S) -> [S; NQ] {
        let mut out = *q;
        for i in 0..NB {
            let (iq, iv) = (self.topology.idx_q[i], self.topology.idx_v[i]);
            let (nq, nv) = (self.topology.nq[i], self.topology.nv[i]);
            // A valid topology keeps the ranges in `q` and `v`
            // (`Topology::try_new`); one that does not fit leaves those
            // coordinates as they were.
            let (Some(q_i), Some(v_i), Some(out_i)) = (
                q.get(iq..iq + nq),
                v.get(iv..iv + nv),
                out.get_mut(iq..iq + nq),
            ) else {
                continue;
            };
            self.joints[i].integrate(q_i, v_i, dt, out_i);
        }
        out
    }

    /// Renormalises every quaternion in `q` in place. A quaternion is
    /// divided by its largest entry first, so one of norm 1e200 or a
    /// subnormal one normalises correctly; a zero or non-finite one has no
    /// direction to keep and is an error, never a silent zero.
    ///
    /// # Errors
    /// [`Error::InvalidConfiguration`] naming the first joint whose
    /// coordinates are not finite ([`ConfigurationError::NonFinite`]) or
    /// whose quaternion is zero ([`ConfigurationError::QuaternionNotUnit`]
    /// with norm 0); `q` is then left as it was.
    ///
    /// [`ConfigurationError::NonFinite`]: crate::error::ConfigurationError::NonFinite
    /// [`ConfigurationError::QuaternionNotUnit`]: crate::error::ConfigurationError::QuaternionNotUnit
    pub fn normalize(&self, q: &mut [S; NQ]) -> Result<()> {
        let mut out = *q;
        // Joint by joint rather than through `check_configuration`, which
        // every algorithm inlines: sharing it changed their code on the MCU.
        for i in 0..NB {
            let iq = self.topology.idx_q[i];
            let joint_q = out
                .get_mut(iq..iq + self.topology.nq[i])
                .ok_or_else(|| inconsistent_topology(i))?;
            self.joints[i].normalize(joint_q);
            self.joints[i]
                .check_configuration(joint_q)
                .map_err(|reason| Error::InvalidConfiguration { joint: i, reason })?;
        }
        *q = out;
        Ok(())
    }

    /// [`normalize`](Self::normalize) without the check, for the
    /// integrators: a zero quaternion stays zero and the next dynamics
    /// call names its joint.
    pub(crate) fn normalize_unvalidated(&self, q: &mut [S; NQ]) {
        for i in 0..NB {
            let iq = self.topology.idx_q[i];
            // A valid topology keeps the range in `q` (`Topology::try_new`).
            if let Some(joint_q) = q.get_mut(iq..iq + self.topology.nq[i]) {
                self.joints[i].normalize(joint_q);
            }
        }
    }
}

/// `true` only when every entry of `x` is finite: an infinite or NaN entry
/// makes the sum of the entries infinite or NaN, so a finite sum proves
/// them all finite. `false` also when the sum of finite entries overflows;
/// the caller then searches the entries. One addition per entry, sixteen
/// partial sums and no early exit, so that the test of a whole matrix runs
/// in vector lanes with enough independent sums to hide the additions'
/// latency.
#[inline]
fn all_finite<S: Scalar>(x: &[S]) -> bool {
    let chunks = x.chunks_exact(16);
    let rest = chunks.remainder();
    let mut sums = [S::ZERO; 16];
    for chunk in chunks {
        for (sum, v) in sums.iter_mut().zip(chunk) {
            *sum += *v;
        }
    }
    for (sum, v) in sums.iter_mut().zip(rest) {
        *sum += *v;
    }
    sums.iter().fold(S::ZERO, |a, b| a + *b).is_finite()
}

/// `true` only when every entry of `x` is finite, as [`all_finite`] for
/// short vectors (a configuration): four partial sums, so that the host
/// adds two entries per instruction without waiting on one long chain,
/// and no fold of sixteen sums for a model of one or two coordinates.
/// `false` also when the sum of finite entries overflows; the caller then
/// walks the entries.
#[inline(always)]
fn sum_is_finite<S: Scalar>(x: &[S]) -> bool {
    let mut sums = [S::ZERO; 4];
    for chunk in x.chunks(4) {
        for (sum, v) in sums.iter_mut().zip(chunk) {
            *sum += *v;
        }
    }
    ((sums[0] + sums[1]) + (sums[2] + sums[3])).is_finite()
}

/// The error of a topology whose index tables do not fit the model's
/// vectors at body `i`: the early exit of a range tested in safe code,
/// never taken (every [`Topology`] is built by `Topology::try_new`).
#[cold]
pub(crate) fn inconsistent_topology(i: usize) -> Error {
    Error::InvalidModel {
        body: i,
        problem: crate::error::ModelProblem::InconsistentTopology,
    }
}

/// Returns an error naming the first non-finite entry of `x`.
pub(crate) fn check_finite<S: Scalar>(x: &[S], quantity: Quantity) -> Result<()> {
    match x.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(Error::NonFinite { quantity, index }),
        None => Ok(()),
    }
}

/// Returns an error naming the first non-finite entry of a result `x`
/// computed from finite inputs: the inputs overflowed the scalar type.
pub(crate) fn check_result<S: Scalar>(x: &[S], quantity: Quantity) -> Result<()> {
    match x.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(Error::NonFiniteResult { quantity, index }),
        None => Ok(()),
    }
}

/// [`check_result`] for results that are spatial vectors (one per body):
/// one finiteness test of their sum, the search for the vector to name
/// (or for none, when the sum of finite vectors overflowed) only on
/// failure.
pub(crate) fn check_vectors_result<S: Scalar, V: VectorOps<S>>(
    x: &[V],
    quantity: Quantity,
) -> Result<()> {
    let mut sum = V::ZERO;
    for v in x {
        sum += *v;
    }
    if sum.is_finite() {
        return Ok(());
    }
    match x.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(Error::NonFiniteResult { quantity, index }),
        None => Ok(()),
    }
}

/// [`check_result`] for large results (the derivative matrices): the
/// vectorised test first, the search for the entry to name (or for none,
/// when the test's sum overflowed) only on failure. Its own function so
/// that images that check only short vectors do not grow.
pub(crate) fn check_matrix_result<S: Scalar>(x: &[S], quantity: Quantity) -> Result<()> {
    if all_finite(x) {
        return Ok(());
    }
    check_result(x, quantity)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A model assembled at run time reaches the hinted ranges only when
    /// its joints match the topology (Miri checks each hint it reaches).
    #[test]
    fn run_time_assembly_checks_what_the_hints_assume() {
        use crate::joint::Axis;
        use crate::spatial::Vec3;
        let body = Inertia::point_mass(1.0, Vec3::new(0.5, 0.0, 0.0));
        let gravity = Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81));
        let joints = [Joint::free_flyer(), Joint::revolute(Axis::Z)];
        let swapped = Topology::new([None, Some(0)], [1, 7], [1, 6], 8);
        let refused = Model::<f64, 2, 8, 7>::try_from_parts(
            swapped,
            joints,
            [Transform::IDENTITY; 2],
            [body; 2],
            gravity,
        );
        assert_eq!(
            refused.err(),
            Some(Error::InvalidModel {
                body: 0,
                problem: ModelProblem::JointCoordinateMismatch,
            })
        );
        let model = Model::<f64, 2, 8, 7>::try_from_parts(
            Topology::new([None, Some(0)], [7, 1], [6, 1], 8),
            joints,
            [Transform::IDENTITY; 2],
            [body; 2],
            gravity,
        )
        .expect("the joints match the layout");
        assert_eq!(model.configuration_range(0), (0, 7));
        assert_eq!(model.configuration_range(1), (7, 1));
        assert_eq!(model.topology().velocity_range(1), (6, 1));
        let q = model.neutral_configuration();
        assert_eq!(q[3..7], [0.0, 0.0, 0.0, 1.0]);
        assert!(model.check_configuration(&q).is_ok());
        assert!(Model::<f64, 2, 8, 7>::try_new(
            [Some(1), None],
            joints,
            [Transform::IDENTITY; 2],
            [body; 2],
            gravity,
        )
        .is_err());
    }

    /// The vectorised test passes finite entries whose sum overflows (after
    /// the search finds none) and names the first non-finite entry, also
    /// when infinities of both signs would cancel to NaN in the sum.
    #[test]
    fn matrix_check_overflowing_sum_and_named_entry() {
        assert!(check_matrix_result(&[f64::MAX; 20], Quantity::Derivative).is_ok());
        assert!(check_matrix_result(&[f32::MAX; 7], Quantity::Derivative).is_ok());
        let mut x = [1.0f64; 37];
        x[33] = f64::NAN;
        assert!(matches!(
            check_matrix_result(&x, Quantity::Derivative),
            Err(Error::NonFiniteResult { index: 33, .. })
        ));
        x[33] = 1.0;
        x[5] = f64::INFINITY;
        x[21] = f64::NEG_INFINITY;
        assert!(matches!(
            check_matrix_result(&x, Quantity::Derivative),
            Err(Error::NonFiniteResult { index: 5, .. })
        ));
    }

    /// The configuration's finiteness test by sums passes finite
    /// coordinates whose sum overflows (the joints are then walked and
    /// find nothing) and names the joint of a NaN or of infinities of both
    /// signs, which would cancel to NaN in the sum.
    #[test]
    fn configuration_check_overflowing_sum_and_named_joint() {
        use crate::joint::{Axis, ConfigurationError, Joint};
        use crate::spatial::{Motion, Transform, Vec3};
        let link = crate::spatial::Inertia::point_mass(1.0, Vec3::new(0.5, 0.0, 0.0));
        let chain: Model<f64, 5, 5, 5> = Model::new(
            [None, Some(0), Some(1), Some(2), Some(3)],
            [Joint::revolute(Axis::Z); 5],
            [Transform::IDENTITY; 5],
            [link; 5],
            Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
        );
        assert!(chain.check_configuration(&[f64::MAX; 5]).is_ok());
        let mut q = [0.1; 5];
        q[3] = f64::NAN;
        assert!(matches!(
            chain.check_configuration(&q),
            Err(Error::InvalidConfiguration {
                joint: 3,
                reason: ConfigurationError::NonFinite
            })
        ));
        q[3] = 0.1;
        q[1] = f64::INFINITY;
        q[4] = f64::NEG_INFINITY;
        assert!(matches!(
            chain.check_configuration(&q),
            Err(Error::InvalidConfiguration { joint: 1, .. })
        ));
    }
}
