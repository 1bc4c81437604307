//! What control-level computations cost on a Cortex-M4F: the Panda
//! flange's Jacobian and `J̇ v`, one inverse-kinematics step, one tick of
//! the `task_space` example's controller, the Panda's analytic
//! derivatives of inverse and forward dynamics, the muscle robot's with its
//! muscles, and one tick of the `mpc_pendulum` example's model-predictive
//! controller.
//!
//! Measured as `cost_probe` measures (seeded random inputs, instructions
//! by QEMU `-icount` and SysTick, stack bytes from a painted window), in an
//! image of its own: linking these computations into `cost_probe` changes
//! how the optimiser inlines RNEA and ABA there, and with it the costs of
//! the rows that image has measured all along. `cargo xtask costs` appends
//! these rows to `cost_probe`'s in the cost table.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn::algorithm::derivatives::{aba_derivatives, rnea_derivatives, DerivativeData};
use rodyn::algorithm::frames::{frame_classical_acceleration, frame_placement, ReferenceFrame};
use rodyn::algorithm::inverse_kinematics::{self, IkData};
use rodyn::algorithm::jacobian::{frame_jacobian, joint_jacobians, JacobianData};
use rodyn::algorithm::kinematics::{forward_kinematics, forward_kinematics_acceleration};
use rodyn::drive::{aba_derivatives_with_drives, DriveDerivatives};
use rodyn::spatial::{Mat3, Motion, Transform, Vec3};
use rodyn::Data;
use rodyn_firmware::control::{PoseReference, TaskGains, TaskSpaceImpedance};
use rodyn_firmware::exit::{exit, exit_with, CHECK_FAILED};
use rodyn_firmware::measure::{probe_scene, InstructionCounter, StateIndex, STATES};
use rodyn_firmware::models::panda::MODEL_F32 as PANDA;
use rodyn_firmware::models::pendulum::{MODEL_F32 as PENDULUM, RETURN_SPRING_F32 as SPRING};
use rodyn_firmware::models::{
    muscle_robot as robot, PANDA_ENCODER_OFFSETS, PANDA_FLANGE, PANDA_READY, PANDA_TORQUE_LIMITS,
};
use rodyn_firmware::rng::XorShift32;
use rodyn_firmware::simulated::{wire, Signals};
use rodyn_scenarios::pendulum_mpc::{reference, PendulumMpc};

/// The Panda's flange (`models::PANDA_FLANGE`) for task-space control, at
/// random angles (±π) and rates (±2 rad/s):
/// * its Jacobian in the world's axes at its origin, from the angles alone
///   (`joint_jacobians`, then `frame_jacobian`);
/// * `J̇ v`, its classical acceleration at zero joint accelerations
///   (`forward_kinematics_acceleration`, then
///   `frame_classical_acceleration`, as `frame_jacobian_time_variation`'s
///   documentation recommends);
/// * one damped least-squares inverse-kinematics step
///   (`inverse_kinematics::step`, λ = 1e-3) toward the flange's pose at
///   other random angles.
fn probe_flange(counter: &InstructionCounter) -> bool {
    const NV: usize = 7;
    let draw = |rng: &mut XorShift32| {
        let (mut q, mut v) = ([0.0f32; NV], [0.0f32; NV]);
        rng.fill_symmetric(&mut q, core::f32::consts::PI);
        rng.fill_symmetric(&mut v, 2.0);
        (q, v)
    };
    let mut data = Data::new();
    let mut jac = JacobianData::new();
    let mut columns = [Motion::new(Vec3::ZERO, Vec3::ZERO); NV];
    let aligned = ReferenceFrame::LocalWorldAligned;
    let jacobian = probe_scene("panda-7dof", "flange-Jacobian", counter, draw, |(q, _)| {
        joint_jacobians(&PANDA, &mut data, &mut jac, q).is_ok()
            && frame_jacobian(&PANDA, &data, &jac, &PANDA_FLANGE, aligned, &mut columns).is_ok()
    });
    let jdot_v = probe_scene("panda-7dof", "flange-Jdot-v", counter, draw, |(q, v)| {
        forward_kinematics_acceleration(&PANDA, &mut data, q, v, &[0.0; NV]).is_ok()
            && frame_classical_acceleration(&data, &PANDA_FLANGE, aligned).is_ok()
    });

    let mut target_data = Data::new();
    let draw_target = |rng: &mut XorShift32| {
        let (q, _) = draw(rng);
        let (q_target, _) = draw(rng);
        let target = forward_kinematics(&PANDA, &mut target_data, &q_target)
            .and_then(|()| frame_placement(&target_data, &PANDA_FLANGE))
            .unwrap_or(Transform::IDENTITY);
        (q, target)
    };
    let mut ws = IkData::new();
    let ik_step = probe_scene(
        "panda-7dof",
        "IK-step",
        counter,
        draw_target,
        |(q, target)| {
            inverse_kinematics::step(&PANDA, &mut data, &mut ws, &PANDA_FLANGE, target, 1.0e-3, q)
                .is_ok()
        },
    );
    jacobian & jdot_v & ik_step
}

