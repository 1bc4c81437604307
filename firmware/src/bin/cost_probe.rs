//! What each rodyn algorithm costs on a Cortex-M4F, per model.
//!
//! The same source runs on the other cores of the Cortex-M family's cost
//! tables (`docs/sections/cortex_m_family.md`), and with the `f64` feature
//! computes in f64 (`measure::Real`) on the same states.
//!
//! For every model and algorithm, [`STATES`] random states (seeded
//! xorshift) are fed to one call each; the log reports the minimum and
//! maximum instructions per call (QEMU `-icount shift=6` and SysTick, see
//! `measure`) and the most stack bytes a call used (painted window). Equal
//! minimum and maximum mean the cost does not depend on the data. Every
//! tenth state crosses a data-dependent branch the others do not reach
//! (`measure::BRANCH_EVERY`): the revolute joints wound beyond the f32
//! sine's fast range, the muscles shortening faster than they can pull.
//! `cargo xtask costs` turns the log into the table of the README.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use rodyn::algorithm::crba::{crba_planned, CrbaPlan};
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::algorithm::rnea::rnea;
use rodyn::sim::SemiImplicitEuler;
use rodyn::space::Space;
use rodyn::{Data, Model, Scalar};
use rodyn_firmware::exit::{exit, exit_with, CHECK_FAILED};
use rodyn_firmware::measure::{
    branch_state, fill_symmetric, probe_scene, stack_bytes, Cost, InstructionCounter, Real,
    StateIndex, REAL_NAME, SEED, STATES, WOUND,
};
#[cfg(not(feature = "f64"))]
use rodyn_firmware::models::{
    aibo::{CRBA_PLAN_F32 as QUADRUPED_PLAN, MODEL_F32 as QUADRUPED},
    muscle_robot::{MODEL_F32 as ROBOT, MUSCLES_F32 as ROBOT_MUSCLES},
    panda::{CRBA_PLAN_F32 as PANDA_PLAN, MODEL_F32 as PANDA},
    pendulum::{CRBA_PLAN_F32 as PENDULUM_PLAN, MODEL_F32 as PENDULUM},
    PENDULUM_PLANAR, PENDULUM_PLANAR_CRBA_PLAN,
};
#[cfg(feature = "f64")]
use rodyn_firmware::models::{
    aibo::{CRBA_PLAN_F64 as QUADRUPED_PLAN, MODEL_F64 as QUADRUPED},
    muscle_robot::{MODEL_F64 as ROBOT, MUSCLES_F64 as ROBOT_MUSCLES},
    panda::{CRBA_PLAN_F64 as PANDA_PLAN, MODEL_F64 as PANDA},
    pendulum::{CRBA_PLAN_F64 as PENDULUM_PLAN, MODEL_F64 as PENDULUM},
    PENDULUM_PLANAR_F64 as PENDULUM_PLANAR,
    PENDULUM_PLANAR_F64_CRBA_PLAN as PENDULUM_PLANAR_CRBA_PLAN,
};
use rodyn_firmware::models::{
    muscle_robot as robot,
    quadruped::{self, QuadrupedLoads},
};
use rodyn_firmware::rng::XorShift32;

/// The algorithms probed, as they appear in the table.
#[derive(Clone, Copy)]
enum Algorithm {
    Rnea,
    Crba,
    CrbaForwardDynamics,
    Aba,
}

impl Algorithm {
    const ALL: [Self; 4] = [Self::Rnea, Self::Crba, Self::CrbaForwardDynamics, Self::Aba];
    fn name(self) -> &'static str {
        match self {
            Self::Rnea => "RNEA",
            Self::Crba => "CRBA",
            Self::CrbaForwardDynamics => "CRBA+LTDL-FD",
            Self::Aba => "ABA",
        }
    }
}

