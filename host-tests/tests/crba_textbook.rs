//! The tuned CRBA passes against the book's algorithm
//! (`rodyn::algorithm::crba::textbook`, Featherstone Table 6.2), and the
//! book's algorithm against Pinocchio.
//!
//! On every committed fixture, on random trees numbered depth first or
//! not, on random floating trees and on random planar chains: `crba_with`
//! by each [`CrbaPass`] and `crba` (the default pass), each without a plan
//! and with the model's [`CrbaPlan`] (its quarter turns recognised, which
//! puts the tuned passes in turned frames), against `textbook::crba` in
//! the same scalar.
//! Error: `max |M − M_book| / max |M_book|` over the whole matrix.
//!
//! - f64, local pass: 1e-12 (rounding of a few dozen operations per
//!   entry; measured worst is printed by `--nocapture`).
//! - f64, root-frame pass: 1e-12 as well on the fixtures; its entries are
//!   differences of terms that grow with the distance from the root, which
//!   the fixtures' links (a metre or less) keep small.
//! - f32, default pass against the f64 book: 2e-6, the mass-matrix bound
//!   `f32_accuracy` uses for the worst fixture (4 ε_f32 ≈ 5e-7 per
//!   operation chain, a few chains per entry).
//! - the book against Pinocchio's mass matrix: 1e-9, the bound of
//!   `pinocchio_reference`.

use rodyn::algorithm::crba::{
    crba, crba_planned, crba_planned_with, crba_with, textbook, CrbaPass, CrbaPlan,
};
use rodyn::planar::Planar;
use rodyn::space::Space;
use rodyn::{Data, Model, Scalar};
use rodyn_host_tests::fixture::Fixture;
use rodyn_host_tests::for_each_fixture;
use rodyn_host_tests::random::{
    random_configuration, random_floating_tree, random_planar_chain, random_tree, Rng,
};

const F64_BOUND: f64 = 1e-12;
const F32_BOUND: f64 = 2e-6;
const PINOCCHIO_BOUND: f64 = 1e-9;

/// `max |a − b| / max |b|`.
fn relative<const NV: usize>(a: &[[f64; NV]; NV], b: &[[f64; NV]; NV]) -> f64 {
    let (mut diff, mut scale) = (0.0f64, 0.0f64);
    for r in 0..NV {
        for c in 0..NV {
            diff = diff.max((a[r][c] - b[r][c]).abs());
            scale = scale.max(b[r][c].abs());
        }
    }
    diff / scale.max(f64::MIN_POSITIVE)
}

fn to_f64<S: Scalar, const NV: usize>(m: &[[S; NV]; NV]) -> [[f64; NV]; NV] {
    core::array::from_fn(|r| core::array::from_fn(|c| m[r][c].to_f64()))
}

/// Every pass, and the default, without a plan and with the model's,
/// against the book in `S`; returns the worst error.
fn tuned_against_book<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    q: &[S; NQ],
    what: &str,
) -> f64 {
    let book = to_f64(&textbook::crba(model, q).unwrap());
    let plan = CrbaPlan::new(model);
    let mut data = Data::new();
    let mut worst = 0.0f64;
    let (local, root) = (CrbaPass::Local, CrbaPass::RootFrame);
    let names = [
        "default",
        "local",
        "root frame",
        "planned default",
        "planned local",
        "planned root frame",
    ];
    // One matrix at a time: six 60 x 60 ones overflow a test thread's stack.
    for (k, name) in names.into_iter().enumerate() {
        let got = match k {
            0 => crba(model, &mut data, q),
            1 => crba_with(model, &mut data, q, local),
            2 => crba_with(model, &mut data, q, root),
            3 => crba_planned(model, &plan, &mut data, q),
            4 => crba_planned_with(model, &plan, &mut data, q, local),
            _ => crba_planned_with(model, &plan, &mut data, q, root),
        }
        .unwrap();
        let e = relative(&to_f64(got), &book);
        assert!(
            e <= F64_BOUND,
            "{what}, {name} pass: {e:.2e} above {F64_BOUND:e}"
        );
        worst = worst.max(e);
    }
    worst
}