/// One tick of `task_space`'s controller (`control::TaskSpaceImpedance` on
/// the Panda's flange, with its gains): seven encoder reads over the
/// simulated SPI, the flange's Jacobian and `J̇`, the pseudo-inverse
/// solves, RNEA and seven PWM commands. The arm stands within ±0.3 rad of
/// its ready pose; the reference pose is the flange's there, turned by up
/// to ±0.1 rad and moved by up to ±2 cm, with random velocities and
/// accelerations.
fn probe_task_space_tick(counter: &InstructionCounter) -> bool {
    const NV: usize = 7;
    let signals = Signals::<NV>::new();
    let (encoders, drives) = wire(&signals, PANDA_ENCODER_OFFSETS, PANDA_TORQUE_LIMITS);
    let mut controller = TaskSpaceImpedance::new(
        &PANDA,
        PANDA_FLANGE,
        encoders,
        drives,
        TaskGains::PANDA_FLANGE,
        PANDA_READY,
        1.0e-3,
    );
    let mut ready = Data::new();
    let Ok(start) = forward_kinematics(&PANDA, &mut ready, &PANDA_READY)
        .and_then(|()| frame_placement(&ready, &PANDA_FLANGE))
    else {
        return false;
    };
    let draw = |rng: &mut XorShift32| {
        for (angle, q) in signals.angles.iter().zip(PANDA_READY) {
            angle.set(q + rng.uniform(-0.3, 0.3));
        }
        let mut r = [0.0f32; 19];
        rng.fill_symmetric(&mut r, 1.0);
        let axis = Vec3::new(r[0], r[1], r[2] + 2.0);
        let axis = axis * (1.0 / axis.norm());
        let v = |k: usize, scale: f32| Vec3::new(r[k], r[k + 1], r[k + 2]) * scale;
        PoseReference {
            pose: Transform::new(
                Mat3::from_axis_angle(&axis, 0.1 * r[3]).mul_mat(&start.rot),
                start.trans + v(4, 0.02),
            ),
            velocity: Motion::new(v(7, 0.5), v(10, 0.2)),
            acceleration: Motion::new(v(13, 2.0), v(16, 1.0)),
        }
    };
    probe_scene(
        "panda-7dof",
        "task-space-tick",
        counter,
        draw,
        |reference| controller.tick(reference).is_ok(),
    )
}

