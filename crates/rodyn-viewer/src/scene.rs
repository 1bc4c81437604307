//! What the page shows: the model, its visual geometry and a trajectory.
//! Units are SI (m, kg, s, N); frames follow rodyn's (a body's frame is its
//! joint's frame).

/// A rigid pose `aMb`: the rotation of b's axes in a, then b's origin in a.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    /// Rotation matrix, rows.
    pub rot: [[f64; 3]; 3],
    /// Translation, m.
    pub trans: [f64; 3],
}

impl Pose {
    /// The identity.
    pub const IDENTITY: Self = Self {
        rot: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        trans: [0.0; 3],
    };

    /// The pose as the page reads it: 12 numbers, the rotation's rows then
    /// the translation, rounded to a micrometre (a microradian).
    pub(crate) fn to_page(self) -> [f64; 12] {
        let mut out = [0.0; 12];
        for (o, v) in out
            .iter_mut()
            .zip(self.rot.iter().flatten().chain(&self.trans))
        {
            *o = round_micro(*v);
        }
        out
    }
}

/// `x` rounded to 1e-6: the page draws pixels, and short numbers keep the
/// JSON of a long trajectory small.
pub(crate) fn round_micro(x: f64) -> f64 {
    (x * 1e6).round() / 1e6
}

/// The joint that moves a body relative to its parent.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Joint {
    /// Rotation about a unit axis of the body frame.
    Revolute {
        /// Unit axis.
        axis: [f64; 3],
    },
    /// Translation along a unit axis of the body frame.
    Prismatic {
        /// Unit axis.
        axis: [f64; 3],
    },
    /// A free-floating base, `q = [x y z qx qy qz qw]`.
    FreeFlyer,
    /// A planar floating base, `q = [x y θ]` (θ about z).
    PlanarFloating,
}

impl Joint {
    /// Configuration coordinates.
    #[must_use]
    pub fn nq(&self) -> usize {
        match self {
            Self::Revolute { .. } | Self::Prismatic { .. } => 1,
            Self::FreeFlyer => 7,
            Self::PlanarFloating => 3,
        }
    }
}

/// One moving body.
#[derive(Clone, Debug)]
pub struct Body {
    /// The body's (link's) name.
    pub name: String,
    /// The name of the joint that moves it.
    pub joint_name: String,
    /// Parent body (`None`: the world); smaller than this body's index.
    pub parent: Option<usize>,
    /// The joint.
    pub joint: Joint,
    /// The joint frame at `q = 0` in the parent's frame.
    pub placement: Pose,
    /// Mass, kg.
    pub mass: f64,
    /// Centre of mass in the body frame, m.
    pub com: [f64; 3],
    /// Rotational inertia about the centre of mass, body axes, kg m².
    pub inertia: [[f64; 3]; 3],
    /// The joint coordinate's range `[lower, upper]` (rad or m) for its
    /// slider, from the URDF's `<limit>`; `None`: unlimited (a slider of
    /// ±π for an angle, about the robot's size for a length).
    pub limits: Option<[f64; 2]>,
}

/// A joint that follows another (URDF `<mimic>`):
/// `q_follower = multiplier q_leader + offset`. Its slider follows the
/// leader's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mimic {
    /// The follower's body, a revolute or prismatic joint.
    pub follower: usize,
    /// The leader's body, a revolute or prismatic joint.
    pub leader: usize,
    /// Multiplier.
    pub multiplier: f64,
    /// Offset, rad or m.
    pub offset: f64,
}

/// The shape of a piece of visual geometry.
#[derive(Clone, Debug, PartialEq)]
pub enum Geometry {
    /// A box centred on its frame, full edge lengths, m.
    Box {
        /// Edge lengths along x, y, z.
        size: [f64; 3],
    },
    /// A cylinder along z centred on its frame.
    Cylinder {
        /// Radius, m.
        radius: f64,
        /// Length, m.
        length: f64,
    },
    /// A sphere centred on its frame.
    Sphere {
        /// Radius, m.
        radius: f64,
    },
    /// A mesh file of [`Scene::meshes`].
    Mesh {
        /// Index into [`Scene::meshes`].
        mesh: usize,
        /// Scale along the frame's axes.
        scale: [f64; 3],
    },
}

