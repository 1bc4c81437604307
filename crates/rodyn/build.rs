//! Chooses the tuning profile, `cfg(rodyn_tuning = "in_order")` or
//! `cfg(rodyn_tuning = "out_of_order")`, that `src/tuning.rs` reads.
//!
//! A few kernels have two forms that compute the same values and differ
//! only in how fast they run on a given kind of core (see `src/tuning.rs`).
//! The profile names the kind of core rather than an instruction set:
//!
//! * the environment variable `RODYN_TUNING` (`in-order` or
//!   `out-of-order`), when set, decides (for a whole project, in the
//!   `[env]` table of its `.cargo/config.toml`);
//! * otherwise the target does: `in_order` for microcontroller-class
//!   targets, which are the bare-metal 32-bit Arm targets (`target_os =
//!   "none"`: Cortex-M and Cortex-R, every one of them an in-order core),
//!   every `thumbv*` target whatever its OS (Cortex-M under an RTOS such as
//!   NuttX) and the bare-metal 32-bit RISC-V targets (the RV32
//!   microcontroller cores are in-order); `out_of_order` for everything
//!   else, including 32-bit Arm Linux (Cortex-A9, A15, A17 and A72 run
//!   out of order; a board with an in-order Cortex-A7 or A53 sets
//!   `RODYN_TUNING=in-order`) and 64-bit RISC-V.
//!
//! The forms were chosen by measuring on x86-64 hosts and the Cortex-M4;
//! the other targets get the form of the nearest kind of core, unmeasured.

use std::env;

/// The variable that overrides the target's default.
const OVERRIDE: &str = "RODYN_TUNING";

fn main() {
    refuse_std_on_bare_metal();
    println!("cargo::rustc-check-cfg=cfg(rodyn_tuning, values(\"in_order\", \"out_of_order\"))");
    println!("cargo::rerun-if-env-changed={OVERRIDE}");
    let profile = match env::var(OVERRIDE).as_deref() {
        Ok("in-order") => "in_order",
        Ok("out-of-order") => "out_of_order",
        Ok("") | Err(env::VarError::NotPresent) => default_profile(),
        Ok(other) => {
            println!(
                "cargo::error=rodyn: {OVERRIDE}={other:?}; the tuning profiles are \
                 `in-order` and `out-of-order` (unset: the target's default)"
            );
            return;
        }
        Err(env::VarError::NotUnicode(_)) => {
            println!("cargo::error=rodyn: {OVERRIDE} is not Unicode");
            return;
        }
    };
    println!("cargo::rustc-cfg=rodyn_tuning=\"{profile}\"");
}

/// The profile of the target being compiled for (see the module docs).
fn default_profile() -> &'static str {
    let var = |name: &str| env::var(name).unwrap_or_default();
    let (arch, os, target) = (
        var("CARGO_CFG_TARGET_ARCH"),
        var("CARGO_CFG_TARGET_OS"),
        var("TARGET"),
    );
    let bare_metal = os == "none";
    let microcontroller = (bare_metal && (arch == "arm" || arch == "riscv32"))
        || (arch == "arm" && target.starts_with("thumbv"));
    if microcontroller {
        "in_order"
    } else {
        "out_of_order"
    }
}

/// Stops a build of the default `std` feature for a target without the
/// standard library (`target_os = "none"`: every microcontroller) with one
/// message that says what to write, instead of rustc's "can't find crate
/// for `std`" in every crate above.
fn refuse_std_on_bare_metal() {
    let std_on = env::var_os("CARGO_FEATURE_STD").is_some();
    let bare_metal = env::var("CARGO_CFG_TARGET_OS").is_ok_and(|os| os == "none");
    if std_on && bare_metal {
        let target = env::var("TARGET").unwrap_or_default();
        println!(
            "cargo::error=rodyn: the `std` feature (on by default) needs the standard library, \
             which {target} does not have. Depend on rodyn without it: \
             rodyn = {{ version = \"0.1\", default-features = false, features = [\"libm\"] }}"
        );
    }
}
