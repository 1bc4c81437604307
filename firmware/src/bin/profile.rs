//! One call of every algorithm on every model, each between two marker
//! calls, for `cargo xtask profile`: QEMU logs every instruction executed
//! and the xtask attributes them to the source lines they came from.
//!
//! The order of the calls is the order of the `profile` lines in the log;
//! the xtask pairs the n-th marked stretch of the trace with the n-th line.
#![no_std]
#![no_main]

use core::hint::black_box;
use core::sync::atomic::{AtomicU32, Ordering};
use cortex_m_rt::entry;
use rodyn::algorithm::crba::{crba_planned, CrbaPlan};
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::algorithm::rnea::rnea;
use rodyn::space::Space;
use rodyn::{Data, Model};
use rodyn_firmware::exit::{exit, SUCCESS};
use rodyn_firmware::models::aibo::{CRBA_PLAN_F32 as QUADRUPED_PLAN, MODEL_F32 as QUADRUPED};
use rodyn_firmware::models::panda::{CRBA_PLAN_F32 as PANDA_PLAN, MODEL_F32 as PANDA};
use rodyn_firmware::models::pendulum::{CRBA_PLAN_F32 as PENDULUM_PLAN, MODEL_F32 as PENDULUM};
use rodyn_firmware::models::{PENDULUM_PLANAR, PENDULUM_PLANAR_CRBA_PLAN};
use rodyn_firmware::rng::XorShift32;

/// Written by the markers, so that neither is empty and the two cannot be
/// merged into one function.
static MARKS: AtomicU32 = AtomicU32::new(0);

/// Start of a profiled stretch (the xtask finds it by its symbol name).
/// The empty `asm!` may read and write any memory the compiler cannot prove
/// private, so no work on the (escaped) data moves across a marker.
#[inline(never)]
#[no_mangle]
extern "C" fn rodyn_profile_begin() {
    MARKS.fetch_add(1, Ordering::Relaxed);
    // SAFETY: an empty instruction sequence.
    unsafe { core::arch::asm!("", options(nostack, preserves_flags)) };
}

/// End of a profiled stretch.
#[inline(never)]
#[no_mangle]
extern "C" fn rodyn_profile_end() {
    MARKS.fetch_add(0x1_0000, Ordering::Relaxed);
    // SAFETY: an empty instruction sequence.
    unsafe { core::arch::asm!("", options(nostack, preserves_flags)) };
}

/// Every algorithm once on `model`, at the cost probe's first random state.
fn profile<const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    name: &str,
    model: &Model<f32, NB, NQ, NV, G>,
    plan: &CrbaPlan<f32, NB, G>,
) {
    let mut rng = XorShift32::new(0x5EED_0001);
    let mut q = [0.0f32; NQ];
    rng.fill_symmetric(&mut q, core::f32::consts::PI);
    if let Err(e) = model.normalize(&mut q) {
        defmt::error!("{=str}: normalize: {}", name, e);
        return;
    }
    let mut v = [0.0f32; NV];
    rng.fill_symmetric(&mut v, 2.0);
    let mut u = [0.0f32; NV];
    rng.fill_symmetric(&mut u, 5.0);
    // The inputs are opaque and the workspace escapes, so that the compiler
    // can neither fold a call nor drop it as dead, nor move it past a marker.
    let (q, v, u) = (black_box(q), black_box(v), black_box(u));
    // Nor specialise the calls for this one constant model.
    let model = black_box(model);
    let mut data = Data::<f32, NB, NV, G>::new();
    black_box(&mut data);
    // Written out, so that nothing but the call sits between the markers.
    defmt::println!("profile model={=str} algorithm=RNEA", name);
    rodyn_profile_begin();
    let ok = rnea(model, &mut data, &q, &v, &u, None).is_ok();
    rodyn_profile_end();
    black_box(&data);
    report(ok);
    defmt::println!("profile model={=str} algorithm=CRBA", name);
    rodyn_profile_begin();
    let ok = crba_planned(model, plan, &mut data, &q).is_ok();
    rodyn_profile_end();
    black_box(&data);
    report(ok);
    defmt::println!("profile model={=str} algorithm=CRBA+LTDL-FD", name);
    rodyn_profile_begin();
    let ok = Crba::forward_dynamics_planned(model, plan, &mut data, &q, &v, &u, None).is_ok();
    rodyn_profile_end();
    black_box(&data);
    report(ok);
    defmt::println!("profile model={=str} algorithm=ABA", name);
    rodyn_profile_begin();
    let ok = Aba::forward_dynamics(model, &mut data, &q, &v, &u, None).is_ok();
    rodyn_profile_end();
    black_box(&data);
    report(ok);
}

/// A call that returned an error stopped early: its profile is not a full
/// call's, and the xtask says so.
fn report(ok: bool) {
    if !ok {
        defmt::println!("refused");
    }
}

#[entry]
fn main() -> ! {
    profile("pendulum", &PENDULUM, &PENDULUM_PLAN);
    profile(
        "pendulum-planar",
        &PENDULUM_PLANAR,
        &PENDULUM_PLANAR_CRBA_PLAN,
    );
    profile("panda-7dof", &PANDA, &PANDA_PLAN);
    profile("quadruped-floating", &QUADRUPED, &QUADRUPED_PLAN);
    exit(SUCCESS)
}
