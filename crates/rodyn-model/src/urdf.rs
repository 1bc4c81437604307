//! URDF reader, with Pinocchio's semantics for the same file.
//!
//! * Body order: depth-first from the root link, the children of a link taken
//!   in the byte order of their joints' names (urdfdom keeps joints in a
//!   `std::map`), so body indices equal Pinocchio's joint indices minus one.
//! * A joint's `<origin xyz rpy>` is its frame at `q = 0` in the parent link's
//!   frame, with `R = Rz(yaw) Ry(pitch) Rx(roll)`.
//! * A link's `<inertial><origin>` places the centre of mass and rotates the
//!   inertia tensor into the link frame (`R I Rᵀ`).
//! * `continuous` is `revolute`; `floating` is a free-flyer; `fixed` merges the
//!   child link into its parent body (inertia combined, the link kept as a
//!   frame and an endpoint).
//! * The root link is the world unless a floating base is asked for, in which
//!   case a free-flyer named `root_joint` moves it (Pinocchio's
//!   `buildModel(urdf, JointModelFreeFlyer())`). A fixed root's inertia does not
//!   move and is dropped, as Pinocchio adds it to the universe.
//!
//! Limits, dynamics, mimic, meshes and transmissions do not enter the
//! dynamics; each is reported once as a warning.

use crate::codegen::fits_f32;
use crate::description::{Body, EndpointDef, Frame, JointType, MimicDef, ModelDescription};
use crate::diagnostic::{
    settle_warnings, Diagnostic, LineIndex, Location, Result, WarningKind, WarningKinds,
};
use crate::geometry::{norm, scale, Pose, RigidInertia, Vec3};
use crate::physics::{check_mass, check_subtrees_have_mass, tensor_problem, TensorProblem};
use roxmltree::{Document, Node};
use std::collections::{BTreeMap, HashMap};
use std::path::Path;

/// Gravity along -z (URDF's "up" is +z), 9.81 m/s² as in Pinocchio's URDF models.
pub const URDF_GRAVITY: Vec3 = [0.0, 0.0, -9.81];

/// How to read a URDF.
///
/// `#[non_exhaustive]`: a later option is not a breaking change. Build it
/// with [`UrdfOptions::new`] and the `with_…` methods.
///
/// ```
/// use rodyn_model::urdf::UrdfOptions;
///
/// let options = UrdfOptions::new().with_floating_base(true).with_strict(true);
/// assert!(options.floating_base && options.strict);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct UrdfOptions {
    /// Put a free-flyer between the world and the root link.
    pub floating_base: bool,
    /// Refuse what is only warned about otherwise: a link's tensor that
    /// breaks the triangle inequality or is not positive semi-definite at
    /// rounding level or before a fixed joint merges it, a massless link
    /// with a tensor, a robot without a name.
    pub strict: bool,
    /// Kinds of warning not to report (nor to refuse in strict mode).
    pub silence: WarningKinds,
}

impl UrdfOptions {
    /// A fixed root, warnings reported but not refused, nothing silenced
    /// (the same as `default()`, usable in a `const`).
    ///
    /// ```
    /// use rodyn_model::urdf::UrdfOptions;
    ///
    /// const OPTIONS: UrdfOptions = UrdfOptions::new();
    /// assert_eq!(OPTIONS, UrdfOptions::default());
    /// ```
    #[must_use]
    pub const fn new() -> Self {
        Self {
            floating_base: false,
            strict: false,
            silence: WarningKinds::NONE,
        }
    }

    /// These options with a free-flyer under the root link, or not.
    ///
    /// ```
    /// use rodyn_model::urdf::UrdfOptions;
    ///
    /// assert!(UrdfOptions::new().with_floating_base(true).floating_base);
    /// ```
    #[must_use]
    pub const fn with_floating_base(mut self, floating_base: bool) -> Self {
        self.floating_base = floating_base;
        self
    }

    /// These options with strict mode on or off.
    ///
    /// ```
    /// use rodyn_model::urdf::UrdfOptions;
    ///
    /// assert!(UrdfOptions::new().with_strict(true).strict);
    /// ```
    #[must_use]
    pub const fn with_strict(mut self, strict: bool) -> Self {
        self.strict = strict;
        self
    }

