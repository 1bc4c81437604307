//! Errors: what failed and where, never a silent NaN.

use crate::spatial::ParameterProblem;
use core::fmt;

/// Which input or result a non-finite value was found in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// Joint configuration `q`.
    Configuration,
    /// Joint velocity `v`.
    Velocity,
    /// Joint acceleration `a`.
    Acceleration,
    /// Joint torque `tau`.
    Torque,
    /// An external force on a body.
    ExternalForce,
    /// A model parameter (inertia, placement, gravity).
    ModelParameter,
    /// An auxiliary state of a simulation, such as a muscle activation.
    AuxiliaryState,
    /// An energy (a result).
    Energy,
    /// The mass matrix (a result; `index` is the diagonal entry).
    MassMatrix,
    /// A simulation's time or step.
    Time,
    /// A contact parameter or a contact point's state.
    Contact,
    /// A drive input `w` (a muscle activation, a motor current).
    DriveInput,
    /// A derivative of the dynamics (a result; `index` is `row · NV +
    /// column` of its matrix).
    Derivative,
    /// The length of a muscle's path (`index` is the muscle's input).
    PathLength,
    /// The lengthening velocity of a muscle's path (`index` is the
    /// muscle's input).
    PathVelocity,
    /// A point given to
    /// [`GroundContact::force_at`](crate::sim::contact::GroundContact::force_at):
    /// its position (`index` 0–2) or velocity (3–5).
    ContactPoint,
    /// A frame's placement in its body (`index` is the frame's body), or
    /// the frame's pose, velocity or acceleration formed from it.
    FramePlacement,
    /// A body's spatial acceleration (a result; `index` is the body): it
    /// overflows when the products of the joint velocities do.
    BodyAcceleration,
    /// The centroidal momentum map or its time variation (a result;
    /// `index` counts its entries, row by row).
    CentroidalMap,
    /// An inverse-kinematics target pose.
    Target,
    /// A drive element's parameter or result (a spring's tension or
    /// energy, a motor's reflected inertia; `index` as the element
    /// documents).
    Drive,
    /// A point of a drive's path (a spring's, a damper's, a muscle's;
    /// `index` is the point's place along the path, from 0), or the path's
    /// length and rate formed from the points.
    PathPoint,
    /// An argument of a muscle curve or of the activation dynamics (a
    /// normalised fibre length or velocity, a tendon length or force, a
    /// force-velocity multiplier, an excitation or activation; `index` is
    /// the argument's place, from 0), or the curve's value (`index` 0) and
    /// slopes (1, 2).
    MuscleCurve,
    /// A Jacobian's column (`index` is the column) given to
    /// [`mul_rates`](crate::algorithm::jacobian::mul_rates), or its product
    /// with the joint rates (`index` 0).
    Jacobian,
    /// A dense linear system solved by
    /// [`cholesky_solve`](crate::algorithm::dense::cholesky_solve): a row of
    /// its factor `L` or an entry of its right-hand side (`index` is the
    /// row), or of its solution.
    LinearSystem,
    /// A world pose given to a reader (`index` is the body whose pose it
    /// is; 0 for a frame's pose given alone).
    WorldPose,
}

