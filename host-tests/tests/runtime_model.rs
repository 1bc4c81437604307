//! The run-time model against the compiled one and against Pinocchio.
//!
//! Every 3-D model of `models/` is compiled by `build.rs` into const Rust;
//! the run-time model loads the same file and must give the compiled
//! model's results to 1e-12 relative on every algorithm, at seeded random
//! states. The Pinocchio fixtures check the URDFs of `models/urdf/` the
//! same way against Pinocchio's numbers. Bad input must come back as an
//! error that names it. The planar models (`two_link_muscles`, the gait
//! models) run as their 3-D equivalents at run time, whose layout is not
//! the compiled planar model's: they are not compared here.

use rodyn::algorithm::aba::aba;
use rodyn::algorithm::centroidal::{centroidal_map, CentroidalData};
use rodyn::algorithm::constrained_dynamics::{
    constrained_forward_dynamics, impulse_dynamics, ConstraintData, ConstraintSettings, Contact,
};
use rodyn::algorithm::crba::crba;
use rodyn::algorithm::derivatives::{aba_derivatives, rnea_derivatives, DerivativeData};
use rodyn::algorithm::energy::{center_of_mass, kinetic_energy, potential_energy};
use rodyn::algorithm::frame_chain::frame_jacobian_from_q;
use rodyn::algorithm::frames::{frame_placement, ReferenceFrame};
use rodyn::algorithm::jacobian::{
    frame_jacobian_time_variation, joint_jacobians_time_variation, JacobianData,
};
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::algorithm::rnea::{gravity_torques, nonlinear_effects, rnea};
use rodyn::space::VectorOps;
use rodyn::spatial::{Motion, Transform, Vec3};
use rodyn::{Data, Frame, Model};
use rodyn_host_tests::fixture::Fixture;
use rodyn_model::runtime::{ContactSpec, Reference, RuntimeErrorKind, RuntimeModel};
use std::path::{Path, PathBuf};

mod compiled {
    include!(concat!(env!("OUT_DIR"), "/pendulum.rs"));
    include!(concat!(env!("OUT_DIR"), "/panda.rs"));
    include!(concat!(env!("OUT_DIR"), "/aibo.rs"));
    include!(concat!(env!("OUT_DIR"), "/solo12.rs"));
    include!(concat!(env!("OUT_DIR"), "/wheeled_arm.rs"));
    include!(concat!(env!("OUT_DIR"), "/two_link_muscles.rs"));
}

/// Relative agreement: `|x - y|∞ ≤ 1e-12 max(1, |y|∞)`.
const TOLERANCE: f64 = 1e-12;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn assert_close(what: &str, x: &[f64], reference: &[f64], tolerance: f64) {
    assert_eq!(x.len(), reference.len(), "{what}: lengths");
    let scale = reference.iter().fold(1.0_f64, |m, r| m.max(r.abs()));
    let worst = x
        .iter()
        .zip(reference)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0_f64, f64::max);
    assert!(
        worst <= tolerance * scale,
        "{what}: differs by {worst:e} (scale {scale:e})\n  got {x:?}\n want {reference:?}"
    );
}

/// A small seeded generator for velocities and accelerations.
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
    fn vector(&mut self, n: usize) -> Vec<f64> {
        (0..n).map(|_| self.next()).collect()
    }
}

fn flat<const NV: usize>(m: &[[f64; NV]]) -> Vec<f64> {
    m.iter().flat_map(|r| r.iter().copied()).collect()
}

fn rows_linear_first<const NV: usize>(columns: &[Motion<f64>; NV]) -> Vec<f64> {
    let mut out = vec![0.0; 6 * NV];
    for (k, c) in columns.iter().enumerate() {
        for (r, x) in c.to_linear_first().into_iter().enumerate() {
            out[r * NV + k] = x;
        }
    }
    out
}

fn homogeneous(m: &Transform<f64>) -> [f64; 16] {
    let r = m.rot.m;
    [
        r[0][0], r[0][1], r[0][2], m.trans.x, r[1][0], r[1][1], r[1][2], m.trans.y, r[2][0],
        r[2][1], r[2][2], m.trans.z, 0.0, 0.0, 0.0, 1.0,
    ]
}

