//! Shared helpers for rodyn's host tests: random states and sample models.
pub mod fixture;
pub mod random;