impl Quantity {
    /// The quantity in words.
    #[must_use]
    pub const fn describe(&self) -> &'static str {
        match self {
            Self::Configuration => "joint configuration q",
            Self::Velocity => "joint velocity v",
            Self::Acceleration => "joint acceleration",
            Self::Torque => "joint torque",
            Self::ExternalForce => "external force",
            Self::ModelParameter => "model parameter",
            Self::AuxiliaryState => "auxiliary state",
            Self::Energy => "energy",
            Self::MassMatrix => "mass matrix",
            Self::Time => "time or step",
            Self::Contact => "contact",
            Self::DriveInput => "drive input",
            Self::Derivative => "derivative",
            Self::PathLength => "muscle path length",
            Self::PathVelocity => "muscle path velocity",
            Self::ContactPoint => "contact point",
            Self::FramePlacement => "frame placement",
            Self::BodyAcceleration => {
                "body acceleration (joint velocities too large: their products overflow)"
            }
            Self::CentroidalMap => "centroidal momentum map",
            Self::Target => "target pose",
            Self::Drive => "drive element",
            Self::PathPoint => "drive path point",
            Self::MuscleCurve => "muscle curve argument",
            Self::Jacobian => "Jacobian",
            Self::LinearSystem => "linear system",
            Self::WorldPose => "world pose",
        }
    }

    /// What the index of an error about this quantity counts.
    #[must_use]
    pub const fn index_name(&self) -> &'static str {
        match self {
            Self::ExternalForce | Self::BodyAcceleration | Self::ModelParameter => "body",
            Self::FramePlacement => "frame on body",
            Self::Contact => "contact",
            Self::PathLength | Self::PathVelocity => "muscle input",
            Self::PathPoint => "point",
            Self::MuscleCurve => "argument",
            Self::Jacobian => "column",
            Self::LinearSystem => "row",
            Self::WorldPose => "body",
            _ => "entry",
        }
    }
}

/// What is wrong with a model parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModelProblem {
    /// Negative or non-finite mass.
    InvalidMass,
    /// Rotational inertia not symmetric positive semi-definite, or breaking
    /// the triangle inequality of principal moments.
    InvalidInertia,
    /// A joint axis that is not of unit length.
    AxisNotUnit,
    /// A placement whose rotation is not orthonormal.
    RotationNotOrthonormal,
    /// A parameter with a NaN or infinite entry.
    NonFiniteParameter,
    /// A placement whose rotation is orthonormal but a reflection
    /// (determinant −1), which no rigid motion is.
    Reflection,
    /// Finite numbers whose products (such as `m |c|²` or `m²`) overflow
    /// the scalar type, so the algorithms could not use them.
    Overflow,
    /// The topology's index tables do not fit the model's vectors (a
    /// parent after its child, coordinates past the end). Never reported
    /// since every [`Topology`](crate::topology::Topology) comes from
    /// [`Topology::try_new`](crate::topology::Topology::try_new) and its
    /// tables cannot be written; kept for the model's checks that test
    /// the ranges in safe code and for compatibility.
    InconsistentTopology,
    /// The joint's coordinate counts (`nq`, `nv`) differ from those the
    /// topology lays out for its body: the algorithms would index the
    /// joint's coordinates outside its range.
    JointCoordinateMismatch,
    /// The tree's layout is inconsistent (reported by
    /// [`Model::try_new`](crate::Model::try_new) for a tree read at run
    /// time); the body is the one the check names, or 0 for a count that
    /// does not add up.
    Topology(TopologyProblem),
}

/// Which check of a tree's layout failed (the detail of
/// [`ModelProblem::Topology`]; [`TopologyError`](crate::topology::TopologyError)
/// carries the counts). Fieldless, so that [`Error`] stays as small as the
/// control tick's results need.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum TopologyProblem {
    /// A body's parent does not come before it (`parent[i] < i` fails).
    ParentAfterChild,
    /// A joint with more than six degrees of freedom.
    TooManyJointDofs,
    /// The joints' configuration coordinates do not add up to `NQ`.
    ConfigurationCount,
    /// The joints' velocity coordinates do not add up to `NV`.
    VelocityCount,
}

impl TopologyProblem {
    /// A one-sentence explanation.
    #[must_use]
    pub const fn message(self) -> &'static str {
        match self {
            Self::ParentAfterChild => {
                "every body's parent must come before it (parent[i] < i); reorder the bodies"
            }
            Self::TooManyJointDofs => "a joint has more than 6 degrees of freedom",
            Self::ConfigurationCount => "the joints' configuration coordinates do not add up to NQ",
            Self::VelocityCount => "the joints' velocity coordinates do not add up to NV",
        }
    }
}

