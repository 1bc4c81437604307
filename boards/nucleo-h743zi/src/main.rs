//! rodyn on the Nucleo-H743ZI (ST STM32H743ZI: Cortex-M7 with a
//! double-precision FPU, here at 400 MHz, f64).
//!
//! The Panda's 1 kHz computed-torque loop of `rodyn-board-loop` in f64, on
//! the FPv5's double-precision unit (`target-cpu=cortex-m7` in
//! `.cargo/config.toml`), timed by the DWT cycle counter. What is the
//! board's: the PLL that takes the 64 MHz HSI to 400 MHz (voltage scale 1,
//! the rating every silicon revision has), the L1 caches, a general-purpose
//! timer behind embassy-time (`time-driver-any`), and the log over RTT
//! through the on-board ST-LINK.
#![no_std]
#![no_main]

use cortex_m::peripheral::DWT;
use defmt_rtt as _;
use embassy_executor::Spawner;
use embassy_stm32::rcc::{
    AHBPrescaler, APBPrescaler, Pll, PllDiv, PllMul, PllPreDiv, PllSource, Sysclk, VoltageScale,
};
use embassy_stm32::Config;
use panic_probe as _;
use rodyn_board_loop::cycles::CycleCounter;
use rodyn_scenarios::panda;

/// The core clock [`clocks`] sets: 64 MHz / 4 × 50 / 2.
const CORE_HZ: u32 = 400_000_000;

#[embassy_executor::task]
async fn control(cycles: CycleCounter) -> ! {
    rodyn_board_loop::task::run(&panda::MODEL_F64, cycles, CORE_HZ).await
}

/// PLL1 from the HSI to 400 MHz at the core; the AHB and every APB at
/// 200 MHz and below, their limits at voltage scale 1 (RM0433, "RCC").
fn clocks() -> Config {
    let mut config = Config::default();
    let rcc = &mut config.rcc;
    rcc.pll1 = Some(Pll {
        source: PllSource::HSI,
        prediv: PllPreDiv::DIV4,
        mul: PllMul::MUL50,
        fracn: None,
        divp: Some(PllDiv::DIV2),
        divq: None,
        divr: None,
    });
    rcc.sys = Sysclk::PLL1_P;
    rcc.ahb_pre = AHBPrescaler::DIV2;
    rcc.apb1_pre = APBPrescaler::DIV2;
    rcc.apb2_pre = APBPrescaler::DIV2;
    rcc.apb3_pre = APBPrescaler::DIV2;
    rcc.apb4_pre = APBPrescaler::DIV2;
    rcc.voltage_scale = VoltageScale::Scale1;
    config
}

#[embassy_executor::main]
async fn main(spawner: Spawner) {
    let _peripherals = embassy_stm32::init(clocks());
    let Some(mut core) = cortex_m::Peripherals::take() else {
        defmt::error!("the core peripherals were taken before main");
        return;
    };
    // The tick's code runs from flash (wait states at 400 MHz) and reads
    // its model from there: the caches hide both after the first tick.
    core.SCB.enable_icache();
    core.SCB.enable_dcache(&mut core.CPUID);
    // The Cortex-M7's DWT ignores writes until its lock is opened.
    DWT::unlock();
    let cycles = CycleCounter::start(&mut core.DCB, core.DWT);
    match control(cycles) {
        Ok(task) => spawner.spawn(task),
        Err(e) => defmt::error!("cannot spawn the control task: {}", e),
    }
}