/// Probes every algorithm on `model`, printing one `cost` line each:
/// angles within ±π, and on every tenth state (`branch_state`) the
/// revolute joints wound by [`WOUND`] (1592 turns) beyond the f32 sine's
/// fast range, so that the maximum includes the exact argument reduction
/// of every joint. Returns false when an algorithm failed.
fn probe<const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    name: &str,
    model: &Model<Real, NB, NQ, NV, G>,
    plan: &CrbaPlan<Real, NB, G>,
    counter: &InstructionCounter,
) -> bool {
    let mut data = Data::<Real, NB, NV, G>::new();
    for algorithm in Algorithm::ALL {
        let mut rng = XorShift32::new(SEED);
        let mut cost = Cost::NONE;
        // The same calls without the wound states: the figures the goals
        // are stated for.
        let mut fast = Cost::NONE;
        let mut refused = 0;
        for k in 0..STATES {
            let mut q = [0.0; NQ];
            fill_symmetric(&mut rng, &mut q, core::f32::consts::PI);
            if branch_state(k) {
                // The quadruped's free flyer (more coordinates than
                // velocities) comes first with seven coordinates; the other
                // models have revolute joints only.
                let first = if NQ > NV { 7 } else { 0 };
                for x in &mut q[first..] {
                    *x += Real::from(WOUND);
                }
            }
            if let Err(e) = model.normalize(&mut q) {
                defmt::error!("{=str}: normalize: {}", name, e);
                return false;
            }
            let mut v = [0.0; NV];
            fill_symmetric(&mut rng, &mut v, 2.0);
            let mut u = [0.0; NV];
            fill_symmetric(&mut rng, &mut u, 5.0);
            let mut call = || -> bool {
                match algorithm {
                    Algorithm::Rnea => rnea(model, &mut data, &q, &v, &u, None).is_ok(),
                    Algorithm::Crba => crba_planned(model, plan, &mut data, &q).is_ok(),
                    Algorithm::CrbaForwardDynamics => {
                        Crba::forward_dynamics_planned(model, plan, &mut data, &q, &v, &u, None)
                            .is_ok()
                    }
                    Algorithm::Aba => {
                        Aba::forward_dynamics(model, &mut data, &q, &v, &u, None).is_ok()
                    }
                }
            };
            let (ok, instructions) = counter.count(&mut call);
            let (ok_again, stack) = stack_bytes(&mut call);
            if ok && ok_again {
                cost.add(instructions, stack);
                if !branch_state(k) {
                    fast.add(instructions, stack);
                }
            } else {
                // A reported failure (in f32, CRBA's factorisation refuses
                // a few states of the light-legged quadruped as not
                // positive definite): counted, and kept out of the costs,
                // since an early return is cheaper than a full call.
                refused += 1;
            }
        }
        if refused > 0 {
            defmt::println!(
                "refused model={=str} algorithm={=str} states={} of {}",
                name,
                algorithm.name(),
                refused,
                STATES
            );
        }
        if refused == STATES {
            defmt::error!("{=str} {=str}: every state failed", name, algorithm.name());
            return false;
        }
        cost.report(name, algorithm.name());
        defmt::println!(
            "fast model={=str} algorithm={=str} min={} max={}",
            name,
            algorithm.name(),
            fast.min,
            fast.max
        );
    }
    true
}

/// The muscle robot (`models/two_link_muscles.toml`): forward dynamics with
/// its four muscles, and the same plus the full sensitivity matrix
/// `∂q̈/∂a` (2 × 4), at random angles (±1 rad), rates (±2 rad/s) and
/// activations (0 to 1): fibres on both sides of their optimal length
/// (passive force off and on), shortening and lengthening. Every tenth
/// state has its rates scaled to ±60 rad/s, where some muscles shorten
/// faster than their maximum contraction velocity (`f_V = 0`).
fn probe_muscle_robot(counter: &InstructionCounter) -> bool {
    use robot::{NU, NV};
    let index = StateIndex::new();
    let draw = |rng: &mut XorShift32| {
        let (mut q, mut v): ([Real; NV], [Real; NV]) = ([0.0; NV], [0.0; NV]);
        fill_symmetric(rng, &mut q, 1.0);
        fill_symmetric(rng, &mut v, 2.0);
        if index.next_is_branch() {
            for x in &mut v {
                *x *= 30.0;
            }
        }
        let a: [Real; NU] = core::array::from_fn(|_| Real::from(rng.uniform(0.0, 1.0)));
        (q, v, a)
    };
    let mut data = robot::RobotData::new();
    let mut forces = robot::RobotForces::new();
    let forward = probe_scene(
        "muscle-robot",
        "FD+4-muscles",
        counter,
        draw,
        |(q, v, a)| {
            robot::forward_dynamics(&ROBOT, &ROBOT_MUSCLES, &mut data, q, v, a, &mut forces).is_ok()
        },
    );
    let mut d_ddq_d_a = [[0.0; NU]; NV];
    let sensitivity = probe_scene("muscle-robot", "FD+dqdd/da", counter, draw, |(q, v, a)| {
        robot::sensitivity(
            &ROBOT,
            &ROBOT_MUSCLES,
            &mut data,
            q,
            v,
            a,
            &mut forces,
            &mut d_ddq_d_a,
        )
        .is_ok()
    });
    forward & sensitivity
}

