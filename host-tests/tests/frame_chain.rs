//! One frame's kinematics from q along its chain
//! (`rodyn::algorithm::frame_chain`) against the all-joints path
//! (`joint_jacobians_time_variation`, then `frame_jacobian`,
//! `frame_jacobian_time_variation` times v, `frame_velocity`,
//! `frame_placement`), and the tuned forms against the book's
//! (`frame_chain::plain`), on every robot of the Pinocchio fixtures: the
//! UR5, the Panda, Solo12, the branched tree, and ANYmal, the Unitree G1
//! and Talos (`fixtures/frame_chain/`), a frame with a random placement on
//! every body, in each reference frame; and for the last three, the
//! chain's Jacobians of their feet, hands and grippers against Pinocchio's
//! `computeFrameJacobian` (1e-12).
//!
//! Each error is `‖x − x_ref‖∞ / max(‖x_ref‖∞, 1)` over a Jacobian's
//! entries, a velocity, `J̇ v` or a placement: at most 1e-14 in f64, and
//! 5e-6 in f32 against the f32 all-joints path (both round in f32; the
//! worst measured is printed with `--nocapture`).

use rodyn::algorithm::frame_chain::{
    chain_jacobian, chain_kinematics, chains_jacobians, frame_jacobian_from_q,
    frame_kinematics_from_q, plain, FrameChain,
};
use rodyn::algorithm::frames::{frame_placement, frame_velocity, ReferenceFrame};
use rodyn::algorithm::jacobian::{
    frame_jacobian, frame_jacobian_time_variation, joint_jacobians_time_variation, mul_rates,
    to_linear_first, JacobianData,
};
use rodyn::prelude::*;
use rodyn::{Error, Frame};
use rodyn_host_tests::fixture::Fixture;
use rodyn_host_tests::frame_chain_fixture::{load, FrameChainFixture, ANYMAL, G1, TALOS};
use rodyn_host_tests::random::Rng;

const REFERENCES: [ReferenceFrame; 3] = [
    ReferenceFrame::Local,
    ReferenceFrame::World,
    ReferenceFrame::LocalWorldAligned,
];

const F64_TOLERANCE: f64 = 1e-14;
const F32_TOLERANCE: f64 = 5e-6;
/// rodyn's f64 Jacobians against Pinocchio's (different rounding).
const PINOCCHIO_TOLERANCE: f64 = 1e-12;

/// The largest error seen, and where.
#[derive(Default)]
struct Worst {
    error: f64,
    at: String,
}

impl Worst {
    fn add(&mut self, x: &[f64], reference: &[f64], at: impl FnOnce() -> String) {
        assert_eq!(x.len(), reference.len());
        let scale = reference.iter().fold(1.0_f64, |m, r| m.max(r.abs()));
        let diff = x
            .iter()
            .zip(reference)
            .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        let e = if diff.is_nan() {
            f64::INFINITY
        } else {
            diff / scale
        };
        if e > self.error || (e.is_infinite() && self.at.is_empty()) {
            self.error = e;
            self.at = at();
        }
    }
}

fn motions<S: Scalar>(m: &[Motion<S>]) -> Vec<f64> {
    m.iter()
        .flat_map(|c| c.to_linear_first())
        .map(|x| x.to_f64())
        .collect()
}

fn placement<S: Scalar>(x: &Transform<S>) -> Vec<f64> {
    let mut out: Vec<f64> = x.rot.m.iter().flatten().map(|v| v.to_f64()).collect();
    out.extend(x.trans.to_array().iter().map(|v| v.to_f64()));
    out
}

