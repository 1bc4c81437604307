//! ABA against CRBA forward dynamics on revolute chains of 1 to 120 links.
//!
//! ```text
//! cargo run -p rodyn-bench --release --bin crossover [-- --rounds N --ms M --out FILE]
//! cargo run -p rodyn-bench --release --bin crossover -- --replot [--out FILE]
//! ```
//!
//! Times both methods on the planar chains (planar algebra and their 3-D
//! equivalents, `f64` and `f32`), prints a markdown table of the medians and
//! the crossover per variant, and draws `docs/img/perf/crossover.svg`: the
//! time of CRBA forward dynamics divided by that of ABA against the number
//! of links. Below 1, CRBA is faster. The medians go to a CSV file beside
//! the chart (`crossover.csv`); `--replot` draws the chart from that file
//! without timing anything (timings are wall clock, so only the drawing can
//! be regenerated).

use clap::Parser;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use rodyn_bench::arguments::{milliseconds, Rounds};
use rodyn_bench::cases::{Case, ModelCase};
use rodyn_bench::models::{planar_chain, planar_chain_3d};
use rodyn_bench::timing::median;
use rodyn_bench::Algorithm;
use rodyn_cli::writable_file;
use rodyn_plot_markers::marker;
use std::io::Write as _;

const STATES: usize = 32;
const SEED: u64 = 0xC805;

/// One curve of the chart: a geometry and a scalar type.
const VARIANTS: [&str; 4] = ["planar f32", "planar f64", "3-D f32", "3-D f64"];

/// The four variants of the chain of `N` links, in [`VARIANTS`] order.
fn chain_cases<const N: usize>() -> [Box<dyn Case>; 4] {
    let planar = ModelCase::new(planar_chain::<N>(), STATES, SEED);
    let spatial = ModelCase::new(planar_chain_3d::<N>(), STATES, SEED);
    [
        Box::new(planar.to_f32()),
        Box::new(planar),
        Box::new(spatial.to_f32()),
        Box::new(spatial),
    ]
}

/// Chain lengths, each with its four variants.
fn all_chains() -> Vec<(usize, [Box<dyn Case>; 4])> {
    macro_rules! chains {
        ($($n:literal),*) => { vec![$(($n, chain_cases::<$n>())),*] };
    }
    chains!(1, 2, 3, 4, 6, 8, 10, 12, 16, 20, 30, 40, 60, 80, 120)
}

/// ABA against CRBA forward dynamics for chains of 1 to 120 links.
#[derive(Parser)]
struct Options {
    /// Rounds, each timing every chain once (1 to 100).
    #[arg(long, default_value = "5", allow_hyphen_values = true)]
    rounds: Rounds,
    /// Milliseconds per measurement (at most 10000).
    #[arg(long, default_value = "10", value_parser = milliseconds, allow_hyphen_values = true)]
    ms: f64,
    /// The chart (SVG); the medians go beside it with the extension .csv.
    #[arg(long, default_value = "docs/img/perf/crossover.svg")]
    out: String,
    /// Draw the chart from the CSV file beside --out instead of timing.
    #[arg(long)]
    replot: bool,
}

/// The CSV file beside the chart `out`.
fn csv_path(out: &str) -> std::path::PathBuf {
    std::path::Path::new(out).with_extension("csv")
}

