//! A URDF's `<visual>` geometry for the viewer: boxes, cylinders, spheres
//! and mesh files, on the bodies the links were merged into. The dynamics
//! never read it (see [`crate::urdf`]).
//!
//! A mesh's `filename` is found relative to the URDF's folder, or, for
//! `package://NAME/REST`, as `DIR/NAME/REST` for each `DIR` of the package
//! search path, then as `REST` under a folder named `NAME` that holds the
//! URDF (the layout of a ROS package and of example-robot-data).

use crate::description::ModelDescription;
use crate::diagnostic::{Diagnostic, Location, Result};
use crate::geometry::Pose;
use rodyn_viewer::{Geometry, Mesh, MeshFormat, Visual};
use roxmltree::Node;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// The visual geometry of a model, its mesh files read, and what was
/// skipped (a mesh not found or of a format the viewer cannot read).
#[derive(Clone, Debug, Default)]
pub struct Visuals {
    /// Visuals on bodies (or the world).
    pub visuals: Vec<Visual>,
    /// The mesh files, each once.
    pub meshes: Vec<Mesh>,
    /// What was left out, and why.
    pub warnings: Vec<Diagnostic>,
}

/// The visuals of `model`'s URDF (the model file itself, or the URDF a
/// rodyn file includes); none for a model without one.
///
/// # Errors
/// The URDF cannot be read again, or a `<visual>` has a malformed number.
pub fn read_visuals(model: &ModelDescription, package_path: &[PathBuf]) -> Result<Visuals> {
    let Some(urdf) = model_urdf(model) else {
        return Ok(Visuals::default());
    };
    let text = crate::read_model_file(urdf)
        .map_err(|e| Diagnostic::error(Location::start_of(urdf), e.to_string()))?;
    let doc = roxmltree::Document::parse(&text).map_err(|e| {
        Diagnostic::error(Location::at_offset(urdf, &text, 0), format!("not XML: {e}"))
    })?;
    let reader = Reader {
        file: urdf,
        text: &text,
        package_path,
    };
    reader.read(&doc, model)
}

/// The URDF a model was read from: the model file itself, or the one a
/// rodyn file includes.
pub(crate) fn model_urdf(model: &ModelDescription) -> Option<&Path> {
    model
        .included_files
        .iter()
        .find(|f| {
            f.extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("urdf"))
        })
        .map(PathBuf::as_path)
}

struct Reader<'a> {
    file: &'a Path,
    text: &'a str,
    package_path: &'a [PathBuf],
}

