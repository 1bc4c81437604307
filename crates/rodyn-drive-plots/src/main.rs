//! Figures for the drives section of the README: the first seed's two-link,
//! four-muscle robot simulated under given excitations, and the sensitivity
//! matrix ∂q̈/∂a along the trajectory.
//!
//! Run from anywhere in the workspace:
//! `cargo run -p rodyn-drive-plots --release [-- --out DIR]`
//! It writes `muscle_robot_trajectory.svg` and `muscle_robot_sensitivity.svg`
//! into `DIR` (by default `docs/img/drives/`), and prints a summary.

use plotters::prelude::*;
use rodyn::algorithm::forward_dynamics::Aba;
use rodyn::sim::{Integrator, Rk4};
use rodyn_cli::writable_dir;
use rodyn_plot_markers::{marker, sparse, ShapesByColour};
use rodyn_scenarios::muscle_robot::{
    self as robot, example_excitation, RobotForces, RobotLoads, INITIAL_ACTIVATION, NU, NV,
};
use std::path::PathBuf;

/// Simulated time (s) and RK4 step (s), as the core example
/// `cargo run -p rodyn-scenarios --example muscle_robot`.
const DURATION: f64 = 2.0;
const DT: f64 = 1e-3;

/// One recorded instant.
struct Sample {
    t: f64,
    q: [f64; NV],
    u: [f64; NU],
    a: [f64; NU],
    sensitivity: [[f64; NU]; NV],
}

/// RK4 (`rodyn::sim::Rk4`, the activations as auxiliary states) under the
/// example's excitations, with the sensitivity matrix recorded every step.
fn simulate() -> Result<Vec<Sample>, rodyn::Error> {
    let model = robot::MODEL_F64;
    let muscles = robot::MUSCLES_F64;
    let mut data = rodyn::Data::new();
    let mut forces = RobotForces::new();
    let mut loads = RobotLoads::new(&muscles, example_excitation::<f64>);
    let mut rk4 = Rk4::default();
    let mut x = robot::rest_state(INITIAL_ACTIVATION);
    let mut samples = Vec::new();
    let steps = (DURATION / DT).round() as usize;
    for n in 0..=steps {
        let mut sensitivity = [[0.0; NU]; NV];
        robot::sensitivity(
            &model,
            &muscles,
            &mut data,
            &x.q,
            &x.v,
            &x.z,
            &mut forces,
            &mut sensitivity,
        )?;
        samples.push(Sample {
            t: x.t,
            q: x.q,
            u: example_excitation(x.t),
            a: x.z,
            sensitivity,
        });
        if n < steps {
            rk4.step(Aba, &model, &mut data, &mut x, DT, &mut loads)?;
        }
    }
    Ok(samples)
}

const MUSCLE_COLORS: [RGBColor; NU] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
];

/// One curve: legend label, colour, dashed or not, points (t, y).
type Series = (String, RGBColor, bool, Vec<(f64, f64)>);

/// Markers drawn on each curve.
const MARKERS_PER_CURVE: usize = 10;

/// Width of the legend column right of each panel (px).
const LEGEND_WIDTH: i32 = 150;

/// Draws one panel of time series, its legend in a column to its right
/// so that the legend covers no curve.
fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    title: &str,
    y_label: &str,
    series: &[Series],
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    let (lo, hi) = series
        .iter()
        .flat_map(|s| s.3.iter().map(|p| p.1))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), y| {
            (lo.min(y), hi.max(y))
        });
    let pad = 0.05 * (hi - lo).max(1e-9);
    let width = area.dim_in_pixel().0 as i32;
    let (plot_area, legend_area) = area.split_horizontally(width - LEGEND_WIDTH);
    let mut chart = ChartBuilder::on(&plot_area)
        .caption(title, ("sans-serif", 18))
        .margin(8)
        .x_label_area_size(32)
        .y_label_area_size(56)
        .build_cartesian_2d(0.0..DURATION, (lo - pad)..(hi + pad))?;
    chart
        .configure_mesh()
        .x_desc("t (s)")
        .y_desc(y_label)
        .light_line_style(WHITE)
        .draw()?;
    let font = ("sans-serif", 14).into_font().color(&BLACK);
    // Each colour also gets a marker shape, a few per curve, so that the
    // curves part without their colours.
    let mut shapes = ShapesByColour::default();
    for (k, (name, color, dashed, points)) in series.iter().enumerate() {
        let shape = shapes.shape(*color);
        chart.draw_series(
            sparse(points, shape, MARKERS_PER_CURVE)
                .map(|p| EmptyElement::at(p) + marker(shape, *color, (0, 0))),
        )?;
        let style = color.stroke_width(2);
        let y = 50 + 22 * k as i32;
        if *dashed {
            chart.draw_series(DashedLineSeries::new(points.iter().copied(), 6, 4, style))?;
            legend_area.draw(&PathElement::new(vec![(4, y), (12, y)], style))?;
            legend_area.draw(&PathElement::new(vec![(18, y), (26, y)], style))?;
        } else {
            chart.draw_series(LineSeries::new(points.iter().copied(), style))?;
            legend_area.draw(&PathElement::new(vec![(4, y), (26, y)], style))?;
        }
        legend_area.draw(&marker(shape, *color, (15, y)))?;
        legend_area.draw(&Text::new(name.clone(), (32, y - 8), font.clone()))?;
    }
    Ok(())
}

