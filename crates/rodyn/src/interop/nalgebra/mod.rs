//! rodyn's types as nalgebra's fixed-size types and back (feature
//! `nalgebra`, `no_std`).
//!
//! | rodyn                         | nalgebra                           | how                                   |
//! |-------------------------------|------------------------------------|---------------------------------------|
//! | [`Vec3`]                      | `Vector3`                          | `From`/`Into`, both ways              |
//! | [`Mat3`], [`Sym3`]            | `Matrix3`                          | `From`/`Into` (`Sym3` into only)      |
//! | a rotation [`Mat3`]           | `Rotation3`, `UnitQuaternion`      | `From`/`Into`, both ways              |
//! | [`Transform`]                 | `IsometryMatrix3`, `Isometry3`     | `From`/`Into`, both ways              |
//! | [`Motion`], [`Force`]         | `Vector6`, **linear part first**   | `From`/`Into`, both ways              |
//! | `q`, `v`, `τ`: `[S; N]`       | `SVector<S, N>`                    | nalgebra's own `From`/`Into`          |
//! | `[[S; C]; R]` (rows: `M`)     | `SMatrix<S, R, C>`                 | [`matrix_from_rows`], [`rows_from_matrix`] |
//! | Jacobian `[Motion<S>; NV]`    | `SMatrix<S, 6, NV>`, linear rows first | [`jacobian_matrix`]               |
//!
//! **Order of a spatial vector.** rodyn keeps a [`Motion`] and a [`Force`]
//! angular part first (`ang`, then `lin`: Featherstone's `[ω; v]`), but a
//! `Vector6` made from one holds the **linear part first**, `[v; ω]` and
//! `[f; n]`, as Pinocchio's `Motion::toVector()` and `Force::toVector()` and
//! its 6×NV Jacobians do, so a Jacobian's rows and a twist's entries line
//! up with Pinocchio's (and with [`Motion::to_linear_first`]).
//!
//! **Rows, not columns.** rodyn's matrices are arrays of rows
//! (`mass_matrix[r][c]`), nalgebra's `From<[[S; R]; C]>` reads an array of
//! *columns*: use [`matrix_from_rows`] for rodyn's arrays, which gives the
//! same matrix either way only for a symmetric one such as `M`.
//!
//! **Placements.** A [`Transform`] `aMb` and nalgebra's isometry agree: a
//! point maps as `p_a = rot p_b + trans`. Through `IsometryMatrix3` (a
//! `Rotation3`) the round trip is exact; through `Isometry3` (a unit
//! quaternion) the rotation is rounded once each way.
//!
//! The transform and quaternion conversions need nalgebra's `RealField`
//! (`f32`, `f64`); the others take any [`Scalar`](crate::Scalar).
//!
//! # A rodyn call from nalgebra values
//!
//! `q` and `v` arrive as nalgebra vectors; the frame Jacobian and the mass
//! matrix leave as nalgebra matrices.
//!
//! ```
//! use nalgebra::{SMatrix, SVector, Vector6};
//! use rodyn::algorithm::crba::crba;
//! use rodyn::algorithm::frames::{frame_velocity, ReferenceFrame};
//! use rodyn::algorithm::jacobian::{frame_jacobian, joint_jacobians, JacobianData};
//! use rodyn::algorithm::kinematics::forward_kinematics_velocity;
//! use rodyn::interop::nalgebra::{jacobian_matrix, matrix_from_rows};
//! use rodyn::prelude::*;
//! use rodyn::Frame;
//!
//! // A double pendulum about z, links 1 m, 1 kg at each link's tip.
//! const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
//! const PENDULUM: Model<f64, 2, 2, 2> = Model::new(
//!     [None, Some(0)],
//!     [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
//!     [Transform::IDENTITY, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))],
//!     [LINK, LINK],
//!     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
//! );
//! // The tip of the second link.
//! const TIP: Frame<f64> = Frame::new(1, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0)));
//!
//! /// The tip's Jacobian (world-aligned axes at the tip, rows `[v; ω]`)
//! /// and the mass matrix at `q`.
//! fn jacobian_and_mass(
//!     q: &SVector<f64, 2>,
//! ) -> Result<(SMatrix<f64, 6, 2>, SMatrix<f64, 2, 2>), rodyn::Error> {
//!     let q: [f64; 2] = (*q).into();
//!     let (mut data, mut jac) = (Data::new(), JacobianData::new());
//!     joint_jacobians(&PENDULUM, &mut data, &mut jac, &q)?;
//!     let mut columns = [Motion::ZERO; 2];
//!     frame_jacobian(&PENDULUM, &data, &jac, &TIP, ReferenceFrame::LocalWorldAligned, &mut columns)?;
//!     let mass = crba(&PENDULUM, &mut data, &q)?;
//!     Ok((jacobian_matrix(&columns), matrix_from_rows(mass)))
//! }
//!
//! let (q, v) = (SVector::<f64, 2>::new(0.4, -0.9), SVector::<f64, 2>::new(1.5, 0.5));
//! let (j, m) = jacobian_and_mass(&q)?;
//!
//! // M = [3 + 2 cos q₂, 1 + cos q₂; 1 + cos q₂, 1] for this pendulum.
//! let c2 = q[1].cos();
//! let expected = SMatrix::<f64, 2, 2>::new(3.0 + 2.0 * c2, 1.0 + c2, 1.0 + c2, 1.0);
//! assert!((m - expected).abs().max() < 1e-12);
//!
//! // J v is the tip's velocity as rodyn computes it, linear part first.
//! let mut data = Data::new();
//! forward_kinematics_velocity(&PENDULUM, &mut data, &q.into(), &v.into())?;
//! let twist: Vector6<f64> = frame_velocity(&data, &TIP, ReferenceFrame::LocalWorldAligned)?.into();
//! assert!((j * v - twist).abs().max() < 1e-12);
//! // The tip moves along (−(sin q₁ + sin(q₁+q₂)), cos q₁ + cos(q₁+q₂)) for q̇₁.
//! let (s1, s12) = (q[0].sin(), (q[0] + q[1]).sin());
//! assert!((j[(0, 0)] + s1 + s12).abs() < 1e-12 && j[(5, 0)] == 1.0);
//! # Ok::<(), rodyn::Error>(())
//! ```

mod jacobian;
mod matrix;
mod rotation;
mod spatial_vector;
mod transform;
mod vector;

pub use jacobian::jacobian_matrix;
pub use matrix::{matrix_from_rows, rows_from_matrix};

#[cfg(doc)]
use crate::spatial::{Force, Mat3, Motion, Sym3, Transform, Vec3};
