//! Shared helpers for rodyn's host tests: random states and sample models.
pub mod contact_fixture;
#[cfg(doctest)]
pub mod doc_snippets;
pub mod fixture;
pub mod frame_chain_fixture;
pub mod random;
pub mod subject_gait;

// The measured walker's model (`models/gait_subject01.toml`), compiled by
// build.rs as a firmware's build script would.
include!(concat!(env!("OUT_DIR"), "/gait_subject01.rs"));
