//! `rodyn-model render`: a stick figure of a model at a configuration, as
//! SVG, from rodyn's forward kinematics on the run-time model.
//!
//! Bodies are lines from their parent's joint to their own joint and on to
//! their endpoints; joints are circles, endpoints dots; springs, dampers and
//! muscles are polylines through their endpoints.

use crate::description::ForceLaw;
use crate::runtime::RuntimeModel;
use rodyn::spatial::Vec3;
use std::fmt::Write;

/// Where the picture looks from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// The x-y plane (planar models), y up.
    Xy,
    /// The x-z plane (side view of a z-up robot), z up.
    Xz,
    /// The y-z plane (front view), z up.
    Yz,
    /// Isometric, z up.
    Isometric,
}

impl View {
    /// Parses `xy`, `xz`, `yz` or `iso`.
    #[must_use]
    pub fn parse(s: &str) -> Option<Self> {
        Some(match s {
            "xy" => Self::Xy,
            "xz" => Self::Xz,
            "yz" => Self::Yz,
            "iso" => Self::Isometric,
            _ => return None,
        })
    }
    /// Picture coordinates (right, up) of a world point.
    fn project(self, p: &Vec3<f64>) -> (f64, f64) {
        match self {
            Self::Xy => (p.x, p.y),
            Self::Xz => (p.x, p.z),
            Self::Yz => (p.y, p.z),
            Self::Isometric => {
                let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
                ((p.x - p.y) * c, p.z + (p.x + p.y) * s)
            }
        }
    }
}

/// The SVG picture of `model` at `q` (the file's layout), `width` pixels wide.
///
/// # Errors
/// An invalid configuration.
pub fn render_svg(
    model: &RuntimeModel,
    q: &[f64],
    view: View,
    width: f64,
) -> Result<String, crate::runtime::RuntimeError> {
    let d = model.description();
    let poses = model.body_poses(q)?;
    let endpoints = model.endpoint_positions(&poses);
    let joint_at = |i: usize| view.project(&poses[i].trans);
    let origin = view.project(&Vec3::ZERO);
    // Segments: parent joint -> joint, joint -> each endpoint on the body.
    let mut segments: Vec<((f64, f64), (f64, f64))> = Vec::new();
    for (i, b) in d.bodies.iter().enumerate() {
        let from = b.parent.map_or(origin, joint_at);
        if b.parent.is_some()
            || !matches!(
                b.joint,
                crate::description::JointType::FreeFlyer
                    | crate::description::JointType::PlanarFloating
            )
        {
            segments.push((from, joint_at(i)));
        }
    }
    for (e, p) in d.endpoints.iter().zip(&endpoints) {
        if let Some(b) = e.body {
            segments.push((joint_at(b), view.project(p)));
        }
    }
    let mut points: Vec<(f64, f64)> = segments.iter().flat_map(|(a, b)| [*a, *b]).collect();
    points.push(origin);
    points.extend(endpoints.iter().map(|p| view.project(p)));
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (x, y) in &points {
        x0 = x0.min(*x);
        x1 = x1.max(*x);
        y0 = y0.min(*y);
        y1 = y1.max(*y);
    }
    let span = (x1 - x0).max(y1 - y0).max(1e-3);
    let margin = 0.08 * span;
    let scale = width / (x1 - x0 + 2.0 * margin).max(span * 0.5);
    let height = (y1 - y0 + 2.0 * margin) * scale;
    let px = |(x, y): (f64, f64)| ((x - x0 + margin) * scale, (y1 + margin - y) * scale);
    let stroke = (span * scale / 150.0).max(1.5);
    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0}" height="{height:.0}" viewBox="0 0 {width:.1} {height:.1}">"#
    );
    let _ = writeln!(svg, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let _ = writeln!(
        svg,
        r#"<title>{} ({} bodies, nq = {}, nv = {})</title>"#,
        d.name,
        d.bodies.len(),
        d.nq(),
        d.nv()
    );
    // Ground line through the world origin for planar and side views.
    let (gx0, gy) = px((x0 - margin, origin.1));
    let (gx1, _) = px((x1 + margin, origin.1));
    let _ = writeln!(
        svg,
        r##"<line x1="{gx0:.1}" y1="{gy:.1}" x2="{gx1:.1}" y2="{gy:.1}" stroke="#bbb" stroke-width="1" stroke-dasharray="4 4"/>"##
    );
    for (a, b) in &segments {
        let ((ax, ay), (bx, by)) = (px(*a), px(*b));
        let _ = writeln!(
            svg,
            r##"<line x1="{ax:.1}" y1="{ay:.1}" x2="{bx:.1}" y2="{by:.1}" stroke="#334" stroke-width="{stroke:.1}" stroke-linecap="round"/>"##
        );
    }
    for f in &d.force_elements {
        let colour = match f.law {
            ForceLaw::Spring { .. } => "#1f77b4",
            ForceLaw::Damper { .. } => "#2ca02c",
            ForceLaw::Muscle { .. } => "#d62728",
        };
        let pts = f.path.iter().map(|&e| {
            let (x, y) = px(view.project(&endpoints[e]));
            format!("{x:.1},{y:.1}")
        });
        let _ = writeln!(
            svg,
            r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="{:.1}" opacity="0.8"/>"#,
            pts.collect::<Vec<_>>().join(" "),
            stroke * 0.6
        );
    }
    for i in 0..d.bodies.len() {
        let (x, y) = px(joint_at(i));
        let _ = writeln!(
            svg,
            r##"<circle cx="{x:.1}" cy="{y:.1}" r="{:.1}" fill="white" stroke="#334" stroke-width="{:.1}"/>"##,
            stroke * 1.6,
            stroke * 0.6
        );
    }
    draw_axes_and_scale(&mut svg, view, span, scale, stroke, &px, (x0, y0, margin));
    for (e, p) in d.endpoints.iter().zip(&endpoints) {
        let (x, y) = px(view.project(p));
        let colour = if d
            .contacts
            .iter()
            .any(|c| d.endpoints[c.endpoint].name == e.name)
        {
            "#ff7f0e"
        } else {
            "#9467bd"
        };
        let _ = writeln!(
            svg,
            r#"<circle cx="{x:.1}" cy="{y:.1}" r="{:.1}" fill="{colour}"><title>{}</title></circle>"#,
            stroke * 1.1,
            e.name
        );
    }
    let _ = writeln!(svg, "</svg>");
    Ok(svg)
}