impl From<ParameterProblem> for ModelProblem {
    /// The algebra's reason as the model's problem (the model names the
    /// body).
    fn from(problem: ParameterProblem) -> Self {
        match problem {
            ParameterProblem::NonFinite => Self::NonFiniteParameter,
            ParameterProblem::InvalidMass => Self::InvalidMass,
            ParameterProblem::InvalidInertia => Self::InvalidInertia,
            ParameterProblem::Overflow => Self::Overflow,
            ParameterProblem::RotationNotOrthonormal => Self::RotationNotOrthonormal,
            ParameterProblem::Reflection => Self::Reflection,
        }
    }
}

/// A setting of an algorithm that [`Error::InvalidSetting`] names: a field
/// of its settings or one of its arguments.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Setting {
    /// Baumgarte's position gain `K_p` of the contacts.
    PositionGain,
    /// Baumgarte's velocity gain `K_d` of the contacts.
    VelocityGain,
    /// The damping `μ` of a contact solve (redundant contacts).
    ContactDamping,
    /// The coefficient of restitution `e` of an impact.
    Restitution,
    /// The number of unactuated leading velocity coordinates.
    Unactuated,
    /// The regularisation `ε` of the contact force distribution.
    Regularisation,
    /// Coulomb's friction coefficient `μ`.
    Friction,
    /// The number of projected Gauss–Seidel sweeps.
    Sweeps,
    /// The fraction `β` of a penetration removed per step.
    DepthRecovery,
    /// The height above the ground within which points become contacts.
    Margin,
    /// The implicit damping of one joint coordinate.
    JointDamping {
        /// The velocity coordinate.
        dof: usize,
    },
    /// The damping `λ` of inverse kinematics' least-squares steps.
    IkDamping,
    /// The tolerance of inverse kinematics on the pose error.
    IkTolerance,
}

impl Setting {
    /// The setting in words.
    #[must_use]
    pub const fn name(&self) -> &'static str {
        match self {
            Self::PositionGain => "Baumgarte position gain Kp",
            Self::VelocityGain => "Baumgarte velocity gain Kd",
            Self::ContactDamping => "contact damping",
            Self::Restitution => "restitution",
            Self::Unactuated => "number of unactuated coordinates",
            Self::Regularisation => "regularisation of the contact forces",
            Self::Friction => "friction coefficient",
            Self::Sweeps => "sweeps",
            Self::DepthRecovery => "depth recovery",
            Self::Margin => "contact margin",
            Self::JointDamping { .. } => "joint damping",
            Self::IkDamping => "inverse-kinematics damping",
            Self::IkTolerance => "inverse-kinematics tolerance",
        }
    }

    /// Where it is set: the field or argument.
    #[must_use]
    pub const fn field(&self) -> &'static str {
        match self {
            Self::PositionGain => "ConstraintSettings::kp",
            Self::VelocityGain => "ConstraintSettings::kd",
            Self::ContactDamping => "ConstraintSettings::damping, impulse_dynamics' damping",
            Self::Restitution => "impulse_dynamics' restitution",
            Self::Unactuated => "ContactInverseDynamicsSettings::unactuated",
            Self::Regularisation => "ContactInverseDynamicsSettings::regularisation",
            Self::Friction => {
                "ContactInverseDynamicsSettings::friction, TimeSteppingSettings::friction"
            }
            Self::Sweeps => "TimeSteppingSettings::sweeps",
            Self::DepthRecovery => "TimeSteppingSettings::depth_recovery",
            Self::Margin => "TimeSteppingSettings::margin",
            Self::JointDamping { .. } => "time_step's damping",
            Self::IkDamping => "IkSettings::damping, step's damping",
            Self::IkTolerance => "IkSettings::tolerance",
        }
    }

    /// What it must be.
    #[must_use]
    pub const fn requirement(&self) -> &'static str {
        match self {
            Self::PositionGain
            | Self::VelocityGain
            | Self::ContactDamping
            | Self::Friction
            | Self::Margin
            | Self::JointDamping { .. } => "must be finite and not negative",
            Self::Restitution | Self::DepthRecovery => "must lie in [0, 1]",
            Self::Unactuated => "must be at most 6 and at most the model's velocity coordinates",
            Self::Regularisation | Self::IkDamping | Self::IkTolerance => {
                "must be finite and positive"
            }
            Self::Sweeps => "must be at least 1",
        }
    }
}

