//! # rodyn-viewer
//!
//! A 3-D viewer that needs nothing but a browser: [`write_html`] turns a
//! [`Scene`] — bodies, their joints and inertias, visual geometry and mesh
//! files, and optionally a recorded trajectory — into one self-contained
//! HTML page. three.js (vendored, unmodified; see `vendor/three/README.md`)
//! and the page's own small script are inlined, the scene is a JSON block,
//! meshes are inside it: the file opens from `file://` offline. three.js
//! and the mesh files are gzip-compressed (base64 text), and the browser
//! inflates them with its `DecompressionStream`.
//!
//! The producer writes data, the page only renders: world poses of every
//! body at every sample of a trajectory come from the producer (rodyn's
//! forward kinematics); the page composes joint transforms itself only for
//! its joint sliders.
//!
//! ```
//! use rodyn_viewer::{Body, Joint, Pose, Scene, write_html};
//! let mut scene = Scene::new("pendulum");
//! scene.bodies.push(Body {
//!     name: "rod".into(),
//!     joint_name: "hinge".into(),
//!     parent: None,
//!     joint: Joint::Revolute { axis: [0.0, 1.0, 0.0] },
//!     placement: Pose::IDENTITY,
//!     mass: 1.0,
//!     com: [0.0, 0.0, -0.5],
//!     inertia: [[0.08, 0.0, 0.0], [0.0, 0.08, 0.0], [0.0, 0.0, 1e-3]],
//!     limits: Some([-2.0, 2.0]),
//! });
//! let html = write_html(&scene).unwrap();
//! assert!(html.starts_with("<!DOCTYPE html>"));
//! ```
#![warn(missing_docs)]

mod ellipsoid;
mod html;
mod scene;

pub use ellipsoid::{inertia_ellipsoid, Ellipsoid};
pub use html::{write_html, HtmlError};
pub use scene::{
    Body, ContactPoint, Endpoint, Geometry, Joint, Mesh, MeshFormat, Mimic, Pose, Scene,
    Trajectory, Visual,
};
