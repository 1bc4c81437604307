//! rodyn's types with other crates' types, each crate behind its feature.
//!
//! * `nalgebra`, module `interop::nalgebra`: `From`/`Into` between
//!   rodyn's vectors, matrices, placements and spatial vectors and
//!   nalgebra's fixed-size types, and the joint-space arrays (`q`, `v`, the
//!   mass matrix, Jacobians) as `SVector` and `SMatrix`. Turns on `approx`.
//! * `approx`: approx's `AbsDiffEq`, `RelativeEq` and `UlpsEq` for `Vec3`,
//!   `Mat3`, `Sym3`, `Motion`, `Force`, `Transform` and `Inertia`, entry by
//!   entry with the scalar's own comparison, so `assert_relative_eq!` takes
//!   rodyn's values as they are.
//!
//! Both are `no_std`: on a microcontroller they take their float functions
//! from the `libm` feature, like the rest of rodyn.

#[cfg(feature = "approx")]
mod approx;
#[cfg(feature = "nalgebra")]
pub mod nalgebra;
