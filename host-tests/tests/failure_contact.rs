//! Failure map 5: contact stiffness against step for the quadruped. A
//! stiffer ground needs a smaller step for the explicit schemes; past the
//! boundary rodyn reports a non-finite state or the robot does not come to
//! rest, but no NaN state is ever returned. The implicit Euler lands at
//! steps several times larger.

use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::sim::contact::NormalLaw;
use rodyn::sim::{ImplicitEuler, Integrator, Rk4, SemiImplicitEuler};
use rodyn::{Data, Error};
use rodyn_scenarios::quadruped::{self, QuadrupedLoads};

/// Lands for `duration`; `Ok(true)` when at rest near the expected height.
fn lands<I: Integrator>(mut integrator: I, k: f64, dt: f64, duration: f64) -> Result<bool, Error> {
    let model = quadruped::model::<f64>().unwrap();
    let mut loads = QuadrupedLoads::<f64>::standing();
    loads.ground.normal = NormalLaw::LinearSpringDamper {
        stiffness: k,
        damping: 10.0 * (k / 5.0e3).sqrt(),
    };
    let stance = loads.stance_height();
    let mut state = loads.initial_state(stance + 0.03);
    let mut data = Data::new();
    for _ in 0..(duration / dt).round() as usize {
        let result = integrator.step(Aba, &model, &mut data, &mut state, dt, &mut loads);
        assert!(
            state.q.iter().chain(&state.v).all(|x| x.is_finite()),
            "state must stay finite"
        );
        result?;
    }
    let speed = state.v[..6].iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let expected = stance - 0.002 - model.total_mass() * 9.81 / (4.0 * k);
    let height = quadruped::trunk_position(&state.q).z;
    Ok(speed < 0.02 && (height - expected).abs() < 0.005)
}

#[test]
fn stiff_ground_needs_small_steps_for_explicit_schemes() {
    // Default ground (5 kN/m): semi-implicit Euler lands at 0.5 ms.
    assert_eq!(
        lands(SemiImplicitEuler::default(), 5.0e3, 5e-4, 1.0),
        Ok(true)
    );
    // 1 MN/m: at 2 ms semi-implicit Euler and RK4 blow up (reported) or do
    // not come to rest.
    assert!(!matches!(
        lands(SemiImplicitEuler::default(), 1.0e6, 2e-3, 0.3),
        Ok(true)
    ));
    assert!(!matches!(lands(Rk4::default(), 1.0e6, 2e-3, 0.3), Ok(true)));
}

#[test]
fn implicit_euler_lands_on_a_stiff_ground_at_a_large_step() {
    assert_eq!(lands(ImplicitEuler::default(), 1.0e6, 2e-3, 1.0), Ok(true));
}