/// Every algorithm of `runtime` against the compiled `model` at a few
/// seeded states; `contact_frames` are held as points, then as frames.
#[allow(clippy::too_many_lines)]
fn agree<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model: &Model<f64, NB, NQ, NV>,
    frames: &[Frame<f64>],
    frame_names: &[&str],
    runtime: &RuntimeModel,
    contact_frames: &[usize],
) {
    assert_eq!((runtime.nq(), runtime.nv()), (NQ, NV), "{name}: sizes");
    assert_eq!(runtime.frame_names(), frame_names, "{name}: frame names");
    let mut ws = runtime.workspace();
    let mut data: Box<Data<f64, NB, NV>> = Box::default();
    let mut rng = Lcg(7);
    for seed in 0..4 {
        let what = |algorithm: &str| format!("{name} seed {seed}: {algorithm}");
        let q_vec = runtime.random_configuration(seed);
        let q: [f64; NQ] = q_vec.clone().try_into().unwrap();
        let v: [f64; NV] = rng.vector(NV).try_into().unwrap();
        let a: [f64; NV] = rng.vector(NV).try_into().unwrap();
        let tau: [f64; NV] = rng.vector(NV).try_into().unwrap();
        let mut out = vec![0.0; NV];

        runtime.rnea(&mut ws, &q, &v, &a, &mut out).unwrap();
        assert_close(
            &what("rnea"),
            &out,
            rnea(model, &mut data, &q, &v, &a, None).unwrap(),
            TOLERANCE,
        );
        runtime.aba(&mut ws, &q, &v, &tau, &mut out).unwrap();
        assert_close(
            &what("aba"),
            &out,
            aba(model, &mut data, &q, &v, &tau, None).unwrap(),
            TOLERANCE,
        );
        runtime
            .forward_dynamics_crba(&mut ws, &q, &v, &tau, &mut out)
            .unwrap();
        assert_close(
            &what("crba forward dynamics"),
            &out,
            aba(model, &mut data, &q, &v, &tau, None).unwrap(),
            1e-9,
        );
        runtime
            .nonlinear_effects(&mut ws, &q, &v, &mut out)
            .unwrap();
        assert_close(
            &what("nle"),
            &out,
            nonlinear_effects(model, &mut data, &q, &v, None).unwrap(),
            TOLERANCE,
        );
        runtime.gravity(&mut ws, &q, &mut out).unwrap();
        assert_close(
            &what("gravity"),
            &out,
            gravity_torques(model, &mut data, &q).unwrap(),
            TOLERANCE,
        );
        let mut m = vec![0.0; NV * NV];
        runtime.crba(&mut ws, &q, &mut m).unwrap();
        assert_close(
            &what("crba"),
            &m,
            &flat(&crba(model, &mut data, &q).unwrap()[..]),
            TOLERANCE,
        );

        let ke = runtime.kinetic_energy(&mut ws, &q, &v).unwrap();
        assert_close(
            &what("kinetic energy"),
            &[ke],
            &[kinetic_energy(model, &mut data, &q, &v).unwrap()],
            TOLERANCE,
        );
        let pe = runtime.potential_energy(&mut ws, &q).unwrap();
        assert_close(
            &what("potential energy"),
            &[pe],
            &[potential_energy(model, &mut data, &q).unwrap()],
            TOLERANCE,
        );
        let mut com = [0.0; 3];
        runtime.com(&mut ws, &q, &mut com).unwrap();
        let (c, _) = center_of_mass(model, &mut data, &q).unwrap();
        assert_close(&what("com"), &com, &[c.x, c.y, c.z], TOLERANCE);

        let mut cd: Box<CentroidalData<f64, NB, NV>> = Box::default();
        centroidal_map(model, &mut data, &mut cd, &q).unwrap();
        let mut ag_ref = vec![0.0; 6 * NV];
        for (k, col) in cd.ag.iter().enumerate() {
            for (r, x) in col.to_linear_first().into_iter().enumerate() {
                ag_ref[r * NV + k] = x;
            }
        }
        let mut ag = vec![0.0; 6 * NV];
        runtime.centroidal_map(&mut ws, &q, &mut ag).unwrap();
        assert_close(&what("centroidal map"), &ag, &ag_ref, TOLERANCE);

        forward_kinematics(model, &mut data, &q).unwrap();
        let mut jac: Box<JacobianData<f64, NV>> = Box::default();
        joint_jacobians_time_variation(model, &mut data, &mut jac, &q, &v).unwrap();
        for (frame, frame_name) in frames.iter().zip(frame_names) {
            let mut placement = [0.0; 16];
            runtime
                .frame_placement(&mut ws, &q, frame_name, &mut placement)
                .unwrap();
            let o_m_f = frame_placement(&data, frame).unwrap();
            assert_close(
                &what(&format!("placement of {frame_name}")),
                &placement,
                &homogeneous(&o_m_f),
                TOLERANCE,
            );
            for (reference, rodyn_reference) in [
                (Reference::Local, ReferenceFrame::Local),
                (Reference::World, ReferenceFrame::World),
                (
                    Reference::LocalWorldAligned,
                    ReferenceFrame::LocalWorldAligned,
                ),
            ] {
                let mut columns = [Motion::ZERO; NV];
                frame_jacobian_from_q(model, &q, frame, rodyn_reference, &mut columns).unwrap();
                let mut j = vec![0.0; 6 * NV];
                runtime
                    .frame_jacobian(&mut ws, &q, frame_name, reference, &mut j)
                    .unwrap();
                assert_close(
                    &what(&format!("J of {frame_name} {reference:?}")),
                    &j,
                    &rows_linear_first(&columns),
                    TOLERANCE,
                );
                frame_jacobian_time_variation(
                    model,
                    &data,
                    &jac,
                    frame,
                    rodyn_reference,
                    &mut columns,
                )
                .unwrap();
                runtime
                    .frame_jacobian_time_variation(&mut ws, &q, &v, frame_name, reference, &mut j)
                    .unwrap();
                assert_close(
                    &what(&format!("dJ of {frame_name} {reference:?}")),
                    &j,
                    &rows_linear_first(&columns),
                    TOLERANCE,
                );
            }
        }

        let mut deriv: Box<DerivativeData<f64, NB, NV>> = Box::default();
        let (mut d1, mut d2, mut d3) = (vec![0.0; NV * NV], vec![0.0; NV * NV], vec![0.0; NV * NV]);
        rnea_derivatives(model, &mut data, &mut deriv, &q, &v, &a, None).unwrap();
        runtime
            .rnea_derivatives(&mut ws, &q, &v, &a, &mut d1, &mut d2, &mut d3)
            .unwrap();
        assert_close(&what("dtau/dq"), &d1, &flat(&deriv.dtau_dq[..]), TOLERANCE);
        assert_close(&what("dtau/dv"), &d2, &flat(&deriv.dtau_dv[..]), TOLERANCE);
        assert_close(
            &what("dtau/da"),
            &d3,
            &flat(&data.mass_matrix[..]),
            TOLERANCE,
        );
        aba_derivatives(model, &mut data, &mut deriv, &q, &v, &tau, None).unwrap();
        runtime
            .aba_derivatives(&mut ws, &q, &v, &tau, &mut d1, &mut d2, &mut d3)
            .unwrap();
        assert_close(&what("dddq/dq"), &d1, &flat(&deriv.ddq_dq[..]), TOLERANCE);
        assert_close(&what("dddq/dv"), &d2, &flat(&deriv.ddq_dv[..]), TOLERANCE);
        assert_close(&what("minv"), &d3, &flat(&deriv.minv[..]), TOLERANCE);

        for six_d in [false, true] {
            // Frame contacts on every foot of a point-footed robot would
            // hold more directions than it has: one is enough.
            let contact_frames = if six_d {
                &contact_frames[..contact_frames.len().min(1)]
            } else {
                contact_frames
            };
            let held: Vec<Contact<f64>> = contact_frames
                .iter()
                .map(|&k| {
                    if six_d {
                        Contact::frame(frames[k], Transform::IDENTITY)
                    } else {
                        Contact::point(frames[k], Vec3::ZERO)
                    }
                })
                .collect();
            let specs: Vec<ContactSpec> = contact_frames
                .iter()
                .map(|&k| {
                    if six_d {
                        ContactSpec::frame(frame_names[k])
                    } else {
                        ContactSpec::point(frame_names[k])
                    }
                })
                .collect();
            let rows = rodyn::algorithm::constrained_dynamics::constrained_rows(&held);
            let mut cdata: Box<ConstraintData<f64, NV, 36>> = Box::default();
            let (ddq_ref, lambda_ref) = constrained_forward_dynamics(
                model,
                &mut data,
                &mut cdata,
                &q,
                &v,
                &tau,
                &held,
                &ConstraintSettings::default(),
            )
            .unwrap();
            let (ddq_ref, lambda_ref) = (ddq_ref.to_vec(), lambda_ref.to_vec());
            let (mut ddq, mut lambda) = (vec![0.0; NV], vec![0.0; rows]);
            runtime
                .constrained_dynamics(&mut ws, &q, &v, &tau, &specs, &mut ddq, &mut lambda)
                .unwrap();
            assert_close(
                &what(&format!("constrained ddq (6-D {six_d})")),
                &ddq,
                &ddq_ref,
                TOLERANCE,
            );
            assert_close(
                &what(&format!("constrained lambda (6-D {six_d})")),
                &lambda,
                &lambda_ref,
                TOLERANCE,
            );
            let (v_ref, impulse_ref) =
                impulse_dynamics(model, &mut data, &mut cdata, &q, &v, &held, 0.5, 0.0).unwrap();
            let (v_ref, impulse_ref) = (v_ref.to_vec(), impulse_ref.to_vec());
            runtime
                .impulse_dynamics(&mut ws, &q, &v, &specs, 0.5, &mut ddq, &mut lambda)
                .unwrap();
            assert_close(
                &what(&format!("impulse v+ (6-D {six_d})")),
                &ddq,
                &v_ref,
                TOLERANCE,
            );
            assert_close(
                &what(&format!("impulses (6-D {six_d})")),
                &lambda,
                &impulse_ref,
                TOLERANCE,
            );
        }
    }
}

