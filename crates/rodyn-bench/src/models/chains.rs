//! Planar revolute chains of `N` links, the models of the ABA/CRBA crossover.
//!
//! Link k has the parameters that `tools/pinocchio/make_models.py`
//! (`planar_link`) writes into `models/urdf/planar_chain_N.urdf`: smooth,
//! aperiodic variations of length, mass, centre of mass and inertia, so that
//! a chain of N links is a prefix of a longer one. The comparison binary
//! checks that the chains built here and the URDF files loaded by Pinocchio
//! give the same torques.

use rodyn::planar::{Planar, PlanarInertia, PlanarJoint, PlanarMotion, PlanarTransform, Vec2};
use rodyn::prelude::*;

/// Gravity of the planar chains: along -y, in the plane of motion (m/s²).
pub const CHAIN_GRAVITY: [f64; 3] = [0.0, -9.81, 0.0];

/// Where the first joint sits in the world frame (m).
const BASE_OFFSET: [f64; 2] = [0.05, 0.1];

/// Length, mass, centre of mass (x, y) and rotational inertia about the
/// centre of mass (`ixx`, `ixy`, `iyy`, `izz`) of link k.
struct Link {
    length: f64,
    mass: f64,
    com: [f64; 2],
    ixx: f64,
    ixy: f64,
    iyy: f64,
    izz: f64,
}

fn link(k: usize) -> Link {
    let k = k as f64;
    let length = 0.2 + 0.1 * (1.0 + (1.3 * k + 0.4).sin());
    let mass = 1.0 + 0.6 * (0.9 * k).cos();
    let com = [
        length * (0.45 + 0.1 * (2.1 * k).sin()),
        0.02 * (1.7 * k).cos(),
    ];
    let radius = 0.02 + 0.005 * (0.5 * k).sin();
    let ixx = 0.5 * mass * radius * radius;
    let iyy =
        mass * (length * length / 12.0 + radius * radius / 4.0) * (1.0 + 0.2 * (0.8 * k).sin());
    // A thin plate in the x-y plane: the perpendicular-axis theorem.
    let izz = ixx + iyy;
    let ixy = 0.3 * (ixx * iyy).sqrt() * (1.1 * k + 0.2).sin();
    Link {
        length,
        mass,
        com,
        ixx,
        ixy,
        iyy,
        izz,
    }
}

/// Offset of joint k in the frame of body k - 1 (the world for k = 0).
fn joint_offset(k: usize) -> [f64; 2] {
    if k == 0 {
        BASE_OFFSET
    } else {
        [link(k - 1).length, 0.0]
    }
}

/// The chain of `N` links on planar algebra.
#[must_use]
pub fn planar_chain<const N: usize>() -> Model<f64, N, N, N, Planar> {
    Model::new_planar(
        core::array::from_fn(|i| i.checked_sub(1)),
        [PlanarJoint::Revolute; N],
        core::array::from_fn(|k| {
            let [x, y] = joint_offset(k);
            PlanarTransform::from_translation(Vec2::new(x, y))
        }),
        core::array::from_fn(|k| {
            let l = link(k);
            PlanarInertia::new(l.mass, Vec2::new(l.com[0], l.com[1]), l.izz)
        }),
        PlanarMotion::new(0.0, Vec2::new(CHAIN_GRAVITY[0], CHAIN_GRAVITY[1])),
    )
}

/// The same chain as a 3-D model: revolute joints about z. Its CRBA plan
/// (`CrbaPlan::new`, as the benchmark cases build it) recognises the
/// placements' (trivial) quarter turns as a model compiler declares them.
#[must_use]
pub fn planar_chain_3d<const N: usize>() -> Model<f64, N, N, N> {
    Model::new(
        core::array::from_fn(|i| i.checked_sub(1)),
        [Joint::revolute(Axis::Z); N],
        core::array::from_fn(|k| {
            let [x, y] = joint_offset(k);
            Transform::from_translation(Vec3::new(x, y, 0.0))
        }),
        core::array::from_fn(|k| {
            let l = link(k);
            Inertia::new(
                l.mass,
                Vec3::new(l.com[0], l.com[1], 0.0),
                Sym3::new(l.ixx, l.ixy, 0.0, l.iyy, 0.0, l.izz),
            )
        }),
        Motion::new(Vec3::ZERO, Vec3::from_array(CHAIN_GRAVITY)),
    )
}
