//! What rigid contacts cost on a Cortex-M4F: the quadruped's constrained
//! forward dynamics with four feet held, their plastic impact, one
//! rigid-contact time step of the plant, and one tick of
//! `quadruped_rigid`'s trunk controller (inverse dynamics with contacts);
//! and the legged robot's kinematics they build on: all the quadruped's
//! joint Jacobians, its centroidal map with the centroidal inertia
//! (CCRBA), one foot's Jacobian from q along its leg and the four feet's
//! together.
//!
//! Measured as `cost_probe` measures (seeded random inputs, instructions
//! by QEMU `-icount` and SysTick, stack bytes from a painted window), in an
//! image of its own so that the other probes' rows keep their inlining.
//! `cargo xtask costs` appends these rows to the cost table.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn::algorithm::centroidal::{centroidal_map, CentroidalData};
use rodyn::algorithm::constrained_dynamics::{
    constrained_forward_dynamics, constrained_forward_dynamics_with, impulse_dynamics,
    ConstraintData, ConstraintMethod, ConstraintSettings, Contact,
};
use rodyn::algorithm::frame_chain::{chain_jacobian, chains_jacobians, FrameChain};
use rodyn::algorithm::frames::{frame_placement, ReferenceFrame};
use rodyn::algorithm::jacobian::{joint_jacobians, JacobianData};
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::sim::time_stepping::time_step;
use rodyn::sim::State;
use rodyn::spatial::{Motion, Vec3};
use rodyn::{Data, Scalar};
use rodyn_firmware::exit::{exit, exit_with, CHECK_FAILED};
use rodyn_firmware::measure::{probe_scene, InstructionCounter, STATES};
use rodyn_firmware::models::aibo::MODEL_F32;
use rodyn_firmware::models::quadruped::{self, RigidContactData, LEGS, NB, NQ, NV};
use rodyn_firmware::rng::XorShift32;
use rodyn_scenarios::quadruped_balance::{TrunkController, TrunkControllerData};

/// Model label of the rows.
const MODEL: &str = "quadruped-rigid";

/// The quadruped with its four feet on the ground: the stance pose with
/// every joint within ±0.02 rad of it (the feet stay within the contact
/// margin), rates within ±0.5 rad/s and m/s, a time in the trot's first
/// 3 s:
/// * constrained forward dynamics with the four feet held as points, by
///   the KKT method (CRBA and `Lᵀ D L`) and by the articulated-body method
///   (ABA and test forces), Baumgarte gains;
/// * the plastic impact of the four feet (`impulse_dynamics`);
/// * one rigid-contact time step of the plant (`time_step`: 30 sweeps of
///   projected Gauss–Seidel, friction 0.8, the drives' damping implicit),
///   and the same step with the trunk 5 cm higher, every foot outside the
///   contact margin (no contact in the active set: the step's other end);
/// * one tick of the trunk controller (`TrunkController::torques`) with
///   two diagonal feet touching, as in the trot, and with all four, the
///   most it ever solves.
fn probe_quadruped_contacts(counter: &InstructionCounter) -> bool {
    let controller = TrunkController::<f32>::trotting();
    let stance = controller.gait.initial_state(controller.height);
    let feet = quadruped::foot_frames::<f32>();
    let draw = |rng: &mut XorShift32| {
        let mut q = stance.q;
        let mut offsets = [0.0f32; NV - 6];
        rng.fill_symmetric(&mut offsets, 0.02);
        for (qi, d) in q[7..].iter_mut().zip(offsets) {
            *qi += d;
        }
        let mut v = [0.0f32; NV];
        rng.fill_symmetric(&mut v, 0.5);
        let t = rng.uniform(0.0, 3.0);
        (q, v, t)
    };
    // The feet held where they are.
    let anchored = |data: &mut Data<f32, NB, NV>, q: &[f32; NQ]| {
        let mut contacts = [Contact::point(feet[0], Vec3::ZERO); LEGS];
        forward_kinematics(&MODEL_F32, data, q).ok()?;
        for (contact, foot) in contacts.iter_mut().zip(&feet) {
            *contact = Contact::point(*foot, frame_placement(data, foot).ok()?.trans);
        }
        Some(contacts)
    };
    let mut data = Data::new();
    let mut cdata = ConstraintData::<f32, NV, { 3 * LEGS }>::new();
    let gains = ConstraintSettings::baumgarte(25.0, 7.0);
    let fd = probe_scene(
        MODEL,
        "constrained-FD(4-feet)",
        counter,
        draw,
        |(q, v, _)| {
            anchored(&mut data, q).is_some_and(|contacts| {
                let tau = [0.0; NV];
                constrained_forward_dynamics(
                    &MODEL_F32, &mut data, &mut cdata, q, v, &tau, &contacts, &gains,
                )
                .is_ok()
            })
        },
    );
    let fd_articulated = probe_scene(
        MODEL,
        "constrained-FD-ABM(4-feet)",
        counter,
        draw,
        |(q, v, _)| {
            anchored(&mut data, q).is_some_and(|contacts| {
                let tau = [0.0; NV];
                constrained_forward_dynamics_with(
                    ConstraintMethod::ArticulatedBody,
                    &MODEL_F32,
                    &mut data,
                    &mut cdata,
                    q,
                    v,
                    &tau,
                    &contacts,
                    &gains,
                )
                .is_ok()
            })
        },
    );
    let impulse = probe_scene(MODEL, "impulse(4-feet)", counter, draw, |(q, v, _)| {
        anchored(&mut data, q).is_some_and(|contacts| {
            impulse_dynamics(&MODEL_F32, &mut data, &mut cdata, q, v, &contacts, 0.0, 0.0).is_ok()
        })
    });
    let ground = quadruped::rigid_ground::<f32>();
    let damping = controller.joint_damping();
    let mut contact = RigidContactData::<f32>::new();
    // One closure measures both rows, with the trunk's lift (m) in its
    // input: with a single call site the optimiser inlines `time_step`
    // into it as it did when the four-feet row was the only one.
    let mut step = |(q, v, lift): &mut ([f32; NQ], [f32; NV], f32)| {
        let mut state = State::new(*q, *v);
        state.q[2] += *lift;
        let tau = [0.0; NV];
        time_step(
            &MODEL_F32,
            &mut data,
            &mut contact,
            &mut state,
            &tau,
            &damping,
            &feet,
            &ground,
            1e-3,
        )
        .is_ok()
            && contact.in_contact.iter().all(|c| *c == (*lift <= 0.0))
    };
    let lifted = |lift: f32| {
        move |rng: &mut XorShift32| {
            let (q, v, _) = draw(rng);
            (q, v, lift)
        }
    };
    let step_four = probe_scene(MODEL, "rigid-step(4-feet)", counter, lifted(0.0), &mut step);
    let step_up = probe_scene(
        MODEL,
        "rigid-step(feet-up)",
        counter,
        lifted(0.05),
        &mut step,
    );
    let mut control = TrunkControllerData::<f32>::new();
    let trot = [true, false, false, true];
    let tick = probe_scene(MODEL, "control-tick(2-feet)", counter, draw, |(q, v, t)| {
        controller
            .torques(&MODEL_F32, &mut data, &mut control, *t, q, v, &trot)
            .is_ok()
    });
    let tick_four = probe_scene(MODEL, "control-tick(4-feet)", counter, draw, |(q, v, t)| {
        controller
            .torques(&MODEL_F32, &mut data, &mut control, *t, q, v, &[true; LEGS])
            .is_ok()
    });
    fd & fd_articulated & impulse & step_four & step_up & tick & tick_four
}