    /// These options silencing `silence`'s kinds of warning.
    ///
    /// ```
    /// use rodyn_model::{urdf::UrdfOptions, WarningKind, WarningKinds};
    ///
    /// let options = UrdfOptions::new().with_silence(WarningKinds::NONE.with(WarningKind::Limit));
    /// assert!(options.silence.contains(WarningKind::Limit));
    /// ```
    #[must_use]
    pub const fn with_silence(mut self, silence: WarningKinds) -> Self {
        self.silence = silence;
        self
    }
}

/// Reads URDF `text` (the content of `file`) into a checked model.
///
/// # Errors
/// The first problem found, with its position in `file`.
pub fn read_urdf(file: &Path, text: &str, options: UrdfOptions) -> Result<ModelDescription> {
    if let Some(offset) = too_deep(text) {
        return Err(Diagnostic::error(
            Location::at_offset(file, text, offset),
            format!(
                "elements are nested more than {MAX_NESTING} levels deep here; a URDF needs \
                 about 5 (robot, link, inertial, origin)"
            ),
        ));
    }
    let doc = Document::parse(text).map_err(|e| {
        let pos = e.pos();
        Diagnostic::error(
            Location {
                file: file.to_path_buf(),
                line: pos.row,
                column: pos.col,
            },
            format!("this is not well-formed XML: {e}"),
        )
    })?;
    let reader = Reader {
        file,
        text,
        lines: LineIndex::new(text),
        lenient: std::cell::RefCell::new(Vec::new()),
    };
    reader.read(&doc, options)
}

/// Deepest element nesting read. The XML parser recurses once per level,
/// and build scripts run unoptimised with a small stack: a 1,500-level
/// file overflowed it.
pub const MAX_NESTING: usize = 64;

/// The byte offset of the first element opened deeper than
/// [`MAX_NESTING`], by a scan of the tags that skips comments, processing
/// instructions, declarations, CDATA and quoted attribute values; `None`
/// when the file stays within it (malformed XML is left to the parser).
fn too_deep(text: &str) -> Option<usize> {
    let bytes = text.as_bytes();
    let find = |from: usize, pattern: &[u8]| {
        bytes[from..]
            .windows(pattern.len())
            .position(|w| w == pattern)
            .map(|p| from + p + pattern.len())
    };
    let (mut depth, mut i) = (0_usize, 0_usize);
    while let Some(start) = bytes[i..].iter().position(|&b| b == b'<').map(|p| i + p) {
        let rest = &bytes[start + 1..];
        i = if rest.starts_with(b"!--") {
            find(start, b"-->")?
        } else if rest.starts_with(b"![CDATA[") {
            find(start, b"]]>")?
        } else if rest.starts_with(b"?") || rest.starts_with(b"!") {
            find(start, b">")?
        } else {
            // A start, end or empty-element tag: find its `>` outside quotes.
            let mut quote = None;
            let mut end = None;
            for (k, &b) in rest.iter().enumerate() {
                match (quote, b) {
                    (Some(q), _) if b == q => quote = None,
                    (Some(_), _) => {}
                    (None, b'"' | b'\'') => quote = Some(b),
                    (None, b'>') => {
                        end = Some(start + 1 + k);
                        break;
                    }
                    _ => {}
                }
            }
            let end = end?;
            if rest.first() == Some(&b'/') {
                depth = depth.saturating_sub(1);
            } else if bytes[end - 1] != b'/' {
                depth += 1;
                if depth > MAX_NESTING {
                    return Some(start);
                }
            }
            end + 1
        };
    }
    None
}

struct Reader<'a> {
    file: &'a Path,
    text: &'a str,
    lines: LineIndex,
    /// Findings that do not harm the dynamics: warnings, or errors in
    /// strict mode.
    lenient: std::cell::RefCell<Vec<Diagnostic>>,
}

/// A `<link>` as written.
struct Link {
    inertia: Option<RigidInertia>,
    location: Location,
}

/// A `<joint>` as written.
struct JointDecl<'a> {
    name: &'a str,
    kind: JointKind,
    /// Declared `continuous`.
    continuous: bool,
    /// Its `<mimic>`: the leader joint's name, multiplier and offset.
    mimic: Option<(&'a str, f64, f64)>,
    parent: &'a str,
    child: &'a str,
    origin: Pose,
    location: Location,
}

