//! Every model shipped in `models/`, compiled by the build script: it
//! validates, its sizes and names are what the file says, and its numbers
//! give the dynamics they should.

use rodyn::algorithm::kinematics::forward_kinematics_velocity;
use rodyn::algorithm::rnea::gravity_torques;
use rodyn::spatial::{Inertia, Sym3, Vec3};
use rodyn::Data;
use rodyn_model_generated_tests::{
    aibo, gait_planar, panda, panda_with_motors, pendulum, solo12_with_contacts, two_link_muscles,
};

#[test]
fn every_shipped_model_validates_in_both_scalar_types() {
    pendulum::MODEL_F64.validate().unwrap();
    pendulum::MODEL_F32.validate().unwrap();
    two_link_muscles::MODEL_F64.validate().unwrap();
    two_link_muscles::MODEL_F32.validate().unwrap();
    gait_planar::MODEL_F64.validate().unwrap();
    gait_planar::MODEL_F32.validate().unwrap();
    aibo::MODEL_F64.validate().unwrap();
    aibo::MODEL_F32.validate().unwrap();
    panda_with_motors::MODEL_F64.validate().unwrap();
    panda_with_motors::MODEL_F32.validate().unwrap();
    solo12_with_contacts::MODEL_F64.validate().unwrap();
    solo12_with_contacts::MODEL_F32.validate().unwrap();
}

#[test]
fn sizes_and_names_follow_the_files() {
    assert_eq!(
        (pendulum::NB, pendulum::NQ, pendulum::NV, pendulum::NE),
        (1, 1, 1, 2)
    );
    assert_eq!(
        (
            two_link_muscles::NB,
            two_link_muscles::NV,
            two_link_muscles::NU
        ),
        (2, 2, 4)
    );
    // Eight segments, seven revolute joints on a planar floating pelvis.
    assert_eq!(
        (gait_planar::NB, gait_planar::NQ, gait_planar::NV),
        (8, 10, 10)
    );
    assert_eq!(gait_planar::v::SACROILIAC, 3);
    // Floating base (7 + 6) and three joints per leg.
    assert_eq!((aibo::NB, aibo::NQ, aibo::NV, aibo::NC), (13, 19, 18, 4));
    assert_eq!(
        aibo::ENDPOINTS_F64[aibo::endpoint::HR_FOOT].body,
        Some(aibo::body::HR_SHANK)
    );
    // The Panda's merged links are endpoints on panda_link7.
    let tcp = panda_with_motors::ENDPOINTS_F64[panda_with_motors::endpoint::PANDA_HAND_TCP];
    assert_eq!(tcp.body, Some(panda_with_motors::body::PANDA_LINK7));
    assert_eq!(
        panda_with_motors::MOTOR4_F64.dof,
        panda_with_motors::v::PANDA_JOINT4
    );
    assert_eq!(solo12_with_contacts::NC, 4);
}

#[test]
fn the_prosthetic_side_is_marked() {
    let socket = gait_planar::ENDPOINTS_F64[gait_planar::endpoint::SOCKET];
    assert_eq!(socket.body, Some(gait_planar::body::R_THIGH));
    assert_eq!(
        gait_planar::MODEL_F64.parent(gait_planar::body::R_SHANK),
        Some(gait_planar::body::R_THIGH)
    );
}

#[test]
fn gait_model_masses_follow_winters_table() {
    // Winter (2009) Table 4.1 fractions of 75 kg, summing to the whole body.
    let m = gait_planar::MODEL_F64.total_mass();
    assert!((m - 75.0).abs() < 1e-9, "{m}");
    let thigh = gait_planar::MODEL_F64.inertia(gait_planar::body::L_THIGH);
    assert!((thigh.mass - 7.5).abs() < 1e-12);
    // Radius of gyration 0.1385 m: I = m r².
    assert!((thigh.izz - 7.5 * 0.1385 * 0.1385).abs() < 1e-12);
}

#[test]
fn aibo_is_about_one_and_a_half_kilograms_in_millimetres() {
    // Lengths in the file are mm; the model is in metres.
    let m = aibo::MODEL_F64.total_mass();
    assert!((m - 1.6).abs() < 1e-9, "{m}");
    let knee = aibo::MODEL_F64.placement(aibo::body::FL_SHANK);
    assert!((knee.trans.z + 0.0695).abs() < 1e-15);
    let foot = aibo::ENDPOINTS_F64[aibo::endpoint::FL_FOOT];
    assert!((foot.position.z + 0.076).abs() < 1e-15);
}

