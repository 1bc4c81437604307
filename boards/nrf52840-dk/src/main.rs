//! rodyn on the nRF52840-DK (Nordic nRF52840: Cortex-M4F at 64 MHz, f32).
//!
//! The Panda's 1 kHz computed-torque loop of `rodyn-board-loop`, timed by
//! the DWT cycle counter. What is the board's: the 32 MHz and 32.768 kHz
//! crystals of the DK as clock sources, the flash's instruction cache, the
//! RTC1 behind embassy-time (through the `time-driver-rtc1` feature), and
//! the log over RTT through the on-board J-Link (`cargo run --release`
//! flashes with probe-rs and prints the log).
#![no_std]
#![no_main]

use defmt_rtt as _;
use embassy_executor::Spawner;
use embassy_nrf::config::{Config, HfclkSource, LfclkSource};
use panic_probe as _;
use rodyn_board_loop::cycles::CycleCounter;
use rodyn_scenarios::panda;

/// The nRF52840's core clock, fixed by the chip.
const CORE_HZ: u32 = 64_000_000;

#[embassy_executor::task]
async fn control(cycles: CycleCounter) -> ! {
    rodyn_board_loop::task::run(&panda::MODEL_F32, cycles, CORE_HZ).await
}

#[embassy_executor::main]
async fn main(spawner: Spawner) {
    let mut config = Config::default();
    // The crystals: the core clock and the RTC's ticks to their ppm.
    config.hfclk_source = HfclkSource::ExternalXtal;
    config.lfclk_source = LfclkSource::ExternalXtal;
    let _peripherals = embassy_nrf::init(config);
    // The flash's instruction cache is off after reset; the tick's code
    // runs from flash.
    embassy_nrf::pac::NVMC
        .icachecnf()
        .write(|w| w.set_cacheen(true));

    let Some(mut core) = cortex_m::Peripherals::take() else {
        defmt::error!("the core peripherals were taken before main");
        return;
    };
    let cycles = CycleCounter::start(&mut core.DCB, core.DWT);
    match control(cycles) {
        Ok(task) => spawner.spawn(task),
        Err(e) => defmt::error!("cannot spawn the control task: {}", e),
    }
}
