//! Prints, as markdown, the worst relative error against Pinocchio of each
//! algorithm on each fixture, in f32 (the MCU scalar) and in f64.
//!
//! ```text
//! cargo run --release -p rodyn-host-tests --example f32_error_table
//! ```
//!
//! Error measure: `‖x − x_ref‖∞ / ‖x_ref‖∞`, the worst over the fixture's
//! states (see `rodyn_host_tests::fixture::compare`). In f32 the inputs are
//! rounded to f32 too, so the table shows what a caller with f32 data gets.

use rodyn::Scalar;
use rodyn_host_tests::fixture::compare::{compare_fixture, Check, Errors};
use rodyn_host_tests::for_each_fixture;

/// The columns of the table.
const COLUMNS: [Check; 7] = [
    Check::Rnea,
    Check::RneaFext,
    Check::Crba,
    Check::Aba,
    Check::CrbaFd,
    Check::GravityTorques,
    Check::KineticEnergy,
];

fn row<S: Scalar, const NB: usize, const NQ: usize, const NV: usize>(name: &str) -> String {
    let errors: Errors =
        compare_fixture::<S, NB, NQ, NV>(name).unwrap_or_else(|e| panic!("{name}: {e}"));
    let cells: Vec<String> = COLUMNS
        .iter()
        .map(|&c| format!("{:.1e}", errors.get(c)))
        .collect();
    format!("| {name} | {NV} | {} |", cells.join(" | "))
}

macro_rules! table {
    ($scalar:ty; $(($id:ident, $name:literal, $nb:literal, $nq:literal, $nv:literal)),* $(,)?) => {{
        let header: Vec<&str> = COLUMNS.iter().map(|c| c.name()).collect();
        println!("| model | nv | {} |", header.join(" | "));
        println!("|---|---:|{}", "---:|".repeat(COLUMNS.len()));
        $( println!("{}", row::<$scalar, $nb, $nq, $nv>($name)); )*
    }};
}

macro_rules! f32_table {
    ($($fixture:tt)*) => { table!(f32; $($fixture)*) };
}
macro_rules! f64_table {
    ($($fixture:tt)*) => { table!(f64; $($fixture)*) };
}

fn main() {
    println!("### f32: relative error against Pinocchio (f64)\n");
    for_each_fixture!(f32_table);
    println!("\n### f64: relative error against Pinocchio\n");
    for_each_fixture!(f64_table);
}