/// The two-link robot's muscles are routed so that every fibre is near its
/// optimal length with the arm hanging (`q = 0`): path lengths of 0.228,
/// 0.228, 0.400 and 0.522 m, each the tendon's slack length plus a fibre
/// within 10 % of its optimal length.
#[test]
fn two_link_robot_fibres_are_near_optimal_when_hanging() {
    let model = two_link_muscles::MODEL_F64;
    let mut data = Data::new();
    forward_kinematics_velocity(&model, &mut data, &[0.0; 2], &[0.0; 2]).unwrap();
    let muscles = [
        two_link_muscles::M1_F64,
        two_link_muscles::M2_F64,
        two_link_muscles::M3_F64,
        two_link_muscles::M4_F64,
    ];
    for (k, (muscle, expected)) in muscles.iter().zip([0.228, 0.228, 0.400, 0.522]).enumerate() {
        assert_eq!(muscle.input, k);
        let length = muscle.path.kinematics(&data).unwrap().length;
        assert!((length - expected).abs() < 1e-3, "m{}: {length} m", k + 1);
        let fibre = length - muscle.params.tendon_slack_length;
        let stretch = fibre / muscle.params.optimal_fiber_length;
        assert!((stretch - 1.0).abs() < 0.1, "m{}: l/l0 = {stretch}", k + 1);
    }
}

/// Contacts are `rodyn::sim` ground laws at the file's endpoints, ready for
/// `GroundContact::add_forces`: a foot 1 mm deep carries k δ.
#[test]
fn aibo_contacts_are_ground_contacts_at_the_feet() {
    use rodyn::sim::contact::NormalLaw;
    for c in 0..aibo::NC {
        let ground = aibo::CONTACTS_F64[c];
        assert_eq!(
            ground.normal,
            NormalLaw::LinearSpringDamper {
                stiffness: 5.0e3,
                damping: 50.0
            }
        );
        assert_eq!(ground.friction, 0.8);
        let foot = aibo::CONTACT_POINTS_F64[c];
        assert_eq!(foot, aibo::ENDPOINTS_F64[aibo::CONTACT_ENDPOINTS[c]]);
    }
    assert_eq!(
        aibo::CONTACT_ENDPOINTS[aibo::contact::HR_FOOT_CONTACT],
        aibo::endpoint::HR_FOOT
    );
    let ground = aibo::CONTACTS_F32[aibo::contact::FL_FOOT_CONTACT];
    let force = ground
        .force_at(&Vec3::new(0.0, 0.0, -1.0e-3), &Vec3::ZERO)
        .unwrap();
    assert!((force.z - 5.0).abs() < 1e-5, "{}", force.z);
    assert_eq!((force.x, force.y), (0.0, 0.0));
}

/// On-line parameter change: a payload on the Panda's last body changes the
/// gravity torques by exactly the payload's weight times its lever arms.
#[test]
fn a_payload_changes_the_gravity_torques_by_its_weight() {
    let mut model = panda::MODEL_F64;
    let mut data = Data::new();
    let q = [0.3, -0.5, 0.2, -1.8, 0.1, 1.4, 0.6];
    let before = *gravity_torques(&model, &mut data, &q).unwrap();

    // 1.5 kg point payload 0.1 m beyond the flange on panda_link7's z axis.
    let last = panda::body::PANDA_LINK7;
    let payload_mass = 1.5;
    let payload_at = Vec3::new(0.0, 0.0, 0.107 + 0.1);
    let old = *model.inertia(last);
    let payload = Inertia::new(payload_mass, payload_at, Sym3::ZERO);
    use rodyn::space::BodyInertia;
    model.set_inertia(last, old.combine(&payload)).unwrap();
    let after = *gravity_torques(&model, &mut data, &q).unwrap();

    // Expected change: tau_j += -(z_j x (p - o_j)) . (m g) for each revolute
    // joint j, with z_j the world axis and o_j the world origin of joint j.
    // Body poses come from forward kinematics (RNEA does not compute them).
    use rodyn::space::RigidTransform;
    rodyn::algorithm::kinematics::forward_kinematics(&model, &mut data, &q).unwrap();
    let g = Vec3::new(0.0, 0.0, -9.81);
    let p = data.o_m_i[last].act_point(&payload_at);
    for j in 0..panda::NV {
        let x = &data.o_m_i[j];
        let axis = x.rot.column(2); // every Panda joint turns about its z
        let lever = Vec3::new(p.x - x.trans.x, p.y - x.trans.y, p.z - x.trans.z);
        let expected = -axis.cross(&lever).dot(&g.scale(payload_mass));
        let got = after[j] - before[j];
        assert!(
            (got - expected).abs() < 1e-9,
            "joint {j}: {got} vs {expected}"
        );
    }
    // The heaviest change is real: at least some N m on the shoulder.
    assert!((after[1] - before[1]).abs() > 0.5);
    // An impossible payload is refused and leaves the model unchanged.
    let negative = Inertia::new(-1.0, payload_at, Sym3::ZERO);
    assert!(model.set_inertia(last, negative).is_err());
    let again = *gravity_torques(&model, &mut data, &q).unwrap();
    assert_eq!(again, after);
}

#[test]
fn pendulum_endpoints_and_spring() {
    let tip = pendulum::ENDPOINTS_F64[pendulum::endpoint::TIP];
    assert_eq!(tip.body, Some(pendulum::body::LINK));
    assert_eq!(tip.position, Vec3::new(0.0, -1.0, 0.0));
    let anchor = pendulum::ENDPOINTS_F64[pendulum::endpoint::ANCHOR];
    assert_eq!(anchor.body, None);
    assert_eq!(pendulum::RETURN_SPRING_F64.stiffness, 20.0);
    assert_eq!(pendulum::RETURN_SPRING_F32.rest_length, 0.3_f32);
}
