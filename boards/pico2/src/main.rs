//! rodyn on the Raspberry Pi Pico 2 (RP2350: Cortex-M33 at 150 MHz, f32).
//!
//! The Panda's 1 kHz computed-torque loop of `rodyn-board-loop`, timed by
//! the DWT cycle counter, on core 0. What is the board's: embassy-rp's
//! clocks (the 12 MHz crystal, the system clock at 150 MHz), TIMER0 behind
//! embassy-time (its 1 MHz tick, `time-driver`), the boot ROM's image
//! definition (embassy-rp places it, `memory.x` puts it first in flash),
//! and the log over RTT through a debug probe on the SWD header (the Pico 2
//! has none on board: a Raspberry Pi Debug Probe or a second Pico running
//! debugprobe).
#![no_std]
#![no_main]

use defmt_rtt as _;
use embassy_executor::Spawner;
use panic_probe as _;
use rodyn_board_loop::cycles::CycleCounter;
use rodyn_scenarios::panda;

#[embassy_executor::task]
async fn control(cycles: CycleCounter, core_hz: u32) -> ! {
    rodyn_board_loop::task::run(&panda::MODEL_F32, cycles, core_hz).await
}

#[embassy_executor::main]
async fn main(spawner: Spawner) {
    let _peripherals = embassy_rp::init(embassy_rp::config::Config::default());
    let Some(mut core) = cortex_m::Peripherals::take() else {
        defmt::error!("the core peripherals were taken before main");
        return;
    };
    let cycles = CycleCounter::start(&mut core.DCB, core.DWT);
    match control(cycles, embassy_rp::clocks::clk_sys_freq()) {
        Ok(task) => spawner.spawn(task),
        Err(e) => defmt::error!("cannot spawn the control task: {}", e),
    }
}
