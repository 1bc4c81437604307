//! Rigid contact with Coulomb friction by time stepping
//! (`rodyn::sim::time_stepping`), on a box whose four bottom corners are
//! the contact points: sliding to rest as Coulomb's law says, landing
//! without bouncing or sinking, sticking on a slope below the friction
//! angle, and bad settings.

use rodyn::algorithm::energy::{kinetic_energy, potential_energy};
use rodyn::error::Setting;
use rodyn::joint::{FreeFlyer, Joint};
use rodyn::prelude::*;
use rodyn::sim::time_stepping::{time_step, TimeSteppingData, TimeSteppingSettings};
use rodyn::sim::State;
use rodyn::{Error, Frame};

const G: f64 = 9.81;
const MASS: f64 = 2.0;
/// Half the box's sides (m).
const HALF: [f64; 3] = [0.1, 0.05, 0.025];

fn box_model<S: Scalar>(gravity: Vec3<f64>) -> Model<S, 1, 7, 6> {
    let [a, b, c] = HALF.map(|h| 2.0 * h);
    let k = MASS / 12.0;
    let inertia = Inertia::new(
        MASS,
        Vec3::ZERO,
        Sym3::diagonal(
            k * (b * b + c * c),
            k * (a * a + c * c),
            k * (a * a + b * b),
        ),
    );
    Model::new(
        [None],
        [Joint::FreeFlyer(FreeFlyer)],
        [Transform::IDENTITY],
        [inertia],
        Motion::new(Vec3::ZERO, gravity),
    )
    .cast()
    .unwrap()
}

fn corners<S: Scalar>() -> [Frame<S, Spatial>; 4] {
    let [a, b, c] = HALF;
    [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)].map(|(x, y)| {
        Frame::new(
            0,
            Transform::from_translation(Vec3::new(
                S::from_f64(x * a),
                S::from_f64(y * b),
                S::from_f64(-c),
            )),
        )
    })
}

/// A box resting on its bottom face at the origin, level, moving at `v`
/// (the free flyer's `[linear; angular]` in body axes, here the world's).
fn resting_box<S: Scalar>(v: [f64; 6]) -> State<S, 7, 6> {
    let mut q = [S::ZERO; 7];
    q[2] = S::from_f64(HALF[2]);
    q[6] = S::ONE;
    State::new(q, v.map(S::from_f64))
}

fn run<S: Scalar>(
    state: &mut State<S, 7, 6>,
    seconds: f64,
    dt: f64,
    friction: f64,
    gravity: Vec3<f64>,
    mut each: impl FnMut(&State<S, 7, 6>, &TimeSteppingData<S, 6, 12, 4>),
) {
    let model = box_model::<S>(gravity);
    let mut data = Data::new();
    let mut sdata = TimeSteppingData::<S, 6, 12, 4>::new();
    let settings = TimeSteppingSettings::with_friction(S::from_f64(friction));
    let points = corners::<S>();
    for _ in 0..(seconds / dt).round() as usize {
        time_step(
            &model,
            &mut data,
            &mut sdata,
            state,
            &[S::ZERO; 6],
            &[S::ZERO; 6],
            &points,
            &settings,
            S::from_f64(dt),
        )
        .unwrap();
        each(state, &sdata);
    }
}