/// The smallest chain length from which ABA stays faster than CRBA.
fn crossover(lengths: &[usize], ratio: &[f64]) -> Option<usize> {
    let last_crba_win = ratio.iter().rposition(|&r| r < 1.0);
    match last_crba_win {
        None => lengths.first().copied(),
        Some(k) => lengths.get(k + 1).copied(),
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    rodyn_plot_markers::register_sans_serif();
    let opts = Options::parse();
    // The chart is written after minutes of timing: check its place first.
    writable_file(std::path::Path::new(&opts.out)).map_err(|e| format!("--out: {e}"))?;
    if opts.replot {
        let (lengths, ratios) = read_csv(&csv_path(&opts.out))?;
        draw(&opts.out, &lengths, &ratios)?;
        eprintln!("wrote {}", opts.out);
        return Ok(());
    }
    let mut chains = all_chains();
    let target_ns = opts.ms * 1.0e6;
    let methods = [Algorithm::Aba, Algorithm::CrbaForwardDynamics];
    // calls[chain][variant][method], fixed for every round.
    let calls: Vec<Vec<[usize; 2]>> = chains
        .iter_mut()
        .map(|(_, cases)| {
            cases
                .iter_mut()
                .map(|c| {
                    // A method that fails on the chain (CRBA's factorisation in
                    // f32 on long chains) gets no timing: 0 calls, NaN below.
                    methods.map(|m| {
                        if c.succeeds(m) {
                            c.calibrate(m, target_ns)
                        } else {
                            0
                        }
                    })
                })
                .collect()
        })
        .collect();
    let mut samples: Vec<[[Vec<f64>; 2]; 4]> =
        (0..chains.len()).map(|_| Default::default()).collect();
    for round in 0..opts.rounds.get() {
        eprint!("round {}/{}\r", round + 1, opts.rounds.get());
        let _ = std::io::stderr().flush();
        for (c, (_, cases)) in chains.iter_mut().enumerate() {
            for (v, case) in cases.iter_mut().enumerate() {
                // Alternate the order of the two methods between rounds.
                for step in 0..2 {
                    let m = (step + round) % 2;
                    let ns = match calls[c][v][m] {
                        0 => f64::NAN,
                        n => case.time(methods[m], n),
                    };
                    samples[c][v][m].push(ns);
                }
            }
        }
    }
    eprintln!();

    let lengths: Vec<usize> = chains.iter().map(|(n, _)| *n).collect();
    // ns[variant][method][chain]
    let mut ns = vec![[vec![0.0; lengths.len()], vec![0.0; lengths.len()]]; 4];
    for (c, per_variant) in samples.iter_mut().enumerate() {
        for (v, per_method) in per_variant.iter_mut().enumerate() {
            for (m, values) in per_method.iter_mut().enumerate() {
                ns[v][m][c] = median(values);
            }
        }
    }
    let ratios: Vec<Vec<f64>> = ns
        .iter()
        .map(|[aba, crba]| crba.iter().zip(aba).map(|(c, a)| c / a).collect())
        .collect();

    rodyn_cli::outln!(
        "{} rounds, medians, ns per call; ratio = CRBA forward dynamics / ABA.\n",
        opts.rounds.get()
    );
    rodyn_cli::out!("| links |");
    for v in VARIANTS {
        rodyn_cli::out!(" ABA {v} | CRBA {v} | ratio |");
    }
    rodyn_cli::outln!();
    rodyn_cli::outln!("|---:|{}", "---:|---:|---:|".repeat(VARIANTS.len()));
    for (c, n) in lengths.iter().enumerate() {
        rodyn_cli::out!("| {n} |");
        for v in 0..VARIANTS.len() {
            let (aba, crba, ratio) = (ns[v][0][c], ns[v][1][c], ratios[v][c]);
            if ratio.is_finite() {
                rodyn_cli::out!(" {aba:.0} | {crba:.0} | {ratio:.2} |");
            } else {
                // CRBA reported the mass matrix as not positive definite.
                rodyn_cli::out!(" {aba:.0} | fails | – |");
            }
        }
        rodyn_cli::outln!();
    }
    rodyn_cli::outln!();
    for (v, name) in VARIANTS.iter().enumerate() {
        match crossover(&lengths, &ratios[v]) {
            Some(n) => rodyn_cli::outln!("{name}: ABA is faster from {n} links on"),
            None => rodyn_cli::outln!("{name}: CRBA is faster at every length measured"),
        }
    }

    write_csv(&csv_path(&opts.out), &lengths, &ns, &ratios)?;
    draw(&opts.out, &lengths, &ratios)?;
    eprintln!("wrote {} and its CSV", opts.out);
    Ok(())
}

/// `links,variant,aba_ns,crba_ns,ratio`, one line per chain and variant;
/// a failed CRBA leaves its time and ratio empty.
fn write_csv(
    path: &std::path::Path,
    lengths: &[usize],
    ns: &[[Vec<f64>; 2]],
    ratios: &[Vec<f64>],
) -> std::io::Result<()> {
    let mut csv = String::from("links,variant,aba_ns,crba_ns,ratio\n");
    for (c, n) in lengths.iter().enumerate() {
        for (v, name) in VARIANTS.iter().enumerate() {
            let (aba, crba, ratio) = (ns[v][0][c], ns[v][1][c], ratios[v][c]);
            if ratio.is_finite() {
                csv.push_str(&format!("{n},{name},{aba:.0},{crba:.0},{ratio:.2}\n"));
            } else {
                csv.push_str(&format!("{n},{name},{aba:.0},,\n"));
            }
        }
    }
    std::fs::write(path, csv)
}

/// The chain lengths and, per variant in [`VARIANTS`] order, the ratios
/// (NaN where CRBA failed) of a CSV file [`write_csv`] wrote. An error
/// names the file, the line and what is wrong.
fn read_csv(path: &std::path::Path) -> Result<(Vec<usize>, Vec<Vec<f64>>), String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let mut lengths: Vec<usize> = Vec::new();
    let mut ratios = vec![Vec::new(); VARIANTS.len()];
    for (k, line) in text.lines().enumerate().skip(1) {
        let at = || format!("{}:{}", path.display(), k + 1);
        let fields: Vec<&str> = line.split(',').collect();
        let [links, variant, _, _, ratio] = fields[..] else {
            return Err(format!(
                "{}: expected 5 fields, found {}",
                at(),
                fields.len()
            ));
        };
        let links: usize = links
            .parse()
            .map_err(|_| format!("{}: links `{links}` is not a count", at()))?;
        let v = VARIANTS
            .iter()
            .position(|&name| name == variant)
            .ok_or_else(|| format!("{}: unknown variant `{variant}`", at()))?;
        let ratio = match ratio {
            "" => f64::NAN,
            r => r
                .parse::<f64>()
                .ok()
                .filter(|r| r.is_finite() && *r > 0.0)
                .ok_or_else(|| format!("{}: ratio `{r}` is not a positive number", at()))?,
        };
        if lengths.last() != Some(&links) {
            lengths.push(links);
        }
        if ratios[v].len() + 1 != lengths.len() {
            return Err(format!("{}: variant `{variant}` out of order", at()));
        }
        ratios[v].push(ratio);
    }
    if lengths.is_empty() || ratios.iter().any(|r| r.len() != lengths.len()) {
        return Err(format!(
            "{}: every variant needs one line per chain length",
            path.display()
        ));
    }
    Ok((lengths, ratios))
}

