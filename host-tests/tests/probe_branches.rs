//! The firmware cost probes' random states reach both sides of the core's
//! data-dependent branches (issue 22 item 5; the branch table in
//! `docs/sections/firmware.md`). The states are redrawn here exactly as
//! `firmware/src/bin/cost_probe.rs` draws them (the same xorshift32, seed
//! and order), in f32, and each branch's side is counted.

use rodyn::algorithm::frames::frame_placement;
use rodyn::algorithm::kinematics::{forward_kinematics, forward_kinematics_velocity};
use rodyn::Data;
use rodyn_scenarios::muscle_robot as robot;
use rodyn_scenarios::quadruped::{self, QuadrupedLoads, LEGS};

/// `firmware/src/rng.rs`'s generator.
struct XorShift32(u32);

impl XorShift32 {
    fn next_u32(&mut self) -> u32 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.0 = x;
        x
    }
    fn uniform(&mut self, lo: f32, hi: f32) -> f32 {
        let unit = (self.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0);
        lo + (hi - lo) * unit
    }
    fn fill_symmetric(&mut self, out: &mut [f32], range: f32) {
        for x in out {
            *x = self.uniform(-range, range);
        }
    }
}

/// `firmware/src/measure/probe.rs`'s seed, number of states and branch
/// states (the last of every ten).
const SEED: u32 = 0x5EED_0001;
const STATES: usize = 100;
fn branch_state(k: usize) -> bool {
    k % 10 == 9
}

/// `cost_probe`'s muscle-robot rows (`FD+4-muscles`, `FD+dqdd/da`; the
/// same draw as `control_cost_probe`'s `dqdd/d(q,v)` but for its branch
/// states): fibres shorter and longer than optimal (passive force off and
/// on), shortening and lengthening, and on the branch states (rates ×30)
/// shortening faster than the maximum contraction velocity.
#[test]
fn muscle_robot_states_cover_the_muscle_branches() {
    use robot::{NU, NV};
    let mut rng = XorShift32(SEED);
    let mut data = Data::new();
    // Muscle states: [passive off, passive on], [stalled, shortening,
    // lengthening].
    let mut passive = [0usize; 2];
    let mut velocity = [0usize; 3];
    // Fibres held at their shortest (the geometry stops: no fibre
    // velocity while the path moves).
    let mut shortest = 0usize;
    for k in 0..STATES {
        let (mut q, mut v) = ([0.0f32; NV], [0.0f32; NV]);
        rng.fill_symmetric(&mut q, 1.0);
        rng.fill_symmetric(&mut v, 2.0);
        if branch_state(k) {
            for x in &mut v {
                *x *= 30.0;
            }
        }
        let a: [f32; NU] = core::array::from_fn(|_| rng.uniform(0.0, 1.0));
        forward_kinematics_velocity(&robot::MODEL_F32, &mut data, &q, &v).unwrap();
        for (m, a) in robot::MUSCLES_F32.iter().zip(a) {
            let kin = m.path.kinematics(&data).unwrap();
            let s = m.state_on(&kin, a).unwrap();
            let l_norm = s.fiber_length / m.params.optimal_fiber_length;
            passive[usize::from(l_norm > 1.0)] += 1;
            // The three pieces of the force-velocity curve.
            let vn = s.normalized_velocity;
            let piece = usize::from(vn > -1.0) + usize::from(vn > 0.0);
            velocity[piece] += 1;
            if s.fiber_velocity == 0.0 && kin.lengthening_velocity != 0.0 {
                shortest += 1;
            }
        }
    }
    println!(
        "passive off/on {passive:?}, stalled/shortening/lengthening {velocity:?}, \
         shortest fibre {shortest}"
    );
    assert!(passive.iter().chain(&velocity).all(|&n| n > 0));
}

/// `cost_probe`'s `step(SIE,ABA)` row (the trunk within ±1 cm of its
/// stance height, the joints within ±0.2 rad of the stance): states with
/// every foot in the air (no contact force), every foot in the ground, and
/// some of each.
#[test]
fn quadruped_step_states_have_feet_on_and_off_the_ground() {
    let trot = QuadrupedLoads::<f32>::trotting();
    let model = quadruped::model::<f32>().unwrap();
    let feet = quadruped::foot_frames::<f32>();
    let mut data = Data::new();
    let mut rng = XorShift32(SEED);
    // States by the number of feet below the ground.
    let mut touching = [0usize; LEGS + 1];
    for _ in 0..STATES {
        let height = trot.stance_height() + rng.uniform(-0.01, 0.01);
        let mut state = trot.initial_state(height);
        for x in &mut state.q[7..] {
            *x += rng.uniform(-0.2, 0.2);
        }
        rng.fill_symmetric(&mut state.v, 0.5);
        let _t = rng.uniform(0.0, 1.0);
        forward_kinematics(&model, &mut data, &state.q).unwrap();
        let down = feet
            .iter()
            .filter(|foot| frame_placement(&data, foot).unwrap().trans.z < 0.0)
            .count();
        touching[down] += 1;
    }
    println!("states with 0..=4 feet in the ground: {touching:?}");
    assert!(touching.iter().all(|&n| n > 0), "{touching:?}");
}