#[derive(Clone, Copy)]
enum JointKind {
    Moving(JointType),
    Fixed,
}

/// Elements that do not enter the dynamics: counted, then reported once each.
#[derive(Default)]
struct Ignored {
    first: BTreeMap<&'static str, (WarningKind, Location, usize)>,
}

impl Ignored {
    fn note(&mut self, kind: WarningKind, what: &'static str, location: Location) {
        self.first.entry(what).or_insert((kind, location, 0)).2 += 1;
    }
    fn into_warnings(self) -> Vec<Diagnostic> {
        self.first
            .into_iter()
            .map(|(what, (kind, location, count))| {
                let times = if count == 1 {
                    "once".to_string()
                } else {
                    format!("{count} times")
                };
                Diagnostic::warning_of(
                    kind,
                    location,
                    format!("ignored {what} ({times} in this file)"),
                )
            })
            .collect()
    }
}

impl<'a> Reader<'a> {
    fn at(&self, offset: usize) -> Location {
        Location::at_offset_indexed(self.file, self.text, &self.lines, offset)
    }
    fn at_node(&self, node: Node<'_, '_>) -> Location {
        self.at(node.range().start)
    }
    fn error<T>(&self, node: Node<'_, '_>, message: impl Into<String>) -> Result<T> {
        Err(Diagnostic::error(self.at_node(node), message))
    }

    /// The location of attribute `name` of `node` (its value), or of `node`.
    fn at_attribute(&self, node: Node<'_, '_>, name: &str) -> Location {
        node.attribute_node(name)
            .map_or_else(|| self.at_node(node), |a| self.at(a.range_value().start))
    }

    fn required_attribute<'n>(&self, node: Node<'n, '_>, name: &str) -> Result<&'n str> {
        node.attribute(name).map_or_else(
            || {
                self.error(
                    node,
                    format!("<{}> needs a `{name}` attribute", node.tag_name().name()),
                )
            },
            Ok,
        )
    }

    fn number(&self, node: Node<'_, '_>, name: &str, text: &str) -> Result<f64> {
        match text.trim().parse::<f64>() {
            Ok(x) if x.is_finite() && !fits_f32(x) => Err(Diagnostic::error(
                self.at_attribute(node, name),
                format!(
                    "`{name}` is {x:e}, which the model's f32 version cannot hold \
                     (magnitudes up to 3.4e38)"
                ),
            )),
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(Diagnostic::error(
                self.at_attribute(node, name),
                format!("`{name}` must be a finite number, not `{text}`"),
            )),
        }
    }

    fn scalar_attribute(&self, node: Node<'_, '_>, name: &str) -> Result<f64> {
        let text = self.required_attribute(node, name)?;
        self.number(node, name, text)
    }

    fn vec3_attribute(&self, node: Node<'_, '_>, name: &str, default: Vec3) -> Result<Vec3> {
        let Some(text) = node.attribute(name) else {
            return Ok(default);
        };
        let parts = text.split_whitespace().collect::<Vec<_>>();
        if parts.len() != 3 {
            return Err(Diagnostic::error(
                self.at_attribute(node, name),
                format!("`{name}` needs three numbers, found `{text}`"),
            ));
        }
        let mut v = [0.0; 3];
        for (x, part) in v.iter_mut().zip(parts) {
            *x = self.number(node, name, part)?;
        }
        Ok(v)
    }

    fn origin(&self, parent: Node<'_, '_>) -> Result<Pose> {
        match child(parent, "origin") {
            None => Ok(Pose::IDENTITY),
            Some(o) => Ok(Pose::from_xyz_rpy(
                &self.vec3_attribute(o, "xyz", [0.0; 3])?,
                &self.vec3_attribute(o, "rpy", [0.0; 3])?,
            )),
        }
    }

