//! # rodyn
//!
//! Rigid-body dynamics for robots and human-motion models that runs in
//! microcontroller firmware as well as on a desktop: `no_std`, no allocator,
//! no recursion, no panics on a valid model.
//!
//! * The **topology** of a model (which body hangs on which, by which joint)
//!   is fixed at compile time through const parameters; a `const` model with
//!   an inconsistent tree does not compile.
//! * The **parameters** (masses, inertias, placements, gravity) are ordinary
//!   values that can be changed at run time.
//! * Every algorithm is generic over the **scalar** ([`Scalar`]: `f32` on a
//!   Cortex-M4F, `f64` or the forward-mode [`Dual`] on a host) and over the
//!   **geometry** ([`Spatial`](spatial::Spatial) 3-D or
//!   [`Planar`](planar::Planar)).
//! * A [`Model`] is read-only during an algorithm; a [`Data`] holds every
//!   intermediate, preallocated, and can live in a `static`.
//!
//! ```
//! use rodyn::prelude::*;
//! use rodyn::algorithm::{rnea::rnea, forward_dynamics::{Aba, ForwardDynamics}};
//!
//! // A double pendulum swinging about z in the x-y plane, links 1 m, 1 kg at the tips.
//! const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
//! const MODEL: Model<f64, 2, 2, 2> = Model::new(
//!     [None, Some(0)],
//!     [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
//!     [Transform::IDENTITY, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))],
//!     [LINK, LINK],
//!     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
//! );
//! let mut data = Data::new();
//! let (q, v, a) = ([0.1, -0.2], [0.5, 0.3], [1.0, -1.0]);
//! let tau = *rnea(&MODEL, &mut data, &q, &v, &a, None)?;
//! let ddq = Aba::forward_dynamics(&MODEL, &mut data, &q, &v, &tau, None)?;
//! assert!((ddq[0] - a[0]).abs() < 1e-12 && (ddq[1] - a[1]).abs() < 1e-12);
//! # Ok::<(), rodyn::Error>(())
//! ```
//!
//! ## Features
//! * `std` (default): float functions from the standard library.
//! * `libm`: float functions from `libm`, for `no_std` targets.
//! * `defmt`: `defmt::Format` for errors, for firmware logging.
//! * `nalgebra`: `From`/`Into` between rodyn's vectors, matrices,
//!   placements and spatial vectors and nalgebra's fixed-size types
//!   ([`interop::nalgebra`](crate::interop)); turns on `approx`.
//! * `approx`: approx's `AbsDiffEq`, `RelativeEq` and `UlpsEq` for rodyn's
//!   value types ([`interop`]).
//!
//! ## Tuning profile
//! A few kernels have two forms that give the same results (to rounding)
//! and differ in speed by kind of core. The build takes the in-order forms
//! on bare-metal 32-bit Arm (Cortex-M, Cortex-R), every `thumbv*` target
//! and bare-metal 32-bit RISC-V, the out-of-order forms elsewhere; set
//! `RODYN_TUNING=in-order` or `RODYN_TUNING=out-of-order` in the build's
//! environment (for a project: the `[env]` table of `.cargo/config.toml`)
//! to choose, for example `in-order` for a Cortex-A7 or A53 under Linux.
#![cfg_attr(not(feature = "std"), no_std)]
#![forbid(unsafe_op_in_unsafe_fn)]
#![warn(missing_docs)]
// Index loops over bodies and coordinates mirror the book's equations
// (`for i in 0..NB`, `M[r][c]`); iterator chains would hide them.
#![allow(clippy::needless_range_loop)]

pub mod algorithm;
pub mod data;
pub mod drive;
pub mod endpoint;
pub mod error;
pub mod frame;
pub mod interop;
pub mod joint;
pub mod model;
pub mod planar;
pub mod scalar;
pub mod sensitivity;
pub mod sim;
pub mod space;
pub mod spatial;
pub mod topology;
mod tuning;
pub mod update;

/// How many points a test's sweep visits: `full`, or `miri` under Miri
/// (`cargo xtask lint`), which interprets every operation and checks it
/// for undefined behaviour, so that the whole suite stays a few minutes
/// there.
#[cfg(test)]
pub(crate) const fn test_points(full: usize, miri: usize) -> usize {
    if cfg!(miri) {
        miri
    } else {
        full
    }
}

pub use data::Data;
pub use endpoint::Endpoint;
pub use error::{Error, Result};
pub use frame::Frame;
pub use model::Model;
pub use scalar::{Dual, Scalar};

/// The types most programs need.
pub mod prelude {
    pub use crate::joint::{Axis, Joint, JointModel};
    pub use crate::space::{
        ArticulatedInertia, BodyInertia, ForceVector, MotionVector, RigidTransform, Space,
        VectorOps,
    };
    pub use crate::spatial::{Force, Inertia, Mat3, Motion, Spatial, Sym3, Transform, Vec3};
    pub use crate::{Data, Dual, Error, Model, Scalar};
}
