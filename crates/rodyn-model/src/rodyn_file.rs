//! rodyn's own model file (TOML): a skeleton written out body by body or
//! included from a URDF, plus what URDF cannot say: endpoints, springs,
//! dampers and muscles along paths of endpoints, motors, contacts, planar
//! models. The format is documented in `models/README.md`.
//!
//! Units: `[units]` chooses the unit of the lengths (`m`, `cm`, `mm`), masses
//! (`kg`, `g`) and angles (`rad`, `deg`) written in the file; every other
//! quantity (inertia, stiffness, damping, force, torque constant) is SI.

use crate::codegen::fits_f32;
use crate::description::{
    Body, Contact, EndpointDef, ForceElement, ForceLaw, Frame, JointType, ModelDescription, Motor,
};
use crate::diagnostic::{Diagnostic, LineIndex, Location, Result, WarningKinds};
use crate::geometry::{norm, scale, Pose, RigidInertia, Vec3};
use crate::names::{check_distinct, check_not_reserved};
use crate::physics::{check_mass, check_rotational_inertia, check_subtrees_have_mass};
use crate::urdf::{read_urdf, UrdfOptions};
use serde::Deserialize;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

type S<T> = Spanned<T>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    model: ModelSection,
    #[serde(default)]
    units: Units,
    #[serde(default)]
    body: Vec<BodyDecl>,
    #[serde(default)]
    endpoint: Vec<EndpointDecl>,
    #[serde(default)]
    frame: Vec<FrameDecl>,
    #[serde(default)]
    spring: Vec<SpringDecl>,
    #[serde(default)]
    damper: Vec<DamperDecl>,
    #[serde(default)]
    muscle: Vec<MuscleDecl>,
    #[serde(default)]
    motor: Vec<MotorDecl>,
    #[serde(default)]
    contact: Vec<ContactDecl>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ModelSection {
    name: S<String>,
    #[serde(default)]
    planar: bool,
    gravity: Option<S<Vec<f64>>>,
    include: Option<S<String>>,
    #[serde(default)]
    floating_base: bool,
    /// Warnings about what cannot harm the dynamics become errors.
    #[serde(default)]
    strict: bool,
    /// Placements within 1e-10 of a quarter turn become exact ones.
    #[serde(default)]
    round_quarter_turns: bool,
    /// Kinds of warning not to report (`WarningKind` names).
    #[serde(default)]
    silence: Vec<S<String>>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct Units {
    length: Option<S<String>>,
    mass: Option<S<String>>,
    angle: Option<S<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BodyDecl {
    name: S<String>,
    parent: S<String>,
    joint: S<String>,
    #[serde(rename = "type")]
    kind: S<String>,
    axis: Option<S<Vec<f64>>>,
    origin: Option<S<Vec<f64>>>,
    rpy: Option<S<Vec<f64>>>,
    angle: Option<S<f64>>,
    mass: S<f64>,
    com: Option<S<Vec<f64>>>,
    inertia: Option<S<toml::Value>>,
    radius_of_gyration: Option<S<toml::Value>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct EndpointDecl {
    name: S<String>,
    body: S<String>,
    position: S<Vec<f64>>,
}

/// A named frame (placement and orientation) on a body or URDF link.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FrameDecl {
    name: S<String>,
    body: S<String>,
    position: Option<S<Vec<f64>>>,
    rpy: Option<S<Vec<f64>>>,
    angle: Option<S<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SpringDecl {
    name: S<String>,
    path: S<Vec<S<String>>>,
    stiffness: S<f64>,
    rest_length: S<f64>,
    #[serde(default)]
    cubic_stiffness: Option<S<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct DamperDecl {
    name: S<String>,
    path: S<Vec<S<String>>>,
    damping: S<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MuscleDecl {
    name: S<String>,
    path: S<Vec<S<String>>>,
    max_isometric_force: S<f64>,
    optimal_fiber_length: S<f64>,
    tendon_slack_length: S<f64>,
    #[serde(default)]
    pennation_angle: Option<S<f64>>,
    max_contraction_velocity: Option<S<f64>>,
    activation_time_constant: Option<S<f64>>,
    deactivation_time_constant: Option<S<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MotorDecl {
    name: S<String>,
    joint: S<String>,
    gear_ratio: S<f64>,
    rotor_inertia: S<f64>,
    torque_constant: S<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ContactDecl {
    name: S<String>,
    endpoint: S<String>,
    stiffness: S<f64>,
    damping: S<f64>,
    friction: S<f64>,
    /// m/s; the slip at which friction reaches tanh(1) ≈ 76 % of Coulomb's.
    #[serde(default)]
    slip_velocity: Option<S<f64>>,
}

/// Unit conversion factors to SI.
struct Scale {
    length: f64,
    mass: f64,
    angle: f64,
}

/// Reads a rodyn model file `text` (the content of `file`); `strict` turns
/// the warnings of an included URDF about what cannot harm the dynamics
/// into errors (as `strict = true` in the file's `[model]` table does).
///
/// # Errors
/// The first problem found, with its position in `file` (or in an included
/// URDF).
pub fn read_rodyn_file(file: &Path, text: &str, strict: bool) -> Result<ModelDescription> {
    read_rodyn_file_with(file, text, crate::LoadOptions::new().with_strict(strict))
}

/// [`read_rodyn_file`] with the caller's options: strict mode and the
/// silenced kinds of warning (the file's `silence` adds to them).
///
/// # Errors
/// As [`read_rodyn_file`]; also a `silence` entry that is no kind of warning.
pub fn read_rodyn_file_with(
    file: &Path,
    text: &str,
    options: crate::LoadOptions,
) -> Result<ModelDescription> {
    let strict = options.strict;
    let silence = options.silence;
    let parsed: File = toml::from_str(text).map_err(|e| {
        let at = e.span().map_or(0, |s| s.start);
        Diagnostic::error(
            Location::at_offset(file, text, at),
            e.message().trim_end().replace('\n', " "),
        )
    })?;
    Reader {
        file,
        text,
        lines: LineIndex::new(text),
        strict,
        silence,
    }
    .read(parsed)
}

struct Reader<'a> {
    file: &'a Path,
    text: &'a str,
    lines: LineIndex,
    /// Strict mode asked by the caller (the file may ask too).
    strict: bool,
    /// Kinds of warning the caller silenced (the file may add some).
    silence: WarningKinds,
}

impl Reader<'_> {
    fn at(&self, span: Range<usize>) -> Location {
        Location::at_offset_indexed(self.file, self.text, &self.lines, span.start)
    }
    fn error<T, U>(&self, at: &S<U>, message: impl Into<String>) -> Result<T> {
        Err(Diagnostic::error(self.at(at.span()), message))
    }

    fn unit(&self, spec: &Option<S<String>>, table: &[(&str, f64)], what: &str) -> Result<f64> {
        let Some(spec) = spec else {
            return Ok(1.0);
        };
        match table.iter().find(|(name, _)| *name == spec.get_ref()) {
            Some((_, factor)) => Ok(*factor),
            None => {
                let known = table
                    .iter()
                    .map(|(n, _)| format!("`{n}`"))
                    .collect::<Vec<_>>();
                self.error(
                    spec,
                    format!(
                        "unknown {what} unit `{}`; use one of {}",
                        spec.get_ref(),
                        known.join(", ")
                    ),
                )
            }
        }
    }

    /// A finite number, optionally required to be positive or non-negative.
    fn number(&self, x: &S<f64>, what: &str, sign: Sign) -> Result<f64> {
        let v = *x.get_ref();
        let ok = v.is_finite()
            && match sign {
                Sign::Any => true,
                Sign::Positive => v > 0.0,
                Sign::NonNegative => v >= 0.0,
            };
        if ok && !fits_f32(v) {
            return self.error(
                x,
                format!("{what} is {v:e}, which the model's f32 version cannot hold (magnitudes up to 3.4e38)"),
            );
        }
        if ok {
            Ok(v)
        } else {
            let need = match sign {
                Sign::Any => "a finite number",
                Sign::Positive => "a positive number",
                Sign::NonNegative => "zero or a positive number",
            };
            self.error(x, format!("{what} is {v}; it must be {need}"))
        }
    }

    /// A point or direction: 3 numbers, or 2 (z = 0) in a planar model.
    fn vector(&self, v: &S<Vec<f64>>, what: &str, planar: bool, factor: f64) -> Result<Vec3> {
        let x = v.get_ref();
        if let Some(bad) = x.iter().find(|x| x.is_finite() && !fits_f32(**x * factor)) {
            return self.error(
                v,
                format!("{what} has the entry {bad:e}, which the model's f32 version cannot hold (magnitudes up to 3.4e38)"),
            );
        }
        let out = match (x.len(), planar) {
            (3, _) => [x[0], x[1], x[2]],
            (2, true) => [x[0], x[1], 0.0],
            (_, true) => {
                return self.error(
                    v,
                    format!("{what} needs 2 numbers (x, y) in a planar model, or 3"),
                )
            }
            (_, false) => return self.error(v, format!("{what} needs 3 numbers (x, y, z)")),
        };
        if out.iter().any(|c| !c.is_finite()) {
            return self.error(v, format!("{what} has a non-finite component"));
        }
        Ok(scale(&out, factor))
    }

    fn read(&self, f: File) -> Result<ModelDescription> {
        let scale_to_si = Scale {
            length: self.unit(
                &f.units.length,
                &[("m", 1.0), ("cm", 0.01), ("mm", 0.001)],
                "length",
            )?,
            mass: self.unit(&f.units.mass, &[("kg", 1.0), ("g", 0.001)], "mass")?,
            angle: self.unit(
                &f.units.angle,
                &[("rad", 1.0), ("deg", std::f64::consts::PI / 180.0)],
                "angle",
            )?,
        };
        let planar = f.model.planar;
        let silence = self.silence.union(self.silenced_by_file(&f.model)?);
        let mut model = match &f.model.include {
            Some(include) => {
                let path = self
                    .file
                    .parent()
                    .unwrap_or(Path::new("."))
                    .join(include.get_ref());
                let text = crate::read_model_file(&path).map_err(|e| {
                    Diagnostic::error(
                        self.at(include.span()),
                        format!("cannot read the included file `{}`: {e}", path.display()),
                    )
                })?;
                let options = UrdfOptions {
                    floating_base: f.model.floating_base,
                    strict: self.strict || f.model.strict,
                    silence,
                };
                let mut m = read_urdf(&path, &text, options)?;
                m.included_files.insert(0, self.file.to_path_buf());
                m
            }
            None => ModelDescription {
                name: String::new(),
                planar,
                gravity: [0.0, 0.0, -9.81],
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
            },
        };
        model.round_quarter_turns = f.model.round_quarter_turns;
        model.name = f.model.name.get_ref().clone();
        model.planar = planar;
        if planar {
            model.gravity = [0.0, -9.81, 0.0];
        }
        if let Some(g) = &f.model.gravity {
            model.gravity = self.vector(g, "gravity", planar, 1.0)?;
        }
        if f.model.floating_base && f.model.include.is_none() {
            return self.error(
                &f.model.name,
                "`floating_base` applies to an included URDF; in a rodyn file give the root body `type = \"floating\"`",
            );
        }
        for b in &f.body {
            self.add_body(&mut model, b, &scale_to_si)?;
        }
        if model.bodies.is_empty() {
            return self.error(
                &f.model.name,
                "the model has no moving body; add a [[body]] or an `include`",
            );
        }
        check_subtrees_have_mass(&model)?;
        if planar {
            crate::codegen::check_planar(&model)?;
        }
        for e in &f.endpoint {
            self.add_endpoint(&mut model, e, &scale_to_si)?;
        }
        for fr in &f.frame {
            self.add_frame(&mut model, fr, &scale_to_si)?;
        }
        check_distinct(
            "endpoint",
            model
                .endpoints
                .iter()
                .map(|e| (e.name.as_str(), &e.location)),
        )?;
        self.add_drives(&mut model, &f, &scale_to_si)?;
        Ok(model)
    }

    /// The kinds of warning the file's `silence` names.
    fn silenced_by_file(&self, model: &ModelSection) -> Result<WarningKinds> {
        let mut set = WarningKinds::NONE;
        for name in &model.silence {
            set = set.union(
                WarningKinds::parse_one(name.get_ref())
                    .map_err(|why| Diagnostic::error(self.at(name.span()), why))?,
            );
        }
        Ok(set)
    }

    /// The body a frame name is fixed to and the frame's pose in it.
    fn frame(&self, model: &ModelDescription, name: &S<String>) -> Result<(Option<usize>, Pose)> {
        if name.get_ref() == "world" {
            return Ok((None, Pose::IDENTITY));
        }
        match model.frames.iter().find(|fr| &fr.name == name.get_ref()) {
            Some(fr) => Ok((fr.body, fr.pose)),
            None => self.error(
                name,
                format!("there is no body or link named `{}` (bodies must be declared before they are used; `world` is the ground)", name.get_ref()),
            ),
        }
    }

    fn add_body(&self, model: &mut ModelDescription, b: &BodyDecl, si: &Scale) -> Result<()> {
        let name = b.name.get_ref();
        let planar = model.planar;
        if model.frames.iter().any(|fr| &fr.name == name) || name == "world" {
            return self.error(
                &b.name,
                format!("a body or link named `{name}` already exists"),
            );
        }
        if model
            .bodies
            .iter()
            .any(|x| &x.joint_name == b.joint.get_ref())
        {
            return self.error(
                &b.joint,
                format!("a joint named `{}` already exists", b.joint.get_ref()),
            );
        }
        let (parent, parent_pose) = self.frame(model, &b.parent)?;
        let axis = match &b.axis {
            None if planar => [0.0, 0.0, 1.0],
            None => [1.0, 0.0, 0.0],
            Some(a) => {
                let v = self.vector(a, "the axis", planar, 1.0)?;
                let n = norm(&v);
                if n < 1e-12 {
                    return self.error(
                        a,
                        format!(
                            "joint `{}` has a zero axis; an axis needs a direction",
                            b.joint.get_ref()
                        ),
                    );
                }
                scale(&v, 1.0 / n)
            }
        };
        let joint = match b.kind.get_ref().as_str() {
            "revolute" | "continuous" => JointType::Revolute { axis },
            "prismatic" => JointType::Prismatic { axis },
            "floating" if planar => JointType::PlanarFloating,
            "floating" => JointType::FreeFlyer,
            other => {
                return self.error(
                    &b.kind,
                    format!("unknown joint type `{other}`; rodyn files know revolute, continuous, prismatic and floating"),
                )
            }
        };
        if matches!(joint, JointType::FreeFlyer | JointType::PlanarFloating) && parent.is_some() {
            return self.error(
                &b.kind,
                "a floating joint must attach its body to the world (`parent = \"world\"`)",
            );
        }
        let translation = match &b.origin {
            Some(o) => self.vector(o, "the origin", planar, si.length)?,
            None => [0.0; 3],
        };
        let rpy = self.rpy(b.rpy.as_ref(), b.angle.as_ref(), planar, si)?;
        let placement = parent_pose.compose(&Pose::from_xyz_rpy(&translation, &rpy));
        let what = format!("body `{name}`");
        let mass = *b.mass.get_ref() * si.mass;
        check_mass(mass, &what, &self.at(b.mass.span()))?;
        let com = match &b.com {
            Some(c) => self.vector(c, "the centre of mass", planar, si.length)?,
            None => [0.0; 3],
        };
        let inertia = self.rotational_inertia(b, mass, planar, si)?;
        let at = b.inertia.as_ref().map_or(b.name.span(), Spanned::span);
        check_rotational_inertia(&inertia, &what, &self.at(at))?;
        let index = model.bodies.len();
        model.bodies.push(Body {
            name: name.clone(),
            joint_name: b.joint.get_ref().clone(),
            parent,
            joint,
            continuous: b.kind.get_ref() == "continuous",
            placement,
            inertia: RigidInertia { mass, com, inertia },
            location: self.at(b.name.span()),
        });
        model.frames.push(Frame {
            name: name.clone(),
            body: Some(index),
            pose: Pose::IDENTITY,
        });
        Ok(())
    }

    /// `inertia` (kg m² about the centre of mass, body axes) or
    /// `radius_of_gyration` (file length unit): a number in a planar model
    /// (about z), else three principal values or a full 3x3 matrix.
    fn rotational_inertia(
        &self,
        b: &BodyDecl,
        mass: f64,
        planar: bool,
        si: &Scale,
    ) -> Result<[[f64; 3]; 3]> {
        let (value, factor) = match (&b.inertia, &b.radius_of_gyration) {
            (Some(_), Some(r)) => {
                return self.error(r, "give either `inertia` or `radius_of_gyration`, not both")
            }
            (Some(i), None) => (i, None),
            (None, Some(r)) => (r, Some(si.length)),
            (None, None) => return Ok([[0.0; 3]; 3]),
        };
        let bad = |why: &str| self.error(value, why.to_string());
        let num = |v: &toml::Value| v.as_float().or_else(|| v.as_integer().map(|i| i as f64));
        let diag = |d: [f64; 3]| [[d[0], 0.0, 0.0], [0.0, d[1], 0.0], [0.0, 0.0, d[2]]];
        let m = match value.get_ref() {
            v if num(v).is_some() => {
                let x = num(v).unwrap_or(0.0);
                if !planar {
                    return bad("a single number is a planar model's moment about z; a 3-D body needs three principal values or a 3x3 matrix");
                }
                // The x and y moments do not enter a planar model; making them
                // equal to z keeps the tensor physical.
                diag([x, x, x])
            }
            toml::Value::Array(rows) if rows.len() == 3 && rows.iter().all(|r| num(r).is_some()) => {
                diag([0, 1, 2].map(|k| num(&rows[k]).unwrap_or(0.0)))
            }
            toml::Value::Array(rows) if factor.is_none() && rows.len() == 3 && rows.iter().all(|r| r.as_array().is_some_and(|c| c.len() == 3 && c.iter().all(|x| num(x).is_some()))) => {
                let mut m = [[0.0; 3]; 3];
                for (i, r) in rows.iter().enumerate() {
                    for (j, x) in r.as_array().into_iter().flatten().enumerate() {
                        m[i][j] = num(x).unwrap_or(0.0);
                    }
                }
                m
            }
            _ => return bad("the inertia must be a number (planar), three principal values, or a 3x3 matrix of numbers"),
        };
        Ok(match factor {
            // I = m r² for each radius of gyration.
            Some(f) => {
                let mut out = [[0.0; 3]; 3];
                for k in 0..3 {
                    let r = m[k][k] * f;
                    out[k][k] = mass * r * r;
                }
                out
            }
            None => m,
        })
    }

    /// Roll, pitch and yaw in radians from `rpy` (3-D) or `angle` (planar,
    /// about z), in the file's angle unit.
    fn rpy(
        &self,
        rpy: Option<&S<Vec<f64>>>,
        angle: Option<&S<f64>>,
        planar: bool,
        si: &Scale,
    ) -> Result<Vec3> {
        Ok(match (rpy, angle) {
            (Some(_), Some(a)) => return self.error(a, "give either `rpy` or `angle`, not both"),
            (Some(r), None) if planar => {
                return self.error(
                    r,
                    "a planar model rotates placements about z only: use `angle`",
                )
            }
            (Some(r), None) => {
                let x = r.get_ref();
                if x.len() != 3 || x.iter().any(|c| !c.is_finite()) {
                    return self.error(r, "`rpy` needs 3 finite angles (roll, pitch, yaw)");
                }
                scale(&[x[0], x[1], x[2]], si.angle)
            }
            (None, Some(a)) => [0.0, 0.0, self.number(a, "the angle", Sign::Any)? * si.angle],
            (None, None) => [0.0; 3],
        })
    }

    /// A `[[frame]]`: a placement on a body or URDF link, kept in the
    /// generated module's frames.
    fn add_frame(&self, model: &mut ModelDescription, f: &FrameDecl, si: &Scale) -> Result<()> {
        let name = f.name.get_ref();
        if model.frames.iter().any(|fr| &fr.name == name) || name == "world" {
            return self.error(
                &f.name,
                format!("a body, link or frame named `{name}` already exists"),
            );
        }
        let (body, pose) = self.frame(model, &f.body)?;
        if body.is_none() {
            return self.error(
                &f.body,
                format!(
                    "frame `{name}` is fixed to the world (`{}`), which never moves; a frame \
                     needs a moving body",
                    f.body.get_ref()
                ),
            );
        }
        let position = match &f.position {
            Some(p) => self.vector(p, "the position", model.planar, si.length)?,
            None => [0.0; 3],
        };
        let rpy = self.rpy(f.rpy.as_ref(), f.angle.as_ref(), model.planar, si)?;
        model.frames.push(Frame {
            name: name.clone(),
            body,
            pose: pose.compose(&Pose::from_xyz_rpy(&position, &rpy)),
        });
        Ok(())
    }

    fn add_endpoint(
        &self,
        model: &mut ModelDescription,
        e: &EndpointDecl,
        si: &Scale,
    ) -> Result<()> {
        let (body, pose) = self.frame(model, &e.body)?;
        let p = self.vector(&e.position, "the position", model.planar, si.length)?;
        model.endpoints.push(EndpointDef {
            name: e.name.get_ref().clone(),
            body,
            position: pose.act_point(&p),
            location: self.at(e.name.span()),
        });
        Ok(())
    }

    fn path(
        &self,
        model: &ModelDescription,
        element: &S<String>,
        path: &S<Vec<S<String>>>,
    ) -> Result<Vec<usize>> {
        if path.get_ref().len() < 2 {
            return self.error(
                path,
                format!(
                    "the path of `{}` needs at least two endpoints",
                    element.get_ref()
                ),
            );
        }
        path.get_ref()
            .iter()
            .map(|name| {
                model
                    .endpoints
                    .iter()
                    .position(|e| &e.name == name.get_ref())
                    .map_or_else(
                        || {
                            self.error(
                                name,
                                format!(
                                    "`{}` names the endpoint `{}`, which does not exist",
                                    element.get_ref(),
                                    name.get_ref()
                                ),
                            )
                        },
                        Ok,
                    )
            })
            .collect()
    }

    fn add_drives(&self, model: &mut ModelDescription, f: &File, si: &Scale) -> Result<()> {
        let mut names: Vec<(&str, Location)> = Vec::new();
        for s in &f.spring {
            let law = ForceLaw::Spring {
                stiffness: self.number(&s.stiffness, "the stiffness", Sign::NonNegative)?,
                rest_length: self.number(&s.rest_length, "the rest length", Sign::NonNegative)?
                    * si.length,
                cubic_stiffness: match &s.cubic_stiffness {
                    Some(k) => self.number(k, "the cubic stiffness", Sign::NonNegative)?,
                    None => 0.0,
                },
            };
            let path = self.path(model, &s.name, &s.path)?;
            model.force_elements.push(ForceElement {
                name: s.name.get_ref().clone(),
                path,
                law,
            });
            names.push((s.name.get_ref(), self.at(s.name.span())));
        }
        for d in &f.damper {
            let law = ForceLaw::Damper {
                damping: self.number(&d.damping, "the damping", Sign::NonNegative)?,
            };
            let path = self.path(model, &d.name, &d.path)?;
            model.force_elements.push(ForceElement {
                name: d.name.get_ref().clone(),
                path,
                law,
            });
            names.push((d.name.get_ref(), self.at(d.name.span())));
        }
        for m in &f.muscle {
            let optional = |x: &Option<S<f64>>, what: &str, default: f64| -> Result<f64> {
                x.as_ref()
                    .map_or(Ok(default), |v| self.number(v, what, Sign::Positive))
            };
            let law = ForceLaw::Muscle {
                max_isometric_force: self.number(
                    &m.max_isometric_force,
                    "the maximum isometric force",
                    Sign::Positive,
                )?,
                optimal_fiber_length: self.number(
                    &m.optimal_fiber_length,
                    "the optimal fibre length",
                    Sign::Positive,
                )? * si.length,
                tendon_slack_length: self.number(
                    &m.tendon_slack_length,
                    "the tendon slack length",
                    Sign::NonNegative,
                )? * si.length,
                pennation_angle: match &m.pennation_angle {
                    Some(a) => self.number(a, "the pennation angle", Sign::NonNegative)? * si.angle,
                    None => 0.0,
                },
                max_contraction_velocity: optional(
                    &m.max_contraction_velocity,
                    "the maximum contraction velocity",
                    10.0,
                )?,
                activation_time_constant: optional(
                    &m.activation_time_constant,
                    "the activation time constant",
                    0.015,
                )?,
                deactivation_time_constant: optional(
                    &m.deactivation_time_constant,
                    "the deactivation time constant",
                    0.050,
                )?,
            };
            let path = self.path(model, &m.name, &m.path)?;
            model.force_elements.push(ForceElement {
                name: m.name.get_ref().clone(),
                path,
                law,
            });
            names.push((m.name.get_ref(), self.at(m.name.span())));
        }
        for m in &f.motor {
            let Some(body) = model
                .bodies
                .iter()
                .position(|b| &b.joint_name == m.joint.get_ref())
            else {
                return self.error(
                    &m.joint,
                    format!(
                        "motor `{}` drives the joint `{}`, which does not exist",
                        m.name.get_ref(),
                        m.joint.get_ref()
                    ),
                );
            };
            if model.bodies[body].joint.nv() != 1 {
                return self.error(
                    &m.joint,
                    format!(
                        "motor `{}` needs a joint with one degree of freedom",
                        m.name.get_ref()
                    ),
                );
            }
            model.motors.push(Motor {
                name: m.name.get_ref().clone(),
                body,
                gear_ratio: self.number(&m.gear_ratio, "the gear ratio", Sign::Positive)?,
                rotor_inertia: self.number(
                    &m.rotor_inertia,
                    "the rotor inertia",
                    Sign::NonNegative,
                )?,
                torque_constant: self.number(
                    &m.torque_constant,
                    "the torque constant",
                    Sign::Positive,
                )?,
            });
            names.push((m.name.get_ref(), self.at(m.name.span())));
        }
        for c in &f.contact {
            let Some(endpoint) = model
                .endpoints
                .iter()
                .position(|e| &e.name == c.endpoint.get_ref())
            else {
                return self.error(
                    &c.endpoint,
                    format!(
                        "contact `{}` names the endpoint `{}`, which does not exist",
                        c.name.get_ref(),
                        c.endpoint.get_ref()
                    ),
                );
            };
            model.contacts.push(Contact {
                name: c.name.get_ref().clone(),
                endpoint,
                stiffness: self.number(&c.stiffness, "the contact stiffness", Sign::Positive)?,
                damping: self.number(&c.damping, "the contact damping", Sign::NonNegative)?,
                friction: self.number(
                    &c.friction,
                    "the friction coefficient",
                    Sign::NonNegative,
                )?,
                // Positive: the friction law divides the slip by it.
                slip_velocity: match &c.slip_velocity {
                    Some(v) => self.number(v, "the slip velocity", Sign::Positive)?,
                    None => Contact::DEFAULT_SLIP_VELOCITY,
                },
            });
            names.push((c.name.get_ref(), self.at(c.name.span())));
        }
        check_distinct("drive or contact", names.iter().map(|(n, l)| (*n, l)))?;
        check_not_reserved("drive or contact", names.iter().map(|(n, l)| (*n, l)))
    }
}

#[derive(Clone, Copy)]
enum Sign {
    Any,
    Positive,
    NonNegative,
}