    fn read(&self, doc: &Document<'_>, options: UrdfOptions) -> Result<ModelDescription> {
        let robot = doc.root_element();
        if robot.tag_name().name() != "robot" {
            return self.error(
                robot,
                format!(
                    "a URDF file's top element must be <robot>, not <{}>",
                    robot.tag_name().name()
                ),
            );
        }
        let name = match robot.attribute("name") {
            Some(name) => name.to_string(),
            None => {
                let stem = self
                    .file
                    .file_stem()
                    .map_or_else(|| "robot".into(), |s| s.to_string_lossy().into_owned());
                self.lenient(Diagnostic::warning_of(
                    WarningKind::UnnamedRobot,
                    self.at_node(robot),
                    format!("<robot> has no `name` attribute; the model is named `{stem}` after the file"),
                ));
                stem
            }
        };
        let mut ignored = Ignored::default();
        let mut links: HashMap<&str, Link> = HashMap::new();
        let mut link_order: Vec<&str> = Vec::new();
        let mut joints: Vec<JointDecl<'_>> = Vec::new();
        // Joint names seen so far, for the duplicate check in constant time.
        let mut joint_index: HashMap<String, usize> = HashMap::new();
        for node in robot.children().filter(Node::is_element) {
            match node.tag_name().name() {
                "link" => {
                    let link_name = self.required_attribute(node, "name")?;
                    let link = self.read_link(node, &mut ignored)?;
                    if let Some(first) = links.get(link_name) {
                        return self.error(
                            node,
                            format!(
                                "a second link is named `{link_name}`; the first is at {}",
                                first.location
                            ),
                        );
                    }
                    links.insert(link_name, link);
                    link_order.push(link_name);
                }
                "joint" => {
                    let joint = self.read_joint(node, &mut ignored)?;
                    if let Some(&first) = joint_index.get(joint.name) {
                        return self.error(
                            node,
                            format!(
                                "a second joint is named `{}`; the first is at {}",
                                joint.name, joints[first].location
                            ),
                        );
                    }
                    joint_index.insert(joint.name.to_owned(), joints.len());
                    joints.push(joint);
                }
                "transmission" => ignored.note(
                    WarningKind::Transmission,
                    "<transmission> (rodyn models motors in its own file)",
                    self.at_node(node),
                ),
                "gazebo" => ignored.note(
                    WarningKind::Gazebo,
                    "<gazebo> (simulator settings)",
                    self.at_node(node),
                ),
                "material" => {}
                other => ignored.note(
                    WarningKind::UnknownElement,
                    if other.is_empty() {
                        "an unnamed element"
                    } else {
                        "an unknown element under <robot>"
                    },
                    self.at_node(node),
                ),
            }
        }
        if links.is_empty() {
            return self.error(robot, "the robot has no <link>");
        }
        let joint_of_child = self.check_tree(&links, &joints)?;
        let root = self.find_root(robot, &links, &link_order, &joint_of_child, &joints)?;
        let mut model = self.assemble(name, root, &links, &joints, options)?;
        self.resolve_mimics(&mut model, &joints);
        check_subtrees_have_mass(&model)?;
        // The bodies the dynamics use, after fixed joints merged their links.
        for body in &model.bodies {
            match tensor_problem(&body.inertia.inertia) {
                Some(p @ TensorProblem::NotPositiveSemiDefinite(_)) => {
                    return Err(Diagnostic::error(
                        body.location.clone(),
                        format!(
                            "body `{}` (its link and the links fixed to it) {}",
                            body.name,
                            p.describe()
                        ),
                    ));
                }
                Some(p) => self.lenient(Diagnostic::warning_of(
                    WarningKind::BodyTensor,
                    body.location.clone(),
                    format!(
                        "body `{}` (its link and the links fixed to it) {}; no real body has such a tensor, but the dynamics are defined",
                        body.name,
                        p.describe()
                    ),
                )),
                None => {}
            }
        }
        let mut lenient = self.lenient.take();
        lenient.retain(|w| !w.kind.is_some_and(|k| options.silence.contains(k)));
        if options.strict {
            if let Some(first) = lenient.into_iter().next() {
                return Err(Diagnostic::error(
                    first.location,
                    format!("{} (strict mode)", first.message),
                ));
            }
        } else {
            model.warnings.extend(lenient);
        }
        model.warnings.extend(ignored.into_warnings());
        model.warnings = settle_warnings(std::mem::take(&mut model.warnings), options.silence);
        Ok(model)
    }

    /// Records a finding that does not harm the dynamics.
    fn lenient(&self, warning: Diagnostic) {
        self.lenient.borrow_mut().push(warning);
    }

