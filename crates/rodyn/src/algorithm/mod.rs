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
//! | [`centroidal`]        | CoM Jacobian, centroidal momentum matrix, CCRBA | Orin 2013     |
//! | [`inverse_kinematics`] | damped least-squares steps to a frame pose     |               |

pub mod aba;
pub mod centroidal;
pub mod constrained_dynamics;
pub mod crba;
pub mod energy;
pub mod forward_dynamics;
pub mod frames;
pub mod inverse_kinematics;
pub mod jacobian;
pub mod kinematics;
pub mod ltdl;
pub mod rnea;