/// The quadruped's kinematics for control, at random configurations (a
/// random unit quaternion, joints within ±π): all joint Jacobians
/// (`joint_jacobians`, world columns) and the centroidal map `A_g` with
/// the centroidal inertia (`centroidal_map`, Pinocchio's
/// `computeCentroidalMap` and `ccrba`).
fn probe_quadruped_kinematics(counter: &InstructionCounter) -> bool {
    let draw = |rng: &mut XorShift32| {
        let mut q = [0.0f32; NQ];
        rng.fill_symmetric(&mut q, core::f32::consts::PI);
        let mut quaternion = [0.0f32; 4];
        rng.fill_symmetric(&mut quaternion, 1.0);
        let squares: f32 = quaternion.iter().map(|x| x * x).sum();
        let norm = Scalar::sqrt(squares).max(1e-3);
        for (qi, x) in q[3..7].iter_mut().zip(quaternion) {
            *qi = x / norm;
        }
        q
    };
    let mut data = Data::new();
    let mut jac = JacobianData::new();
    let jacobians = probe_scene(
        "quadruped-floating",
        "joint-Jacobians",
        counter,
        draw,
        |q| joint_jacobians(&MODEL_F32, &mut data, &mut jac, q).is_ok(),
    );
    let mut cd = CentroidalData::new();
    let ccrba = probe_scene("quadruped-floating", "CCRBA", counter, draw, |q| {
        centroidal_map(&MODEL_F32, &mut data, &mut cd, q).is_ok()
    });
    // One foot's Jacobian from q along its leg, and the four feet's as a
    // set (the free flyer's columns formed once); world axes at the foot.
    // (No closure here: `xtask/src/stack_bound.rs` names the rows'
    // closures by their order.)
    let [f0, f1, f2, f3] = quadruped::foot_frames::<f32>();
    let (Some(a), Some(b), Some(c), Some(d)) = (
        FrameChain::new(&MODEL_F32, f0),
        FrameChain::new(&MODEL_F32, f1),
        FrameChain::new(&MODEL_F32, f2),
        FrameChain::new(&MODEL_F32, f3),
    ) else {
        return false;
    };
    let chains = [a, b, c, d];
    let aligned = ReferenceFrame::LocalWorldAligned;
    let mut columns = [[Motion::new(Vec3::ZERO, Vec3::ZERO); NV]; LEGS];
    let foot = probe_scene("quadruped-floating", "foot-Jacobian", counter, draw, |q| {
        chain_jacobian(&MODEL_F32, q, &chains[0], aligned, &mut columns[0]).is_ok()
    });
    let feet = probe_scene(
        "quadruped-floating",
        "four-feet-Jacobians",
        counter,
        draw,
        |q| chains_jacobians(&MODEL_F32, &mut data, q, &chains, aligned, &mut columns).is_ok(),
    );
    jacobians & ccrba & foot & feet
}

#[entry]
fn main() -> ! {
    let Some(mut peripherals) = cortex_m::Peripherals::take() else {
        exit(CHECK_FAILED)
    };
    let counter = InstructionCounter::start(&mut peripherals.SYST);
    defmt::println!("contact_cost_probe: f32, {} random states per call", STATES);
    exit_with(probe_quadruped_contacts(&counter) & probe_quadruped_kinematics(&counter))
}
