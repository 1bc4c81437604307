//! # rodyn-plot-markers
//!
//! The point markers of rodyn's figures: a curve gets a shape as well as a
//! colour, so that a reader can tell curves apart in grey print, with a
//! colour-vision deficiency, or where two colours are close. Every shape is
//! one filled polygon (the circle an octagon), so that a series of mixed
//! shapes has one element type.
//!
//! ```
//! use plotters::style::RGBColor;
//! use rodyn_plot_markers::{marker, sparse, ShapesByColour};
//! let red = RGBColor(200, 0, 0);
//! let mut shapes = ShapesByColour::default();
//! assert_eq!(shapes.shape(red), 0);
//! assert_eq!(shapes.shape(RGBColor(0, 0, 200)), 1);
//! assert_eq!(shapes.shape(red), 0, "a colour keeps its shape");
//! let points: Vec<(f64, f64)> = (0..100).map(|k| (k as f64, 0.0)).collect();
//! assert_eq!(sparse(&points, 0, 10).count(), 10);
//! let _triangle = marker(1, red, (0, 0));
//! ```
#![warn(missing_docs)]

mod font;

pub use font::register_sans_serif;
use plotters::element::Polygon;
use plotters::style::{Color, RGBColor};

/// Marker outlines around their anchor, pixels (y down): circle (an
/// octagon), triangle, square, diamond. Each fits a 10 px box, large
/// enough to read beside a 2 px line.
pub const SHAPES: [&[(i32, i32)]; 4] = [
    &[
        (2, -4),
        (4, -2),
        (4, 2),
        (2, 4),
        (-2, 4),
        (-4, 2),
        (-4, -2),
        (-2, -4),
    ],
    &[(0, -5), (5, 4), (-5, 4)],
    &[(-4, -4), (4, -4), (4, 4), (-4, 4)],
    &[(0, -5), (5, 0), (0, 5), (-5, 0)],
];

/// Marker `shape` (an index into [`SHAPES`], taken modulo its length)
/// filled with `colour`, centred `at` pixels from its anchor (a legend
/// entry puts it on its sample line; on a curve it is `(0, 0)`).
#[must_use]
pub fn marker(shape: usize, colour: RGBColor, at: (i32, i32)) -> Polygon<(i32, i32)> {
    let corners = SHAPES[shape % SHAPES.len()]
        .iter()
        .map(|&(x, y)| (at.0 + x, at.1 + y))
        .collect::<Vec<_>>();
    Polygon::new(corners, colour.filled())
}

/// Shapes handed out by colour: the first colour met gets the circle, the
/// next the triangle, and so on; curves of one colour (a quantity's
/// measured and modelled curves, say, told apart by their dashes) share
/// a shape.
#[derive(Clone, Debug, Default)]
pub struct ShapesByColour {
    met: Vec<RGBColor>,
}

impl ShapesByColour {
    /// The shape index of `colour`.
    pub fn shape(&mut self, colour: RGBColor) -> usize {
        if let Some(k) = self.met.iter().position(|c| *c == colour) {
            return k;
        }
        self.met.push(colour);
        self.met.len() - 1
    }
}

/// About `count` evenly spaced points of `points` to put markers on, the
/// first shifted along by a share of the spacing that grows with `shape`:
/// curves that run together (an idle muscle's, both legs' at rest) then
/// show their markers side by side instead of on top of one another.
pub fn sparse(
    points: &[(f64, f64)],
    shape: usize,
    count: usize,
) -> impl Iterator<Item = (f64, f64)> + '_ {
    let step = (points.len() / count.max(1)).max(1);
    let first = ((shape % SHAPES.len()) * step / SHAPES.len()).min(points.len().saturating_sub(1));
    points.iter().copied().skip(first).step_by(step)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markers_are_centred_on_their_anchor() {
        for (k, shape) in SHAPES.iter().enumerate() {
            let (xs, ys): (Vec<i32>, Vec<i32>) = shape.iter().copied().unzip();
            let (left, right) = (*xs.iter().min().unwrap(), *xs.iter().max().unwrap());
            assert_eq!(left, -right, "shape {k} is not centred in x");
            let (top, bottom) = (*ys.iter().min().unwrap(), *ys.iter().max().unwrap());
            assert!(
                (top + bottom).abs() <= 1,
                "shape {k} is off centre in y by {}",
                top + bottom
            );
        }
    }

    #[test]
    fn sparse_markers_of_neighbouring_shapes_do_not_coincide() {
        let points: Vec<(f64, f64)> = (0..200).map(|k| (f64::from(k), 0.0)).collect();
        let circles: Vec<f64> = sparse(&points, 0, 10).map(|p| p.0).collect();
        let triangles: Vec<f64> = sparse(&points, 1, 10).map(|p| p.0).collect();
        assert_eq!(circles.len(), 10);
        assert_eq!(circles[..3], [0.0, 20.0, 40.0]);
        assert_eq!(triangles[..3], [5.0, 25.0, 45.0]);
    }

    #[test]
    fn short_curves_get_a_marker_per_point() {
        let points = [(0.0, 1.0), (1.0, 2.0), (2.0, 3.0)];
        assert_eq!(sparse(&points, 0, 10).count(), 3);
        assert_eq!(sparse(&points, 3, 10).count(), 3);
        assert_eq!(sparse(&[], 2, 10).count(), 0);
    }
}