impl fmt::Display for Setting {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())?;
        if let Self::JointDamping { dof } = self {
            write!(f, " of velocity coordinate {dof}")?;
        }
        Ok(())
    }
}

/// What is wrong with a drive element (see [`crate::drive`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum DriveProblem {
    /// An endpoint names a body the model does not have.
    BodyOutOfRange {
        /// The body index given.
        body: usize,
    },
    /// A joint drive names a velocity coordinate the model does not have.
    DofOutOfRange {
        /// The velocity coordinate given.
        dof: usize,
    },
    /// An element reads an entry past the end of the drive-input vector.
    InputOutOfRange {
        /// The input index given.
        input: usize,
    },
    /// A muscle parameter that is non-finite or outside its physical range;
    /// `index` counts the fields of
    /// [`ThelenParameters`](crate::drive::ThelenParameters) in order (0:
    /// maximum isometric force … 11: maximum lengthening force).
    MuscleParameter {
        /// The field's index.
        index: usize,
    },
    /// An element without derivatives with respect to the state (see
    /// [`ForceElement::add_state_derivatives`](crate::drive::ForceElement::add_state_derivatives)).
    NotDifferentiable,
}

/// The error type of every fallible rodyn function.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// An input contained NaN or infinity; `index` is the coordinate (or body) index.
    NonFinite {
        /// Which input.
        quantity: Quantity,
        /// Index of the first offending entry.
        index: usize,
    },
    /// A joint configuration that is not on the joint's manifold.
    InvalidConfiguration {
        /// Body (joint) index.
        joint: usize,
        /// The problem.
        reason: ConfigurationError,
    },
    /// ABA met a joint whose `D = Sᵀ I^A S` is not safely positive definite:
    /// the subtree it moves is (nearly) massless in the joint's direction.
    SingularArticulatedInertia {
        /// Body (joint) index.
        joint: usize,
        /// The pivot found, relative to the articulated inertia's scale.
        relative_pivot: f64,
    },
    /// The mass matrix is not (numerically) positive definite.
    MassMatrixNotPositiveDefinite {
        /// Velocity coordinate at which the factorisation broke down.
        dof: usize,
        /// The pivot found, relative to its own diagonal entry of the mass
        /// matrix (`D[k] / M[k][k]`: the share of the coordinate's inertia
        /// that the others do not already account for).
        relative_pivot: f64,
    },
    /// A model parameter is physically impossible.
    InvalidModel {
        /// Body index.
        body: usize,
        /// The problem.
        problem: ModelProblem,
    },
    /// A scalar type conversion that the model does not support (custom joints).
    UnsupportedCast {
        /// Body index of the custom joint.
        body: usize,
    },
    /// A drive element that does not fit the model or the input vector.
    InvalidDrive {
        /// The problem.
        problem: DriveProblem,
    },
    /// A frame fixed on a body the model does not have.
    FrameBodyOutOfRange {
        /// The frame's body index.
        body: usize,
    },
    /// An iterative solver (inverse kinematics) used its whole iteration
    /// budget without meeting its tolerance.
    NotConverged {
        /// Iterations run.
        iterations: usize,
        /// The residual's norm when it stopped.
        residual: f64,
    },
    /// Finite inputs gave a non-finite result: numbers beyond what the
    /// scalar type holds (a velocity of 1e154 squared in f64, 1e19 in f32).
    NonFiniteResult {
        /// Which result.
        quantity: Quantity,
        /// Index of the first offending entry.
        index: usize,
    },
    /// A body index past the model's bodies (a parameter setter, a contact
    /// point).
    BodyOutOfRange {
        /// The body index given.
        body: usize,
    },
    /// More constrained rows than a workspace holds.
    TooManyConstraints {
        /// Rows asked for.
        rows: usize,
        /// Rows the workspace holds.
        capacity: usize,
    },
    /// A setting (a gain, a coefficient, a count) outside its range;
    /// [`Setting`] names it and says what it must be.
    InvalidSetting {
        /// Which setting.
        setting: Setting,
    },
    /// Contacts that constrain the same motion twice (a rank-deficient
    /// contact Jacobian) with no damping to choose among the forces.
    RedundantConstraints {
        /// The constrained row at which the Delassus matrix's factorisation
        /// broke down.
        row: usize,
        /// The contact that row belongs to (its index in the slice given).
        contact: usize,
    },
    /// A pose given to an algorithm (an inverse-kinematics target, a
    /// frame's placement) that is not a rigid motion.
    InvalidPose {
        /// Which pose: `Quantity::Target`, or `Quantity::FramePlacement`
        /// with `index` the frame's body.
        quantity: Quantity,
        /// The frame's body, or 0.
        index: usize,
        /// What is wrong with it (a non-finite entry, a rotation that is
        /// not orthonormal or is a reflection, a translation that
        /// overflows).
        problem: ModelProblem,
    },
    /// A finite input outside the range the model describes, such as a
    /// path that stretches a muscle fibre past
    /// [`MAX_NORMALIZED_FIBER_LENGTH`](crate::drive::muscle::MAX_NORMALIZED_FIBER_LENGTH)
    /// optimal lengths, where the force law would give an absurd force.
    OutOfRange {
        /// Which input.
        quantity: Quantity,
        /// Its index (for a muscle, the muscle's input).
        index: usize,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite { quantity, index } => {
                write!(
                    f,
                    "non-finite {} ({} {index})",
                    quantity.describe(),
                    quantity.index_name()
                )
            }
            Self::InvalidConfiguration { joint, reason } => match reason {
                ConfigurationError::NonFinite => {
                    write!(f, "joint {joint}: non-finite configuration")
                }
                ConfigurationError::QuaternionNotUnit { norm } => write!(
                    f,
                    "joint {joint}: quaternion norm {norm} is not 1 (normalise q first)"
                ),
                ConfigurationError::AngleNotUnit { norm } => write!(
                    f,
                    "joint {joint}: (cos, sin) of norm {norm} is not on the unit circle"
                ),
            },
            Self::SingularArticulatedInertia {
                joint,
                relative_pivot,
            } => write!(
                f,
                "joint {joint}: articulated inertia is singular along the joint \
                 (D / trace(I^A) = {relative_pivot:e}); the subtree is nearly massless"
            ),
            Self::MassMatrixNotPositiveDefinite {
                dof,
                relative_pivot,
            } => write!(
                f,
                "mass matrix is not positive definite at dof {dof} \
                 (pivot / its diagonal entry = {relative_pivot:e})"
            ),
            Self::InvalidModel {
                body,
                problem: ModelProblem::Topology(problem),
            } => write!(f, "body {body}: {}", problem.message()),
            Self::InvalidModel {
                body,
                problem: ModelProblem::JointCoordinateMismatch,
            } => write!(
                f,
                "body {body}: its joint's coordinate counts (nq, nv) differ from the topology's"
            ),
            Self::InvalidModel { body, problem } => {
                write!(f, "body {body}: invalid model parameter: {problem:?}")
            }
            Self::UnsupportedCast { body } => write!(
                f,
                "body {body}: custom joints cannot be converted to another scalar type"
            ),
            Self::InvalidDrive { problem } => write!(f, "invalid drive element: {problem:?}"),
            Self::FrameBodyOutOfRange { body } => {
                write!(f, "frame on body {body}, which the model does not have")
            }
            Self::NotConverged {
                iterations,
                residual,
            } => write!(
                f,
                "no convergence in {iterations} iterations (residual {residual:e})"
            ),
            Self::NonFiniteResult { quantity, index } => write!(
                f,
                "non-finite result: {} ({} {index}); the inputs are finite \
                 but too large for the scalar type",
                quantity.describe(),
                quantity.index_name()
            ),
            Self::BodyOutOfRange { body } => {
                write!(f, "body {body}, which the model does not have")
            }
            Self::TooManyConstraints { rows, capacity } => write!(
                f,
                "{rows} constrained rows, more than the workspace's {capacity}"
            ),
            Self::InvalidSetting { setting } => {
                write!(
                    f,
                    "invalid setting: {} ({}) {}",
                    setting,
                    setting.field(),
                    setting.requirement()
                )
            }
            Self::RedundantConstraints { row, contact } => write!(
                f,
                "the contacts are redundant at constrained row {row} (contact {contact}); \
                 give a damping or drop a contact"
            ),
            Self::InvalidPose {
                quantity,
                index,
                problem,
            } => write!(
                f,
                "{} ({} {index}) is not a rigid motion: {}",
                quantity.describe(),
                quantity.index_name(),
                match problem {
                    ModelProblem::NonFiniteParameter => "a NaN or infinite entry",
                    ModelProblem::RotationNotOrthonormal =>
                        "its rotation is not orthonormal (RᵀR ≠ I)",
                    ModelProblem::Reflection => "its rotation is a reflection (det R = −1)",
                    ModelProblem::Overflow => "its translation overflows the scalar type",
                    _ => "invalid",
                }
            ),
            Self::OutOfRange { quantity, index } => write!(
                f,
                "{} ({} {index}) is outside the range the model describes",
                quantity.describe(),
                quantity.index_name()
            ),
        }
    }
}