/// Every body's frame (a random placement each), every state, every
/// reference frame: the chain's results against the all-joints path's
/// and the plain forms'. Returns the worst error.
fn compare<S: Scalar, const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    model: &Model<f64, NB, NQ, NV>,
    states: &[QV<NQ, NV>],
) -> f64 {
    let model = model.cast::<S>().unwrap();
    let mut rng = Rng::new(0xC4A1);
    let frames: Vec<Frame<S>> = (0..NB)
        .map(|b| Frame::new(b, rng.placement().cast::<S>()))
        .collect();
    let mut data = Box::new(Data::<S, NB, NV>::new());
    let mut jac = Box::new(JacobianData::<S, NV>::new());
    let mut worst = Worst::default();
    for (s, (q, v)) in states.iter().enumerate() {
        let q: [S; NQ] = q.map(S::from_f64);
        let v: [S; NV] = v.map(S::from_f64);
        joint_jacobians_time_variation(&model, &mut data, &mut jac, &q, &v).unwrap();
        for frame in &frames {
            let chain = FrameChain::try_new(&model, frame).unwrap();
            for reference in REFERENCES {
                let at = || format!("{name} state {s} body {} {reference:?}", frame.body);
                let mut all = [Motion::<S>::ZERO; NV];
                frame_jacobian(&model, &data, &jac, frame, reference, &mut all).unwrap();
                let mut dj = [Motion::<S>::ZERO; NV];
                frame_jacobian_time_variation(&model, &data, &jac, frame, reference, &mut dj)
                    .unwrap();
                let dj_v = mul_rates::<S, NV, Spatial>(&dj, &v).unwrap();
                let velocity = frame_velocity(&data, frame, reference).unwrap();
                let o_m_f = frame_placement(&data, frame).unwrap();

                let mut j = [Motion::<S>::ZERO; NV];
                let x = chain_jacobian(&model, &q, &chain, reference, &mut j).unwrap();
                worst.add(&motions(&j), &motions(&all), || format!("{} J", at()));
                worst.add(&placement(&x), &placement(&o_m_f), || format!("{} M", at()));
                let mut j_from_q = [Motion::<S>::ZERO; NV];
                let x_from_q =
                    frame_jacobian_from_q(&model, &q, frame, reference, &mut j_from_q).unwrap();
                assert_eq!((j_from_q, x_from_q), (j, x), "{}", at());

                let mut jp = [Motion::<S>::ZERO; NV];
                let xp = plain::chain_jacobian(&model, &q, &chain, reference, &mut jp).unwrap();
                worst.add(&motions(&jp), &motions(&all), || {
                    format!("{} plain J", at())
                });
                worst.add(&motions(&j), &motions(&jp), || {
                    format!("{} J vs plain", at())
                });
                worst.add(&placement(&xp), &placement(&x), || {
                    format!("{} M vs plain", at())
                });

                let mut jk = [Motion::<S>::ZERO; NV];
                let m = chain_kinematics(&model, &q, &v, &chain, reference, &mut jk).unwrap();
                assert_eq!(jk, j, "{}: the Jacobian of chain_kinematics", at());
                assert_eq!(m.placement, x, "{}", at());
                worst.add(&motions(&[m.velocity]), &motions(&[velocity]), || {
                    format!("{} J v", at())
                });
                worst.add(&motions(&[m.dj_v]), &motions(&[dj_v]), || {
                    format!("{} dJ v", at())
                });
                let mut jk_from_q = [Motion::<S>::ZERO; NV];
                let m_from_q =
                    frame_kinematics_from_q(&model, &q, &v, frame, reference, &mut jk_from_q)
                        .unwrap();
                assert_eq!((m_from_q, jk_from_q), (m, jk), "{}", at());

                let mut jkp = [Motion::<S>::ZERO; NV];
                let mp =
                    plain::chain_kinematics(&model, &q, &v, &chain, reference, &mut jkp).unwrap();
                worst.add(&motions(&[mp.velocity]), &motions(&[velocity]), || {
                    format!("{} plain J v", at())
                });
                worst.add(&motions(&[mp.dj_v]), &motions(&[dj_v]), || {
                    format!("{} plain dJ v", at())
                });
                worst.add(&motions(&[m.dj_v]), &motions(&[mp.dj_v]), || {
                    format!("{} dJ v vs plain", at())
                });
            }
        }
        // Every pair of frames, and the last four bodies' frames together,
        // as a set against one at a time.
        let chains: Vec<FrameChain<S, NB>> = frames
            .iter()
            .map(|f| FrameChain::try_new(&model, f).unwrap())
            .collect();
        for reference in REFERENCES {
            for a in 0..NB {
                let b = (a * 7 + 3) % NB;
                check_set(
                    &model,
                    &mut data,
                    &q,
                    &[chains[a], chains[b]],
                    reference,
                    &mut worst,
                );
            }
            if NB >= 4 {
                let last4: [FrameChain<S, NB>; 4] = core::array::from_fn(|k| chains[NB - 4 + k]);
                check_set(&model, &mut data, &q, &last4, reference, &mut worst);
            }
        }
    }
    println!("{name}: worst {:.2e} at {}", worst.error, worst.at);
    worst.error
}

