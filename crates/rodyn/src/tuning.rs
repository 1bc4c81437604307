//! The tuning profile: where a kernel has two forms that compute the same
//! values (to rounding) and differ only in speed on a kind of core, the
//! form this build takes.
//!
//! The profile is `cfg(rodyn_tuning = "in_order")` or
//! `cfg(rodyn_tuning = "out_of_order")`, set by the build script
//! (`build.rs`): `RODYN_TUNING=in-order` or `RODYN_TUNING=out-of-order`
//! in the environment when set, otherwise from the target, in order for
//! microcontroller-class targets (bare-metal 32-bit Arm and RISC-V, and
//! every `thumbv*` target) and out of order for the rest.
//!
//! * An **in-order** core (Cortex-M, Cortex-R, RV32 microcontrollers) runs
//!   one instruction after another: every instruction costs, and a load
//!   that follows a store costs nothing more. It wants the fewest
//!   instructions and registers.
//! * An **out-of-order** core (x86-64, Apple cores, Cortex-A9 and A72) overlaps
//!   independent work and hides instructions among it, but waits on a
//!   load that spans two recent stores, on stores to scattered rows and on
//!   long dependent chains. It takes extra instructions that shorten what
//!   it waits on.
//!
//! Each choice was measured on x86-64 hosts and the Cortex-M4 (the
//! performance notebook, `docs/sections/performance_notebook.md`, has the
//! figures under the algorithm's heading); the constants below name them.
//! The choices that are inlining attributes read the profile where they
//! stand, as `#[cfg_attr(rodyn_tuning = "...", inline(...))]`:
//!
//! * `RevoluteJoint::placed_transform`, its `_from_sin_cos` form and
//!   `Joint::placed_transform`: `inline(always)` out of order, plain
//!   `inline` in order (forced into every pass, the in-order build grows
//!   and spills).
//! * `ArticulatedInertia::add_act_plane` (ABA): out of line in order (the
//!   kernel's intermediates fill the register file on their own), inlined
//!   out of order (scheduled with its caller, it spills less on x86-64's
//!   16 registers).
//! * RNEA's `forward_pass`, `backward_force_pass` and
//!   `backward_force_pass_with`: inlined into each caller in order (so
//!   that `a: None` folds away), out of line and shared by RNEA and the
//!   nonlinear effects out of order.
//! * `SpatialVariation::of_body` (the derivatives' world pass):
//!   `inline(always)` out of order, where the call made the pass spill its
//!   vector registers around it; left to the compiler in order.
//! * `Planar::turned_joint_step` (planar CRBA given the joint angles'
//!   sines and cosines): only out of order, where [`ANGLES_FIRST`] forms
//!   them; in order its extra call site of `compose` changed other
//!   inlining and cost instructions.
//!
//! Both profiles pass the same tests: `cargo xtask test` runs the core's
//! and the host tests' suites a second time with `RODYN_TUNING=in-order`.

#[cfg(not(any(rodyn_tuning = "in_order", rodyn_tuning = "out_of_order")))]
compile_error!("rodyn: no tuning profile; the build script sets `cfg(rodyn_tuning)`");

/// Whether this build is tuned for an out-of-order core.
const OUT_OF_ORDER: bool = cfg!(rodyn_tuning = "out_of_order");

/// Whether the passes over the bodies form the sines and cosines of all
/// the joint angles before the bodies' work (`JointSinCos`): each pair is a
/// long chain of dependent operations, which one body's work beside it
/// does not cover; formed in a pass of their own, two at a time, they
/// overlap. An in-order core would only pay for storing them.
pub(crate) const ANGLES_FIRST: bool = OUT_OF_ORDER;

/// Whether RNEA's backward pass carries the force handed to the body just
/// before (a chain's parent) in a local: a sum stored piecewise and read
/// back whole at once waits on store-to-load forwarding. An in-order core
/// has no such stall; there the local only costs instructions.
pub(crate) const CARRY: bool = OUT_OF_ORDER;

/// Whether ABA forms a one-coordinate joint's column `U = Iᴬ S` in a local
/// before storing it: the column is read at once, and a copy read back
/// from `Data` (stored piecewise, read whole) waits on store-to-load
/// forwarding. On an in-order core the local costs instructions.
pub(crate) const COLUMN_IN_LOCAL: bool = OUT_OF_ORDER;