    fn read_link(&self, node: Node<'_, '_>, ignored: &mut Ignored) -> Result<Link> {
        let location = self.at_node(node);
        let mut inertia = None;
        for element in node.children().filter(Node::is_element) {
            match element.tag_name().name() {
                "inertial" => inertia = Some(self.read_inertial(node, element)?),
                "visual" | "collision" => ignored.note(
                    WarningKind::Geometry,
                    "<visual> and <collision> geometry (meshes and shapes do not enter the dynamics)",
                    self.at_node(element),
                ),
                _ => ignored.note(
                    WarningKind::UnknownElement,
                    "an unknown element in <link>",
                    self.at_node(element),
                ),
            }
        }
        Ok(Link { inertia, location })
    }

    fn read_inertial(&self, link: Node<'_, '_>, inertial: Node<'_, '_>) -> Result<RigidInertia> {
        let link_name = link.attribute("name").unwrap_or("?");
        let what = format!("link `{link_name}`");
        let Some(mass_node) = child(inertial, "mass") else {
            return self.error(inertial, format!("{what} has an <inertial> without <mass>"));
        };
        let mass = self.scalar_attribute(mass_node, "value")?;
        let Some(i) = child(inertial, "inertia") else {
            return self.error(
                inertial,
                format!("{what} has an <inertial> without <inertia>"),
            );
        };
        let get = |n| self.scalar_attribute(i, n);
        let (ixx, ixy, ixz, iyy, iyz, izz) = (
            get("ixx")?,
            get("ixy")?,
            get("ixz")?,
            get("iyy")?,
            get("iyz")?,
            get("izz")?,
        );
        let inertia = [[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]];
        let mass_at = self.at_attribute(mass_node, "value");
        if mass == 0.0 {
            // Pinocchio keeps such a link's tensor, and so does rodyn; a
            // moving link with neither mass nor tensor is refused below.
            if inertia.iter().flatten().any(|x| *x != 0.0) {
                self.lenient(Diagnostic::warning_of(
                    WarningKind::MasslessTensor,
                    mass_at,
                    format!("{what} has mass 0 but a non-zero inertia tensor; the tensor is kept"),
                ));
            }
        } else {
            check_mass(mass, &what, &mass_at)?;
        }
        // Each link's tensor on its own: only a warning, since a fixed
        // joint may merge it into a body that is fine; the merged bodies
        // are checked after assembly.
        if let Some(problem) = tensor_problem(&inertia) {
            self.lenient(Diagnostic::warning_of(
                WarningKind::LinkTensor,
                self.at_node(i),
                format!(
                    "{what} {} (the body it belongs to is checked after fixed joints merge links)",
                    problem.describe()
                ),
            ));
        }
        // The tensor is given in the inertial frame; rodyn wants it in the link frame.
        let local = RigidInertia {
            mass,
            com: [0.0; 3],
            inertia,
        };
        Ok(local.expressed_in(&self.origin(inertial)?))
    }

