//! The compiler's intermediate model: what a URDF or rodyn file says, resolved
//! into rodyn's terms (bodies in topological order, fixed joints merged,
//! names resolved to indices) and checked, before any Rust is written.
//!
//! Units are SI throughout (m, kg, rad, N, s); the readers convert.

use crate::diagnostic::{Diagnostic, Location};
use crate::geometry::{Pose, RigidInertia, Vec3};

/// The joint that moves a body relative to its parent.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum JointType {
    /// Rotation about a unit axis in the joint frame (URDF revolute, continuous).
    Revolute {
        /// Unit axis.
        axis: Vec3,
    },
    /// Translation along a unit axis in the joint frame.
    Prismatic {
        /// Unit axis.
        axis: Vec3,
    },
    /// A free-floating base, Pinocchio's layout: `q = [x y z qx qy qz qw]`,
    /// `v = [linear; angular]` in the body frame.
    FreeFlyer,
    /// A free-floating base of a planar model: `q = [x y θ]`,
    /// `v = [vx vy ω]` in the body frame.
    PlanarFloating,
}

impl JointType {
    /// Configuration coordinates.
    #[must_use]
    pub fn nq(&self) -> usize {
        match self {
            Self::Revolute { .. } | Self::Prismatic { .. } => 1,
            Self::FreeFlyer => 7,
            Self::PlanarFloating => 3,
        }
    }
    /// Velocity coordinates.
    #[must_use]
    pub fn nv(&self) -> usize {
        match self {
            Self::Revolute { .. } | Self::Prismatic { .. } => 1,
            Self::FreeFlyer => 6,
            Self::PlanarFloating => 3,
        }
    }
    /// A short description: `revolute about z`, `prismatic along (0.6, 0.8, 0)`.
    #[must_use]
    pub fn describe(&self) -> String {
        match self {
            Self::Revolute { axis } => format!("revolute about {}", describe_axis(axis)),
            Self::Prismatic { axis } => format!("prismatic along {}", describe_axis(axis)),
            Self::FreeFlyer => "free-flyer".to_string(),
            Self::PlanarFloating => "planar floating".to_string(),
        }
    }
}

/// `x`, `-z` or `(0.6, 0.8, 0)`.
#[must_use]
pub fn describe_axis(axis: &Vec3) -> String {
    for (k, name) in ["x", "y", "z"].iter().enumerate() {
        let mut unit = [0.0; 3];
        unit[k] = 1.0;
        if *axis == unit {
            return (*name).to_string();
        }
        unit[k] = -1.0;
        if *axis == unit {
            return format!("-{name}");
        }
    }
    format!("({}, {}, {})", axis[0], axis[1], axis[2])
}

/// One moving body of the tree: a link moved by a non-fixed joint, with the
/// links fixed to it merged in.
#[derive(Clone, Debug)]
pub struct Body {
    /// The link's name.
    pub name: String,
    /// The name of the joint that moves it.
    pub joint_name: String,
    /// Parent body (`None`: the world). Always smaller than this body's index.
    pub parent: Option<usize>,
    /// The joint.
    pub joint: JointType,
    /// A `continuous` joint (a revolute joint without limits): one angle in
    /// rodyn's `q`, `(cos θ, sin θ)` in Pinocchio's.
    pub continuous: bool,
    /// The joint frame at `q = 0` in the parent body's frame.
    pub placement: Pose,
    /// The body's inertia in its own frame, merged links included.
    pub inertia: RigidInertia,
    /// Where the joint was declared.
    pub location: Location,
}

/// A named frame fixed to a body or to the world: every link of a URDF (a
/// moving link is the identity on its own body, a link merged through a
/// fixed joint sits somewhere on its parent).
#[derive(Clone, Debug)]
pub struct Frame {
    /// The link's name.
    pub name: String,
    /// The body it is fixed to (`None`: the world).
    pub body: Option<usize>,
    /// The frame in the body's frame.
    pub pose: Pose,
}