/// The run-time model's drives against the compiled module's elements:
/// forward dynamics under the drives and the drives' generalized forces
/// `τ_drive + Σ Jᵀ f_drive` (the compiled side's as `g(q) − RNEA(q, 0, 0, f)`),
/// at seeded states and inputs `w` in `[0, 1]` (activations, currents in A).
fn drives_agree<E, G, const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model: &Model<f64, NB, NQ, NV, G>,
    elements: &E,
    nu: usize,
    runtime: &RuntimeModel,
) where
    G: rodyn::space::Space,
    E: rodyn::drive::ForceElement<f64, G, NB, NV>,
{
    use rodyn::algorithm::forward_dynamics::Aba;
    use rodyn::drive::{drive_forces, forward_dynamics_with_drives, DriveForces};
    assert_eq!(runtime.nu(), nu, "{name}: drive inputs");
    let mut ws = runtime.workspace();
    let mut data: Box<Data<f64, NB, NV, G>> = Box::default();
    let mut forces: Box<DriveForces<f64, G, NB, NV>> = Box::default();
    let mut rng = Lcg(11);
    for seed in 0..4 {
        let what = |quantity: &str| format!("{name} seed {seed}: {quantity}");
        let q: [f64; NQ] = runtime.random_configuration(seed).try_into().unwrap();
        let v: [f64; NV] = rng.vector(NV).try_into().unwrap();
        let tau: [f64; NV] = rng.vector(NV).try_into().unwrap();
        let w: Vec<f64> = rng.vector(nu).iter().map(|x| 0.5 + 0.5 * x).collect();
        let mut out = vec![0.0; NV];

        runtime
            .aba_with_drives(&mut ws, &q, &v, &tau, &w, &mut out)
            .unwrap();
        let ddq = forward_dynamics_with_drives::<Aba, _, _, _, NB, NQ, NV>(
            model,
            &mut data,
            &q,
            &v,
            &tau,
            elements,
            &w,
            &mut forces,
        )
        .unwrap();
        assert_close(&what("aba with drives"), &out, ddq, TOLERANCE);

        runtime
            .drive_generalized_forces(&mut ws, &q, &v, &w, &mut out)
            .unwrap();
        drive_forces(model, &mut data, &q, &v, elements, &w, &mut forces).unwrap();
        let zero = [0.0; NV];
        let held = *gravity_torques(model, &mut data, &q).unwrap();
        let pulled = rnea(model, &mut data, &q, &zero, &zero, Some(&forces.f_ext)).unwrap();
        let reference: Vec<f64> = (0..NV)
            .map(|k| forces.tau[k] + (held[k] - pulled[k]))
            .collect();
        assert!(
            reference.iter().any(|x| x.abs() > 1e-3),
            "{}: the drives pull",
            what("generalized forces")
        );
        assert_close(&what("generalized forces"), &out, &reference, TOLERANCE);
    }
}