/// The Panda's analytic derivatives: `∂τ/∂(q, v)` with `M`, and
/// `∂q̈/∂(q, v, τ)`, at random angles (±π), rates (±2) and accelerations or
/// torques (±5).
fn probe_derivatives(counter: &InstructionCounter) -> bool {
    const NB: usize = 7;
    let draw = |rng: &mut XorShift32| {
        let (mut q, mut v, mut u) = ([0.0f32; NB], [0.0f32; NB], [0.0f32; NB]);
        rng.fill_symmetric(&mut q, core::f32::consts::PI);
        rng.fill_symmetric(&mut v, 2.0);
        rng.fill_symmetric(&mut u, 5.0);
        (q, v, u)
    };
    let mut data = Data::new();
    let mut deriv = DerivativeData::<f32, NB, NB>::new();
    let inverse = probe_scene(
        "panda-7dof",
        "RNEA-derivatives",
        counter,
        draw,
        |(q, v, a)| rnea_derivatives(&PANDA, &mut data, &mut deriv, q, v, a, None).is_ok(),
    );
    let forward = probe_scene(
        "panda-7dof",
        "ABA-derivatives",
        counter,
        draw,
        |(q, v, tau)| aba_derivatives(&PANDA, &mut data, &mut deriv, q, v, tau, None).is_ok(),
    );
    inverse & forward
}

/// The muscle robot's `dq̈/d(q, q̇)` with its four muscles, analytic
/// (`drive::aba_derivatives_with_drives`: the rigid body's derivatives,
/// the muscle paths' gradients and Hessians, the muscles' tension
/// partials), at random angles (±1 rad), rates (±2 rad/s) and activations
/// (0 to 1), the rates of every tenth state 30 times faster (some muscles
/// shortening faster than they can pull), as `cost_probe` draws its
/// muscle-robot states.
fn probe_muscle_robot_derivatives(counter: &InstructionCounter) -> bool {
    use robot::{NB, NU, NV};
    let index = StateIndex::new();
    let draw = |rng: &mut XorShift32| {
        let (mut q, mut v) = ([0.0f32; NV], [0.0f32; NV]);
        rng.fill_symmetric(&mut q, 1.0);
        rng.fill_symmetric(&mut v, 2.0);
        if index.next_is_branch() {
            for x in &mut v {
                *x *= 30.0;
            }
        }
        let a: [f32; NU] = core::array::from_fn(|_| rng.uniform(0.0, 1.0));
        (q, v, a)
    };
    let mut data = Data::new();
    let mut deriv = DerivativeData::<f32, NB, NV, _>::new();
    let mut jac = JacobianData::new();
    let mut drive = DriveDerivatives::new();
    probe_scene("muscle-robot", "dqdd/d(q,v)", counter, draw, |(q, v, a)| {
        aba_derivatives_with_drives(
            &robot::MODEL_F32,
            &mut data,
            &mut deriv,
            &mut jac,
            &mut drive,
            q,
            v,
            &[0.0; NV],
            &robot::MUSCLES_F32,
            a,
        )
        .is_ok()
    })
}

/// One tick of `mpc_pendulum`'s controller (`pendulum_mpc::PendulumMpc`:
/// one iLQR iteration over 25 stages, its references included) after its
/// warm-up, at random times of the reference (0 to 4 s) from states within
/// ±0.05 rad and ±0.2 rad/s of it.
fn probe_mpc_tick(counter: &InstructionCounter) -> bool {
    let mut mpc = PendulumMpc::new(&PENDULUM, &SPRING);
    // The first tick warms the plan up with more iterations: not counted.
    if mpc.tick(0.0, &[0.0, 0.0]).is_err() {
        return false;
    }
    let draw = |rng: &mut XorShift32| {
        let t = rng.uniform(0.0, 4.0);
        let r = reference::<f32>(t);
        (
            t,
            [
                r[0] + rng.uniform(-0.05, 0.05),
                r[1] + rng.uniform(-0.2, 0.2),
            ],
        )
    };
    probe_scene("pendulum", "MPC-tick(iLQR,25)", counter, draw, |(t, x)| {
        mpc.tick(*t, x).is_ok()
    })
}

#[entry]
fn main() -> ! {
    let Some(mut peripherals) = cortex_m::Peripherals::take() else {
        exit(CHECK_FAILED)
    };
    let counter = InstructionCounter::start(&mut peripherals.SYST);
    defmt::println!("control_cost_probe: f32, {} random states per call", STATES);
    let passed = probe_flange(&counter)
        & probe_task_space_tick(&counter)
        & probe_derivatives(&counter)
        & probe_muscle_robot_derivatives(&counter)
        & probe_mpc_tick(&counter);
    exit_with(passed)
}