#[cfg(feature = "std")]
extern crate std;

#[cfg(feature = "std")]
impl std::error::Error for Error {}

/// Written out rather than derived: the derived `format` was inlined at
/// each error that prints a quantity, each copy with its own table (flash
/// in the pendulum image for every copy; the performance notebook,
/// "Firmware size"); out of line there is one.
#[cfg(feature = "defmt")]
impl defmt::Format for Quantity {
    #[inline(never)]
    fn format(&self, f: defmt::Formatter<'_>) {
        match self {
            Self::Configuration => defmt::write!(f, "Configuration"),
            Self::Velocity => defmt::write!(f, "Velocity"),
            Self::Acceleration => defmt::write!(f, "Acceleration"),
            Self::Torque => defmt::write!(f, "Torque"),
            Self::ExternalForce => defmt::write!(f, "ExternalForce"),
            Self::ModelParameter => defmt::write!(f, "ModelParameter"),
            Self::AuxiliaryState => defmt::write!(f, "AuxiliaryState"),
            Self::Energy => defmt::write!(f, "Energy"),
            Self::MassMatrix => defmt::write!(f, "MassMatrix"),
            Self::Time => defmt::write!(f, "Time"),
            Self::Contact => defmt::write!(f, "Contact"),
            Self::DriveInput => defmt::write!(f, "DriveInput"),
            Self::Derivative => defmt::write!(f, "Derivative"),
            Self::PathLength => defmt::write!(f, "PathLength"),
            Self::PathVelocity => defmt::write!(f, "PathVelocity"),
            Self::ContactPoint => defmt::write!(f, "ContactPoint"),
            Self::FramePlacement => defmt::write!(f, "FramePlacement"),
            Self::BodyAcceleration => defmt::write!(f, "BodyAcceleration"),
            Self::CentroidalMap => defmt::write!(f, "CentroidalMap"),
            Self::Target => defmt::write!(f, "Target"),
            Self::Drive => defmt::write!(f, "Drive"),
            Self::PathPoint => defmt::write!(f, "PathPoint"),
            Self::MuscleCurve => defmt::write!(f, "MuscleCurve"),
            Self::Jacobian => defmt::write!(f, "Jacobian"),
            Self::LinearSystem => defmt::write!(f, "LinearSystem"),
            Self::WorldPose => defmt::write!(f, "WorldPose"),
        }
    }
}