/// Sliding at 1.5 m/s with μ = 0.4, the box slows at μ g (within 1e-4
/// m/s at every step) and stops after v₀² / (2 μ g) = 0.287 m, flat on the
/// ground, in f64 and f32: the four corners' friction is all in the slip's
/// direction, with no internal forces eating the cone.
#[test]
fn a_sliding_box_stops_where_coulomb_says() {
    let (v0, mu, dt) = (1.5, 0.4, 1e-3);
    let stop = v0 * v0 / (2.0 * mu * G);
    fn check<S: Scalar>(v0: f64, mu: f64, dt: f64, stop: f64, tolerance: f64) {
        let mut state = resting_box::<S>([v0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        let gravity = Vec3::new(0.0, 0.0, -G);
        let (mut worst_speed, mut worst_height) = (0.0_f64, 0.0_f64);
        run(&mut state, 0.6, dt, mu, gravity, |s, sdata| {
            let t = s.t.to_f64();
            let want = (v0 - mu * G * t).max(0.0);
            worst_speed = worst_speed.max((s.v[0].to_f64() - want).abs());
            worst_height = worst_height.max((s.q[2].to_f64() - HALF[2]).abs());
            assert!(
                sdata.in_contact.iter().all(|c| *c),
                "a corner left the ground"
            );
        });
        let travelled = state.q[0].to_f64();
        eprintln!(
            "{}: stopped after {travelled:.5} m (Coulomb: {stop:.5}); speed within \
             {worst_speed:.1e} m/s, height within {worst_height:.1e} m",
            core::any::type_name::<S>()
        );
        assert!((travelled - stop).abs() < tolerance * stop, "{travelled} m");
        assert!(worst_speed < 1e-4, "{worst_speed}");
        assert!(worst_height < 1e-4, "{worst_height}");
        assert!(
            state.v.iter().all(|v| v.to_f64().abs() < 1e-6),
            "{:?}",
            state.v
        );
    }
    // One step's deceleration μ g dt is the scheme's own error in the
    // stopping time: 0.4 % of the distance here.
    check::<f64>(v0, mu, dt, stop, 5e-3);
    check::<f32>(v0, mu, dt, stop, 5e-3);
}

/// Dropped from 10 cm with a spin, the box lands without bouncing off or
/// sinking more than a millimetre, and comes to rest: the contacts never
/// add energy, and every impulse stays in its friction cone.
#[test]
fn a_dropped_box_lands_and_rests() {
    let gravity = Vec3::new(0.0, 0.0, -G);
    let model = box_model::<f64>(gravity);
    let mut data = Data::new();
    let mut state = resting_box::<f64>([0.3, 0.0, 0.0, 0.0, 2.0, 1.0]);
    state.q[2] += 0.1;
    let energy = |s: &State<f64, 7, 6>, data: &mut Data<f64, 1, 6>| {
        kinetic_energy(&model, data, &s.q, &s.v).unwrap()
            + potential_energy(&model, data, &s.q).unwrap()
    };
    let start = energy(&state, &mut data);
    let (mut deepest, mut landed_at) = (0.0_f64, None);
    let mut after_landing = f64::INFINITY;
    run(&mut state, 1.5, 1e-3, 0.8, gravity, |s, sdata| {
        deepest = deepest.min(sdata.gaps.iter().copied().fold(0.0, f64::min));
        // Every impulse inside its friction cone, pushing, never pulling.
        for i in &sdata.impulses {
            let tangential = i.x.hypot(i.y);
            assert!(
                i.z >= 0.0 && tangential <= 0.8 * i.z * (1.0 + 1e-12),
                "{i:?}"
            );
        }
        if landed_at.is_none() && sdata.impulses.iter().any(|i| i.z > 0.0) {
            landed_at = Some(s.t);
        }
        if landed_at.is_some() {
            let e = energy(s, &mut Data::new());
            // Free fall by semi-implicit Euler changes the energy by
            // O(g² dt²) per step; contacts only take it away.
            assert!(
                e <= after_landing + 1e-6,
                "energy rose to {e} from {after_landing}"
            );
            after_landing = e;
        }
    });
    let landed_at = landed_at.expect("the box never touched the ground");
    eprintln!(
        "landed at {landed_at:.3} s, deepest corner {:.2} mm, energy {start:.4} J -> {after_landing:.4} J",
        deepest * 1e3
    );
    assert!(
        (landed_at - (2.0 * 0.1 / G).sqrt()).abs() < 0.02,
        "{landed_at}"
    );
    assert!(deepest > -1e-3, "sank {deepest} m");
    assert!(
        state.v.iter().all(|v| v.abs() < 1e-3),
        "still moving: {:?}",
        state.v
    );
    assert!(
        (state.q[2] - HALF[2]).abs() < 2e-4,
        "rests at {}",
        state.q[2]
    );
}

/// On a slope of 20° (gravity tilted), μ = 0.5 > tan 20° holds the box
/// still; μ = 0.2 lets it slide down at g (sin 20° − μ cos 20°).
#[test]
fn a_box_on_a_slope_sticks_or_slides_by_the_friction_angle() {
    let angle = 20f64.to_radians();
    let gravity = Vec3::new(-G * angle.sin(), 0.0, -G * angle.cos());
    let mut state = resting_box::<f64>([0.0; 6]);
    run(&mut state, 0.5, 1e-3, 0.5, gravity, |_, _| {});
    assert!(state.q[0].abs() < 1e-6, "crept {} m", state.q[0]);
    let mut state = resting_box::<f64>([0.0; 6]);
    run(&mut state, 0.5, 1e-3, 0.2, gravity, |_, _| {});
    let a = G * (angle.sin() - 0.2 * angle.cos());
    let want = -0.5 * a * 0.5 * 0.5;
    assert!(
        (state.q[0] - want).abs() < 0.01 * want.abs(),
        "{} m against {want} m",
        state.q[0]
    );
}

/// Bad settings and inputs are errors and leave the state as it was.
#[test]
fn bad_settings_are_errors() {
    let model = box_model::<f64>(Vec3::new(0.0, 0.0, -G));
    let mut data = Data::new();
    let mut sdata = TimeSteppingData::<f64, 6, 12, 4>::new();
    let good = TimeSteppingSettings::with_friction(0.5);
    let points = corners::<f64>();
    let mut state = resting_box::<f64>([0.0; 6]);
    let before = state;
    for (settings, setting) in [
        (TimeSteppingSettings::with_friction(-1.0), Setting::Friction),
        (good.with_sweeps(0), Setting::Sweeps),
        (good.with_depth_recovery(1.5), Setting::DepthRecovery),
        (good.with_margin(f64::NAN), Setting::Margin),
    ] {
        let error = time_step(
            &model, &mut data, &mut sdata, &mut state, &[0.0; 6], &[0.0; 6], &points, &settings,
            1e-3,
        )
        .unwrap_err();
        assert_eq!(error, Error::InvalidSetting { setting });
    }
    let mut small = TimeSteppingData::<f64, 6, 9, 4>::new();
    let error = time_step(
        &model, &mut data, &mut small, &mut state, &[0.0; 6], &[0.0; 6], &points, &good, 1e-3,
    )
    .unwrap_err();
    assert_eq!(
        error,
        Error::TooManyConstraints {
            rows: 12,
            capacity: 9
        }
    );
    let mut missing = points;
    missing[2] = Frame::new(1, Transform::IDENTITY);
    let error = time_step(
        &model, &mut data, &mut sdata, &mut state, &[0.0; 6], &[0.0; 6], &missing, &good, 1e-3,
    )
    .unwrap_err();
    assert_eq!(error, Error::FrameBodyOutOfRange { body: 1 });
    let time = rodyn::error::Quantity::Time;
    for (dt, want) in [
        (
            0.0,
            Error::OutOfRange {
                quantity: time,
                index: 1,
            },
        ),
        (
            -1e-3,
            Error::OutOfRange {
                quantity: time,
                index: 1,
            },
        ),
        (
            f64::NAN,
            Error::NonFinite {
                quantity: time,
                index: 0,
            },
        ),
    ] {
        let error = time_step(
            &model, &mut data, &mut sdata, &mut state, &[0.0; 6], &[0.0; 6], &points, &good, dt,
        )
        .unwrap_err();
        assert_eq!(error, want, "dt = {dt}");
    }
    let mut negative = [0.0; 6];
    negative[1] = -1.0;
    let error = time_step(
        &model, &mut data, &mut sdata, &mut state, &[0.0; 6], &negative, &points, &good, 1e-3,
    )
    .unwrap_err();
    assert_eq!(
        error,
        Error::InvalidSetting {
            setting: Setting::JointDamping { dof: 1 }
        }
    );
    let mut tau = [0.0; 6];
    tau[3] = f64::NAN;
    assert!(time_step(
        &model, &mut data, &mut sdata, &mut state, &tau, &[0.0; 6], &points, &good, 1e-3,
    )
    .is_err());
    assert_eq!(state, before);
}

/// Joint damping is taken implicitly: on frictionless ground a box damped
/// by `c` along x loses speed as `v / (1 + h c / m)` per step (backward
/// Euler), with no overshoot even at `h c / m = 10`, where the explicit
/// update would flip the sign and grow.
#[test]
fn damping_is_implicit() {
    let model = box_model::<f64>(Vec3::new(0.0, 0.0, -G));
    let points = corners::<f64>();
    let settings = TimeSteppingSettings::with_friction(0.0);
    for ratio in [0.1, 10.0] {
        let dt = 1e-3;
        let c = ratio * MASS / dt;
        let mut damping = [0.0; 6];
        damping[0] = c;
        let mut state = resting_box::<f64>([1.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        let mut data = Data::new();
        let mut sdata = TimeSteppingData::<f64, 6, 12, 4>::new();
        for k in 1..=20 {
            time_step(
                &model, &mut data, &mut sdata, &mut state, &[0.0; 6], &damping, &points, &settings,
                dt,
            )
            .unwrap();
            let want = (1.0 + ratio).powi(-k);
            assert!(
                (state.v[0] - want).abs() < 1e-12,
                "h c / m = {ratio}, step {k}: {} against {want}",
                state.v[0]
            );
        }
    }
}
