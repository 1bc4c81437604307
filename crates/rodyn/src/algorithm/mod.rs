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

pub mod aba;
pub mod crba;
pub mod energy;
pub mod forward_dynamics;
pub mod kinematics;
pub mod ltdl;
pub mod rnea;
