//! The first seed's gait example: inverse dynamics of the planar human
//! model over one (synthetic) gait cycle, and the load at the socket of a
//! right transfemoral prosthesis.
//!
//! ```text
//! cargo run -p rodyn-host-tests --example gait_prosthesis --release [-- --out DIR]
//! ```
//!
//! Reads `host-tests/data/gait/` (written by the `gait_data` example),
//! prints peak values and the floating-base residual, and writes the
//! figures of `docs/sections/gait.md` into `DIR` (by default `docs/img/gait/`).

#[path = "../tests/gait_support/mod.rs"]
#[allow(dead_code)]
mod gait_support;

use gait_support::data::{data_dir, GaitCycle, GroundReaction};
use gait_support::gait_planar::{v, MODEL_F32, MODEL_F64};
use gait_support::inverse_dynamics::{gait_inverse_dynamics, GaitData, GaitFrame};
use plotters::prelude::*;
use rodyn_cli::writable_dir;
use rodyn_plot_markers::{marker, sparse, ShapesByColour};
use std::path::{Path, PathBuf};

/// One curve of a figure: label, colour, values over the cycle.
type Curve = (&'static str, RGBColor, Vec<f64>);

/// Markers drawn on each curve.
const MARKERS_PER_CURVE: usize = 10;

/// Width of the legend column right of the plot (px).
const LEGEND_WIDTH: u32 = 250;

/// Draws curves against percent of the gait cycle into an SVG, the legend
/// in a column beside the plot so that it covers no curve. A curve whose
/// label starts with "left" is dashed: colour tells the quantity, the line
/// the side.
fn plot(
    path: &Path,
    title: &str,
    y_label: &str,
    curves: &[Curve],
) -> Result<(), Box<dyn std::error::Error>> {
    let (lo, hi) = curves
        .iter()
        .flat_map(|c| c.2.iter())
        .fold((0.0_f64, 0.0_f64), |(lo, hi), &y| (lo.min(y), hi.max(y)));
    let pad = 0.08 * (hi - lo).max(1e-9);
    let root = SVGBackend::new(path, (720 + LEGEND_WIDTH, 420)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(title, ("sans-serif", 20))?;
    let (plot_area, legend_area) = root.split_horizontally(720);
    let mut chart = ChartBuilder::on(&plot_area)
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..100.0, (lo - pad)..(hi + pad))?;
    chart
        .configure_mesh()
        .x_desc("% of gait cycle (0 = right heel strike; right toe off at 60 %)")
        .y_desc(y_label)
        .draw()?;
    let font = ("sans-serif", 14).into_font().color(&BLACK);
    let mut shapes = ShapesByColour::default();
    for (k, (label, colour, values)) in curves.iter().enumerate() {
        let n = values.len() - 1;
        let style = ShapeStyle::from(colour).stroke_width(2);
        let points: Vec<(f64, f64)> = values
            .iter()
            .enumerate()
            .map(|(k, &y)| (100.0 * k as f64 / n as f64, y))
            .collect();
        let shape = shapes.shape(*colour);
        chart.draw_series(
            sparse(&points, shape, MARKERS_PER_CURVE)
                .map(|p| EmptyElement::at(p) + marker(shape, *colour, (0, 0))),
        )?;
        let y = 30 + 22 * k as i32;
        if label.starts_with("left") {
            chart.draw_series(DashedLineSeries::new(points, 6, 4, style))?;
            legend_area.draw(&PathElement::new(vec![(4, y), (12, y)], style))?;
            legend_area.draw(&PathElement::new(vec![(18, y), (26, y)], style))?;
        } else {
            chart.draw_series(LineSeries::new(points, style))?;
            legend_area.draw(&PathElement::new(vec![(4, y), (26, y)], style))?;
        }
        legend_area.draw(&marker(shape, *colour, (15, y)))?;
        legend_area.draw(&Text::new(*label, (32, y - 8), font.clone()))?;
    }
    root.present()?;
    Ok(())
}

/// Index and value of the largest |value|.
fn peak(values: &[f64]) -> (usize, f64) {
    values
        .iter()
        .copied()
        .enumerate()
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        .unwrap_or((0, 0.0))
}

/// `--out DIR`, or the docs' figure directory.
fn output_dir() -> Result<PathBuf, String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [] => Ok(Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/img/gait")),
        [flag, dir] if flag == "--out" => Ok(PathBuf::from(dir)),
        _ => Err(format!(
            "unexpected arguments {args:?}; usage: gait_prosthesis [--out DIR]"
        )),
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    rodyn_plot_markers::register_sans_serif();
    let img = output_dir()?;
    writable_dir(&img)?;
    let cycle = GaitCycle::read(&data_dir().join("joint_fourier.csv"))?;
    let reactions = GroundReaction::read_all(&data_dir().join("ground_reaction.csv"))?;
    let mass = MODEL_F64.total_mass();
    let weight = mass * 9.81;
    let mut data = Box::new(GaitData::<f64>::new());
    let mut data32 = Box::new(GaitData::<f32>::new());
    let mut frames: Vec<GaitFrame<f64>> = Vec::new();
    let mut f32_error = 0.0_f64;
    for r in &reactions {
        let (q, v, a) = cycle.state(r.time);
        let frame = gait_inverse_dynamics(&MODEL_F64, &mut data, (&q, &v, &a), &r.right, &r.left)?;
        let cast = |x: &[f64; 10]| x.map(|x| x as f32);
        let frame32 = gait_inverse_dynamics(
            &MODEL_F32,
            &mut data32,
            (&cast(&q), &cast(&v), &cast(&a)),
            &r.right,
            &r.left,
        )?;
        let scale = weight; // errors relative to body weight (N) or BW·m (N m)
        for (x, y) in frame.tau.iter().zip(&frame32.tau) {
            f32_error = f32_error.max((x - f64::from(*y)).abs() / scale);
        }
        frames.push(frame);
    }
    let series = |f: &dyn Fn(&GaitFrame<f64>) -> f64| frames.iter().map(f).collect::<Vec<_>>();
    let per_kg = |f: &dyn Fn(&GaitFrame<f64>) -> f64| series(&|g| f(g) / mass);

    // Floating-base residual: zero only for dynamically consistent data.
    let residual_force = series(&|g| g.tau[0].hypot(g.tau[1]) / weight);
    let residual_moment = series(&|g| g.tau[2]);
    let rms = |x: &[f64]| (x.iter().map(|x| x * x).sum::<f64>() / x.len() as f64).sqrt();
    let (at_f, max_f) = peak(&residual_force);
    let (at_m, max_m) = peak(&residual_moment);
    rodyn_cli::outln!(
        "body mass {mass:.2} kg, {} samples over {:.2} s",
        frames.len(),
        cycle.period()
    );
    rodyn_cli::outln!(
        "pelvis residual force: peak {max_f:.3} BW at {at_f} %, RMS {:.3} BW",
        rms(&residual_force)
    );
    rodyn_cli::outln!(
        "pelvis residual moment: peak {max_m:.1} N m at {at_m} %, RMS {:.1} N m",
        rms(&residual_moment)
    );
    rodyn_cli::outln!(
        "f32 against f64: largest torque difference {f32_error:.2e} BW (N m per N of body weight)"
    );

    // Clinical signs: hip flexor, knee extensor, ankle plantarflexor positive
    // (internal moments; the model's torques turn counter-clockwise about z).
    let joints: [(&str, usize, f64); 7] = [
        ("right hip (flexor +)", v::R_HIP, 1.0),
        ("right knee (extensor +)", v::R_KNEE, 1.0),
        ("right ankle (plantarflexor +)", v::R_ANKLE, -1.0),
        ("left hip (flexor +)", v::L_HIP, 1.0),
        ("left knee (extensor +)", v::L_KNEE, 1.0),
        ("left ankle (plantarflexor +)", v::L_ANKLE, -1.0),
        ("sacroiliac (trunk extensor −)", v::SACROILIAC, 1.0),
    ];
    rodyn_cli::outln!("\n| joint moment | peak (N m/kg) | at % of cycle |\n|---|---|---|");
    let mut torque_curves = Vec::new();
    // Left joints dashed in the right joints' colours.
    let colours = [RED, BLUE, GREEN, RED, BLUE, GREEN, BLACK];
    for ((name, k, sign), colour) in joints.iter().zip(colours) {
        let values = per_kg(&|g| sign * g.tau[*k]);
        let (at, value) = peak(&values);
        rodyn_cli::outln!("| {name} | {value:.3} | {at} |");
        torque_curves.push((*name, colour, values));
    }
    let torque = per_kg(&|g| g.interface.torque);
    let normal = per_kg(&|g| g.interface.normal);
    let shear = per_kg(&|g| g.interface.shear);
    rodyn_cli::outln!("\n| socket load | peak | at % of cycle |\n|---|---|---|");
    for (name, unit, values) in [
        ("τ_p", "N m/kg", &torque),
        ("F_p", "N/kg", &normal),
        ("shear", "N/kg", &shear),
    ] {
        let (at, value) = peak(values);
        rodyn_cli::outln!("| {name} | {value:.3} {unit} | {at} |");
    }

    plot(
        &img.join("joint_moments.svg"),
        "Joint moments over the gait cycle (synthetic data)",
        "moment / body mass (N m/kg)",
        &torque_curves,
    )?;
    plot(
        &img.join("socket_torque.svg"),
        "Socket interface torque τ_p (right transfemoral prosthesis)",
        "τ_p / body mass (N m/kg)",
        &[(
            "τ_p about z at the socket (+ towards hip flexion)",
            RED,
            torque,
        )],
    )?;
    plot(
        &img.join("socket_forces.svg"),
        "Socket interface forces (thigh frame)",
        "force / body mass (N/kg)",
        &[
            ("F_p along the thigh (+ compression)", BLUE, normal),
            ("shear along thigh x (+ anterior)", GREEN, shear),
        ],
    )?;
    let deg = |k: usize| {
        series(&|_| 0.0)
            .iter()
            .enumerate()
            .map(|(j, _)| cycle.coordinates[k].evaluate(reactions[j].time)[0].to_degrees())
            .collect::<Vec<_>>()
    };
    plot(
        &img.join("joint_angles.svg"),
        "Input: right joint angles (model convention, synthetic)",
        "angle (deg)",
        &[
            ("right hip (flexion +)", RED, deg(7)),
            ("right knee (flexion −)", BLUE, deg(8)),
            ("right ankle (dorsiflexion +)", GREEN, deg(9)),
            ("pelvis pitch (anterior tilt −)", BLACK, deg(2)),
        ],
    )?;
    let bw = |f: &dyn Fn(&GroundReaction) -> f64| {
        reactions.iter().map(|r| f(r) / weight).collect::<Vec<_>>()
    };
    plot(
        &img.join("ground_reaction.svg"),
        "Input: ground reaction forces (synthetic)",
        "force (body weights)",
        &[
            ("right vertical", RED, bw(&|r| r.right.force[1])),
            (
                "right anterior",
                RGBColor(255, 140, 0),
                bw(&|r| r.right.force[0]),
            ),
            ("left vertical", RED, bw(&|r| r.left.force[1])),
            (
                "left anterior",
                RGBColor(255, 140, 0),
                bw(&|r| r.left.force[0]),
            ),
        ],
    )?;
    rodyn_cli::outln!("\nwrote {}", img.display());
    Ok(())
}
