//! The first seed's gait example on real walking data: inverse dynamics of
//! OpenSim's subject01 (`data/gait/`) with `models/gait_subject01.toml`,
//! the pelvis residuals, and the load at the socket of a right transfemoral
//! prosthesis over the right gait cycle.
//!
//! ```text
//! cargo run --release -p rodyn-host-tests --example gait_subject01 -- --out DIR
//! ```
//!
//! Writes `DIR/joint_loads.csv` (one row per 60 Hz frame, the data
//! README's sign convention), `DIR/summary.txt` and the figures
//! `DIR/{joint_moments,residuals,socket_loads}.svg`; prints the same
//! summary. `--data DIR` reads the data elsewhere.

use plotters::prelude::*;
use rodyn::Data;
use rodyn_cli::writable_dir;
use rodyn_host_tests::subject_gait::{
    check_coverage, data_dir, inverse_dynamics, model_torques, opensim_loads, read_inputs,
    with_prosthesis, Frame, GRAVITY, LOAD_COLUMNS, MODEL,
};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Right heel strike to the next, s (the data README's events, 20 N).
const RIGHT_CYCLE: (f64, f64) = (0.618, 1.852);
/// Right toe off, s.
const RIGHT_TOE_OFF: f64 = 1.409;
/// Frames at each end distorted by the source's filter and spline end
/// conditions (the data README: about 5 frames, q̈ forced to 0 at the ends).
const EDGE_FRAMES: usize = 5;
/// The prosthetic shank and foot's mass as a fraction of the intact ones':
/// 39.1 %, the mean unloaded prosthetic shank of six above-knee amputees in
/// Hale, S. A. (1990), "Analysis of the swing phase dynamics and muscular
/// effort of the above-knee amputee for varying prosthetic shank loads",
/// Prosthetics and Orthotics International 14:125-135 (1.33 kg). Centres
/// of mass kept and moments of inertia scaled by the same fraction: an
/// assumption of this example, not a measurement.
const PROSTHESIS_MASS_FRACTION: f64 = 0.391;

const USAGE: &str = "usage: gait_subject01 --out <DIR> [--data <DIR>]
  --out <DIR>   where the table, the summary and the figures go (created if missing)
  --data <DIR>  where inverse_dynamics_inputs_60hz.csv is (default: the shared gait data)";

struct Arguments {
    out: PathBuf,
    data: PathBuf,
}

/// The arguments, or `None` after printing the usage for `--help`.
fn arguments() -> Result<Option<Arguments>, String> {
    let mut out = None;
    let mut data = data_dir();
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--out" => {
                out = Some(
                    args.next()
                        .map(PathBuf::from)
                        .ok_or("--out needs a directory")?,
                )
            }
            "--data" => {
                data = args
                    .next()
                    .map(PathBuf::from)
                    .ok_or("--data needs a directory")?
            }
            "-h" | "--help" => {
                println!("{USAGE}");
                return Ok(None);
            }
            other => return Err(format!("unknown argument `{other}`\n{USAGE}")),
        }
    }
    Ok(Some(Arguments {
        out: out.ok_or(format!("--out is missing\n{USAGE}"))?,
        data,
    }))
}

