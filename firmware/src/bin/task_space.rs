//! Task-space control of a 7-DoF arm: the flange tracks a pose trajectory.
//!
//! A task-space impedance controller (`control::TaskSpaceImpedance`: the
//! flange's Jacobian transpose, gravity and feedforward by RNEA, a posture
//! term in the null space) ticks at 1 kHz and drives the Panda's flange
//! round a 5 cm circle in a vertical plane while its axes turn back and
//! forth by up to 0.3 rad. It reads the same 18-bit SPI encoders and
//! commands the same PWM torque drives as `arm_control`, only through
//! embedded-hal traits; behind them stands the arm simulated by ABA, four
//! steps per tick. After 3 s it reports the flange's tracking error, from
//! the simulated arm's true angles, and fails (exit code 1) when the
//! position error exceeds [`MAX_POSITION_ERROR`] or the orientation error
//! [`MAX_ORIENTATION_ERROR`].
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn::algorithm::frames::frame_placement;
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::spatial::log3;
use rodyn::spatial::{Transform, Vec3};
use rodyn::{Data, Scalar};
use rodyn_firmware::control::{CirclePoseTrajectory, TaskGains, TaskSpaceImpedance};
use rodyn_firmware::exit::{exit, exit_with, CHECK_FAILED};
use rodyn_firmware::measure::InstructionCounter;
use rodyn_firmware::models::panda::MODEL_F32 as PANDA;
use rodyn_firmware::models::{
    PANDA_ENCODER_OFFSETS, PANDA_FLANGE, PANDA_READY, PANDA_TORQUE_LIMITS,
};
use rodyn_firmware::simulated::{wire, ArmPlant, Signals};

/// Control period (s): 1 kHz.
const DT: f32 = 1.0e-3;
/// Plant steps per control tick.
const SUBSTEPS: u32 = 4;
/// Control ticks: 3 s.
const TICKS: u32 = 3_000;
/// Ticks left out of the error statistics while the rate filter settles.
const SETTLE_TICKS: u32 = 100;
/// Largest accepted distance of the flange from its reference (mm). With the
/// feedforward, what is left comes from the encoders' and drives'
/// quantisation and the rate filter's lag; the bound leaves about a factor
/// of three over the error of the expected log, and fails a controller
/// that loses the feedforward (the impedance alone lags by millimetres).
const MAX_POSITION_ERROR: f32 = 0.2;
/// Largest accepted angle between the flange's axes and the reference's
/// (mrad), chosen as [`MAX_POSITION_ERROR`].
const MAX_ORIENTATION_ERROR: f32 = 0.5;

/// The flange's pose (world from flange) at `q`.
fn flange_pose(data: &mut Data<f32, 7, 7>, q: &[f32; 7]) -> Transform<f32> {
    match forward_kinematics(&PANDA, data, q).and_then(|()| frame_placement(data, &PANDA_FLANGE)) {
        Ok(pose) => pose,
        Err(e) => {
            defmt::error!("flange pose: {}", e);
            exit(CHECK_FAILED)
        }
    }
}

#[entry]
fn main() -> ! {
    let Some(mut peripherals) = cortex_m::Peripherals::take() else {
        exit(CHECK_FAILED)
    };
    let counter = InstructionCounter::start(&mut peripherals.SYST);

    let signals = Signals::<7>::new();
    let mut plant = ArmPlant::new(&PANDA, PANDA_READY, PANDA_TORQUE_LIMITS);
    plant.publish(&signals);

    let (encoders, drives) = wire(&signals, PANDA_ENCODER_OFFSETS, PANDA_TORQUE_LIMITS);
    let mut controller = TaskSpaceImpedance::new(
        &PANDA,
        PANDA_FLANGE,
        encoders,
        drives,
        TaskGains::PANDA_FLANGE,
        PANDA_READY,
        DT,
    );

    let mut truth = Data::new();
    let start = flange_pose(&mut truth, &PANDA_READY);
    let trajectory = CirclePoseTrajectory {
        start,
        toward_centre: Vec3::new(0.0, 0.0, -1.0),
        along: Vec3::new(0.0, 1.0, 0.0),
        radius: 0.05,
        omega: 4.0,
        ramp: 0.5,
        turn_axis: Vec3::new(0.6, 0.0, 0.8),
        turn_amplitude: 0.15,
        turn_omega: 2.0,
    };
    defmt::println!(
        "task_space: Panda-like 7-DoF arm, flange impedance at 1 kHz, plant by ABA at {} kHz",
        SUBSTEPS
    );
    defmt::println!(
        "flange starts at {} m, circle radius {} m",
        start.trans.to_array(),
        trajectory.radius
    );

    // Position errors in mm, orientation errors in mrad.
    let (mut max_position, mut max_orientation) = (0.0f32, 0.0f32);
    let (mut squared_position, mut squared_orientation) = (0.0f32, 0.0f32);
    let mut max_tick_instructions = 0u32;
    for tick in 0..TICKS {
        let reference = trajectory.at(tick as f32 * DT);
        let (report, instructions) = counter.count(|| controller.tick(&reference));
        let report = match report {
            Ok(report) => report,
            Err(e) => {
                defmt::error!("tick {}: {}", tick, e);
                exit(CHECK_FAILED)
            }
        };
        max_tick_instructions = max_tick_instructions.max(instructions);
        if tick >= SETTLE_TICKS {
            let pose = flange_pose(&mut truth, &plant.state.q);
            let position = 1.0e3 * (reference.pose.trans - pose.trans).norm();
            let orientation = 1.0e3 * log3(&reference.pose.rot.mul_mat_tr(&pose.rot)).norm();
            max_position = max_position.max(position);
            max_orientation = max_orientation.max(orientation);
            squared_position += position * position;
            squared_orientation += orientation * orientation;
        }
        if tick % 1000 == 0 {
            defmt::println!("t = {} ms: q = {}, tau = {}", tick, report.q, report.tau);
        }
        if let Err(e) = plant.advance(&signals, DT, SUBSTEPS) {
            defmt::error!("plant at tick {}: {}", tick, e);
            exit(CHECK_FAILED)
        }
    }
    let samples = (TICKS - SETTLE_TICKS) as f32;
    defmt::println!(
        "flange position error: max {} mm, rms {} mm",
        max_position,
        (squared_position / samples).sqrt()
    );
    defmt::println!(
        "flange orientation error: max {} mrad, rms {} mrad",
        max_orientation,
        (squared_orientation / samples).sqrt()
    );
    defmt::println!("controller tick: {} instructions", max_tick_instructions);
    let passed = max_position <= MAX_POSITION_ERROR && max_orientation <= MAX_ORIENTATION_ERROR;
    defmt::println!(
        "max tracking error {} mm, {} mrad (bounds {} mm, {} mrad): {=str}",
        max_position,
        max_orientation,
        MAX_POSITION_ERROR,
        MAX_ORIENTATION_ERROR,
        if passed { "ok" } else { "FAILED" }
    );
    exit_with(passed)
}
