//! The shipped models, compiled by `rodyn-model` from `build.rs`.
//!
//! This crate exists for its tests: it proves that the generated modules
//! compile, validate, and reproduce Pinocchio's dynamics.
#![no_std]

include!(concat!(env!("OUT_DIR"), "/models.rs"));