/// A URDF `<mimic>`: a follower joint that moves with its leader,
/// `q_f = multiplier q_l + offset` (both one-degree-of-freedom joints). The
/// model keeps the follower as a joint of its own; the generated module's
/// `MIMICS` and its `*_mimic` functions couple the two (Pinocchio's
/// `buildModelFromUrdf(..., mimic=True)` layout).
#[derive(Clone, Debug)]
pub struct MimicDef {
    /// The follower's body (joint) index.
    pub follower: usize,
    /// The leader's body (joint) index.
    pub leader: usize,
    /// `multiplier` (default 1).
    pub multiplier: f64,
    /// `offset` (default 0), rad or m.
    pub offset: f64,
}

/// A named point on a body or in the world where forces, contacts and
/// muscle paths attach.
#[derive(Clone, Debug)]
pub struct EndpointDef {
    /// Its name.
    pub name: String,
    /// The body it is fixed to (`None`: the world).
    pub body: Option<usize>,
    /// The point in that body's frame (world frame when `body` is `None`), m.
    pub position: Vec3,
    /// Where it was declared.
    pub location: Location,
}

/// What pulls along a force element's path (the laws of `rodyn::drive`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ForceLaw {
    /// A spring: tension `k (l - l0) + k3 (l - l0)³`.
    Spring {
        /// Stiffness k, N/m.
        stiffness: f64,
        /// Rest length l0, m.
        rest_length: f64,
        /// Cubic stiffness k3, N/m³ (0: a linear spring).
        cubic_stiffness: f64,
    },
    /// A linear damper: tension `d l̇`.
    Damper {
        /// Damping d, N s/m.
        damping: f64,
    },
    /// A Hill-type muscle with a rigid tendon (Thelen 2003).
    Muscle {
        /// Maximum isometric force, N.
        max_isometric_force: f64,
        /// Optimal fibre length, m.
        optimal_fiber_length: f64,
        /// Tendon slack length, m.
        tendon_slack_length: f64,
        /// Pennation angle at optimal fibre length, rad.
        pennation_angle: f64,
        /// Maximum contraction velocity, optimal fibre lengths per second.
        max_contraction_velocity: f64,
        /// Activation time constant, s.
        activation_time_constant: f64,
        /// Deactivation time constant, s.
        deactivation_time_constant: f64,
    },
}

impl ForceLaw {
    /// `spring`, `damper` or `muscle`.
    #[must_use]
    pub fn kind(&self) -> &'static str {
        match self {
            Self::Spring { .. } => "spring",
            Self::Damper { .. } => "damper",
            Self::Muscle { .. } => "muscle",
        }
    }
}

/// A force element acting along a polygon of endpoints.
#[derive(Clone, Debug)]
pub struct ForceElement {
    /// Its name.
    pub name: String,
    /// Endpoint indices along the path, first to last (two or more).
    pub path: Vec<usize>,
    /// The force law.
    pub law: ForceLaw,
}

/// An electric motor driving a one-degree-of-freedom joint through a gear.
#[derive(Clone, Debug)]
pub struct Motor {
    /// Its name.
    pub name: String,
    /// The body whose joint it drives.
    pub body: usize,
    /// Gear ratio (motor turns per joint turn).
    pub gear_ratio: f64,
    /// Rotor inertia on the motor side, kg m².
    pub rotor_inertia: f64,
    /// Torque constant, N m/A.
    pub torque_constant: f64,
}

/// A compliant contact at an endpoint.
#[derive(Clone, Debug)]
pub struct Contact {
    /// Its name.
    pub name: String,
    /// The endpoint in contact.
    pub endpoint: usize,
    /// Normal stiffness, N/m.
    pub stiffness: f64,
    /// Normal damping, N s/m.
    pub damping: f64,
    /// Coulomb friction coefficient (dimensionless).
    pub friction: f64,
    /// Slip velocity scale `s₀` of the regularised friction
    /// `μ λ tanh(|v_t| / s₀)`, m/s.
    pub slip_velocity: f64,
}