impl Reader<'_> {
    fn at(&self, node: Node<'_, '_>) -> Location {
        Location::at_offset(self.file, self.text, node.range().start)
    }

    fn numbers<const N: usize>(
        &self,
        node: Node<'_, '_>,
        name: &str,
        default: [f64; N],
    ) -> Result<[f64; N]> {
        let Some(text) = node.attribute(name) else {
            return Ok(default);
        };
        let parts: Vec<f64> = text
            .split_whitespace()
            .map(str::parse)
            .collect::<std::result::Result<_, _>>()
            .map_err(|_| self.bad(node, name, N, text))?;
        parts.try_into().map_err(|_| self.bad(node, name, N, text))
    }

    fn bad(&self, node: Node<'_, '_>, name: &str, n: usize, text: &str) -> Diagnostic {
        Diagnostic::error(
            self.at(node),
            format!(
                "`{name}` of <{}> needs {n} numbers, found `{text}`",
                node.tag_name().name()
            ),
        )
    }

    fn read(&self, doc: &roxmltree::Document<'_>, model: &ModelDescription) -> Result<Visuals> {
        let robot = doc.root_element();
        let named_colours: HashMap<&str, [f64; 4]> = robot
            .children()
            .filter(|n| n.has_tag_name("material"))
            .filter_map(|m| Some((m.attribute("name")?, self.colour(m).ok()??)))
            .collect();
        let mut out = Visuals::default();
        let mut mesh_index: HashMap<PathBuf, usize> = HashMap::new();
        for link in robot.children().filter(|n| n.has_tag_name("link")) {
            let name = link.attribute("name").unwrap_or_default();
            // Where the link sits: on its own body, merged into another, or
            // on the world.
            let Some(frame) = model.frames.iter().find(|f| f.name == name) else {
                continue;
            };
            for visual in link.children().filter(|n| n.has_tag_name("visual")) {
                let origin = visual.children().find(|n| n.has_tag_name("origin"));
                let pose = match origin {
                    Some(o) => Pose::from_xyz_rpy(
                        &self.numbers(o, "xyz", [0.0; 3])?,
                        &self.numbers(o, "rpy", [0.0; 3])?,
                    ),
                    None => Pose::IDENTITY,
                };
                let colour = match visual.children().find(|n| n.has_tag_name("material")) {
                    Some(m) => self.colour(m)?.or_else(|| {
                        m.attribute("name")
                            .and_then(|n| named_colours.get(n).copied())
                    }),
                    None => None,
                };
                let Some(shape) = visual
                    .children()
                    .find(|n| n.has_tag_name("geometry"))
                    .and_then(|g| g.children().find(Node::is_element))
                else {
                    continue;
                };
                let geometry = match shape.tag_name().name() {
                    "box" => Geometry::Box {
                        size: self.numbers(shape, "size", [0.0; 3])?,
                    },
                    "cylinder" => Geometry::Cylinder {
                        radius: self.numbers(shape, "radius", [0.0])?[0],
                        length: self.numbers(shape, "length", [0.0])?[0],
                    },
                    "sphere" => Geometry::Sphere {
                        radius: self.numbers(shape, "radius", [0.0])?[0],
                    },
                    "mesh" => {
                        let scale = self.numbers(shape, "scale", [1.0; 3])?;
                        match self.mesh(shape, &mut out, &mut mesh_index) {
                            Ok(mesh) => Geometry::Mesh { mesh, scale },
                            Err(warning) => {
                                out.warnings.push(warning);
                                continue;
                            }
                        }
                    }
                    other => {
                        out.warnings.push(Diagnostic::warning(
                            self.at(shape),
                            format!("link `{name}`: <{other}> geometry is not drawn"),
                        ));
                        continue;
                    }
                };
                let on_body = frame.pose.compose(&pose);
                out.visuals.push(Visual {
                    body: frame.body,
                    pose: rodyn_viewer::Pose {
                        rot: on_body.rot,
                        trans: on_body.trans,
                    },
                    geometry,
                    color: colour,
                });
            }
        }
        Ok(out)
    }

    /// A `<material>`'s `<color rgba>`, if it has one.
    fn colour(&self, material: Node<'_, '_>) -> Result<Option<[f64; 4]>> {
        match material.children().find(|n| n.has_tag_name("color")) {
            Some(c) if c.has_attribute("rgba") => Ok(Some(self.numbers(c, "rgba", [0.0; 4])?)),
            _ => Ok(None),
        }
    }

    /// The index of `<mesh>`'s file in `out.meshes`, read on first use;
    /// a warning when it cannot be found or read.
    fn mesh(
        &self,
        shape: Node<'_, '_>,
        out: &mut Visuals,
        index: &mut HashMap<PathBuf, usize>,
    ) -> std::result::Result<usize, Diagnostic> {
        let warn = |m: String| Diagnostic::warning(self.at(shape), m);
        let filename = shape
            .attribute("filename")
            .ok_or_else(|| warn("<mesh> without a `filename` is not drawn".into()))?;
        let format = MeshFormat::from_file_name(filename).ok_or_else(|| {
            warn(format!(
                "`{filename}`: the viewer reads STL, COLLADA (.dae) and OBJ meshes only; not drawn"
            ))
        })?;
        let path = self.resolve(filename).ok_or_else(|| {
            warn(format!(
                "mesh `{filename}` not found (relative to the URDF's folder, or for package:// under a --package-path folder); not drawn"
            ))
        })?;
        if let Some(&k) = index.get(&path) {
            return Ok(k);
        }
        let bytes = std::fs::read(&path)
            .map_err(|e| warn(format!("mesh `{}`: {e}; not drawn", path.display())))?;
        out.meshes.push(Mesh {
            name: filename.to_string(),
            format,
            bytes,
        });
        index.insert(path, out.meshes.len() - 1);
        Ok(out.meshes.len() - 1)
    }

    /// Where `filename` (relative, `file://` or `package://`) is on disk.
    fn resolve(&self, filename: &str) -> Option<PathBuf> {
        let folder = self.file.parent().unwrap_or(Path::new("."));
        if let Some(rest) = filename.strip_prefix("package://") {
            let (package, inside) = rest.split_once('/')?;
            let in_search_path = self
                .package_path
                .iter()
                .map(|dir| dir.join(package).join(inside));
            // A folder named after the package that holds the URDF.
            let in_ancestors = folder
                .ancestors()
                .filter(|a| a.file_name().is_some_and(|n| n == package))
                .map(|a| a.join(inside));
            return in_search_path.chain(in_ancestors).find(|p| p.is_file());
        }
        let path = Path::new(filename.strip_prefix("file://").unwrap_or(filename));
        Some(folder.join(path)).filter(|p| p.is_file())
    }
}