fn check_set<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, const N: usize>(
    model: &Model<S, NB, NQ, NV>,
    data: &mut Data<S, NB, NV>,
    q: &[S; NQ],
    chains: &[FrameChain<S, NB>; N],
    reference: ReferenceFrame,
    worst: &mut Worst,
) {
    let mut set = Box::new([[Motion::<S>::ZERO; NV]; N]);
    let placements = chains_jacobians(model, data, q, chains, reference, &mut set).unwrap();
    for (f, chain) in chains.iter().enumerate() {
        let mut one = [Motion::<S>::ZERO; NV];
        let x = chain_jacobian(model, q, chain, reference, &mut one).unwrap();
        let at = || {
            format!(
                "set of {N}, frame on body {} {reference:?}",
                chain.frame().body
            )
        };
        worst.add(&motions(&set[f]), &motions(&one), || format!("{} J", at()));
        worst.add(&placement(&placements[f]), &placement(&x), || {
            format!("{} M", at())
        });
    }
}

/// A state's `(q, v)`.
type QV<const NQ: usize, const NV: usize> = ([f64; NQ], [f64; NV]);

/// A fixture's states as arrays.
fn fixture_states<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
) -> (Model<f64, NB, NQ, NV>, Vec<QV<NQ, NV>>) {
    let fixture = Fixture::load_named(name).unwrap();
    let model = fixture.model::<NB, NQ, NV>().unwrap();
    let states = fixture
        .states
        .iter()
        .map(|s| {
            let a = s.arrays::<f64, NB, NQ, NV>().unwrap();
            (a.q, a.v)
        })
        .collect();
    (model, states)
}

macro_rules! fixture_tests {
    ($(($id:ident, $name:literal, $nb:literal, $nq:literal, $nv:literal)),* $(,)?) => {
        $(
            #[test]
            fn $id() {
                let (model, states) = fixture_states::<$nb, $nq, $nv>($name);
                assert!(!states.is_empty());
                let e64 = compare::<f64, $nb, $nq, $nv>($name, &model, &states);
                let e32 = compare::<f32, $nb, $nq, $nv>($name, &model, &states);
                assert!(e64 <= F64_TOLERANCE, "{}: f64 {e64:e}", $name);
                assert!(e32 <= F32_TOLERANCE, "{}: f32 {e32:e}", $name);
            }
        )*
    };
}

fixture_tests! {
    (ur5, "ur5", 6, 6, 6),
    (panda, "panda", 7, 7, 7),
    (solo12, "solo12", 13, 19, 18),
    (branched_tree, "branched_tree", 13, 13, 13),
}

