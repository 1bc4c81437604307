//! `rodyn-model view`: a model, its visual geometry and (for a simulation)
//! its motion as a [`rodyn_viewer::Scene`], every pose of a trajectory from
//! rodyn's forward kinematics on the run-time model.

use crate::description::JointType;
use crate::runtime::RuntimeModel;
use crate::visual::Visuals;
use rodyn_viewer::{Body, ContactPoint, Endpoint, Joint, Mimic, Pose, Scene, Trajectory};

/// The scene of `model` with `visuals`, its sliders starting at `q` (the
/// file's layout; empty: zeros), mimic joints following their leaders.
/// The sliders' ranges are unlimited: set [`Body::limits`] from
/// [`crate::joint_limits::read_joint_limits`].
#[must_use]
pub fn scene(model: &RuntimeModel, visuals: Visuals, q: &[f64]) -> Scene {
    let d = model.description();
    let mut scene = Scene::new(d.name.clone());
    let g = d.gravity;
    let g_norm = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
    if g_norm > 0.0 {
        scene.up = g.map(|x| -x / g_norm);
    } else if d.planar {
        scene.up = [0.0, 1.0, 0.0];
    }
    scene.bodies = d
        .bodies
        .iter()
        .map(|b| Body {
            name: b.name.clone(),
            joint_name: b.joint_name.clone(),
            parent: b.parent,
            joint: match b.joint {
                JointType::Revolute { axis } => Joint::Revolute { axis },
                JointType::Prismatic { axis } => Joint::Prismatic { axis },
                JointType::FreeFlyer => Joint::FreeFlyer,
                JointType::PlanarFloating => Joint::PlanarFloating,
            },
            placement: Pose {
                rot: b.placement.rot,
                trans: b.placement.trans,
            },
            mass: b.inertia.mass,
            com: b.inertia.com,
            inertia: b.inertia.inertia,
            limits: None,
        })
        .collect();
    scene.mimics = d
        .mimics
        .iter()
        .map(|m| Mimic {
            follower: m.follower,
            leader: m.leader,
            multiplier: m.multiplier,
            offset: m.offset,
        })
        .collect();
    scene.endpoints = d
        .endpoints
        .iter()
        .map(|e| Endpoint {
            name: e.name.clone(),
            body: e.body,
            position: e.position,
        })
        .collect();
    scene.visuals = visuals.visuals;
    scene.meshes = visuals.meshes;
    scene.q = q.to_vec();
    scene
}

/// The world poses of every body at each configuration of `q` (the file's
/// layout), with the contacts of each sample (`contacts` empty: none).
///
/// # Errors
/// A configuration rodyn refuses (a free flyer's quaternion of the wrong
/// length), naming the sample.
pub fn trajectory(
    model: &RuntimeModel,
    t: &[f64],
    q: &[Vec<f64>],
    contacts: Vec<Vec<ContactPoint>>,
) -> Result<Trajectory, String> {
    let poses = t
        .iter()
        .zip(q)
        .enumerate()
        .map(|(k, (time, q))| {
            let poses = model
                .body_poses(q)
                .map_err(|e| format!("sample {k} (t = {time} s): {e}"))?;
            Ok(poses
                .iter()
                .map(|p| Pose {
                    rot: p.rot.m,
                    trans: [p.trans.x, p.trans.y, p.trans.z],
                })
                .collect())
        })
        .collect::<Result<_, String>>()?;
    Ok(Trajectory {
        t: t.to_vec(),
        poses,
        contacts,
    })
}
