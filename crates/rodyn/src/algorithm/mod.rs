//! The algorithms, one per file, each of the form `algorithm(model, data, inputs…)`.
//!
//! | file                  | computes                                        | book          |
//! |-----------------------|-------------------------------------------------|---------------|
//! | [`kinematics`]        | poses, velocities, accelerations of bodies      | §3.4          |
//! | [`rnea`]              | inverse dynamics, bias forces, gravity torques  | Table 5.1     |
//! | [`crba`]              | the mass matrix                                 | Table 6.2     |
//! | [`ltdl`]              | its sparse `Lᵀ D L` factorisation and solve     | Table 6.3     |
//! | [`aba`]               | forward dynamics in O(n)                        | Table 7.1     |
//! | [`forward_dynamics`]  | ABA or CRBA behind one interface                |               |
//! | [`energy`]            | kinetic, potential energy, centre of mass       |               |
//! | [`frames`]            | frame placements, velocities, accelerations     | §2.11         |
//! | [`jacobian`]          | joint and frame Jacobians, their derivatives    | §4.4          |
//! | [`frame_chain`]       | one frame's (or a few frames') Jacobian and `J̇ v` from q, along its path | §4.4 |
//! | [`centroidal`]        | CoM Jacobian, centroidal momentum matrix, CCRBA | Orin 2013     |
//! | [`inverse_kinematics`] | damped least-squares steps to a frame pose     |               |
//! | [`dense`]             | small dense Cholesky factor and solve           |               |
//! | [`derivatives`]       | `∂τ/∂(q, v)`, `∂q̈/∂(q, v, τ)`                 | Carpentier 2018 |
//! | [`constrained_dynamics`] | forward dynamics and impacts with rigid point and frame contacts | ch. 8 |
//! | [`contact_inverse_dynamics`] | torques and contact forces for a wanted motion of a floating base | Mistry 2010 |
//!
//! The mass matrix of a two-link arm against its closed form (links 1 m,
//! 1 kg point masses at the tips):
//!
//! ```
//! use rodyn::algorithm::crba::crba;
//! use rodyn::prelude::*;
//!
//! const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
//! const ARM: Model<f64, 2, 2, 2> = Model::new(
//!     [None, Some(0)], [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
//!     [Transform::IDENTITY, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))],
//!     [LINK, LINK], Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
//! );
//! let mut data = Data::new();
//! let q2 = 0.5;
//! // CRBA fills the lower triangle (diagonal included) of the symmetric M(q).
//! let m = crba(&ARM, &mut data, &[0.1, q2])?;
//! assert!((m[0][0] - (3.0 + 2.0 * f64::cos(q2))).abs() < 1e-12);
//! assert!((m[1][0] - (1.0 + f64::cos(q2))).abs() < 1e-12);
//! assert!((m[1][1] - 1.0).abs() < 1e-12);
//! # Ok::<(), rodyn::Error>(())
//! ```

pub mod aba;
pub mod centroidal;
pub(crate) mod common;
pub mod constrained_dynamics;
pub mod contact_inverse_dynamics;
pub mod crba;
pub mod dense;
pub mod derivatives;
pub mod energy;
pub mod forward_dynamics;
pub mod frame_chain;
pub mod frames;
pub mod inverse_kinematics;
pub mod jacobian;
pub mod kinematics;
pub mod ltdl;
pub mod rnea;