/// The chain's Jacobians of the frames a controller asks for (feet,
/// hands, grippers) against Pinocchio's `computeFrameJacobian`, in every
/// reference frame: the worst `‖x − x_ref‖∞ / max(‖x_ref‖∞, 1)`.
fn against_pinocchio<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
    fixture: &FrameChainFixture<NB, NQ, NV>,
) -> f64 {
    let mut worst = Worst::default();
    for (s, state) in fixture.states.iter().enumerate() {
        for (f, (frame_name, frame)) in fixture.frames.iter().enumerate() {
            for (r, reference) in [
                ReferenceFrame::Local,
                ReferenceFrame::World,
                ReferenceFrame::LocalWorldAligned,
            ]
            .into_iter()
            .enumerate()
            {
                let mut j = [Motion::ZERO; NV];
                let x = frame_jacobian_from_q(&fixture.model, &state.q, frame, reference, &mut j)
                    .unwrap();
                let rows: Vec<f64> = to_linear_first(&j).iter().flatten().copied().collect();
                let at = || format!("{name} state {s} {frame_name} {reference:?}");
                worst.add(&rows, &state.jacobians[f][r], at);
                worst.add(&placement(&x), &placement(&state.placements[f]), || {
                    format!("{name} state {s} {frame_name} placement")
                });
            }
        }
    }
    println!(
        "{name} against Pinocchio: worst {:.2e} at {}",
        worst.error, worst.at
    );
    worst.error
}

macro_rules! frame_chain_fixture_tests {
    ($(($id:ident, $name:literal, $sizes:path)),* $(,)?) => {
        $(
            #[test]
            fn $id() {
                const NB: usize = $sizes.0;
                const NQ: usize = $sizes.1;
                const NV: usize = $sizes.2;
                let fixture = load::<NB, NQ, NV>($name);
                let states: Vec<_> = fixture.states.iter().map(|s| (s.q, s.v)).collect();
                assert!(!states.is_empty());
                let e64 = compare::<f64, NB, NQ, NV>($name, &fixture.model, &states);
                let e32 = compare::<f32, NB, NQ, NV>($name, &fixture.model, &states);
                let pin = against_pinocchio($name, &fixture);
                assert!(e64 <= F64_TOLERANCE, "{}: f64 {e64:e}", $name);
                assert!(e32 <= F32_TOLERANCE, "{}: f32 {e32:e}", $name);
                assert!(pin <= PINOCCHIO_TOLERANCE, "{}: against Pinocchio {pin:e}", $name);
            }
        )*
    };
}

frame_chain_fixture_tests! {
    (anymal, "anymal", ANYMAL),
    (g1, "g1", G1),
    (talos, "talos", TALOS),
}

/// Bad input is an error that names it, never a panic or a NaN.
#[test]
fn bad_input_is_an_error() {
    let (model, states) = fixture_states::<13, 19, 18>("solo12");
    let (q, v) = states[0];
    let foot = Frame::new(12, Transform::IDENTITY);
    let mut j = [Motion::ZERO; 18];
    let r = ReferenceFrame::Local;
    assert_eq!(
        frame_jacobian_from_q(&model, &q, &Frame::new(13, Transform::IDENTITY), r, &mut j),
        Err(Error::FrameBodyOutOfRange { body: 13 })
    );
    assert!(FrameChain::new(&model, Frame::new(13, Transform::IDENTITY)).is_none());
    let mut bad_q = q;
    bad_q[9] = f64::NAN;
    // q[9] is the third joint's (after the free flyer's seven).
    assert!(matches!(
        frame_jacobian_from_q(&model, &bad_q, &foot, r, &mut j),
        Err(Error::InvalidConfiguration { joint: 3, .. })
    ));
    let mut bad_v = v;
    bad_v[4] = f64::INFINITY;
    assert!(matches!(
        frame_kinematics_from_q(&model, &q, &bad_v, &foot, r, &mut j),
        Err(Error::NonFinite { .. })
    ));
    let mut not_unit = q;
    not_unit[3] = 2.0;
    assert!(matches!(
        frame_jacobian_from_q(&model, &not_unit, &foot, r, &mut j),
        Err(Error::InvalidConfiguration { joint: 0, .. })
    ));
}