/// Whether CRBA's local backward pass writes `M`'s zeros (those between
/// unrelated limbs) and, for `crba`, its entries above the diagonal as it
/// meets each entry, instead of separate clear and mirror loops afterwards.
/// On an out-of-order core the separate loops are stores to scattered rows
/// that it waits on, where stores in the pass hide among its arithmetic;
/// an in-order core pays for every extra instruction and keeps the
/// separate loops.
pub(crate) const ENTRIES_IN_PASS: bool = OUT_OF_ORDER;

/// Whether the copy of `M`'s lower triangle onto the upper goes two rows by
/// two columns at a time, so that each row above takes its entries in
/// adjacent pairs (an out-of-order core overlaps the pairs' stores); an
/// in-order core copies one entry at a time, which takes fewer
/// instructions.
pub(crate) const MIRROR_IN_BLOCKS: bool = OUT_OF_ORDER;

/// Whether CRBA forward dynamics runs the bias forces' passes and CRBA's
/// together, one loop over the bodies forwards and one backwards, instead
/// of RNEA and then CRBA: each joint transform is used at once by both,
/// and an out-of-order core overlaps their independent work on each body.
/// An in-order core keeps the two algorithms apart: fused, the passes take
/// more instructions on short chains and more stack.
pub(crate) const FUSED_PASSES: bool = OUT_OF_ORDER;

/// Whether the `L D Lᵀ` factorisation and its solves take the order that
/// an out-of-order core waits on least: the value that each step of a
/// recurrence has just formed enters that step's sums last, and in the
/// solve by `L` the next coordinate is updated on its own, so that every
/// pass reads the rest with the alignment the previous pass stored it in.
/// An in-order core keeps the plain order (the others only cost it
/// instructions).
pub(crate) const HOST_ORDER: bool = OUT_OF_ORDER;

/// Whether a free flyer behind a placement without rotation (the usual
/// floating base) takes its own transform, shifted, instead of composing
/// it with the identity: on an out-of-order core the skipped 3x3 product
/// is the gain. On an in-order core the test and the second form cost
/// instructions and stack wherever joint transforms are formed, more than
/// the product they skip.
pub(crate) const FREE_FLYER_SHORTCUT: bool = OUT_OF_ORDER;

/// Whether `Model::check_configuration`, once the configuration's sum has
/// shown every entry finite, asks the joints with a further condition only
/// that condition (`JointModel::check_finite_configuration`: a free
/// flyer's quaternion norm, without testing its seven entries again). On
/// the Cortex-M4 the second function cost the quadruped's joint Jacobians,
/// CCRBA and contact images more instructions than it saved its dynamics.
pub(crate) const FINITE_JOINT_CHECKS: bool = OUT_OF_ORDER;

/// Whether the centroidal map's poses form every joint transform first and
/// then compose the chain with the products that skip the zeros of a
/// quarter-turn placement (`Geometry::then_turned_joint`), and the joint
/// Jacobians take their poses from that pass, as does a frame chain whose
/// support path holds every body (`frame_chain`, a serial robot's frame):
/// out of order, the chain's products then have the vector registers to
/// themselves. An in-order
/// core would pay for storing the transforms and reading them back, and
/// for the tests of the placement's form; it keeps one loop and
/// `then_joint`, and the Jacobians' own pose step.
pub(crate) const TURNED_POSES: bool = OUT_OF_ORDER;

#[cfg(test)]
mod tests {
    /// The profile the build script chose, as its `cfg` value.
    const PROFILE: &str = if super::OUT_OF_ORDER {
        "out_of_order"
    } else {
        "in_order"
    };

    #[test]
    fn one_profile_is_chosen() {
        assert_eq!(
            cfg!(rodyn_tuning = "in_order"),
            !cfg!(rodyn_tuning = "out_of_order")
        );
        // The override, when the build had one, is the profile.
        match option_env!("RODYN_TUNING") {
            Some("in-order") => assert_eq!(PROFILE, "in_order"),
            Some("out-of-order") => assert_eq!(PROFILE, "out_of_order"),
            _ => {}
        }
        // Which one the suite ran under, in the test log.
        println!("rodyn tuning profile: {PROFILE}");
    }
}
