//! Paths: lengthening velocity, generalised forces and power balance on
//! random states, in 3-D and in the plane.

// Row and column indices mirror the matrix equations being checked.
#![allow(clippy::needless_range_loop)]

use rodyn::algorithm::kinematics::forward_kinematics_velocity;
use rodyn::algorithm::rnea::rnea;
use rodyn::drive::{Path, PathKinematics};
use rodyn::planar::{Planar, PlanarInertia, PlanarJoint, PlanarMotion, PlanarTransform, Vec2};
use rodyn::prelude::*;
use rodyn::{Endpoint, Error};

/// A small deterministic generator (xorshift64*), uniform in [lo, hi).
struct Rng(u64);
impl Rng {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let x = (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * x
    }
}

/// Three bodies, two branches, three different joint axes.
fn model_3d() -> Model<f64, 3, 3, 3> {
    let body =
        |m: f64, c: Vec3<f64>| Inertia::new(m, c, Sym3::diagonal(0.02 * m, 0.03 * m, 0.025 * m));
    Model::new(
        [None, Some(0), Some(0)],
        [
            Joint::revolute(Axis::Z),
            Joint::revolute(Axis::Y),
            Joint::revolute(Axis::X),
        ],
        [
            Transform::IDENTITY,
            Transform::from_translation(Vec3::new(0.5, 0.0, 0.1)),
            Transform::new(
                Mat3::from_axis_angle(&Vec3::new(0.0, 0.6, 0.8), 0.4),
                Vec3::new(0.0, 0.3, -0.2),
            ),
        ],
        [
            body(1.5, Vec3::new(0.25, 0.0, 0.0)),
            body(0.8, Vec3::new(0.2, 0.05, 0.0)),
            body(0.6, Vec3::new(0.0, 0.15, 0.05)),
        ],
        Motion::new(Vec3::ZERO, Vec3::ZERO),
    )
}

/// A path from the world over all three bodies, with two points on body 1.
fn path_3d() -> Path<f64, Spatial, 5> {
    Path::new([
        Endpoint::in_world(Vec3::new(-0.2, 0.4, 0.3)),
        Endpoint::on_body(0, Vec3::new(0.3, 0.05, 0.1)),
        Endpoint::on_body(1, Vec3::new(0.1, -0.05, 0.2)),
        Endpoint::on_body(1, Vec3::new(0.35, 0.1, 0.0)),
        Endpoint::on_body(2, Vec3::new(0.05, 0.25, -0.1)),
    ])
}

fn kinematics_at<const NB: usize, const NQ: usize, const NV: usize, G, const K: usize>(
    model: &Model<f64, NB, NQ, NV, G>,
    path: &Path<f64, G, K>,
    q: &[f64; NQ],
    v: &[f64; NV],
) -> (PathKinematics<f64, G, K>, Data<f64, NB, NV, G>)
where
    G: rodyn::drive::PointGeometry,
{
    let mut data = Data::new();
    forward_kinematics_velocity(model, &mut data, q, v).unwrap();
    (path.kinematics(&data).unwrap(), data)
}

/// `L̇` against a central difference of `L(q + v t)`; `Jᵀ f` of a unit
/// tension against `-∂L/∂q`; and `Σ vᵢ·fᵢ = -T L̇`.
fn check_path<const NB: usize, const NV: usize, G, const K: usize>(
    model: &Model<f64, NB, NV, NV, G>,
    path: &Path<f64, G, K>,
    rng: &mut Rng,
) where
    G: rodyn::drive::PointGeometry,
{
    const H: f64 = 1e-6;
    for _ in 0..20 {
        let q: [f64; NV] = core::array::from_fn(|_| rng.uniform(-2.0, 2.0));
        let v: [f64; NV] = core::array::from_fn(|_| rng.uniform(-3.0, 3.0));
        let tension = rng.uniform(-50.0, 200.0);
        let (kin, data) = kinematics_at(model, path, &q, &v);

        let length_at = |t: f64| {
            let qt: [f64; NV] = core::array::from_fn(|k| q[k] + v[k] * t);
            kinematics_at(model, path, &qt, &v).0.length
        };
        let fd = (length_at(H) - length_at(-H)) / (2.0 * H);
        approx::assert_relative_eq!(kin.lengthening_velocity, fd, epsilon = 1e-7);

        let mut f_ext = [<G::Force<f64> as VectorOps<f64>>::ZERO; NB];
        path.add_tension(&kin, tension, &data, &mut f_ext).unwrap();

        // Power the endpoint forces deliver to the bodies.
        let power: f64 = (0..NB).map(|i| data.v[i].dot(&f_ext[i])).sum();
        approx::assert_relative_eq!(
            power,
            -tension * kin.lengthening_velocity,
            epsilon = 1e-9,
            max_relative = 1e-12
        );

        // Generalised forces: without gravity, RNEA at rest returns -Jᵀ f.
        let zero = [0.0; NV];
        let mut rdata = Data::new();
        let jt_f: [f64; NV] = rnea(model, &mut rdata, &q, &zero, &zero, Some(&f_ext))
            .unwrap()
            .map(|t| -t);
        for k in 0..NV {
            let mut qp = q;
            let mut qm = q;
            qp[k] += H;
            qm[k] -= H;
            let dl_dq = (kinematics_at(model, path, &qp, &zero).0.length
                - kinematics_at(model, path, &qm, &zero).0.length)
                / (2.0 * H);
            approx::assert_relative_eq!(
                jt_f[k],
                -tension * dl_dq,
                epsilon = 1e-6 * tension.abs().max(1.0)
            );
        }
    }
}