#[test]
fn pendulum_spring_agrees_with_the_compiled_drive() {
    use compiled::pendulum as m;
    let runtime = load("pendulum.toml");
    assert_eq!(runtime.drive_names(), ["return_spring"]);
    drives_agree(
        "pendulum",
        &m::MODEL_F64,
        &m::RETURN_SPRING_F64,
        m::NU,
        &runtime,
    );
}

#[test]
fn panda_motors_agree_with_the_compiled_drives() {
    use compiled::panda as m;
    let runtime = load("panda.toml");
    let motors = [
        m::MOTOR1_F64,
        m::MOTOR2_F64,
        m::MOTOR3_F64,
        m::MOTOR4_F64,
        m::MOTOR5_F64,
        m::MOTOR6_F64,
        m::MOTOR7_F64,
    ];
    drives_agree("panda", &m::MODEL_F64, &motors, m::NU, &runtime);
    assert_eq!(runtime.drive_input_names()[m::input::MOTOR3], "motor3");
    for ((name, motor), compiled) in runtime.motors().iter().zip(&motors) {
        assert_eq!(motor, compiled, "{name}");
        assert_eq!(
            motor.reflected_inertia().unwrap(),
            compiled.reflected_inertia().unwrap(),
            "{name}: reflected inertia"
        );
        assert_eq!(
            motor.torque_per_current().unwrap(),
            compiled.torque_per_current().unwrap(),
            "{name}: torque per ampere"
        );
    }
}

