//! The Rust blocks of `README.md` and `docs/sections/*.md`, compiled and
//! run as doctests (`cargo test -p rodyn-host-tests --doc`): what a reader
//! copies from the docs builds against today's API. Blocks that are not
//! Rust say so (```sh, ```toml, ```text); a block that cannot run alone
//! (a build script) is marked `no_run` and still compiled. The models the
//! snippets include are compiled by this crate's `build.rs`.

#[doc = include_str!("../../README.md")]
pub struct Readme;

#[doc = include_str!("../../docs/sections/accuracy.md")]
pub struct Accuracy;

#[doc = include_str!("../../docs/sections/contacts.md")]
pub struct Contacts;

#[doc = include_str!("../../docs/sections/derivatives.md")]
pub struct Derivatives;

#[doc = include_str!("../../docs/sections/drives.md")]
pub struct Drives;

#[doc = include_str!("../../docs/sections/firmware.md")]
pub struct Firmware;

#[doc = include_str!("../../docs/sections/gait.md")]
pub struct Gait;

#[doc = include_str!("../../docs/sections/joints.md")]
pub struct Joints;

#[doc = include_str!("../../docs/sections/kinematics.md")]
pub struct Kinematics;

#[doc = include_str!("../../docs/sections/model_sweep.md")]
pub struct ModelSweep;

#[doc = include_str!("../../docs/sections/models.md")]
pub struct Models;

#[doc = include_str!("../../docs/sections/model_updates.md")]
pub struct ModelUpdates;

#[doc = include_str!("../../docs/sections/optimal_control.md")]
pub struct OptimalControl;

#[doc = include_str!("../../docs/sections/performance.md")]
pub struct Performance;

#[doc = include_str!("../../docs/sections/performance_notebook.md")]
pub struct PerformanceNotebook;

#[doc = include_str!("../../docs/sections/simulation.md")]
pub struct Simulation;

#[doc = include_str!("../../models/README.md")]
pub struct ModelFiles;
