//! The Aibo-size quadruped of `models/aibo.toml`: it lands and stands, and
//! it trots forward. The file's ground (5 kN/m, 50 N s/m) needs a 0.5 ms
//! step for the explicit schemes (at 1 ms semi-implicit Euler bounces).

use rodyn::algorithm::forward_dynamics::{Aba, Crba};
use rodyn::sim::{ImplicitEuler, Rk4, SemiImplicitEuler};
use rodyn::Data;
use rodyn_scenarios::quadruped::{self, QuadrupedLoads};

#[test]
fn dropped_quadruped_comes_to_rest_standing() {
    let model = quadruped::model::<f64>().unwrap();
    let mut loads = QuadrupedLoads::standing();
    let stance = loads.stance_height();
    let mut state = loads.initial_state(stance + 0.03);
    let mut data = Data::new();
    let mut rk4 = Rk4::default();
    for _ in 0..2000 {
        quadruped::step(
            &mut rk4, Aba, &model, &mut data, &mut loads, &mut state, 1e-3,
        )
        .unwrap();
    }
    // At rest: slow, level, a little below the stance height (the legs give
    // under the PD gains and the feet sink ~1 mm into the ground).
    let speed = state.v.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(speed < 1e-3, "still moving: {speed}");
    let height = quadruped::trunk_position(&state.q).z;
    assert!(
        (height - stance).abs() < 0.005,
        "height {height} vs stance {stance}"
    );
    assert!(state.q[6] > 0.9999, "not level: w = {}", state.q[6]);
    let weight = model.total_mass() * 9.81;
    let support: f64 = loads.reports.iter().map(|r| r.force.z).sum();
    assert!(
        (support - weight).abs() < 0.01 * weight,
        "support {support} N vs weight {weight} N"
    );
}

#[test]
fn implicit_euler_and_crba_stand_too() {
    let model = quadruped::model::<f64>().unwrap();
    let mut loads = QuadrupedLoads::standing();
    let stance = loads.stance_height();
    let mut state = loads.initial_state(stance + 0.03);
    let mut data = Data::new();
    let mut implicit = ImplicitEuler::default();
    for _ in 0..500 {
        quadruped::step(
            &mut implicit,
            Crba,
            &model,
            &mut data,
            &mut loads,
            &mut state,
            4e-3,
        )
        .unwrap();
    }
    let height = quadruped::trunk_position(&state.q).z;
    assert!((height - stance).abs() < 0.005, "height {height}");
}

#[test]
fn open_loop_trot_moves_forward_in_f32() {
    let model = quadruped::model::<f32>().unwrap();
    let mut loads = QuadrupedLoads::trotting();
    let mut state = loads.initial_state(loads.stance_height());
    let mut data = Data::new();
    let mut euler = SemiImplicitEuler::default();
    for _ in 0..6000 {
        quadruped::step(
            &mut euler, Aba, &model, &mut data, &mut loads, &mut state, 5e-4,
        )
        .unwrap();
    }
    // About 0.25 m/s forward (0.80 m in 3 s measured); stays upright and
    // level (trunk above the knees, tilted less than 10°).
    let trunk = quadruped::trunk_position(&state.q);
    assert!(trunk.x > 0.5, "forward {} m in 3 s", trunk.x);
    assert!(trunk.z > 0.09, "trunk height {}", trunk.z);
    assert!(state.q[6] > 0.996, "tilted: w = {}", state.q[6]);
}