/// The length of the scale bar, m: 1, 2 or 5 times a power of ten, about a
/// fifth of the picture's `span` (m).
#[must_use]
pub fn scale_bar_length(span: f64) -> f64 {
    let target = 0.2 * span;
    let power = 10f64.powf(target.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|k| k * power)
        .find(|&l| l <= target)
        .unwrap_or(power)
}

/// The world axes at the origin (x red, y green, z blue, as long as the
/// scale bar, each labelled; an axis seen end-on is left out) and a scale
/// bar in the lower left corner labelled in metres.
fn draw_axes_and_scale(
    svg: &mut String,
    view: View,
    span: f64,
    scale: f64,
    stroke: f64,
    px: &dyn Fn((f64, f64)) -> (f64, f64),
    (x0, y0, margin): (f64, f64, f64),
) {
    let length = scale_bar_length(span);
    let origin = px(view.project(&Vec3::ZERO));
    for (axis, name, colour) in [
        (Vec3::new(length, 0.0, 0.0), "x", "#d62728"),
        (Vec3::new(0.0, length, 0.0), "y", "#2ca02c"),
        (Vec3::new(0.0, 0.0, length), "z", "#1f77b4"),
    ] {
        let tip = px(view.project(&axis));
        if (tip.0 - origin.0).hypot(tip.1 - origin.1) < 2.0 {
            continue;
        }
        let _ = writeln!(
            svg,
            r#"<line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{colour}" stroke-width="{:.1}"/>"#,
            origin.0,
            origin.1,
            tip.0,
            tip.1,
            stroke * 0.6
        );
        let _ = writeln!(
            svg,
            r#"<text x="{:.1}" y="{:.1}" font-family="sans-serif" font-size="12" fill="{colour}">{name}</text>"#,
            tip.0 + 3.0,
            tip.1 - 3.0
        );
    }
    // The bar sits half a margin in from the lower left corner.
    let (bx, by) = px((x0 - 0.5 * margin, y0 - 0.5 * margin));
    let bar = length * scale;
    let label = if length >= 1.0 {
        format!("{length} m")
    } else {
        format!("{} mm", (length * 1000.0).round())
    };
    let _ = writeln!(
        svg,
        r##"<path d="M {bx:.1} {:.1} V {by:.1} H {:.1} V {:.1}" fill="none" stroke="#333" stroke-width="1.5"/>"##,
        by - 4.0,
        bx + bar,
        by - 4.0
    );
    let _ = writeln!(
        svg,
        r##"<text x="{:.1}" y="{:.1}" font-family="sans-serif" font-size="12" fill="#333" text-anchor="middle">{label}</text>"##,
        bx + 0.5 * bar,
        by - 6.0
    );
}

#[cfg(test)]
mod tests {
    use super::scale_bar_length;

    #[test]
    fn the_scale_bar_is_a_round_fifth_of_the_picture() {
        for (span, want) in [
            (1.0, 0.2),
            (1.2, 0.2),
            (0.3, 0.05),
            (2.6, 0.5),
            (6.0, 1.0),
            (0.012, 0.002),
        ] {
            let got = scale_bar_length(span);
            assert!((got - want).abs() < 1e-12 * want, "span {span}: {got}");
        }
    }
}