impl Contact {
    /// The slip velocity (m/s) of a contact whose file gives none. It keeps
    /// a 1 kHz explicit loop stable for robots of a few kilograms: below
    /// `s₀` friction acts as a viscous damper of slope `μ λ / s₀`, the
    /// stiffest term of a light leg.
    pub const DEFAULT_SLIP_VELOCITY: f64 = 0.2;
}

/// A model, ready to be written as Rust or built at run time.
#[derive(Clone, Debug)]
pub struct ModelDescription {
    /// The model's name (a Rust identifier after sanitising).
    pub name: String,
    /// `true` for a planar model (every joint about z, gravity in x-y).
    pub planar: bool,
    /// Gravitational acceleration in the world frame, m/s².
    pub gravity: Vec3,
    /// Bodies, parents before children.
    pub bodies: Vec<Body>,
    /// Link frames.
    pub frames: Vec<Frame>,
    /// Endpoints.
    pub endpoints: Vec<EndpointDef>,
    /// Springs, dampers and muscles.
    pub force_elements: Vec<ForceElement>,
    /// Motors.
    pub motors: Vec<Motor>,
    /// Contacts.
    pub contacts: Vec<Contact>,
    /// Mimic joints (URDF `<mimic>`).
    pub mimics: Vec<MimicDef>,
    /// What was ignored or adjusted while reading.
    pub warnings: Vec<Diagnostic>,
    /// Every file read to build the model (the model file and its includes).
    pub included_files: Vec<std::path::PathBuf>,
    /// Round placements within [`SNAP_TOLERANCE`](crate::geometry::SNAP_TOLERANCE)
    /// of a quarter turn to exact quarter turns (a speed aid for CRBA that
    /// moves the model by up to that much); off by default, when only the
    /// rounding of exact quarter turns is removed.
    pub round_quarter_turns: bool,
}

impl ModelDescription {
    /// The tolerance within which placements are taken as quarter turns:
    /// [`SNAP_TOLERANCE`](crate::geometry::SNAP_TOLERANCE) when
    /// [`round_quarter_turns`](Self::round_quarter_turns) asks for it,
    /// otherwise [`EXACT_TOLERANCE`](crate::geometry::EXACT_TOLERANCE).
    #[must_use]
    pub fn snap_tolerance(&self) -> f64 {
        if self.round_quarter_turns {
            crate::geometry::SNAP_TOLERANCE
        } else {
            crate::geometry::EXACT_TOLERANCE
        }
    }

    /// Number of configuration coordinates.
    #[must_use]
    pub fn nq(&self) -> usize {
        self.bodies.iter().map(|b| b.joint.nq()).sum()
    }
    /// Number of velocity coordinates.
    #[must_use]
    pub fn nv(&self) -> usize {
        self.bodies.iter().map(|b| b.joint.nv()).sum()
    }
    /// First configuration index of each body's joint.
    #[must_use]
    pub fn idx_q(&self) -> Vec<usize> {
        prefix_sums(self.bodies.iter().map(|b| b.joint.nq()))
    }
    /// First velocity index of each body's joint.
    #[must_use]
    pub fn idx_v(&self) -> Vec<usize> {
        prefix_sums(self.bodies.iter().map(|b| b.joint.nv()))
    }
    /// Total mass, kg.
    #[must_use]
    pub fn total_mass(&self) -> f64 {
        self.bodies.iter().map(|b| b.inertia.mass).sum()
    }
    /// The name of a body, or `world`.
    #[must_use]
    pub fn body_name(&self, body: Option<usize>) -> &str {
        body.map_or("world", |b| self.bodies[b].name.as_str())
    }
}

fn prefix_sums(sizes: impl Iterator<Item = usize>) -> Vec<usize> {
    let mut next = 0;
    sizes
        .map(|n| {
            let start = next;
            next += n;
            start
        })
        .collect()
}
