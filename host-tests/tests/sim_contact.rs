//! Ground contact: the force law and its placement on the body.

use rodyn::prelude::*;
use rodyn::sim::contact::{GroundContact, NormalLaw};
use rodyn::Endpoint;

const GROUND: GroundContact<f64> = GroundContact {
    normal: NormalLaw::LinearSpringDamper {
        stiffness: 1.0e4,
        damping: 50.0,
    },
    friction: 0.5,
    slip_scale: 0.01,
};

#[test]
fn normal_force_is_a_spring_damper_that_never_pulls() {
    let f = GROUND
        .force_at(&Vec3::new(0.0, 0.0, -0.002), &Vec3::new(0.0, 0.0, -0.1))
        .unwrap();
    assert!((f.z - (1.0e4 * 0.002 + 50.0 * 0.1)).abs() < 1e-12);
    // Rising fast out of the ground: the damper would pull; clamped to zero.
    let f = GROUND
        .force_at(&Vec3::new(0.0, 0.0, -0.001), &Vec3::new(0.0, 0.0, 1.0))
        .unwrap();
    assert_eq!(f, Vec3::ZERO);
    // Above ground: nothing.
    let f = GROUND
        .force_at(&Vec3::new(0.0, 0.0, 0.001), &Vec3::new(0.3, 0.0, -1.0))
        .unwrap();
    assert_eq!(f, Vec3::ZERO);
}

#[test]
fn hunt_crossley_force_is_continuous_at_touchdown() {
    let hc = GroundContact {
        normal: NormalLaw::HuntCrossley {
            stiffness: 1.0e4,
            damping: 0.5,
        },
        ..GROUND
    };
    let f = hc
        .force_at(&Vec3::new(0.0, 0.0, -1e-9), &Vec3::new(0.0, 0.0, -2.0))
        .unwrap();
    assert!(f.z < 1e-4, "{}", f.z);
    let f = hc
        .force_at(&Vec3::new(0.0, 0.0, -0.01), &Vec3::new(0.0, 0.0, -2.0))
        .unwrap();
    assert!((f.z - 1.0e4 * 0.01 * 2.0).abs() < 1e-9);
}

#[test]
fn friction_opposes_slip_and_saturates_at_coulomb() {
    let p = Vec3::new(0.0, 0.0, -0.001);
    let fast = GROUND.force_at(&p, &Vec3::new(1.0, 0.0, 0.0)).unwrap();
    let normal = 1.0e4 * 0.001;
    assert!((fast.x + 0.5 * normal).abs() < 1e-9 * normal, "{fast:?}");
    let slow = GROUND.force_at(&p, &Vec3::new(0.0, -1e-4, 0.0)).unwrap();
    // Below the slip scale: viscous, μ λ / s₀ per m/s.
    assert!(
        (slow.y - 0.5 * normal / 0.01 * 1e-4).abs() < 1e-3 * slow.y,
        "{slow:?}"
    );
    let still = GROUND.force_at(&p, &Vec3::ZERO).unwrap();
    assert_eq!((still.x, still.y), (0.0, 0.0));
}

#[test]
fn contact_force_lands_on_the_body_in_its_frame() {
    // One free body, rotated 90° about z, with a foot 0.1 m along its x axis
    // that is 1 mm in the ground.
    let model: Model<f64, 1, 7, 6> = Model::new(
        [None],
        [Joint::free_flyer()],
        [Transform::IDENTITY],
        [Inertia::new(
            1.0,
            Vec3::ZERO,
            Sym3::diagonal(0.01, 0.01, 0.01),
        )],
        Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
    );
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let q = [0.0, 0.0, -0.001, 0.0, 0.0, s, s];
    let foot = [Endpoint::on_body(0, Vec3::new(0.1, 0.0, 0.0))];
    let mut f_ext = [Force::ZERO; 1];
    let mut data = Data::new();
    GROUND
        .add_forces(&model, &mut data, &q, &[0.0; 6], &foot, &mut f_ext, None)
        .unwrap();
    // World force (0, 0, 10 N) is (0, 0, 10) in the body frame too (rotation
    // about z); its moment about the body origin is p × f = (0, -1, 0) N m.
    let f = f_ext[0];
    assert!((f.lin.z - 10.0).abs() < 1e-9 && f.lin.x.abs() < 1e-12 && f.lin.y.abs() < 1e-12);
    assert!((f.ang.y + 1.0).abs() < 1e-9 && f.ang.x.abs() < 1e-12 && f.ang.z.abs() < 1e-12);
}