fn main() {
    if let Err(e) = run() {
        eprintln!("gait_subject01: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let Some(args) = arguments()? else {
        return Ok(());
    };
    let input = args.data.join("inverse_dynamics_inputs_60hz.csv");
    let samples = read_inputs(&input)?;
    check_coverage(
        &input,
        &samples,
        2 * EDGE_FRAMES + 1,
        "the filter's edge frames at each end and one between",
        RIGHT_CYCLE,
    )?;
    writable_dir(&args.out).map_err(|e| format!("--out: {e}"))?;
    let (model, model32) = MODEL;
    let mass = model.total_mass();
    let weight = mass * GRAVITY;
    let mut data = Box::new(Data::new());
    let mut data32 = Box::new(Data::new());
    let mut frames: Vec<Frame> = Vec::with_capacity(samples.len());
    let mut f32_worst = (0.0_f64, 0);
    for (k, s) in samples.iter().enumerate() {
        let frame = inverse_dynamics(&model, &mut data, s)?;
        let tau32 = model_torques(&model32, &mut data32, s)?;
        let loads32 = opensim_loads(&tau32.map(f64::from), s.q[0]);
        for (a, b) in frame.loads.iter().zip(&loads32) {
            let difference = (a - b).abs();
            if difference > f32_worst.0 {
                f32_worst = (difference, k);
            }
        }
        frames.push(frame);
    }

    // joint_loads.csv
    let mut csv = String::from("time_s");
    for c in LOAD_COLUMNS {
        csv.push(',');
        csv.push_str(c);
    }
    csv.push('\n');
    for f in &frames {
        let _ = write!(csv, "{:.6}", f.time);
        for x in f.loads {
            let _ = write!(csv, ",{x:.9e}");
        }
        csv.push('\n');
    }
    std::fs::write(args.out.join("joint_loads.csv"), csv)?;

    // Summary.
    let mut summary = String::new();
    let inner = EDGE_FRAMES..frames.len() - EDGE_FRAMES;
    let _ = writeln!(
        summary,
        "subject01: {} frames, {:.3}-{:.3} s, body mass {mass:.3} kg (weight {weight:.1} N)",
        frames.len(),
        frames[0].time,
        frames[frames.len() - 1].time
    );
    let _ = writeln!(
        summary,
        "f32 against f64: largest difference {:.2e} (N or N m) at frame {} ({:.2e} of body weight)",
        f32_worst.0,
        f32_worst.1,
        f32_worst.0 / weight
    );
    let residual = |f: &Frame| f.loads[1].hypot(f.loads[2]) / weight;
    let stats = |values: Vec<f64>| {
        let rms = (values.iter().map(|x| x * x).sum::<f64>() / values.len() as f64).sqrt();
        let peak = values.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        (rms, peak)
    };
    let (force_rms, force_peak) = stats(frames[inner.clone()].iter().map(residual).collect());
    let (moment_rms, moment_peak) =
        stats(frames[inner.clone()].iter().map(|f| f.loads[0]).collect());
    let _ = writeln!(
        summary,
        "pelvis residual force (frames {}..{}, edges excluded): RMS {:.1} % BW, peak {:.1} % BW",
        inner.start,
        inner.end,
        100.0 * force_rms,
        100.0 * force_peak
    );
    let _ = writeln!(
        summary,
        "pelvis residual moment: RMS {moment_rms:.1} N m, peak {moment_peak:.1} N m ({:.2} N m/kg)",
        moment_peak / mass
    );
    let _ = writeln!(
        summary,
        "\njoint moment peaks over frames {}..{} (N m/kg, data README signs):",
        inner.start, inner.end
    );
    for (k, name) in LOAD_COLUMNS.iter().enumerate().skip(3) {
        let values: Vec<f64> = frames[inner.clone()]
            .iter()
            .map(|f| f.loads[k] / mass)
            .collect();
        let max = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let min = values.iter().copied().fold(f64::INFINITY, f64::min);
        let _ = writeln!(summary, "  {name:<26} {min:+.3} .. {max:+.3}");
    }

    // The prosthesis over the right gait cycle: own limb, then the lighter one.
    let prosthetic = with_prosthesis(PROSTHESIS_MASS_FRACTION)?;
    let cycle: Vec<usize> = (0..frames.len())
        .filter(|&k| {
            frames[k].time >= RIGHT_CYCLE.0 - 1e-9 && frames[k].time <= RIGHT_CYCLE.1 + 1e-9
        })
        .collect();
    let percent = |t: f64| 100.0 * (t - RIGHT_CYCLE.0) / (RIGHT_CYCLE.1 - RIGHT_CYCLE.0);
    let mut lighter = Vec::with_capacity(cycle.len());
    for &k in &cycle {
        lighter.push(inverse_dynamics(&prosthetic, &mut data, &samples[k])?);
    }
    let _ = writeln!(
        summary,
        "\nsocket on the right thigh, 0.25 m below the hip; right cycle {:.3}-{:.3} s ({} frames), toe off at {:.0} %",
        RIGHT_CYCLE.0,
        RIGHT_CYCLE.1,
        cycle.len(),
        percent(RIGHT_TOE_OFF)
    );
    let extremes = |values: &[f64]| {
        let max = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let min = values.iter().copied().fold(f64::INFINITY, f64::min);
        (min, max)
    };
    let own: Vec<Frame> = cycle.iter().map(|&k| frames[k]).collect();
    for (label, set) in [
        ("own shank and foot", &own),
        ("prosthesis (39.1 % mass)", &lighter),
    ] {
        let (t0, t1) = extremes(&set.iter().map(|f| f.socket.torque).collect::<Vec<_>>());
        let (n0, n1) = extremes(&set.iter().map(|f| f.socket.normal).collect::<Vec<_>>());
        let (s0, s1) = extremes(&set.iter().map(|f| f.socket.shear).collect::<Vec<_>>());
        let _ = writeln!(
            summary,
            "  {label:<26} τ_p {t0:+.1} .. {t1:+.1} N m, F_p normal {n0:+.1} .. {n1:+.1} N, shear {s0:+.1} .. {s1:+.1} N"
        );
    }
    let swing_change = cycle
        .iter()
        .zip(&lighter)
        .filter(|(&k, _)| frames[k].time > RIGHT_TOE_OFF)
        .map(|(&k, l)| (frames[k].socket.torque - l.socket.torque).abs())
        .fold(0.0_f64, f64::max);
    let _ = writeln!(
        summary,
        "  largest change of τ_p in swing from the lighter limb: {swing_change:.1} N m"
    );
    print!("{summary}");
    std::fs::write(args.out.join("summary.txt"), &summary)?;

    // Figures.
    let time: Vec<f64> = frames.iter().map(|f| f.time).collect();
    let edges = (time[EDGE_FRAMES], time[time.len() - 1 - EDGE_FRAMES]);
    let series = |k: usize, scale: f64| {
        frames
            .iter()
            .map(|f| f.loads[k] * scale)
            .collect::<Vec<_>>()
    };
    plot_time(
        &args.out.join("joint_moments.svg"),
        "Joint moments, subject01 (internal, data README signs)",
        "moment / body mass (N m/kg)",
        &time,
        edges,
        &[
            ("hip flexion r (+ flexor)", RED, series(3, 1.0 / mass)),
            ("knee r (+ extensor)", BLUE, series(4, 1.0 / mass)),
            ("ankle r (+ dorsiflexor)", GREEN, series(5, 1.0 / mass)),
            (
                "hip flexion l",
                RGBColor(255, 140, 0),
                series(6, 1.0 / mass),
            ),
            ("knee l", CYAN, series(7, 1.0 / mass)),
            ("ankle l", MAGENTA, series(8, 1.0 / mass)),
            ("lumbar (+ extensor)", BLACK, series(9, 1.0 / mass)),
        ],
    )?;
    plot_time(
        &args.out.join("residuals.svg"),
        "Pelvis residuals (zero for consistent data)",
        "force (% body weight) / moment (N m)",
        &time,
        edges,
        &[
            ("residual force x (% BW)", RED, series(1, 100.0 / weight)),
            ("residual force y (% BW)", BLUE, series(2, 100.0 / weight)),
            ("residual moment (N m)", BLACK, series(0, 1.0)),
        ],
    )?;
    let cycle_percent: Vec<f64> = cycle.iter().map(|&k| percent(frames[k].time)).collect();
    let socket = |set: &[Frame], pick: fn(&Frame) -> f64| set.iter().map(pick).collect::<Vec<_>>();
    plot_cycle(
        &args.out.join("socket_loads.svg"),
        &cycle_percent,
        percent(RIGHT_TOE_OFF),
        &[
            (
                "τ_p, own limb (N m)",
                RED,
                false,
                socket(&own, |f| f.socket.torque),
            ),
            (
                "τ_p, prosthesis (N m)",
                RED,
                true,
                socket(&lighter, |f| f.socket.torque),
            ),
            (
                "F_p normal, own limb (N / 10)",
                BLUE,
                false,
                socket(&own, |f| f.socket.normal / 10.0),
            ),
            (
                "F_p normal, prosthesis (N / 10)",
                BLUE,
                true,
                socket(&lighter, |f| f.socket.normal / 10.0),
            ),
            (
                "shear, own limb (N / 10)",
                GREEN,
                false,
                socket(&own, |f| f.socket.shear / 10.0),
            ),
            (
                "shear, prosthesis (N / 10)",
                GREEN,
                true,
                socket(&lighter, |f| f.socket.shear / 10.0),
            ),
        ],
    )?;
    println!(
        "wrote joint_loads.csv, summary.txt, joint_moments.svg, residuals.svg and socket_loads.svg to {}",
        args.out.display()
    );
    Ok(())
}

type Curve = (&'static str, RGBColor, Vec<f64>);

/// Curves against time, with the filter-distorted edges shaded.
fn plot_time(
    path: &Path,
    title: &str,
    y_label: &str,
    time: &[f64],
    edges: (f64, f64),
    curves: &[Curve],
) -> Result<(), Box<dyn std::error::Error>> {
    let (lo, hi) = range(curves.iter().flat_map(|c| c.2.iter()));
    let root = SVGBackend::new(path, (900, 480)).into_drawing_area();
    root.fill(&WHITE)?;
    let (t0, t1) = (time[0], time[time.len() - 1]);
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(t0..t1, lo..hi)?;
    chart
        .configure_mesh()
        .x_desc("time (s); grey: first and last 5 frames, distorted by the source filter")
        .y_desc(y_label)
        .draw()?;
    let grey = RGBColor(215, 215, 215).filled();
    chart.draw_series([
        Rectangle::new([(t0, lo), (edges.0, hi)], grey),
        Rectangle::new([(edges.1, lo), (t1, hi)], grey),
    ])?;
    for (label, colour, values) in curves {
        let style = ShapeStyle::from(colour).stroke_width(2);
        chart
            .draw_series(LineSeries::new(
                time.iter().copied().zip(values.iter().copied()),
                style,
            ))?
            .label(*label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], style));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()?;
    root.present()?;
    Ok(())
}

/// Socket loads over the right gait cycle, solid for the own limb and
/// dashed for the prosthesis, toe off marked.
fn plot_cycle(
    path: &Path,
    percent: &[f64],
    toe_off: f64,
    curves: &[(&'static str, RGBColor, bool, Vec<f64>)],
) -> Result<(), Box<dyn std::error::Error>> {
    let (lo, hi) = range(curves.iter().flat_map(|c| c.3.iter()));
    let root = SVGBackend::new(path, (900, 520)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Load on the residual thigh at the socket, right gait cycle",
            ("sans-serif", 20),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..100.0, lo..hi)?;
    chart
        .configure_mesh()
        .x_desc(format!(
            "% of right gait cycle (heel strike 0.618 s; toe off at {toe_off:.0} %)"
        ))
        .y_desc("torque (N m) / force (N / 10), thigh frame")
        .draw()?;
    chart.draw_series(LineSeries::new(
        [(toe_off, lo), (toe_off, hi)],
        BLACK.mix(0.4),
    ))?;
    for (label, colour, dashed, values) in curves {
        let style = ShapeStyle::from(colour).stroke_width(2);
        let points: Vec<(f64, f64)> = percent
            .iter()
            .copied()
            .zip(values.iter().copied())
            .collect();
        if *dashed {
            chart
                .draw_series(DashedLineSeries::new(points, 6, 4, style))?
                .label(*label)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 6, y)], style));
        } else {
            chart
                .draw_series(LineSeries::new(points, style))?
                .label(*label)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], style));
        }
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::LowerRight)
        .draw()?;
    root.present()?;
    Ok(())
}

/// The values' range with a margin.
fn range<'a>(values: impl Iterator<Item = &'a f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((0.0_f64, 0.0_f64), |(lo, hi), &y| (lo.min(y), hi.max(y)));
    let pad = 0.08 * (hi - lo).max(1e-9);
    (lo - pad, hi + pad)
}