/// Visual geometry fixed to a body (or to the world).
#[derive(Clone, Debug, PartialEq)]
pub struct Visual {
    /// The body (`None`: the world).
    pub body: Option<usize>,
    /// The geometry's frame in the body frame.
    pub pose: Pose,
    /// The shape.
    pub geometry: Geometry,
    /// Colour, RGBA in 0..=1 (`None`: the mesh's own, or grey).
    pub color: Option<[f64; 4]>,
}

/// A mesh file's format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshFormat {
    /// STL, binary or ASCII.
    Stl,
    /// COLLADA (`.dae`).
    Collada,
    /// Wavefront OBJ.
    Obj,
}

impl MeshFormat {
    /// The format of a file name's extension (`.stl`, `.dae`, `.obj`, any case).
    #[must_use]
    pub fn from_file_name(name: &str) -> Option<Self> {
        let ext = name.rsplit_once('.')?.1.to_ascii_lowercase();
        Some(match ext.as_str() {
            "stl" => Self::Stl,
            "dae" => Self::Collada,
            "obj" => Self::Obj,
            _ => return None,
        })
    }
    pub(crate) fn name(self) -> &'static str {
        match self {
            Self::Stl => "stl",
            Self::Collada => "dae",
            Self::Obj => "obj",
        }
    }
}

/// A mesh file's contents.
#[derive(Clone, Debug, PartialEq)]
pub struct Mesh {
    /// Where it came from (shown on the page).
    pub name: String,
    /// Its format.
    pub format: MeshFormat,
    /// The file's bytes.
    pub bytes: Vec<u8>,
}

/// A named point on a body.
#[derive(Clone, Debug, PartialEq)]
pub struct Endpoint {
    /// Its name.
    pub name: String,
    /// The body (`None`: the world).
    pub body: Option<usize>,
    /// The point in the body frame, m.
    pub position: [f64; 3],
}

/// A contact at one sample: where, and the force the ground applies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactPoint {
    /// The point, world frame, m.
    pub position: [f64; 3],
    /// The force on the body, world frame, N.
    pub force: [f64; 3],
}

/// A recorded motion: world poses of every body at each sample.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Trajectory {
    /// Sample times, s, increasing.
    pub t: Vec<f64>,
    /// Per sample, the world pose of every body of [`Scene::bodies`].
    pub poses: Vec<Vec<Pose>>,
    /// Per sample, the contacts (empty when the run has none).
    pub contacts: Vec<Vec<ContactPoint>>,
}

/// Everything the page shows.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The model's name (the page's title).
    pub name: String,
    /// The world's up direction (against gravity), for the camera.
    pub up: [f64; 3],
    /// Bodies, parents before children.
    pub bodies: Vec<Body>,
    /// Joints that follow others.
    pub mimics: Vec<Mimic>,
    /// Visual geometry; with none, the page draws each body as capsules
    /// from its joint to its children's joints and to its endpoints.
    pub visuals: Vec<Visual>,
    /// Mesh files the visuals refer to.
    pub meshes: Vec<Mesh>,
    /// Named points (drawn as dots).
    pub endpoints: Vec<Endpoint>,
    /// The configuration the joint sliders start at (empty: zeros, a free
    /// flyer's quaternion the identity).
    pub q: Vec<f64>,
    /// A motion to play instead of the sliders.
    pub trajectory: Option<Trajectory>,
}

impl Scene {
    /// An empty scene named `name`, z up.
    #[must_use]
    pub fn new(name: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            up: [0.0, 0.0, 1.0],
            bodies: Vec::new(),
            mimics: Vec::new(),
            visuals: Vec::new(),
            meshes: Vec::new(),
            endpoints: Vec::new(),
            q: Vec::new(),
            trajectory: None,
        }
    }

    /// Configuration coordinates of the bodies' joints.
    #[must_use]
    pub fn nq(&self) -> usize {
        self.bodies.iter().map(|b| b.joint.nq()).sum()
    }
}
