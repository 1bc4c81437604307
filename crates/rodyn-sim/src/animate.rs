//! Animated GIF of a model's stick figure, seen from the side (x-z plane;
//! a planar model's own plane).

use crate::plot::init_fonts;
use crate::trajectory::Trajectory;
use plotters::prelude::*;
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::planar::{Planar, Vec2};
use rodyn::spatial::{Spatial, Vec3};
use rodyn::{Data, Endpoint, Model};
use std::path::Path;

/// A line between two world points (m).
type Segment = (Vec3<f64>, Vec3<f64>);

/// Writes one frame per `frame_interval` seconds of `trajectory` (at most
/// 200 frames) to an animated GIF, 480 x 360 px. Lines join each body's
/// origin to its parent's and to the endpoints on it; the ground is z = 0.
/// `follow_x` keeps the first body centred horizontally (a walking robot).
pub fn stick_figure_gif<const NB: usize, const NQ: usize, const NV: usize>(
    path: &Path,
    model: &Model<f64, NB, NQ, NV, Spatial>,
    endpoints: &[Endpoint<f64>],
    trajectory: &Trajectory,
    frame_interval: f64,
    follow_x: bool,
) -> Result<usize, Box<dyn std::error::Error>> {
    init_fonts();
    let mut data = Data::new();
    // Segments of every sampled frame in world coordinates.
    let mut frames: Vec<(f64, Vec<Segment>)> = Vec::new();
    let mut next_t = 0.0;
    for (t, q) in trajectory.t.iter().zip(&trajectory.q) {
        if *t + 1e-9 < next_t || frames.len() >= 200 {
            continue;
        }
        next_t = t + frame_interval;
        // Widened f32 quaternions are unit only to f32 precision.
        let mut q: [f64; NQ] = q.as_slice().try_into()?;
        model.normalize(&mut q)?;
        forward_kinematics(model, &mut data, &q)?;
        let mut segments = Vec::new();
        for i in 0..NB {
            let here = data.o_m_i[i].trans;
            let parent = match model.parent(i) {
                Some(p) => data.o_m_i[p].trans,
                None => here,
            };
            segments.push((parent, here));
        }
        for e in endpoints {
            if let Some(b) = e.body {
                segments.push((data.o_m_i[b].trans, e.world_position(&data.o_m_i)?));
            }
        }
        frames.push((*t, segments));
    }
    draw_frames(path, &frames, frame_interval, follow_x, true)
}

/// The same for a planar model, whose x-y plane is drawn as the picture's
/// x-z plane (there is no ground). Lines join each body's origin to its
/// parent's and to `endpoints`; each of `polylines` (a muscle's path) is
/// drawn through its points.
pub fn planar_stick_figure_gif<const NB: usize, const NQ: usize, const NV: usize>(
    path: &Path,
    model: &Model<f64, NB, NQ, NV, Planar>,
    endpoints: &[Endpoint<f64, Planar>],
    polylines: &[&[Endpoint<f64, Planar>]],
    trajectory: &Trajectory,
    frame_interval: f64,
) -> Result<usize, Box<dyn std::error::Error>> {
    init_fonts();
    let mut data = Data::new();
    let in_picture = |p: Vec2<f64>| Vec3::new(p.x, 0.0, p.y);
    let mut frames: Vec<(f64, Vec<Segment>)> = Vec::new();
    let mut next_t = 0.0;
    for (t, q) in trajectory.t.iter().zip(&trajectory.q) {
        if *t + 1e-9 < next_t || frames.len() >= 200 {
            continue;
        }
        next_t = t + frame_interval;
        let q: [f64; NQ] = q.as_slice().try_into()?;
        forward_kinematics(model, &mut data, &q)?;
        let mut segments = Vec::new();
        for i in 0..NB {
            let here = data.o_m_i[i].trans;
            let parent = model.parent(i).map_or(here, |p| data.o_m_i[p].trans);
            segments.push((in_picture(parent), in_picture(here)));
        }
        for e in endpoints {
            if let Some(b) = e.body {
                segments.push((
                    in_picture(data.o_m_i[b].trans),
                    in_picture(e.world_position(&data.o_m_i)?),
                ));
            }
        }
        for line in polylines {
            for pair in line.windows(2) {
                segments.push((
                    in_picture(pair[0].world_position(&data.o_m_i)?),
                    in_picture(pair[1].world_position(&data.o_m_i)?),
                ));
            }
        }
        frames.push((*t, segments));
    }
    draw_frames(path, &frames, frame_interval, false, false)
}

/// Draws `frames` (time, world segments) into an animated GIF, 480 x 360 px,
/// in a fixed view box that holds every frame. `follow_x` keeps the first
/// segment's end centred horizontally; `ground` draws the line z = 0.
fn draw_frames(
    path: &Path,
    frames: &[(f64, Vec<Segment>)],
    frame_interval: f64,
    follow_x: bool,
    ground: bool,
) -> Result<usize, Box<dyn std::error::Error>> {
    // A fixed view box that holds every frame (relative to the followed body).
    let (mut x0, mut x1, mut z0, mut z1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    if ground {
        z0 = 0.0;
    }
    for (_, segs) in frames {
        let cx = if follow_x { segs[0].1.x } else { 0.0 };
        for (a, b) in segs {
            for p in [a, b] {
                x0 = x0.min(p.x - cx);
                x1 = x1.max(p.x - cx);
                z0 = z0.min(p.z);
                z1 = z1.max(p.z);
            }
        }
    }
    let span = ((x1 - x0).max(z1 - z0) * 1.3).max(0.05);
    let (xc, zc) = ((x0 + x1) / 2.0, (z0 + z1) / 2.0);
    let delay = (frame_interval * 1000.0).round().max(20.0) as u32;
    let root = BitMapBackend::gif(path, (480, 360), delay)?.into_drawing_area();
    for (t, segs) in frames {
        root.fill(&WHITE)?;
        let cx = if follow_x { segs[0].1.x } else { 0.0 };
        let half_w = span * 0.5 * 480.0 / 360.0;
        let mut chart = ChartBuilder::on(&root)
            .caption(format!("t = {t:.2} s"), ("sans-serif", 16))
            .margin(8)
            .build_cartesian_2d(
                (xc - half_w)..(xc + half_w),
                (zc - span * 0.5)..(zc + span * 0.5),
            )?;
        if ground {
            chart.draw_series(LineSeries::new(
                [(xc - half_w, 0.0), (xc + half_w, 0.0)],
                RGBColor(120, 90, 60).stroke_width(2),
            ))?;
        }
        for (a, b) in segs {
            chart.draw_series(LineSeries::new(
                [(a.x - cx, a.z), (b.x - cx, b.z)],
                RGBColor(31, 119, 180).stroke_width(3),
            ))?;
            chart.draw_series([Circle::new((b.x - cx, b.z), 3, BLACK.filled())])?;
        }
        root.present()?;
    }
    Ok(frames.len())
}
