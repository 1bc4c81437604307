//! The board-independent part of rodyn's board examples.
//!
//! Every board image runs the same 1 kHz control task: the Franka Panda's
//! computed-torque controller (RNEA each tick) tracking a smooth joint
//! trajectory, against a simulated Panda stepped by ABA between ticks
//! (`rodyn_scenarios::panda_tracking`, tested on the host there). The
//! DWT cycle counter times each controller tick and each plant step, and
//! the log prints cycles per call. A board's own file keeps only what is
//! the board's: its clocks, the timer behind embassy-time's `Ticker`, the
//! scalar its FPU computes in, and its logging transport.
//!
//! | module     | what it holds                                                     |
//! |------------|-------------------------------------------------------------------|
//! | [`cycles`] | the DWT cycle counter and the per-second and per-run statistics  |
//! | [`task`]   | the control loop: wait for the timer's tick, control, step the plant, log |
#![no_std]
#![warn(missing_docs)]

pub mod cycles;
pub mod task;
