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
use rodyn_plot_markers::{marker, sparse, ShapesByColour};
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
                rodyn_cli::outln!("{USAGE}");
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
    rodyn_plot_markers::register_sans_serif();
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
    rodyn_cli::out!("{summary}");
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
    let shade_edges = Shading::Spans(vec![(time[0], edges.0), (edges.1, time[time.len() - 1])]);
    let solid = |label, colour, values| Curve {
        label,
        colour,
        dashed: false,
        values,
    };
    plot_panels(
        &args.out.join("joint_moments.svg"),
        "Joint moments, subject01 (internal, data README signs)",
        "time (s); grey: first and last 5 frames, distorted by the source filter",
        &time,
        &shade_edges,
        &[Panel {
            y_label: "moment / body mass (N m/kg)",
            curves: vec![
                solid("hip flexion r (+ flexor)", RED, series(3, 1.0 / mass)),
                solid("knee r (+ extensor)", BLUE, series(4, 1.0 / mass)),
                solid("ankle r (+ dorsiflexor)", GREEN, series(5, 1.0 / mass)),
                Curve {
                    dashed: true,
                    ..solid("hip flexion l", RED, series(6, 1.0 / mass))
                },
                Curve {
                    dashed: true,
                    ..solid("knee l", BLUE, series(7, 1.0 / mass))
                },
                Curve {
                    dashed: true,
                    ..solid("ankle l", GREEN, series(8, 1.0 / mass))
                },
                solid("lumbar (+ extensor)", BLACK, series(9, 1.0 / mass)),
            ],
        }],
    )?;
    plot_panels(
        &args.out.join("residuals.svg"),
        "Pelvis residuals (zero for consistent data)",
        "time (s); grey: first and last 5 frames, distorted by the source filter",
        &time,
        &shade_edges,
        &[
            Panel {
                y_label: "force (% body weight)",
                curves: vec![
                    solid("residual force x", RED, series(1, 100.0 / weight)),
                    solid("residual force y", BLUE, series(2, 100.0 / weight)),
                ],
            },
            Panel {
                y_label: "moment (N m)",
                curves: vec![solid("residual moment", BLACK, series(0, 1.0))],
            },
        ],
    )?;
    let cycle_percent: Vec<f64> = cycle.iter().map(|&k| percent(frames[k].time)).collect();
    let socket = |set: &[Frame], pick: fn(&Frame) -> f64| set.iter().map(pick).collect::<Vec<_>>();
    let toe_off = percent(RIGHT_TOE_OFF);
    plot_panels(
        &args.out.join("socket_loads.svg"),
        "Load on the residual thigh at the socket, right gait cycle (thigh frame)",
        &format!(
            "% of right gait cycle (heel strike 0.618 s; toe off at {toe_off:.0} %, grey line)"
        ),
        &cycle_percent,
        &Shading::Line(toe_off),
        &[
            Panel {
                y_label: "torque τ_p (N m)",
                curves: vec![
                    solid("own limb", RED, socket(&own, |f| f.socket.torque)),
                    Curve {
                        dashed: true,
                        ..solid("prosthesis", RED, socket(&lighter, |f| f.socket.torque))
                    },
                ],
            },
            Panel {
                y_label: "force (N)",
                curves: vec![
                    solid(
                        "normal F_p, own limb",
                        BLUE,
                        socket(&own, |f| f.socket.normal),
                    ),
                    Curve {
                        dashed: true,
                        ..solid(
                            "normal F_p, prosthesis",
                            BLUE,
                            socket(&lighter, |f| f.socket.normal),
                        )
                    },
                    solid("shear, own limb", GREEN, socket(&own, |f| f.socket.shear)),
                    Curve {
                        dashed: true,
                        ..solid(
                            "shear, prosthesis",
                            GREEN,
                            socket(&lighter, |f| f.socket.shear),
                        )
                    },
                ],
            },
        ],
    )?;
    rodyn_cli::outln!(
        "wrote joint_loads.csv, summary.txt, joint_moments.svg, residuals.svg and socket_loads.svg to {}",
        args.out.display()
    );
    Ok(())
}