fn draw(
    path: &str,
    lengths: &[usize],
    ratios: &[Vec<f64>],
) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (800, 500)).into_drawing_area();
    root.fill(&WHITE)?;
    let max_ratio = ratios.iter().flatten().fold(1.0f64, |m, &r| m.max(r)) * 1.1;
    let min_ratio = ratios.iter().flatten().fold(1.0f64, |m, &r| m.min(r)) * 0.9;
    let max_n = *lengths.last().unwrap_or(&1) as f64;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "rodyn: CRBA forward dynamics time / ABA time, revolute chains",
            ("sans-serif", 20),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(
            (1.0f64..max_n).log_scale(),
            (min_ratio..max_ratio).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc("links (= degrees of freedom)")
        .y_desc("CRBA time / ABA time (ratio; below 1: CRBA faster)")
        .draw()?;
    chart.draw_series(LineSeries::new(
        [(1.0, 1.0), (max_n, 1.0)],
        BLACK.stroke_width(1),
    ))?;
    // Colour and marker per variant, and the line dashed for the planar
    // algebra, so that the curves part without their colours.
    let colours = [
        RGBColor(214, 39, 40),
        RGBColor(31, 119, 180),
        RGBColor(44, 160, 44),
        RGBColor(148, 103, 189),
    ];
    for (v, ((name, ratio), colour)) in VARIANTS.iter().zip(ratios).zip(colours).enumerate() {
        let points: Vec<(f64, f64)> = lengths
            .iter()
            .map(|&n| n as f64)
            .zip(ratio.iter().copied())
            .filter(|(_, r)| r.is_finite())
            .collect();
        let planar = name.starts_with("planar");
        let style = colour.stroke_width(2);
        if planar {
            chart.draw_series(DashedLineSeries::new(points.clone(), 7, 4, style))?;
        } else {
            chart.draw_series(LineSeries::new(points.clone(), style))?;
        }
        chart
            .draw_series(
                points
                    .iter()
                    .map(|&p| EmptyElement::at(p) + marker(v, colour, (0, 0))),
            )?
            .label(*name)
            .legend(move |(x, y)| {
                // One dash as long as the sample for a solid line.
                let (dash, gap) = if planar { (7, 4) } else { (22, 4) };
                EmptyElement::at((x, y))
                    + DashedPathElement::new([(0, 0), (22, 0)], dash, gap, colour.stroke_width(2))
                    + marker(v, colour, (11, 0))
            });
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperLeft)
        .draw()?;
    root.present()?;
    Ok(())
}