/// `--out DIR`, or the docs' figure directory.
fn output_dir() -> Result<PathBuf, String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [] => Ok(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../docs/img/drives")),
        [flag, dir] if flag == "--out" => Ok(PathBuf::from(dir)),
        _ => Err(format!(
            "unexpected arguments {args:?}; usage: rodyn-drive-plots [--out DIR]"
        )),
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    rodyn_plot_markers::register_sans_serif();
    let out = output_dir()?;
    writable_dir(&out)?;
    let samples = simulate()?;

    let trajectory = out.join("muscle_robot_trajectory.svg");
    {
        let root = SVGBackend::new(&trajectory, (900, 640)).into_drawing_area();
        root.fill(&WHITE)?;
        let (top, bottom) = root.split_vertically(300);
        let joint = |i: usize| samples.iter().map(|s| (s.t, s.q[i])).collect::<Vec<_>>();
        panel(
            &top,
            "Muscle robot: joint angles (RK4, dt = 1 ms)",
            "q (rad)",
            &[
                ("q1 shoulder".into(), BLACK, false, joint(0)),
                ("q2 elbow".into(), RGBColor(120, 120, 120), false, joint(1)),
            ],
        )?;
        let mut series = Vec::new();
        for (k, color) in MUSCLE_COLORS.into_iter().enumerate() {
            series.push((
                format!("u{} (excitation)", k + 1),
                color,
                true,
                samples.iter().map(|s| (s.t, s.u[k])).collect(),
            ));
            series.push((
                format!("a{} (activation)", k + 1),
                color,
                false,
                samples.iter().map(|s| (s.t, s.a[k])).collect(),
            ));
        }
        panel(
            &bottom,
            "Excitations u (dashed) and activations a (Thelen 2003)",
            "u, a (fraction of maximum, 0 to 1)",
            &series,
        )?;
        root.present()?;
    }

    let sensitivity = out.join("muscle_robot_sensitivity.svg");
    {
        let root = SVGBackend::new(&sensitivity, (900, 640)).into_drawing_area();
        root.fill(&WHITE)?;
        let (top, bottom) = root.split_vertically(320);
        for (i, (area, joint)) in [(top, "shoulder"), (bottom, "elbow")]
            .into_iter()
            .enumerate()
        {
            let series: Vec<_> = (0..NU)
                .map(|k| {
                    (
                        // Plain text: the legend cannot lay out ∂ or q̈'s
                        // combining accent; the title names the derivative.
                        format!("muscle {} (a{})", k + 1, k + 1),
                        MUSCLE_COLORS[k],
                        false,
                        samples.iter().map(|s| (s.t, s.sensitivity[i][k])).collect(),
                    )
                })
                .collect();
            panel(
                &area,
                &format!("Sensitivity of the {joint} acceleration to the activations"),
                "rad/s² per unit activation",
                &series,
            )?;
        }
        root.present()?;
    }

    let last = samples.last().expect("at least one sample");
    let peak = samples
        .iter()
        .flat_map(|s| s.sensitivity.iter().flatten().map(|x| x.abs()))
        .fold(0.0f64, f64::max);
    rodyn_cli::outln!(
        "{} samples over {DURATION} s; final q = [{:.4}, {:.4}] rad",
        samples.len(),
        last.q[0],
        last.q[1]
    );
    rodyn_cli::outln!("largest |∂q̈/∂a| along the trajectory: {peak:.1} rad/s²");
    rodyn_cli::outln!(
        "wrote {} and {}",
        trajectory.display(),
        sensitivity.display()
    );
    Ok(())
}