/// One curve: solid or dashed, its legend label, its values at the
/// figure's x positions.
struct Curve {
    label: &'static str,
    colour: RGBColor,
    dashed: bool,
    values: Vec<f64>,
}

/// One panel: its y axis (one unit) and its curves.
struct Panel {
    y_label: &'static str,
    curves: Vec<Curve>,
}

/// What a figure marks on every panel behind the curves.
enum Shading {
    /// Grey bands over these x spans.
    Spans(Vec<(f64, f64)>),
    /// A grey vertical line at this x.
    Line(f64),
}

/// Markers drawn on each curve.
const MARKERS_PER_CURVE: usize = 10;

/// Width of the legend column to the right of the panels (px).
const LEGEND_WIDTH: u32 = 210;

/// Panels stacked over a shared x axis, each with its own legend in a
/// column to its right, so no legend covers a curve.
fn plot_panels(
    path: &Path,
    title: &str,
    x_label: &str,
    x: &[f64],
    shading: &Shading,
    panels: &[Panel],
) -> Result<(), Box<dyn std::error::Error>> {
    let height = 60 + 400 * panels.len() as u32;
    let root = SVGBackend::new(path, (900 + LEGEND_WIDTH, height)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(title, ("sans-serif", 20))?;
    let (x0, x1) = (x[0], x[x.len() - 1]);
    for (panel, area) in panels.iter().zip(root.split_evenly((panels.len(), 1))) {
        let (plot_area, legend_area) = area.split_horizontally(900);
        let (lo, hi) = range(panel.curves.iter().flat_map(|c| c.values.iter()));
        let mut chart = ChartBuilder::on(&plot_area)
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, lo..hi)?;
        chart
            .configure_mesh()
            .x_desc(x_label)
            .y_desc(panel.y_label)
            .draw()?;
        let grey = RGBColor(215, 215, 215);
        match shading {
            Shading::Spans(spans) => {
                chart.draw_series(
                    spans
                        .iter()
                        .map(|&(a, b)| Rectangle::new([(a, lo), (b, hi)], grey.filled())),
                )?;
            }
            Shading::Line(at) => {
                chart.draw_series(LineSeries::new(
                    [(*at, lo), (*at, hi)],
                    RGBColor(150, 150, 150).stroke_width(1),
                ))?;
            }
        }
        let font = ("sans-serif", 14).into_font().color(&BLACK);
        let mut shapes = ShapesByColour::default();
        for (k, curve) in panel.curves.iter().enumerate() {
            let style = ShapeStyle::from(curve.colour).stroke_width(2);
            let points: Vec<(f64, f64)> = x
                .iter()
                .copied()
                .zip(curve.values.iter().copied())
                .collect();
            let shape = shapes.shape(curve.colour);
            chart.draw_series(
                sparse(&points, shape, MARKERS_PER_CURVE)
                    .map(|p| EmptyElement::at(p) + marker(shape, curve.colour, (0, 0))),
            )?;
            let y = 40 + 24 * k as i32;
            if curve.dashed {
                chart.draw_series(DashedLineSeries::new(points, 6, 4, style))?;
                legend_area.draw(&PathElement::new(vec![(4, y), (12, y)], style))?;
                legend_area.draw(&PathElement::new(vec![(18, y), (26, y)], style))?;
            } else {
                chart.draw_series(LineSeries::new(points, style))?;
                legend_area.draw(&PathElement::new(vec![(4, y), (26, y)], style))?;
            }
            legend_area.draw(&marker(shape, curve.colour, (15, y)))?;
            legend_area.draw(&Text::new(curve.label, (32, y - 8), font.clone()))?;
        }
    }
    root.present()?;
    Ok(())
}

/// The values' range with a margin.
fn range<'a>(values: impl Iterator<Item = &'a f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((0.0_f64, 0.0_f64), |(lo, hi), &y| (lo.min(y), hi.max(y)));
    let pad = 0.08 * (hi - lo).max(1e-9);
    (lo - pad, hi + pad)
}