/// The quadruped (`models/aibo.toml`): one semi-implicit Euler step of the
/// trot with ground contact at the four feet (contact forces, the PD
/// controller, ABA, the configuration update), from the stance pose with
/// the joints perturbed by up to ±0.2 rad, the trunk within ±1 cm of its
/// stance height, rates up to ±0.5, at a random time of the stride. The
/// draw crosses the contact branch both ways without help: of the 100
/// states, 42 have every foot in the air, 17 all four in the ground and
/// the rest some of each (`host-tests/tests/probe_branches.rs` counts them).
fn probe_quadruped_step(counter: &InstructionCounter) -> bool {
    let trot = QuadrupedLoads::<Real>::trotting();
    let draw = |rng: &mut XorShift32| {
        let mut state =
            trot.initial_state(trot.stance_height() + Real::from(rng.uniform(-0.01, 0.01)));
        for x in &mut state.q[7..] {
            *x += Real::from(rng.uniform(-0.2, 0.2));
        }
        fill_symmetric(rng, &mut state.v, 0.5);
        state.t = Real::from(rng.uniform(0.0, 1.0));
        (state, trot)
    };
    let mut data = Data::new();
    let mut euler = SemiImplicitEuler::default();
    probe_scene(
        "quadruped-contact",
        "step(SIE,ABA)",
        counter,
        draw,
        |(state, loads)| {
            quadruped::step(&mut euler, Aba, &QUADRUPED, &mut data, loads, state, 5.0e-4).is_ok()
        },
    )
}

/// The scalar rows' names: within ±π, and beyond the f32 sine's fast range.
#[cfg(not(feature = "f64"))]
const SIN_COS_ROWS: [&str; 2] = ["f32-sin_cos", "f32-sin_cos(>8192)"];
/// The scalar rows' names: within ±π, and beyond the f32 sine's fast range.
#[cfg(feature = "f64")]
const SIN_COS_ROWS: [&str; 2] = ["f64-sin_cos", "f64-sin_cos(>8192)"];

/// One `sin_cos` as rodyn's scalar computes it without std (libm): every
/// revolute joint pays it once per call of an algorithm. Angles within ±π,
/// and every tenth beyond the f32 fast range (|x| > 8192 rad: in f32 the
/// exact Payne–Hanek reduction; f64's reduction takes that path only
/// beyond 2²⁰·π/2).
fn sin_cos_cost(counter: &InstructionCounter) {
    let mut rng = XorShift32::new(SEED);
    // (min, max) within ±π and beyond the fast range.
    let mut costs = [(u32::MAX, 0); 2];
    for k in 0..STATES {
        let angle = rng.uniform(-core::f32::consts::PI, core::f32::consts::PI);
        let wound = branch_state(k);
        // Computed before the timed window: left to the optimiser, the
        // random generator's arithmetic lands between the two SysTick
        // reads and is counted with the call.
        let angle = core::hint::black_box(Real::from(if wound { angle + WOUND } else { angle }));
        let (_, instructions) = counter.count(|| core::hint::black_box(angle).sin_cos());
        let (min, max) = &mut costs[usize::from(wound)];
        *min = (*min).min(instructions);
        *max = (*max).max(instructions);
    }
    for ((min, max), name) in costs.into_iter().zip(SIN_COS_ROWS) {
        defmt::println!(
            "cost model=scalar algorithm={=str} min={} max={} stack=-",
            name,
            min,
            max
        );
    }
}

#[entry]
fn main() -> ! {
    let Some(mut peripherals) = cortex_m::Peripherals::take() else {
        exit(CHECK_FAILED)
    };
    let counter = InstructionCounter::start(&mut peripherals.SYST);
    defmt::println!(
        "cost_probe: {=str}, {} random states per model and algorithm",
        REAL_NAME,
        STATES
    );
    sin_cos_cost(&counter);
    let passed = probe("pendulum", &PENDULUM, &PENDULUM_PLAN, &counter)
        & probe(
            "pendulum-planar",
            &PENDULUM_PLANAR,
            &PENDULUM_PLANAR_CRBA_PLAN,
            &counter,
        )
        & probe("panda-7dof", &PANDA, &PANDA_PLAN, &counter)
        & probe("quadruped-floating", &QUADRUPED, &QUADRUPED_PLAN, &counter)
        & probe_muscle_robot(&counter)
        & probe_quadruped_step(&counter);
    exit_with(passed)
}