/// The planar muscle arm runs at run time as its 3-D equivalent (joints
/// about z, the same two coordinates): its muscles must pull the same.
#[test]
fn two_link_muscles_agree_with_the_compiled_drives() {
    use compiled::two_link_muscles as m;
    let runtime = load("two_link_muscles.toml");
    let muscles = [m::M1_F64, m::M2_F64, m::M3_F64, m::M4_F64];
    drives_agree("two_link_muscles", &m::MODEL_F64, &muscles, m::NU, &runtime);
}

#[test]
fn drive_inputs_are_checked_by_name() {
    let runtime = load("two_link_muscles.toml");
    let mut ws = runtime.workspace();
    let q = runtime.neutral();
    let v = vec![0.0; runtime.nv()];
    let mut out = vec![0.0; runtime.nv()];
    let err = runtime
        .drive_generalized_forces(&mut ws, &q, &v, &[0.5; 3], &mut out)
        .unwrap_err();
    assert_eq!(err.to_string(), "w has 3 entries, the model has nu = 4");
    let err = runtime
        .aba_with_drives(&mut ws, &q, &v, &v, &[0.5, 0.5, f64::NAN, 0.5], &mut out)
        .unwrap_err();
    assert_eq!(err.kind(), RuntimeErrorKind::InvalidInput);
    assert_eq!(err.to_string(), "w[2] is NaN");
}

fn load(file: &str) -> RuntimeModel {
    RuntimeModel::from_file(&root().join("models").join(file)).unwrap()
}

#[test]
fn pendulum_agrees_with_its_compiled_model() {
    use compiled::pendulum as m;
    agree(
        "pendulum",
        &m::MODEL_F64,
        &m::FRAMES_F64,
        &m::FRAME_NAMES,
        &load("pendulum.toml"),
        &[],
    );
}

