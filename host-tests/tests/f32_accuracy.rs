//! rodyn in f32 (the MCU scalar) against Pinocchio's f64 results: the error
//! is measured per model and algorithm and bounded per model.
//!
//! The model is built in f64 from the fixture and cast with
//! `Model::cast::<f32>()`; the state's inputs are rounded to f32. The error
//! is `‖x − x_ref‖∞ / ‖x_ref‖∞`, the worst over the fixture's states and over
//! the checks grouped under each algorithm in
//! `rodyn_host_tests::fixture::compare::ALGORITHMS` (RNEA with and without
//! external forces, bias and gravity torques; the mass matrix; ABA and
//! CRBA forward dynamics with and without external forces; energies and the
//! centre of mass).
//!
//! The full table: `cargo run --release -p rodyn-host-tests --example f32_error_table`.

use rodyn_host_tests::fixture::compare::{compare_fixture, ALGORITHMS};
use rodyn_host_tests::for_each_fixture;

/// The bound of each algorithm, in the order of `ALGORITHMS`:
/// RNEA, CRBA (M), ABA, CRBA-FD, energies and COM.
///
/// Where they come from: 4x the worst error that
/// `cargo run --release -p rodyn-host-tests --example f32_error_table`
/// measured (x86-64, Rust 1.95, Pinocchio 4.1 fixtures), rounded up to one
/// significant digit. The margin absorbs other platforms' `sin`/`cos` and
/// changes of operation order in the core; a larger change than that is a
/// loss of accuracy to look at, not a bound to raise.
///
/// Forward dynamics degrade with chain length because they invert `M`: its
/// condition number grows from 1e2 (5 links) to 3e6 (60 links), and the
/// error follows `κ(M) ε_f32` (see docs/sections/accuracy.md).
fn bounds(name: &str) -> [f64; 5] {
    match name {
        "ur5" => [2e-6, 8e-7, 9e-6, 6e-6, 8e-7],
        "panda" => [2e-6, 9e-7, 3e-5, 3e-5, 1e-6],
        "solo12" => [1e-6, 2e-7, 2e-4, 2e-4, 2e-6],
        "branched_tree" => [2e-6, 6e-7, 3e-5, 4e-5, 2e-6],
        "planar_chain_1" => [2e-6, 7e-7, 1e-4, 5e-5, 6e-6],
        "planar_chain_2" => [2e-6, 8e-7, 2e-5, 2e-5, 2e-6],
        "planar_chain_3" => [2e-6, 2e-6, 5e-5, 3e-5, 2e-5],
        "planar_chain_5" => [2e-6, 2e-6, 7e-5, 7e-5, 2e-6],
        "planar_chain_10" => [2e-6, 2e-6, 2e-3, 5e-4, 9e-6],
        "planar_chain_20" => [3e-6, 2e-6, 3e-3, 6e-3, 2e-6],
        "planar_chain_40" => [4e-6, 3e-6, 3e-2, 5e-2, 2e-6],
        "planar_chain_60" => [6e-6, 2e-6, 4e-2, 2e-1, 3e-6],
        "spatial_chain_5" => [2e-6, 7e-7, 1e-4, 2e-4, 3e-5],
        "spatial_chain_12" => [3e-6, 2e-6, 3e-4, 4e-4, 6e-5],
        "spatial_chain_40" => [7e-6, 4e-6, 3e-2, 3e-2, 4e-5],
        _ => panic!("{name}: no f32 bound; measure it with the f32_error_table example"),
    }
}

macro_rules! f32_tests {
    ($(($id:ident, $name:literal, $nb:literal, $nq:literal, $nv:literal)),* $(,)?) => {
        $(
            #[test]
            fn $id() {
                let errors = compare_fixture::<f32, $nb, $nq, $nv>($name)
                    .unwrap_or_else(|e| panic!("{}: {e}", $name));
                let bound = bounds($name);
                let mut failed = Vec::new();
                for ((algorithm, checks), bound) in ALGORITHMS.iter().zip(bound) {
                    let error = errors.max_of(checks);
                    // f32 rounding must show: an error of exactly zero would
                    // mean the computation did not run in f32.
                    assert!(error > 0.0, "{}: {algorithm}: no f32 rounding error at all", $name);
                    if error.is_nan() || error > bound {
                        failed.push(format!("{algorithm} {error:.2e} > {bound:e}"));
                    }
                }
                assert!(failed.is_empty(), "{}: f32 error above its bound: {}", $name, failed.join(", "));
            }
        )*
    };
}

for_each_fixture!(f32_tests);