/// Written out rather than derived: with its one variant that carries a
/// field ([`ModelProblem::Topology`]) the derived `format` stops being a
/// table lookup and became the pendulum image's largest formatting
/// function (the performance notebook, "Where the pendulum's 212 bytes
/// went").
#[cfg(feature = "defmt")]
impl defmt::Format for ModelProblem {
    #[inline(never)]
    fn format(&self, f: defmt::Formatter<'_>) {
        match self {
            Self::InvalidMass => defmt::write!(f, "InvalidMass"),
            Self::InvalidInertia => defmt::write!(f, "InvalidInertia"),
            Self::AxisNotUnit => defmt::write!(f, "AxisNotUnit"),
            Self::RotationNotOrthonormal => defmt::write!(f, "RotationNotOrthonormal"),
            Self::NonFiniteParameter => defmt::write!(f, "NonFiniteParameter"),
            Self::Reflection => defmt::write!(f, "Reflection"),
            Self::Overflow => defmt::write!(f, "Overflow"),
            Self::InconsistentTopology => defmt::write!(f, "InconsistentTopology"),
            Self::JointCoordinateMismatch => defmt::write!(f, "JointCoordinateMismatch"),
            Self::Topology(problem) => defmt::write!(f, "Topology({})", problem),
        }
    }
}