#[test]
fn panda_agrees_with_its_compiled_model() {
    use compiled::panda as m;
    let last = m::NF - 1;
    agree(
        "panda",
        &m::MODEL_F64,
        &m::FRAMES_F64,
        &m::FRAME_NAMES,
        &load("panda.toml"),
        &[last],
    );
}

#[test]
fn aibo_agrees_with_its_compiled_model() {
    use compiled::aibo as m;
    agree(
        "aibo",
        &m::MODEL_F64,
        &m::FRAMES_F64,
        &m::FRAME_NAMES,
        &load("aibo.toml"),
        &[],
    );
}

#[test]
fn solo12_agrees_with_its_compiled_model() {
    use compiled::solo12 as m;
    let feet: Vec<usize> = ["FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"]
        .iter()
        .map(|f| m::FRAME_NAMES.iter().position(|n| n == f).unwrap())
        .collect();
    agree(
        "solo12",
        &m::MODEL_F64,
        &m::FRAMES_F64,
        &m::FRAME_NAMES,
        &load("solo12.toml"),
        &feet,
    );
}

#[test]
fn wheeled_arm_agrees_with_its_compiled_model() {
    use compiled::wheeled_arm as m;
    let path = root().join("crates/rodyn-model/generated-tests/urdf/wheeled_arm.urdf");
    let runtime = RuntimeModel::from_urdf(&path, true).unwrap();
    agree(
        "wheeled_arm",
        &m::MODEL_F64,
        &m::FRAMES_F64,
        &m::FRAME_NAMES,
        &runtime,
        &[],
    );
}

/// The URDFs of `models/urdf/` against Pinocchio's results (the fixtures
/// the compiled path is checked with, at the same tolerance).
#[test]
fn urdf_models_agree_with_pinocchio() {
    let fixtures = root().join("host-tests/fixtures");
    let mut checked = 0;
    for entry in std::fs::read_dir(&fixtures).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("json") {
            continue;
        }
        let name = path.file_stem().unwrap().to_str().unwrap().to_string();
        let fixture = Fixture::load(&path).unwrap();
        let floating = fixture.model.nq != fixture.model.nv;
        let urdf = root().join("models/urdf").join(format!("{name}.urdf"));
        let mut runtime = RuntimeModel::from_urdf(&urdf, floating).unwrap();
        runtime.set_gravity(fixture.model.gravity).unwrap();
        let nv = runtime.nv();
        let mut ws = runtime.workspace();
        for (k, s) in fixture.states.iter().enumerate() {
            let what = |a: &str| format!("{name} state {k}: {a}");
            let mut out = vec![0.0; nv];
            let tolerance = 1e-9;
            runtime.rnea(&mut ws, &s.q, &s.v, &s.a, &mut out).unwrap();
            assert_close(&what("rnea"), &out, &s.rnea, tolerance);
            runtime.aba(&mut ws, &s.q, &s.v, &s.tau, &mut out).unwrap();
            assert_close(&what("aba"), &out, &s.aba, tolerance);
            runtime
                .nonlinear_effects(&mut ws, &s.q, &s.v, &mut out)
                .unwrap();
            assert_close(&what("nle"), &out, &s.nonlinear_effects, tolerance);
            runtime.gravity(&mut ws, &s.q, &mut out).unwrap();
            assert_close(&what("gravity"), &out, &s.gravity_torques, tolerance);
            let mut m = vec![0.0; nv * nv];
            runtime.crba(&mut ws, &s.q, &mut m).unwrap();
            let m_ref: Vec<f64> = s.mass_matrix.iter().flatten().copied().collect();
            assert_close(&what("crba"), &m, &m_ref, tolerance);
            let ke = runtime.kinetic_energy(&mut ws, &s.q, &s.v).unwrap();
            assert_close(
                &what("kinetic energy"),
                &[ke],
                &[s.kinetic_energy],
                tolerance,
            );
            let mut com = [0.0; 3];
            runtime.com(&mut ws, &s.q, &mut com).unwrap();
            assert_close(&what("com"), &com, &s.center_of_mass, tolerance);
        }
        checked += 1;
    }
    assert!(checked >= 10, "only {checked} fixtures found");
}