#[test]
fn path_in_space_balances_power_and_matches_finite_differences() {
    check_path(&model_3d(), &path_3d(), &mut Rng(0x9E37_79B9_7F4A_7C15));
}

#[test]
fn path_in_the_plane_balances_power_and_matches_finite_differences() {
    let rod = |m: f64| PlanarInertia::new(m, Vec2::new(0.2, 0.0), 0.01 * m);
    let model: Model<f64, 2, 2, 2, Planar> = Model::new_planar(
        [None, Some(0)],
        [PlanarJoint::Revolute, PlanarJoint::Revolute],
        [
            PlanarTransform::IDENTITY,
            PlanarTransform::from_translation(Vec2::new(0.4, 0.0)),
        ],
        [rod(2.0), rod(1.0)],
        PlanarMotion::new(0.0, Vec2::new(0.0, 0.0)),
    );
    let path = Path::new([
        Endpoint::in_world(Vec2::new(0.1, 0.2)),
        Endpoint::on_body(0, Vec2::new(0.3, 0.05)),
        Endpoint::on_body(1, Vec2::new(0.2, -0.04)),
    ]);
    check_path(&model, &path, &mut Rng(12345));
}

#[test]
fn straight_two_point_path_has_closed_form_length_and_force() {
    // A point on a link turning about z at 1 rad/s, tied to a world point.
    let model: Model<f64, 1, 1, 1> = Model::new(
        [None],
        [Joint::revolute(Axis::Z)],
        [Transform::IDENTITY],
        [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
        Motion::new(Vec3::ZERO, Vec3::ZERO),
    );
    let path = Path::new([
        Endpoint::in_world(Vec3::new(0.0, 2.0, 0.0)),
        Endpoint::on_body(0, Vec3::new(1.0, 0.0, 0.0)),
    ]);
    let (kin, data) = kinematics_at(&model, &path, &[0.0], &[1.0]);
    // From (0, 2) to (1, 0): length √5; the point moves along +y at 1 m/s,
    // toward the anchor: L̇ = (1, -2)/√5 · (0, 1) = -2/√5.
    approx::assert_relative_eq!(kin.length, 5f64.sqrt(), epsilon = 1e-15);
    approx::assert_relative_eq!(
        kin.lengthening_velocity,
        -2.0 / 5f64.sqrt(),
        epsilon = 1e-15
    );
    let mut f_ext = [Force::ZERO; 1];
    path.add_tension(&kin, 10.0, &data, &mut f_ext).unwrap();
    // 10 N toward the anchor, applied at (1, 0, 0): moment about z = x fy.
    let dir = Vec3::new(-1.0, 2.0, 0.0).scale(1.0 / 5f64.sqrt());
    approx::assert_relative_eq!(f_ext[0].lin.x, 10.0 * dir.x, epsilon = 1e-12);
    approx::assert_relative_eq!(f_ext[0].lin.y, 10.0 * dir.y, epsilon = 1e-12);
    approx::assert_relative_eq!(f_ext[0].ang.z, 10.0 * dir.y, epsilon = 1e-12);
}

#[test]
fn coincident_points_give_zero_force_not_nan_and_bad_bodies_are_errors() {
    let model = model_3d();
    let same = Vec3::new(0.3, 0.0, 0.0);
    let path = Path::new([Endpoint::on_body(0, same), Endpoint::on_body(0, same)]);
    let (kin, data) = kinematics_at(&model, &path, &[0.1, 0.2, 0.3], &[1.0, 1.0, 1.0]);
    assert_eq!(kin.length, 0.0);
    assert_eq!(kin.lengthening_velocity, 0.0);
    let mut f_ext = [Force::ZERO; 3];
    path.add_tension(&kin, 100.0, &data, &mut f_ext).unwrap();
    assert!(f_ext.iter().all(|f| *f == Force::ZERO));

    let bad = Path::new([Endpoint::on_body(0, same), Endpoint::on_body(7, same)]);
    assert!(matches!(
        bad.kinematics(&data),
        Err(Error::InvalidDrive {
            problem: rodyn::error::DriveProblem::BodyOutOfRange { body: 7 }
        })
    ));
}

/// A path point that is not finite is named by its place along the path,
/// for the kinematics, for a tension to apply and for the derivatives'
/// length, rather than read as a NaN length.
#[test]
fn a_non_finite_path_point_is_named() {
    use rodyn::error::Quantity;
    let model = model_3d();
    let mut data = Data::new();
    forward_kinematics_velocity(&model, &mut data, &[0.2, -0.1, 0.4], &[0.3, 0.1, -0.2]).unwrap();
    for bad in [f64::NAN, f64::INFINITY] {
        let path = Path::new([
            Endpoint::on_body(1, Vec3::new(0.1, 0.0, 0.0)),
            Endpoint::on_body(2, Vec3::new(0.0, bad, 0.0)),
            Endpoint::in_world(Vec3::new(1.0, 0.0, 0.0)),
        ]);
        assert_eq!(
            path.kinematics(&data).map(|k| k.length),
            Err(Error::NonFinite {
                quantity: Quantity::PathPoint,
                index: 1
            })
        );
    }
    let path = Path::new([
        Endpoint::on_body(1, Vec3::new(0.1, 0.0, 0.0)),
        Endpoint::in_world(Vec3::new(1.0, 0.0, 0.0)),
    ]);
    let kin = path.kinematics(&data).unwrap();
    let mut f_ext = [Force::ZERO; 3];
    assert_eq!(
        path.add_tension(&kin, f64::NAN, &data, &mut f_ext),
        Err(Error::NonFinite {
            quantity: Quantity::ExternalForce,
            index: 1
        })
    );
    assert_eq!(f_ext, [Force::ZERO; 3]);
}