    fn read_joint<'n>(&self, node: Node<'n, '_>, ignored: &mut Ignored) -> Result<JointDecl<'n>> {
        let name = self.required_attribute(node, "name")?;
        let kind_text = self.required_attribute(node, "type")?;
        let link_of = |tag: &str| -> Result<&'n str> {
            match child(node, tag) {
                Some(n) => self.required_attribute(n, "link"),
                None => self.error(node, format!("joint `{name}` has no <{tag}> element")),
            }
        };
        let (parent, child_link) = (link_of("parent")?, link_of("child")?);
        let axis = || -> Result<Vec3> {
            let Some(a) = child(node, "axis") else {
                return Ok([1.0, 0.0, 0.0]);
            };
            let v = self.vec3_attribute(a, "xyz", [1.0, 0.0, 0.0])?;
            let n = norm(&v);
            if n < 1e-12 {
                return Err(Diagnostic::error(
                    self.at_attribute(a, "xyz"),
                    format!("joint `{name}` has a zero axis; an axis needs a direction"),
                ));
            }
            Ok(if (n - 1.0).abs() > 1e-9 {
                scale(&v, 1.0 / n)
            } else {
                v
            })
        };
        let needs_limit = || -> Result<()> {
            if child(node, "limit").is_none() {
                return self.error(
                    node,
                    format!("{kind_text} joint `{name}` has no <limit>; URDF requires one (effort and velocity) for this joint type"),
                );
            }
            Ok(())
        };
        let kind = match kind_text {
            "revolute" => {
                needs_limit()?;
                JointKind::Moving(JointType::Revolute { axis: axis()? })
            }
            "continuous" => JointKind::Moving(JointType::Revolute { axis: axis()? }),
            "prismatic" => {
                needs_limit()?;
                JointKind::Moving(JointType::Prismatic { axis: axis()? })
            }
            "fixed" => JointKind::Fixed,
            "floating" => JointKind::Moving(JointType::FreeFlyer),
            "planar" => {
                return Err(Diagnostic::error(
                    self.at_attribute(node, "type"),
                    format!("joint `{name}` is a URDF planar joint, which rodyn does not have; use a rodyn file with `planar = true` for planar models"),
                ))
            }
            other => {
                return Err(Diagnostic::error(
                    self.at_attribute(node, "type"),
                    format!("joint `{name}` has the unknown type `{other}`; URDF joint types are revolute, continuous, prismatic, fixed, floating and planar"),
                ))
            }
        };
        for element in node.children().filter(Node::is_element) {
            let at = self.at_node(element);
            match element.tag_name().name() {
                "origin" | "parent" | "child" | "axis" => {}
                "limit" => ignored.note(
                    WarningKind::Limit,
                    "<limit> (rodyn does not enforce joint limits)",
                    at,
                ),
                "dynamics" => ignored.note(
                    WarningKind::Dynamics,
                    "<dynamics> damping and friction (model them as drives in a rodyn file)",
                    at,
                ),
                "mimic" => ignored.note(
                    WarningKind::Mimic,
                    "<mimic> in the model's dynamics (MODEL_* keeps each mimicking joint as \
                     an independent joint, as Pinocchio's buildModel without mimic=True; the \
                     generated MIMICS and *_mimic functions give Pinocchio's mimic=True \
                     coordinates and torques)",
                    at,
                ),
                "calibration" | "safety_controller" => ignored.note(
                    WarningKind::Calibration,
                    "<calibration> and <safety_controller>",
                    at,
                ),
                _ => ignored.note(
                    WarningKind::UnknownElement,
                    "an unknown element in <joint>",
                    at,
                ),
            }
        }
        let mimic = match child(node, "mimic") {
            Some(m) => Some((
                self.required_attribute(m, "joint")?,
                match m.attribute("multiplier") {
                    Some(t) => self.number(m, "multiplier", t)?,
                    None => 1.0,
                },
                match m.attribute("offset") {
                    Some(t) => self.number(m, "offset", t)?,
                    None => 0.0,
                },
            )),
            None => None,
        };
        Ok(JointDecl {
            name,
            kind,
            mimic,
            continuous: kind_text == "continuous",
            parent,
            child: child_link,
            origin: self.origin(node)?,
            location: self.at_node(node),
        })
    }

    /// Checks that joints name existing links and that no link has two
    /// parents; returns, for each child link, the index of its joint.
    fn check_tree<'j>(
        &self,
        links: &HashMap<&str, Link>,
        joints: &[JointDecl<'j>],
    ) -> Result<HashMap<&'j str, usize>> {
        let mut joint_of_child = HashMap::new();
        for (k, j) in joints.iter().enumerate() {
            for (role, link) in [("parent", j.parent), ("child", j.child)] {
                if !links.contains_key(link) {
                    return Err(Diagnostic::error(
                        j.location.clone(),
                        format!(
                            "joint `{}` names the {role} link `{link}`, which does not exist",
                            j.name
                        ),
                    ));
                }
            }
            if j.parent == j.child {
                return Err(Diagnostic::error(
                    j.location.clone(),
                    format!("joint `{}` connects link `{}` to itself", j.name, j.parent),
                ));
            }
            if let Some(&first) = joint_of_child.get(j.child) {
                let first: &JointDecl<'_> = &joints[first];
                return Err(Diagnostic::error(
                    j.location.clone(),
                    format!(
                        "link `{}` is the child of two joints, `{}` and `{}`; a tree gives each link one parent",
                        j.child, first.name, j.name
                    ),
                ));
            }
            joint_of_child.insert(j.child, k);
        }
        Ok(joint_of_child)
    }

    /// The one link that is no joint's child; every other link must hang
    /// below it (otherwise the joints form a cycle).
    fn find_root<'l>(
        &self,
        robot: Node<'_, '_>,
        links: &HashMap<&str, Link>,
        link_order: &[&'l str],
        joint_of_child: &HashMap<&str, usize>,
        joints: &[JointDecl<'_>],
    ) -> Result<&'l str> {
        let roots = link_order
            .iter()
            .filter(|l| !joint_of_child.contains_key(*l))
            .copied()
            .collect::<Vec<_>>();
        match roots.as_slice() {
            [root] => {
                // Walk up from every link until a link already known to
                // hang below the root; every link of the walk then does too.
                // Meeting a link of the same walk again is a cycle. Each
                // link is walked over once: linear in the number of links.
                let mut below_root: HashMap<&str, bool> = HashMap::with_capacity(link_order.len());
                below_root.insert(root, true);
                let mut walk: Vec<&str> = Vec::new();
                for start in link_order {
                    walk.clear();
                    let mut link = *start;
                    while !below_root.contains_key(link) {
                        below_root.insert(link, false);
                        walk.push(link);
                        match joint_of_child.get(link) {
                            Some(&k) => link = joints[k].parent,
                            None => break,
                        }
                    }
                    if below_root.get(link) == Some(&false) {
                        let k = joint_of_child[start];
                        return Err(Diagnostic::error(
                            joints[k].location.clone(),
                            format!("the joints form a cycle through link `{start}`; a URDF must be a tree"),
                        ));
                    }
                    for l in &walk {
                        below_root.insert(l, true);
                    }
                }
                Ok(root)
            }
            [] => self.error(robot, "every link is the child of a joint, so the joints form a cycle and there is no root link"),
            [first, second, ..] => Err(Diagnostic::error(
                links[second].location.clone(),
                format!(
                    "the robot has {} root links (`{first}`, `{second}`, ...); every link but one must be the child of a joint",
                    roots.len()
                ),
            )),
        }
    }

    /// Each moving joint's `<mimic>` as a [`MimicDef`] between bodies. A
    /// mimic that cannot be coupled (an unknown leader, a continuous or
    /// floating joint, a chain of mimics) is a warning, and its follower
    /// stays an independent joint.
    fn resolve_mimics(&self, model: &mut ModelDescription, joints: &[JointDecl<'_>]) {
        let body_of: HashMap<&str, usize> = model
            .bodies
            .iter()
            .enumerate()
            .map(|(i, b)| (b.joint_name.as_str(), i))
            .collect();
        let one_dof = |i: usize| {
            matches!(
                model.bodies[i].joint,
                JointType::Revolute { .. } | JointType::Prismatic { .. }
            ) && !model.bodies[i].continuous
        };
        let mut mimics = Vec::new();
        for j in joints {
            let (Some((leader, multiplier, offset)), Some(&follower)) =
                (j.mimic, body_of.get(j.name))
            else {
                continue;
            };
            let why = match body_of.get(leader) {
                None => Some("which is not a moving joint of the robot"),
                Some(&l) if !(one_dof(follower) && one_dof(l)) || follower == l => Some(
                    "but a mimic couples two distinct revolute or prismatic joints (not \
                     continuous, floating or itself)",
                ),
                Some(&l) => {
                    mimics.push(MimicDef {
                        follower,
                        leader: l,
                        multiplier,
                        offset,
                    });
                    None
                }
            };
            if let Some(why) = why {
                self.lenient(Diagnostic::warning_of(
                    WarningKind::Mimic,
                    j.location.clone(),
                    format!(
                        "joint `{}` mimics `{leader}`, {why}; it stays an independent joint",
                        j.name
                    ),
                ));
            }
        }
        let followers: Vec<usize> = mimics.iter().map(|m: &MimicDef| m.follower).collect();
        mimics.retain(|m| {
            if !followers.contains(&m.leader) {
                return true;
            }
            let j = &model.bodies[m.follower];
            self.lenient(Diagnostic::warning_of(
                WarningKind::Mimic,
                j.location.clone(),
                format!(
                    "joint `{}` mimics `{}`, which mimics another joint itself; it stays an \
                     independent joint (make it mimic that joint directly)",
                    j.joint_name, model.bodies[m.leader].joint_name
                ),
            ));
            false
        });
        model.mimics = mimics;
    }

    /// Walks the tree depth-first in Pinocchio's order, merging fixed joints.
    fn assemble(
        &self,
        name: String,
        root: &str,
        links: &HashMap<&str, Link>,
        joints: &[JointDecl<'_>],
        options: UrdfOptions,
    ) -> Result<ModelDescription> {
        let mut children: HashMap<&str, Vec<usize>> = HashMap::new();
        for (k, j) in joints.iter().enumerate() {
            children.entry(j.parent).or_default().push(k);
        }
        for list in children.values_mut() {
            list.sort_by(|&a, &b| joints[a].name.cmp(joints[b].name));
        }
        let mut model = ModelDescription {
            name,
            planar: false,
            gravity: URDF_GRAVITY,
            bodies: Vec::new(),
            frames: Vec::new(),
            endpoints: Vec::new(),
            force_elements: Vec::new(),
            motors: Vec::new(),
            contacts: Vec::new(),
            mimics: Vec::new(),
            warnings: Vec::new(),
            included_files: vec![self.file.to_path_buf()],
            round_quarter_turns: false,
        };
        let root_link = &links[root];
        let root_frame = if options.floating_base {
            model.bodies.push(Body {
                name: root.to_string(),
                joint_name: "root_joint".to_string(),
                parent: None,
                joint: JointType::FreeFlyer,
                continuous: false,
                placement: Pose::IDENTITY,
                inertia: root_link.inertia.unwrap_or(RigidInertia::ZERO),
                location: root_link.location.clone(),
            });
            Some(0)
        } else {
            if root_link.inertia.is_some_and(|i| i.mass > 0.0) {
                model.warnings.push(Diagnostic::warning_of(
                    WarningKind::FixedRootInertia,
                    root_link.location.clone(),
                    format!("the root link `{root}` is fixed to the world, so its inertia never moves and is dropped (as in Pinocchio); ask for a floating base to keep it"),
                ));
            }
            None
        };
        model.frames.push(Frame {
            name: root.to_string(),
            body: root_frame,
            pose: Pose::IDENTITY,
        });
        // Pending joints, each with the body its parent link is fixed to and
        // the parent link's frame in that body. A joint's body is created when
        // the joint is popped, so indices follow Pinocchio's depth-first order.
        let mut stack: Vec<(usize, Option<usize>, Pose)> = Vec::new();
        let push_children = |stack: &mut Vec<_>, link: &str, body, pose: Pose| {
            // Reversed, so that the first joint by name is popped first.
            for &k in children.get(link).into_iter().flatten().rev() {
                stack.push((k, body, pose));
            }
        };
        push_children(&mut stack, root, root_frame, Pose::IDENTITY);
        while let Some((k, body, pose)) = stack.pop() {
            let j = &joints[k];
            let placement = pose.compose(&j.origin);
            let child_inertia = links[j.child].inertia.unwrap_or(RigidInertia::ZERO);
            match j.kind {
                JointKind::Fixed => {
                    if let Some(b) = body {
                        let merged = child_inertia.expressed_in(&placement);
                        model.bodies[b].inertia = model.bodies[b].inertia.combined(&merged);
                    }
                    model.frames.push(Frame {
                        name: j.child.to_string(),
                        body,
                        pose: placement,
                    });
                    model.endpoints.push(EndpointDef {
                        name: j.child.to_string(),
                        body,
                        position: placement.trans,
                        location: j.location.clone(),
                    });
                    push_children(&mut stack, j.child, body, placement);
                }
                JointKind::Moving(joint) => {
                    let index = model.bodies.len();
                    model.bodies.push(Body {
                        name: j.child.to_string(),
                        joint_name: j.name.to_string(),
                        parent: body,
                        joint,
                        continuous: j.continuous,
                        placement,
                        inertia: child_inertia,
                        location: j.location.clone(),
                    });
                    model.frames.push(Frame {
                        name: j.child.to_string(),
                        body: Some(index),
                        pose: Pose::IDENTITY,
                    });
                    push_children(&mut stack, j.child, Some(index), Pose::IDENTITY);
                }
            }
        }
        Ok(model)
    }
}

/// The first child element of `node` named `tag`.
fn child<'a, 'input>(node: Node<'a, 'input>, tag: &str) -> Option<Node<'a, 'input>> {
    node.children()
        .find(|c| c.is_element() && c.tag_name().name() == tag)
}