#[test]
fn bad_input_is_an_error_that_names_it() {
    let panda = load("panda.toml");
    let mut ws = panda.workspace();
    let q = panda.neutral();
    let v = vec![0.0; 7];
    let mut out = vec![0.0; 7];
    let err = |r: Result<(), rodyn_model::runtime::RuntimeError>| r.unwrap_err();

    let e = err(panda.rnea(&mut ws, &q[..6], &v, &v, &mut out));
    assert_eq!(e.to_string(), "q has 6 entries, the model has nq = 7");
    assert_eq!(e.kind(), RuntimeErrorKind::InvalidInput);
    let e = err(panda.aba(&mut ws, &q, &v, &v[..3], &mut out));
    assert_eq!(e.to_string(), "tau has 3 entries, the model has nv = 7");
    let mut bad_v = v.clone();
    bad_v[3] = f64::NAN;
    let e = err(panda.rnea(&mut ws, &q, &bad_v, &v, &mut out));
    assert_eq!(e.to_string(), "v[3] is NaN");
    let mut bad_q = q.clone();
    bad_q[5] = f64::INFINITY;
    assert_eq!(
        err(panda.aba(&mut ws, &bad_q, &v, &v, &mut out)).to_string(),
        "q[5] is infinite"
    );
    let mut placement = [0.0; 16];
    let e = err(panda.frame_placement(&mut ws, &q, "foo", &mut placement));
    assert_eq!(e.to_string(), "unknown frame 'foo'");
    let mut j = vec![0.0; 6 * 7 - 1];
    let frame = panda.frame_names()[0].clone();
    let e = err(panda.frame_jacobian(&mut ws, &q, &frame, Reference::Local, &mut j));
    assert_eq!(
        e.to_string(),
        "out has 41 entries, it must have 6 x nv = 42"
    );

    // A free-flyer's quaternion off the unit sphere names the joint.
    let solo = load("solo12.toml");
    let mut ws_solo = solo.workspace();
    let mut q = solo.neutral();
    q[6] = 2.0;
    let (v, mut out) = (vec![0.0; 18], vec![0.0; 18]);
    let e = err(solo.rnea(&mut ws_solo, &q, &v, &v, &mut out));
    assert!(e.to_string().starts_with("q: joint 'root_joint'"), "{e}");
    // A workspace of another model.
    let e = err(solo.rnea(&mut ws, &solo.neutral(), &v, &v, &mut out));
    assert!(e.to_string().contains("another model"), "{e}");
    // Too many contact rows, an unknown contact frame.
    let feet: Vec<ContactSpec> = (0..7).map(|_| ContactSpec::frame("FL_FOOT")).collect();
    let mut lambda = vec![0.0; 42];
    let mut ddq = vec![0.0; 18];
    let e = err(solo.constrained_dynamics(
        &mut ws_solo,
        &solo.neutral(),
        &v,
        &v,
        &feet,
        &mut ddq,
        &mut lambda,
    ));
    assert!(e.to_string().contains("42 rows"), "{e}");
    let e = err(solo.constrained_dynamics(
        &mut ws_solo,
        &solo.neutral(),
        &v,
        &v,
        &[ContactSpec::point("nowhere")],
        &mut ddq,
        &mut lambda[..3],
    ));
    assert_eq!(e.to_string(), "unknown frame 'nowhere'");
}

#[test]
fn inverse_kinematics_reaches_a_reachable_placement() {
    let panda = load("panda.toml");
    let mut ws = panda.workspace();
    let frame = panda.frame_names().last().unwrap().clone();
    let goal = panda.random_configuration(3);
    let mut target = [0.0; 16];
    panda
        .frame_placement(&mut ws, &goal, &frame, &mut target)
        .unwrap();
    // Start near the goal: damped least squares converges locally.
    let mut q: Vec<f64> = goal.iter().map(|x| x + 0.1).collect();
    panda
        .inverse_kinematics(&mut ws, &frame, &target, 1e-10, 200, &mut q)
        .unwrap();
    let mut reached = [0.0; 16];
    panda
        .frame_placement(&mut ws, &q, &frame, &mut reached)
        .unwrap();
    assert_close("reached placement", &reached, &target, 1e-8);
}
