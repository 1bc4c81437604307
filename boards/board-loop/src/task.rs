//! The 1 kHz control loop every board runs.
//!
//! Each tick waits on embassy-time's `Ticker`, whose deadline the board's
//! hardware timer raises as an interrupt: the core sleeps (`WFE`) between
//! ticks, there is no busy loop. Then the controller's tick is timed, the
//! plant stepped (also timed, apart), and once a second the log prints the
//! cycles per call. After [`RUN_TICKS`] the run's summary is logged and the
//! arm starts again from rest, so an unattended board logs forever.

use crate::cycles::{CycleCounter, CycleStats};
use embassy_time::{Duration, Ticker};
use rodyn::Scalar;
use rodyn_scenarios::panda_tracking::{ArmLoop, Panda, TICK_HZ};

/// Ticks in one run: 3 s, as `firmware/`'s `arm_control`.
pub const RUN_TICKS: u32 = 3 * TICK_HZ;

/// Runs the Panda's controller at [`TICK_HZ`] for ever on a core clocked at
/// `core_hz`, logging its cycles per call.
///
/// embassy-time rounds the period to whole ticks of the board's timer
/// (on the nRF52840's 32.768 kHz RTC, 33 ticks: 1.007 ms); the first log
/// line states the period in use.
pub async fn run<S: Scalar>(model: &Panda<S>, cycles: CycleCounter, core_hz: u32) -> ! {
    let period = Duration::from_hz(u64::from(TICK_HZ));
    let mut ticker = Ticker::every(period);
    let budget = core_hz / TICK_HZ;
    defmt::println!(
        "rodyn: Panda computed torque (RNEA) against its simulated plant (ABA); tick every {} us ({} timer ticks), core at {} Hz: {} cycles per tick",
        period.as_micros(),
        period.as_ticks(),
        core_hz,
        budget
    );
    let mut run = 0u32;
    loop {
        let mut arm = ArmLoop::new(model);
        let mut control = CycleStats::default();
        let mut plant = CycleStats::default();
        let mut second = CycleStats::default();
        let mut over_budget = 0u32;
        while arm.ticks() < RUN_TICKS {
            ticker.next().await;
            let (tau, control_cycles) = cycles.measure(|| arm.control());
            let tau = match tau {
                Ok(tau) => tau,
                Err(e) => {
                    defmt::error!("run {} tick {}: controller: {}", run, arm.ticks(), e);
                    break;
                }
            };
            let (stepped, plant_cycles) = cycles.measure(|| arm.advance(&tau));
            if let Err(e) = stepped {
                defmt::error!("run {} tick {}: plant: {}", run, arm.ticks(), e);
                break;
            }
            control.add(control_cycles);
            second.add(control_cycles);
            plant.add(plant_cycles);
            if control_cycles.saturating_add(plant_cycles) > budget {
                over_budget += 1;
            }
            if arm.ticks().is_multiple_of(TICK_HZ) {
                defmt::println!(
                    "t = {} ms: controller tick {} cycles (min {}, max {} over the last second)",
                    arm.ticks(),
                    second.mean(),
                    second.min,
                    second.max
                );
                second = CycleStats::default();
            }
        }
        defmt::println!(
            "run {}: controller tick (RNEA) {} - {} cycles, mean {}; plant step {} - {} cycles; ticks over the {}-cycle budget: {}; largest tracking error {} rad",
            run,
            control.min,
            control.max,
            control.mean(),
            plant.min,
            plant.max,
            budget,
            over_budget,
            arm.largest_error().to_f64()
        );
        run = run.wrapping_add(1);
    }
}
