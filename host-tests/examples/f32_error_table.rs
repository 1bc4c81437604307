//! Prints, as markdown, the worst relative error against Pinocchio of each
//! algorithm on each fixture, in f32 (the MCU scalar) and in f64.
//!
//! ```text
//! cargo run --release -p rodyn-host-tests --example f32_error_table
//! ```
//!
//! Error measure: `‖x − x_ref‖∞ / ‖x_ref‖∞`, the worst over the fixture's
//! states and over each algorithm's checks (see
//! `rodyn_host_tests::fixture::compare`). In f32 the inputs are rounded to
//! f32 too, so the table shows what a caller with f32 data gets.
//! `κ₂(M)` is the largest 2-norm condition number of the reference mass
//! matrix over the states: forward dynamics loses about that factor.

use nalgebra::DMatrix;
use rodyn::Scalar;
use rodyn_cli::no_arguments;
use rodyn_host_tests::fixture::compare::{compare_fixture, ALGORITHMS};
use rodyn_host_tests::fixture::Fixture;
use rodyn_host_tests::for_each_fixture;

/// The largest condition number of the fixture's reference mass matrices.
fn mass_matrix_condition(name: &str) -> Result<f64, String> {
    let fixture = Fixture::load_named(name).map_err(|e| e.to_string())?;
    Ok(fixture
        .states
        .iter()
        .map(|s| {
            let n = s.mass_matrix.len();
            let m = DMatrix::from_fn(n, n, |r, c| s.mass_matrix[r][c]);
            let eig = m.symmetric_eigen().eigenvalues;
            eig.max() / eig.min()
        })
        .fold(0.0, f64::max))
}

fn row<S: Scalar, const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
) -> Result<String, String> {
    let errors = compare_fixture::<S, NB, NQ, NV>(name).map_err(|e| format!("{name}: {e}"))?;
    let cells: Vec<String> = ALGORITHMS
        .iter()
        .map(|(_, checks)| format!("{:.1e}", errors.max_of(checks)))
        .collect();
    Ok(format!(
        "| {name} | {NV} | {:.0e} | {} |",
        mass_matrix_condition(name)?,
        cells.join(" | ")
    ))
}

macro_rules! table {
    ($scalar:ty; $(($id:ident, $name:literal, $nb:literal, $nq:literal, $nv:literal)),* $(,)?) => {{
        let header: Vec<&str> = ALGORITHMS.iter().map(|(name, _)| *name).collect();
        rodyn_cli::outln!("| model | nv | κ₂(M) | {} |", header.join(" | "));
        rodyn_cli::outln!("|---|---:|---:|{}", "---:|".repeat(ALGORITHMS.len()));
        $( rodyn_cli::outln!("{}", row::<$scalar, $nb, $nq, $nv>($name)?); )*
    }};
}

macro_rules! f32_table {
    ($($fixture:tt)*) => { table!(f32; $($fixture)*) };
}
macro_rules! f64_table {
    ($($fixture:tt)*) => { table!(f64; $($fixture)*) };
}

fn main() -> Result<(), String> {
    no_arguments("f32_error_table", "prints the table of every fixture")?;
    rodyn_cli::outln!("### f32: relative error against Pinocchio\n");
    for_each_fixture!(f32_table);
    rodyn_cli::outln!("\n### f64: relative error against Pinocchio\n");
    for_each_fixture!(f64_table);
    Ok(())
}