fn fixture_checks<const NB: usize, const NQ: usize, const NV: usize>(name: &str) {
    let fixture = Fixture::load_named(name).unwrap();
    let plain = fixture.model::<NB, NQ, NV>().unwrap();
    let plain32 = plain.cast::<f32>().unwrap();
    let (mut worst, mut worst32, mut worst_pin) = (0.0f64, 0.0f64, 0.0f64);
    for (k, state) in fixture.states.iter().enumerate() {
        let s = state.arrays::<f64, NB, NQ, NV>().unwrap();
        let book = textbook::crba(&plain, &s.q).unwrap();
        let e = relative(&book, &s.reference.mass_matrix);
        assert!(
            e <= PINOCCHIO_BOUND,
            "{name} state {k}: book against Pinocchio {e:.2e}"
        );
        worst_pin = worst_pin.max(e);
        let what = format!("{name} state {k}");
        worst = worst.max(tuned_against_book(&plain, &s.q, &what));
        let s32 = state.arrays::<f32, NB, NQ, NV>().unwrap();
        let mut data = Data::new();
        // Planned, as a firmware image runs it.
        let plan32 = CrbaPlan::new(&plain32);
        let got = to_f64(crba_planned(&plain32, &plan32, &mut data, &s32.q).unwrap());
        // The f32-rounded quaternion, unit again to f64 precision (the
        // f64 check rejects it otherwise; `M` does not depend on the base's
        // orientation).
        let mut q64 = s32.q.map(f64::from);
        plain.normalize(&mut q64).unwrap();
        let e = relative(&got, &textbook::crba(&plain, &q64).unwrap());
        assert!(
            e <= F32_BOUND,
            "{name} state {k}: f32 {e:.2e} above {F32_BOUND:e}"
        );
        worst32 = worst32.max(e);
    }
    println!("{name}: f64 {worst:.1e}, f32 {worst32:.1e}, book against Pinocchio {worst_pin:.1e}");
}

macro_rules! fixture_tests {
    ($(($id:ident, $name:literal, $nb:literal, $nq:literal, $nv:literal)),* $(,)?) => {
        $(
            #[test]
            fn $id() {
                fixture_checks::<$nb, $nq, $nv>($name);
            }
        )*
    };
}

for_each_fixture!(fixture_tests);

#[test]
fn random_trees_in_any_numbering() {
    let mut rng = Rng::new(0x5eed_c4ba);
    let mut worst = 0.0f64;
    for trial in 0..20 {
        let model = random_tree::<9>(&mut rng);
        let q = random_configuration(&model, &mut rng);
        worst = worst.max(tuned_against_book(&model, &q, &format!("tree {trial}")));
        let floating = random_floating_tree::<8, 13, 12>(&mut rng);
        let q = random_configuration(&floating, &mut rng);
        worst = worst.max(tuned_against_book(
            &floating,
            &q,
            &format!("floating {trial}"),
        ));
    }
    println!("random trees: f64 {worst:.1e}");
}

#[test]
fn random_planar_chains() {
    let mut rng = Rng::new(0x91a4);
    let mut worst = 0.0f64;
    for trial in 0..20 {
        let (planar, spatial): (Model<f64, 6, 6, 6, Planar>, _) = random_planar_chain(&mut rng);
        let q: [f64; 6] = rng.vector(2.0);
        worst = worst.max(tuned_against_book(&planar, &q, &format!("planar {trial}")));
        // The planar book and the 3-D book agree on the twin.
        let e = relative(
            &textbook::crba(&planar, &q).unwrap(),
            &textbook::crba(&spatial, &q).unwrap(),
        );
        assert!(
            e <= F64_BOUND,
            "planar {trial}: planar and 3-D books {e:.2e}"
        );
    }
    println!("planar chains: f64 {worst:.1e}");
}

#[test]
fn the_book_rejects_what_crba_rejects() {
    let mut rng = Rng::new(7);
    let model = random_tree::<4>(&mut rng);
    let q = [0.1, f64::NAN, 0.3, 0.4];
    assert!(textbook::crba(&model, &q).is_err());
    assert!(crba(&model, &mut Data::new(), &q).is_err());
}