#[cfg(feature = "defmt")]
impl defmt::Format for Error {
    fn format(&self, f: defmt::Formatter<'_>) {
        match self {
            Self::NonFinite { quantity, index } => {
                defmt::write!(f, "non-finite {} at index {}", quantity, index)
            }
            Self::InvalidConfiguration { joint, .. } => {
                defmt::write!(f, "joint {}: invalid configuration", joint)
            }
            Self::SingularArticulatedInertia {
                joint,
                relative_pivot,
            } => defmt::write!(
                f,
                "joint {}: singular articulated inertia ({})",
                joint,
                relative_pivot
            ),
            Self::MassMatrixNotPositiveDefinite {
                dof,
                relative_pivot,
            } => defmt::write!(
                f,
                "mass matrix not positive definite at dof {} ({})",
                dof,
                relative_pivot
            ),
            Self::InvalidModel { body, problem } => {
                defmt::write!(f, "body {}: invalid model parameter {}", body, problem)
            }
            Self::UnsupportedCast { body } => {
                defmt::write!(f, "body {}: custom joint cannot be cast", body)
            }
            Self::InvalidDrive { problem } => {
                defmt::write!(f, "invalid drive element: {}", problem)
            }
            Self::FrameBodyOutOfRange { body } => {
                defmt::write!(f, "frame on missing body {}", body)
            }
            Self::NotConverged {
                iterations,
                residual,
            } => defmt::write!(
                f,
                "no convergence in {} iterations ({})",
                iterations,
                residual
            ),
            Self::NonFiniteResult { quantity, index } => {
                defmt::write!(f, "non-finite result {} at index {}", quantity, index)
            }
            Self::BodyOutOfRange { body } => defmt::write!(f, "missing body {}", body),
            Self::TooManyConstraints { rows, capacity } => {
                defmt::write!(f, "{} constrained rows, capacity {}", rows, capacity)
            }
            Self::InvalidSetting { setting } => {
                defmt::write!(f, "invalid setting {}", setting)
            }
            Self::RedundantConstraints { row, contact } => {
                defmt::write!(f, "redundant contacts at row {} (contact {})", row, contact)
            }
            Self::InvalidPose {
                quantity,
                index,
                problem,
            } => defmt::write!(f, "invalid pose {} {}: {}", quantity, index, problem),
            Self::OutOfRange { quantity, index } => {
                defmt::write!(f, "{} at index {} out of range", quantity, index)
            }
        }
    }
}

/// Shorthand for `core::result::Result<T, rodyn::Error>`.
pub type Result<T> = core::result::Result<T, Error>;

/// What is wrong with a joint's configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ConfigurationError {
    /// A non-finite coordinate.
    NonFinite,
    /// A unit quaternion whose norm is too far from one.
    QuaternionNotUnit {
        /// The norm found.
        norm: f64,
    },
    /// A continuous joint's `(cos θ, sin θ)` in Pinocchio's layout whose
    /// norm is too far from one ([`angle_from_cos_sin`](crate::joint::angle_from_cos_sin)).
    AngleNotUnit {
        /// The norm found.
        norm: f64,
    },
}
