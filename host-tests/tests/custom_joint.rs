//! A joint type defined outside rodyn: a helical (screw) joint that turns
//! by q about z and advances `pitch · q` along z. The algorithms are not
//! edited; the joint enters through `Joint::Custom`.

use rodyn::algorithm::crba::crba;
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::algorithm::rnea::rnea;
use rodyn::joint::{CustomJoint, JointBehaviour};
use rodyn::prelude::*;

/// Rotation `q` about z with translation `pitch · q` along z (m/rad).
struct Helical {
    pitch: f64,
}

impl JointBehaviour<f64> for Helical {
    fn transform(&self, q: &[f64]) -> Transform<f64> {
        Transform::new(
            Mat3::from_axis_angle(&Vec3::new(0.0, 0.0, 1.0), q[0]),
            Vec3::new(0.0, 0.0, self.pitch * q[0]),
        )
    }
    fn motion(&self, qd: &[f64]) -> Motion<f64> {
        Motion::new(
            Vec3::new(0.0, 0.0, qd[0]),
            Vec3::new(0.0, 0.0, self.pitch * qd[0]),
        )
    }
    fn subspace_column(&self, _k: usize) -> Motion<f64> {
        self.motion(&[1.0])
    }
    fn project_force(&self, f: &Force<f64>, out: &mut [f64]) {
        out[0] = f.ang.z + self.pitch * f.lin.z;
    }
    fn neutral(&self, q: &mut [f64]) {
        q[0] = 0.0;
    }
    fn integrate(&self, q: &[f64], v: &[f64], dt: f64, out: &mut [f64]) {
        out[0] = q[0] + v[0] * dt;
    }
}

static SCREW: Helical = Helical { pitch: 0.05 };
static FLAT_SCREW: Helical = Helical { pitch: 0.0 };
const ZERO_PITCH: Joint<f64> = Joint::Custom(CustomJoint {
    nq: 1,
    nv: 1,
    behaviour: &FLAT_SCREW,
});
const HELICAL: Joint<f64> = Joint::Custom(CustomJoint {
    nq: 1,
    nv: 1,
    behaviour: &SCREW,
});
const G: f64 = 9.81;

#[test]
fn a_screw_lifting_a_load_matches_the_closed_form() {
    // A nut of mass m with its centre of mass on the screw axis: the joint
    // moves inertia I_zz + m p² and gravity costs m g p per radian.
    let (m, izz) = (3.0, 0.02);
    let model: Model<f64, 1, 1, 1> = Model::new(
        [None],
        [HELICAL],
        [Transform::IDENTITY],
        [Inertia::new(m, Vec3::ZERO, Sym3::diagonal(0.05, 0.05, izz))],
        Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -G)),
    );
    let mut data = Data::new();
    let p = SCREW.pitch;
    let tau = rnea(&model, &mut data, &[0.7], &[2.0], &[1.5], None).unwrap()[0];
    let expected = (izz + m * p * p) * 1.5 + m * G * p;
    assert!((tau - expected).abs() < 1e-12, "{tau} vs {expected}");
    let ddq = Aba::forward_dynamics(&model, &mut data, &[0.7], &[2.0], &[0.0], None).unwrap()[0];
    assert!((ddq + m * G * p / (izz + m * p * p)).abs() < 1e-12);
}

#[test]
fn a_screw_inside_a_tree_satisfies_the_identities() {
    let model = arm_with_middle_joint(HELICAL);
    model.validate().unwrap();
    let mut data = Data::new();
    let (q, v, a) = ([0.4, -1.1, 0.8], [0.9, -2.0, 1.3], [0.5, 1.5, -2.5]);
    let tau = *rnea(&model, &mut data, &q, &v, &a, None).unwrap();
    for ddq in [
        *Aba::forward_dynamics(&model, &mut data, &q, &v, &tau, None).unwrap(),
        *Crba::forward_dynamics(&model, &mut data, &q, &v, &tau, None).unwrap(),
    ] {
        for k in 0..3 {
            assert!((ddq[k] - a[k]).abs() < 1e-11, "{ddq:?} vs {a:?}");
        }
    }
    // Advancing along z moves the 1.5 kg the screw carries: its diagonal
    // entry of M exceeds a zero-pitch screw's by exactly m p².
    let m = *crba(&model, &mut data, &q).unwrap();
    let m_flat = *crba(&arm_with_middle_joint(ZERO_PITCH), &mut data, &q).unwrap();
    let added = 1.5 * SCREW.pitch * SCREW.pitch;
    assert!(
        (m[1][1] - m_flat[1][1] - added).abs() < 1e-14,
        "{} vs {added}",
        m[1][1] - m_flat[1][1]
    );
    // A custom joint is tied to its scalar type: casting says so.
    assert_eq!(
        model.cast::<f32>().unwrap_err(),
        Error::UnsupportedCast { body: 1 }
    );
}

/// Revolute shoulder, the given middle joint, revolute wrist; off-axis masses.
fn arm_with_middle_joint(middle: Joint<f64>) -> Model<f64, 3, 3, 3> {
    Model::new(
        [None, Some(0), Some(1)],
        [Joint::revolute(Axis::Y), middle, Joint::revolute(Axis::X)],
        [
            Transform::IDENTITY,
            Transform::from_translation(Vec3::new(0.3, 0.0, 0.1)),
            Transform::from_translation(Vec3::new(0.0, 0.1, 0.2)),
        ],
        [
            Inertia::new(
                2.0,
                Vec3::new(0.15, 0.0, 0.0),
                Sym3::diagonal(0.01, 0.02, 0.02),
            ),
            Inertia::new(
                1.0,
                Vec3::new(0.02, 0.01, 0.1),
                Sym3::diagonal(0.01, 0.01, 0.004),
            ),
            Inertia::new(
                0.5,
                Vec3::new(0.0, 0.05, 0.02),
                Sym3::diagonal(0.002, 0.001, 0.002),
            ),
        ],
        Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -G)),
    )
}