/// `cost_probe`'s wound states: every joint angle of ±π plus 1592 turns is
/// beyond the f32 sine's fast range (|x| > 8192 rad).
#[test]
fn wound_angles_leave_the_fast_sine_range() {
    let wound = 1592.0 * 2.0 * core::f32::consts::PI;
    let mut rng = XorShift32(SEED);
    for _ in 0..10_000 {
        let angle = rng.uniform(-core::f32::consts::PI, core::f32::consts::PI);
        let x = angle + wound;
        assert!(x > 8192.0);
        // The same angle to within the f32 spacing there (1e-3 rad).
        let turns = 1592.0 * 2.0 * core::f64::consts::PI;
        assert!((f64::from(x) - turns - f64::from(angle)).abs() < 1e-3);
    }
}

/// `control_cost_probe`'s `IK-step` row: the flange at random angles (±π)
/// and its target at other random angles, as the probe draws them. The
/// rotation between them (the same for any fixed flange offset) takes both
/// branches of `inverse_kinematics::log3`: within 2.69 rad (`cos θ > −0.9`)
/// and near half a turn (the axis from the symmetric part).
#[test]
fn ik_step_states_take_both_branches_of_log3() {
    use rodyn_scenarios::panda::{MODEL_F32 as PANDA, NB, NV};
    let mut rng = XorShift32(SEED);
    let mut draw = || {
        let (mut q, mut v) = ([0.0f32; NV], [0.0f32; NV]);
        rng.fill_symmetric(&mut q, core::f32::consts::PI);
        rng.fill_symmetric(&mut v, 2.0);
        q
    };
    let (mut data, mut target_data) = (Data::new(), Data::new());
    // [within 2.69 rad, near half a turn]
    let mut branches = [0usize; 2];
    let last = NB - 1;
    for _ in 0..STATES {
        let q = draw();
        let q_target = draw();
        forward_kinematics(&PANDA, &mut data, &q).unwrap();
        forward_kinematics(&PANDA, &mut target_data, &q_target).unwrap();
        let rot = data.o_m_i[last]
            .rot
            .tr_mul_mat(&target_data.o_m_i[last].rot);
        let m = rot.m;
        let c = 0.5 * (m[0][0] + m[1][1] + m[2][2] - 1.0);
        branches[usize::from(c <= -0.9)] += 1;
    }
    println!("IK-step rotations within 2.69 rad / near half a turn: {branches:?}");
    assert!(branches.iter().all(|&n| n > 0), "{branches:?}");
}

/// `contact_cost_probe`'s `rigid-step(4-feet)` row: the stance with every
/// joint within ±0.02 rad, rates within ±0.5 (as the probe draws them).
/// At the last Gauss–Seidel sweep some feet's tangential impulses are on
/// the friction cone's edge (projected) and some inside it; some feet are
/// below the ground (the gap term recovers depth) and some above.
#[test]
fn rigid_step_states_project_some_feet_on_the_friction_cone() {
    use rodyn::sim::time_stepping::time_step;
    use rodyn::sim::State;
    use rodyn_scenarios::quadruped::{RigidContactData, NV};
    use rodyn_scenarios::quadruped_balance::TrunkController;
    let controller = TrunkController::<f32>::trotting();
    let stance = controller.gait.initial_state(controller.height);
    let model = quadruped::model::<f32>().unwrap();
    let feet = quadruped::foot_frames::<f32>();
    let ground = quadruped::rigid_ground::<f32>();
    let damping = controller.joint_damping();
    let mut data = Data::new();
    let mut contact = RigidContactData::<f32>::new();
    let mut rng = XorShift32(SEED);
    // Feet [inside the cone, on its edge, without normal impulse], and
    // [below the ground, above it] (the gap term's two sides).
    let mut cone = [0usize; 3];
    let mut gap = [0usize; 2];
    for _ in 0..STATES {
        let mut q = stance.q;
        let mut offsets = [0.0f32; NV - 6];
        rng.fill_symmetric(&mut offsets, 0.02);
        for (qi, d) in q[7..].iter_mut().zip(offsets) {
            *qi += d;
        }
        let mut v = [0.0f32; NV];
        rng.fill_symmetric(&mut v, 0.5);
        let _t = rng.uniform(0.0, 3.0);
        let mut state = State::new(q, v);
        let tau = [0.0; NV];
        time_step(
            &model,
            &mut data,
            &mut contact,
            &mut state,
            &tau,
            &damping,
            &feet,
            &ground,
            1e-3,
        )
        .unwrap();
        assert!(contact.in_contact.iter().all(|c| *c));
        for g in contact.gaps {
            gap[usize::from(g > 0.0)] += 1;
        }
        for impulse in contact.impulses {
            let tangential = impulse.x.hypot(impulse.y);
            let limit = ground.friction * impulse.z;
            let side = if impulse.z <= 0.0 {
                2
            } else {
                usize::from(tangential >= limit * (1.0 - 1e-5))
            };
            cone[side] += 1;
        }
    }
    println!("rigid-step feet inside the friction cone / on its edge / lifting: {cone:?}");
    println!("rigid-step feet below / above the ground: {gap:?}");
    assert!(cone[0] > 0 && cone[1] > 0 && gap[0] > 0 && gap[1] > 0);
}
