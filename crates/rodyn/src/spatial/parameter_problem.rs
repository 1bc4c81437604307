//! What the algebra's validators find wrong with a body's parameters.
//!
//! [`Inertia::validate`](super::Inertia::validate),
//! [`Transform::validate`](super::Transform::validate) and their planar
//! counterparts answer in the algebra's own terms, so that the algebra
//! needs nothing above it; the model names the body
//! ([`ModelProblem`](crate::error::ModelProblem) has a variant for each).

/// Why an inertia or a placement is refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParameterProblem {
    /// A NaN or infinite entry.
    NonFinite,
    /// A negative mass.
    InvalidMass,
    /// A rotational inertia that is not symmetric positive semi-definite,
    /// or breaks the triangle inequality of its principal moments.
    InvalidInertia,
    /// Finite numbers whose products (such as `m |c|²`, `m²` or `|p|⁴`)
    /// overflow the scalar type.
    Overflow,
    /// A rotation that is not orthonormal.
    RotationNotOrthonormal,
    /// An orthonormal matrix that is a reflection (determinant −1).
    Reflection,
}
