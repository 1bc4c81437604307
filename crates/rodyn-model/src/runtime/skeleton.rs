//! A model description as rodyn's parts (joints, placements, inertias,
//! frames), built once at load time and shared by every size class: the
//! numbers are exactly the ones the model compiler writes into the
//! generated code, so the run-time and the compiled model agree to the
//! last bit of their inputs.

use crate::codegen::generated_frames;
use crate::description::{JointType, ModelDescription};
use crate::geometry::{snap_signed_permutation, Pose, IDENTITY};
use rodyn::joint::{Axis, Joint};
use rodyn::spatial::{Inertia, Mat3, Motion, Sym3, Transform, Vec3};
use rodyn::Frame;

/// The 3-D model a description stands for (a planar model as its 3-D
/// equivalent: joints about z, a planar floating base as a free-flyer).
pub(super) struct Skeleton {
    pub parents: Vec<Option<usize>>,
    pub joints: Vec<Joint<f64>>,
    pub placements: Vec<Transform<f64>>,
    pub inertias: Vec<Inertia<f64>>,
    pub gravity: Motion<f64>,
    /// Named frames on moving bodies, as the generated module's `FRAMES_F64`.
    pub frames: Vec<(String, Frame<f64>)>,
    /// One-degree-of-freedom joints.
    pub one_dof: usize,
    /// Free-flyers.
    pub free_flyers: usize,
}

fn vec3(v: &[f64; 3]) -> Vec3<f64> {
    Vec3::new(v[0], v[1], v[2])
}

fn axis(a: &[f64; 3]) -> Axis<f64> {
    match a {
        [1.0, 0.0, 0.0] => Axis::X,
        [0.0, 1.0, 0.0] => Axis::Y,
        [0.0, 0.0, 1.0] => Axis::Z,
        _ => Axis::Unit(vec3(a)),
    }
}

/// A placement as the generated code writes it: rotations within the
/// description's tolerance of a quarter turn made exact.
fn transform(pose: &Pose, tolerance: f64) -> Transform<f64> {
    let rot = snap_signed_permutation(&pose.rot, tolerance).unwrap_or(pose.rot);
    if rot == IDENTITY {
        Transform::from_translation(vec3(&pose.trans))
    } else {
        Transform::new(Mat3::from_rows(rot), vec3(&pose.trans))
    }
}

impl Skeleton {
    pub fn new(description: &ModelDescription) -> Self {
        let tolerance = description.snap_tolerance();
        let mut skeleton = Self {
            parents: Vec::new(),
            joints: Vec::new(),
            placements: Vec::new(),
            inertias: Vec::new(),
            gravity: Motion::new(Vec3::ZERO, vec3(&description.gravity)),
            frames: Vec::new(),
            one_dof: 0,
            free_flyers: 0,
        };
        for b in &description.bodies {
            skeleton.parents.push(b.parent);
            skeleton.joints.push(match b.joint {
                JointType::Revolute { axis: a } => Joint::revolute(axis(&a)),
                JointType::Prismatic { axis: a } => Joint::prismatic(axis(&a)),
                JointType::FreeFlyer | JointType::PlanarFloating => Joint::free_flyer(),
            });
            if matches!(b.joint, JointType::FreeFlyer | JointType::PlanarFloating) {
                skeleton.free_flyers += 1;
            } else {
                skeleton.one_dof += 1;
            }
            skeleton.placements.push(transform(&b.placement, tolerance));
            let r = &b.inertia.inertia;
            skeleton.inertias.push(Inertia::new(
                b.inertia.mass,
                vec3(&b.inertia.com),
                Sym3::new(r[0][0], r[0][1], r[0][2], r[1][1], r[1][2], r[2][2]),
            ));
        }
        skeleton.frames = generated_frames(description)
            .into_iter()
            .map(|(f, body, _)| {
                (
                    f.name.clone(),
                    Frame::new(body, transform(&f.pose, tolerance)),
                )
            })
            .collect();
        skeleton
    }

    /// Bodies.
    pub fn nb(&self) -> usize {
        self.joints.len()
    }
}
