//! rodyn in f64 against Pinocchio's results on every committed fixture.
//!
//! For every fixture and state: RNEA with and without external forces, the
//! mass matrix (both triangles), ABA and CRBA forward dynamics with and
//! without external forces, nonlinear effects, gravity torques, kinetic and
//! potential energy and the centre of mass, each within `TOLERANCE` of
//! Pinocchio, measured as `‖x − x_ref‖∞ / ‖x_ref‖∞` (see
//! `rodyn_host_tests::fixture::compare`).
//!
//! Fixtures: `python3 tools/pinocchio/make_fixtures.py` (Pinocchio 4.1).

use rodyn_host_tests::fixture::catalog::NAMES;
use rodyn_host_tests::fixture::compare::{compare_fixture, Check};
use rodyn_host_tests::fixture::{fixtures_dir, Fixture, FixtureError};
use rodyn_host_tests::for_each_fixture;

/// The accuracy the issue asks of f64 on every fixture.
const TOLERANCE: f64 = 1e-9;

macro_rules! reference_tests {
    ($(($id:ident, $name:literal, $nb:literal, $nq:literal, $nv:literal)),* $(,)?) => {
        $(
            #[test]
            fn $id() {
                let errors = compare_fixture::<f64, $nb, $nq, $nv>($name)
                    .unwrap_or_else(|e| panic!("{}: {e}", $name));
                let failed: Vec<String> = Check::ALL
                    .into_iter()
                    .filter(|&c| errors.get(c).is_nan() || errors.get(c) > TOLERANCE)
                    .map(|c| format!("{} {:.2e}", c.name(), errors.get(c)))
                    .collect();
                assert!(
                    failed.is_empty(),
                    "{}: relative error above {TOLERANCE:e}: {}",
                    $name,
                    failed.join(", ")
                );
            }
        )*
    };
}

for_each_fixture!(reference_tests);

/// A fixture written but not catalogued would silently go untested.
#[test]
fn catalog_lists_every_fixture_file() {
    let mut on_disk: Vec<String> = std::fs::read_dir(fixtures_dir())
        .expect("host-tests/fixtures exists")
        .filter_map(|entry| {
            let path = entry.ok()?.path();
            (path.extension()? == "json").then(|| path.file_stem()?.to_str().map(str::to_owned))?
        })
        .collect();
    on_disk.sort();
    let mut listed: Vec<String> = NAMES.iter().map(|s| (*s).to_owned()).collect();
    listed.sort();
    assert_eq!(on_disk, listed);
}

/// Sizes that do not fit the file are reported, not silently truncated.
#[test]
fn wrong_sizes_are_reported() {
    let fixture = Fixture::load_named("ur5").unwrap();
    match fixture.model::<7, 7, 7>() {
        Err(FixtureError::SizeMismatch {
            expected, found, ..
        }) => assert_eq!((expected, found), (7, 6)),
        other => panic!("expected a size mismatch, got {other:?}"),
    }
    match fixture.states[0].arrays::<f64, 6, 6, 5>() {
        Err(FixtureError::SizeMismatch { what, .. }) => assert_eq!(what, "mass_matrix rows"),
        other => panic!("expected a size mismatch, got {other:?}"),
    }
}

/// A malformed fixture names the body and what is wrong with it.
#[test]
fn malformed_fixtures_are_reported() {
    let text = std::fs::read_to_string(fixtures_dir().join("spatial_chain_5.json")).unwrap();
    let tamper = |from: &str, to: &str| {
        assert!(
            text.contains(from),
            "the fixture no longer contains {from:?}"
        );
        Fixture::parse(&text.replacen(from, to, 1)).unwrap()
    };

    let unknown = tamper("\"type\": \"RY\"", "\"type\": \"Helical\"");
    let err = unknown.model::<5, 5, 5>().unwrap_err();
    assert!(
        matches!(&err, FixtureError::UnsupportedJoint { body: 1, kind, .. } if kind == "Helical"),
        "{err}"
    );

    let no_axis = tamper("\"axis\"", "\"no_axis\"");
    let err = no_axis.model::<5, 5, 5>().unwrap_err();
    assert!(matches!(err, FixtureError::Malformed { .. }), "{err}");
    assert!(err.to_string().contains("needs an \"axis\""), "{err}");

    let bad_parent = tamper("\"parent\": 0,", "\"parent\": 3,");
    let err = bad_parent.model::<5, 5, 5>().unwrap_err();
    assert!(
        matches!(err, FixtureError::Malformed { body: 1, .. }),
        "{err}"
    );

    let negative_mass = tamper("\"mass\": ", "\"mass\": -");
    let err = negative_mass.model::<5, 5, 5>().unwrap_err();
    assert!(matches!(err, FixtureError::InvalidModel(_)), "{err}");

    let err = Fixture::parse("{\"model\": 3}").unwrap_err();
    assert!(err.to_string().contains("line 1"), "{err}");
}

/// The comparison is sharp enough to see a model error far below anything a
/// URDF states: one body's mass off by one part in 10⁷ fails RNEA, CRBA and
/// ABA alike.
#[test]
fn a_tiny_model_error_is_caught() {
    use rodyn::spatial::Inertia;
    use rodyn::Data;
    use rodyn_host_tests::fixture::compare::compare_state;

    let fixture = Fixture::load_named("solo12").unwrap();
    let mut model = fixture.model::<13, 19, 18>().unwrap();
    let mut data = Data::new();
    let state = fixture.states[0].arrays::<f64, 13, 19, 18>().unwrap();
    let exact = compare_state(&model, &mut data, &state).unwrap();

    let body = 6; // a hind-left leg segment
    let i = *model.inertia(body);
    model
        .set_inertia(
            body,
            Inertia::new(i.mass * (1.0 + 1e-7), i.com, i.rot_inertia),
        )
        .unwrap();
    let perturbed = compare_state(&model, &mut data, &state).unwrap();
    for check in [Check::Rnea, Check::Crba, Check::Aba, Check::CrbaFd] {
        assert!(exact.get(check) <= TOLERANCE, "{}", check.name());
        assert!(
            perturbed.get(check) > TOLERANCE,
            "{}: a 1e-7 mass error went unnoticed ({:e})",
            check.name(),
            perturbed.get(check)
        );
    }
}
