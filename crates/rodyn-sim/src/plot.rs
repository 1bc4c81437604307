//! SVG line and scatter plots, with optional logarithmic axes.
//!
//! Logarithmic axes are drawn by plotting log10 of the data on a linear
//! axis labelled in powers of ten: one code path for every combination.

use plotters::coord::types::RangedCoordf64;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::{register_font, FontStyle};
use std::path::Path;
use std::sync::Once;

/// Points (x, y) of one curve.
pub type Curve = Vec<(f64, f64)>;

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mark {
    /// A line through the points.
    Line,
    /// A thin dashed line (references, fronts).
    ThinLine,
    /// A thin dotted line (a second kind of reference).
    Dotted,
    /// Hollow circles, large enough to show a cross or point drawn at the
    /// same place.
    Rings,
    /// A line with points.
    LinePoints,
    /// Large crosses (failures, limits).
    Crosses,
    /// Filled triangles (a third kind of point).
    Triangles,
}

/// One named series.
#[derive(Clone, Debug)]
pub struct Series {
    /// Legend entry.
    pub name: String,
    /// Points (x, y); non-finite points are skipped.
    pub points: Vec<(f64, f64)>,
    /// How it is drawn.
    pub mark: Mark,
    /// Palette index.
    pub color: usize,
}

impl Series {
    /// A series.
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>, mark: Mark, color: usize) -> Self {
        Self {
            name: name.into(),
            points,
            mark,
            color,
        }
    }
}

/// Axis scale.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scale {
    /// Linear.
    Linear,
    /// Base-10 logarithmic.
    Log,
}

/// A plot's labels and axes.
#[derive(Clone, Debug)]
pub struct Figure<'a> {
    /// Title.
    pub title: &'a str,
    /// x label.
    pub x_label: &'a str,
    /// y label.
    pub y_label: &'a str,
    /// x scale.
    pub x_scale: Scale,
    /// y scale.
    pub y_scale: Scale,
}

/// A qualitative palette readable in print.
pub fn color(index: usize) -> RGBColor {
    const PALETTE: [RGBColor; 12] = [
        RGBColor(31, 119, 180),
        RGBColor(255, 127, 14),
        RGBColor(44, 160, 44),
        RGBColor(214, 39, 40),
        RGBColor(148, 103, 189),
        RGBColor(140, 86, 75),
        RGBColor(227, 119, 194),
        RGBColor(127, 127, 127),
        RGBColor(188, 189, 34),
        RGBColor(23, 190, 207),
        RGBColor(0, 0, 0),
        RGBColor(174, 199, 232),
    ];
    PALETTE[index % PALETTE.len()]
}

/// Registers a TrueType font for plotters' text (DejaVu Sans or Liberation
/// Sans from the system); without one, plots have no text.
pub fn init_fonts() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        const CANDIDATES: [&str; 4] = [
            "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
            "/usr/share/fonts/TTF/DejaVuSans.ttf",
            "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
            "/Library/Fonts/Arial.ttf",
        ];
        for path in CANDIDATES {
            if let Ok(bytes) = std::fs::read(path) {
                let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
                if register_font("sans-serif", FontStyle::Normal, bytes).is_ok() {
                    return;
                }
            }
        }
        eprintln!("warning: no TrueType font found (install fonts-dejavu-core); plot text will be missing");
    });
}

fn transform(v: f64, scale: Scale) -> Option<f64> {
    let out = match scale {
        Scale::Linear => v,
        Scale::Log => {
            if v > 0.0 {
                v.log10()
            } else {
                return None;
            }
        }
    };
    out.is_finite().then_some(out)
}

/// A tick label; `span` is the axis length, in the axis's own units.
fn axis_label(v: f64, scale: Scale, span: f64) -> String {
    match scale {
        Scale::Linear => {
            // Tick positions are sums of float steps (0.30000000000000004,
            // -2e-16 for zero): print them to a millionth of the span.
            let digits = (6.0 - span.abs().log10()).ceil().max(0.0) as usize;
            let rounded = format!("{v:.digits$}");
            let v: f64 = rounded.parse().unwrap_or(v);
            let a = v.abs();
            if a != 0.0 && !(1e-3..1e4).contains(&a) {
                format!("{v:.0e}")
            } else if rounded.contains('.') {
                let trimmed = rounded.trim_end_matches('0').trim_end_matches('.');
                if trimmed == "-0" {
                    "0".into()
                } else {
                    trimmed.into()
                }
            } else {
                rounded
            }
        }
        Scale::Log => {
            if (v - v.round()).abs() < 1e-9 {
                format!("1e{}", v.round() as i64)
            } else {
                format!("{:.1e}", 10f64.powf(v))
            }
        }
    }
}

fn range(values: impl Iterator<Item = f64>, scale: Scale) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = match scale {
        Scale::Log => 0.2,
        Scale::Linear => 0.05 * (hi - lo).max(1e-12),
    };
    if hi - lo < 1e-12 {
        (lo - 1.0, hi + 1.0)
    } else {
        (lo - pad, hi + pad)
    }
}

/// Draws `series` into an SVG at `path` (800 x 520 px).
pub fn plot(
    path: &Path,
    figure: &Figure,
    series: &[Series],
) -> Result<(), Box<dyn std::error::Error>> {
    init_fonts();
    let data: Vec<Vec<(f64, f64)>> = series
        .iter()
        .map(|s| {
            s.points
                .iter()
                .filter_map(|&(x, y)| {
                    Some((transform(x, figure.x_scale)?, transform(y, figure.y_scale)?))
                })
                .collect()
        })
        .collect();
    let (x0, x1) = range(data.iter().flatten().map(|p| p.0), figure.x_scale);
    let (y0, y1) = range(data.iter().flatten().map(|p| p.1), figure.y_scale);
    // Up to SMALL_LEGEND entries the legend sits in a corner of the plot
    // that holds no data; a longer one, or one that every corner's data
    // would be under, gets a panel of its own to the right of the plot.
    let corner = free_corner(series, &data, (x0, x1), (y0, y1));
    let side_legend = series.len() > SMALL_LEGEND || corner.is_none();
    let width = if side_legend {
        800 + SIDE_LEGEND_WIDTH
    } else {
        800
    };
    let canvas = SVGBackend::new(path, (width, 520)).into_drawing_area();
    canvas.fill(&WHITE)?;
    let (root, panel) = canvas.split_horizontally(800);
    let mut chart = ChartBuilder::on(&root)
        .caption(figure.title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    let (xs, ys) = (figure.x_scale, figure.y_scale);
    chart
        .configure_mesh()
        .x_desc(figure.x_label)
        .y_desc(figure.y_label)
        .x_label_formatter(&|v| axis_label(*v, xs, x1 - x0))
        .y_label_formatter(&|v| axis_label(*v, ys, y1 - y0))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()?;
    draw_marks(&mut chart, series, &data)?;
    if side_legend {
        draw_side_legend(&panel, series)?;
    } else {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.3))
            .position(corner.unwrap_or(SeriesLabelPosition::UpperRight))
            .label_font(("sans-serif", 13))
            .draw()?;
    }
    canvas.present()?;
    Ok(())
}

/// The series' points (already transformed to axis units) and their
/// legend entries, onto `chart`.
fn draw_marks<'a, DB: DrawingBackend + 'a>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
    series: &[Series],
    data: &[Vec<(f64, f64)>],
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    for (s, points) in series.iter().zip(data) {
        let c = color(s.color);
        let legend_color = c;
        match s.mark {
            Mark::ThinLine | Mark::Dotted => {
                let (dash, gap) = dash_pattern(s.mark);
                chart
                    .draw_series(DashedLineSeries::new(
                        points.iter().copied(),
                        dash,
                        gap,
                        c.stroke_width(1),
                    ))?
                    .label(&s.name)
                    .legend(move |(x, y)| {
                        EmptyElement::at((x, y)) + legend_dashes(legend_color, dash, gap)
                    });
            }
            Mark::Line => {
                chart.draw_series(LineSeries::new(points.iter().copied(), c.stroke_width(2)))?;
                // A dense curve gets a marker every few points, shaped by
                // its palette index, so that curves differ by more than
                // their colour.
                let step = (points.len() / SPARSE_MARKERS).max(1);
                let sparse: Vec<(f64, f64)> = points.iter().copied().step_by(step).collect();
                let shape = PointShape::of(s.color);
                chart
                    .draw_series(
                        sparse
                            .into_iter()
                            .map(move |p| EmptyElement::at(p) + shape.marker(c)),
                    )?
                    .label(&s.name)
                    .legend(move |(x, y)| {
                        EmptyElement::at((x, y))
                            + PathElement::new([(0, 0), (18, 0)], legend_color.stroke_width(2))
                            + shape.marker_at((9, 0), legend_color)
                    });
            }
            Mark::LinePoints => {
                chart.draw_series(LineSeries::new(points.iter().copied(), c.stroke_width(2)))?;
                // The marker's shape follows the palette index, so that
                // lines stay apart where colours are hard to tell apart;
                // the legend shows the line with its marker.
                let pts = points.iter().copied();
                let line = move |x: i32, y: i32| {
                    EmptyElement::at((x, y))
                        + PathElement::new([(0, 0), (18, 0)], legend_color.stroke_width(2))
                };
                let square = |c: RGBColor| Rectangle::new([(-3, -3), (3, 3)], c.filled());
                let diamond =
                    |c: RGBColor| Polygon::new(vec![(0, -5), (5, 0), (0, 5), (-5, 0)], c.filled());
                match PointShape::of(s.color) {
                    PointShape::Circle => {
                        chart
                            .draw_series(pts.map(|p| Circle::new(p, 4, c.filled())))?
                            .label(&s.name)
                            .legend(move |(x, y)| {
                                line(x, y) + Circle::new((9, 0), 4, legend_color.filled())
                            });
                    }
                    PointShape::Triangle => {
                        chart
                            .draw_series(pts.map(|p| TriangleMarker::new(p, 5, c.filled())))?
                            .label(&s.name)
                            .legend(move |(x, y)| {
                                line(x, y) + TriangleMarker::new((9, 0), 5, legend_color.filled())
                            });
                    }
                    PointShape::Square => {
                        chart
                            .draw_series(pts.map(|p| EmptyElement::at(p) + square(c)))?
                            .label(&s.name)
                            .legend(move |(x, y)| {
                                line(x, y)
                                    + Rectangle::new([(6, -3), (12, 3)], legend_color.filled())
                            });
                    }
                    PointShape::Diamond => {
                        chart
                            .draw_series(pts.map(|p| EmptyElement::at(p) + diamond(c)))?
                            .label(&s.name)
                            .legend(move |(x, y)| {
                                line(x, y)
                                    + Polygon::new(
                                        vec![(9, -5), (14, 0), (9, 5), (4, 0)],
                                        legend_color.filled(),
                                    )
                            });
                    }
                }
            }
            Mark::Rings => {
                chart
                    .draw_series(points.iter().map(|&p| Circle::new(p, 6, c.stroke_width(2))))?
                    .label(&s.name)
                    .legend(move |(x, y)| Circle::new((x + 9, y), 5, legend_color.stroke_width(2)));
            }
            Mark::Crosses => {
                chart
                    .draw_series(points.iter().map(|&p| Cross::new(p, 6, c.stroke_width(2))))?
                    .label(&s.name)
                    .legend(move |(x, y)| Cross::new((x + 9, y), 5, legend_color.stroke_width(2)));
            }
            Mark::Triangles => {
                chart
                    .draw_series(
                        points
                            .iter()
                            .map(|&p| TriangleMarker::new(p, 5, c.filled())),
                    )?
                    .label(&s.name)
                    .legend(move |(x, y)| {
                        TriangleMarker::new((x + 9, y), 5, legend_color.filled())
                    });
            }
        }
    }
    Ok(())
}

/// Shape of a line's point markers.
#[derive(Clone, Copy)]
enum PointShape {
    Circle,
    Triangle,
    Square,
    Diamond,
}

impl PointShape {
    /// The shape for palette index `index`: neighbouring colours get
    /// different shapes.
    fn of(index: usize) -> Self {
        [Self::Circle, Self::Triangle, Self::Square, Self::Diamond][index % 4]
    }

    /// The marker centred on its anchor, filled with `c`.
    fn marker(self, c: RGBColor) -> Polygon<(i32, i32)> {
        self.marker_at((0, 0), c)
    }

    /// The marker centred at `at` (pixels from its anchor), as one
    /// polygon (the circle an octagon) so every shape has one type.
    fn marker_at(self, at: (i32, i32), c: RGBColor) -> Polygon<(i32, i32)> {
        let corners: &[(i32, i32)] = match self {
            Self::Circle => &[
                (2, -4),
                (4, -2),
                (4, 2),
                (2, 4),
                (-2, 4),
                (-4, 2),
                (-4, -2),
                (-2, -4),
            ],
            Self::Triangle => &[(0, -5), (5, 4), (-5, 4)],
            Self::Square => &[(-3, -3), (3, -3), (3, 3), (-3, 3)],
            Self::Diamond => &[(0, -5), (5, 0), (0, 5), (-5, 0)],
        };
        let points = corners
            .iter()
            .map(|&(x, y)| (at.0 + x, at.1 + y))
            .collect::<Vec<_>>();
        Polygon::new(points, c.filled())
    }
}

/// Markers on a dense curve drawn as [`Mark::Line`].
const SPARSE_MARKERS: usize = 12;

/// Dash and gap lengths (px) of a dashed or dotted mark.
fn dash_pattern(mark: Mark) -> (u32, u32) {
    if mark == Mark::Dotted {
        (2, 3)
    } else {
        (6, 4)
    }
}

/// A legend's dashed line, 18 px long from its anchor, one path per dash.
fn legend_dashes(
    c: RGBColor,
    dash: u32,
    gap: u32,
) -> DashedPathElement<std::array::IntoIter<(i32, i32), 2>, u32> {
    DashedPathElement::new([(0, 0), (18, 0)], dash, gap, c.stroke_width(2))
}

/// One panel of a multi-panel figure: its own title and series.
#[derive(Clone, Debug)]
pub struct Panel {
    /// Title above the panel.
    pub title: String,
    /// Series drawn in it.
    pub series: Vec<Series>,
}

/// Size of one panel (px).
const PANEL_SIZE: (u32, u32) = (520, 380);

/// Draws `panels` side by side, `columns` to a row, into an SVG at `path`,
/// all on the same axes so that panels compare at a glance. `figure`'s
/// title heads the figure and its labels go on every panel. The legend
/// takes the grid cell after the last panel, outside every plot, and
/// names each distinct series (by name) once: series drawn alike in
/// several panels share one entry.
pub fn plot_panels(
    path: &Path,
    figure: &Figure,
    panels: &[Panel],
    columns: usize,
) -> Result<(), Box<dyn std::error::Error>> {
    init_fonts();
    let transformed = |s: &Series| -> Vec<(f64, f64)> {
        s.points
            .iter()
            .filter_map(|&(x, y)| {
                Some((transform(x, figure.x_scale)?, transform(y, figure.y_scale)?))
            })
            .collect()
    };
    let data: Vec<Vec<Vec<(f64, f64)>>> = panels
        .iter()
        .map(|p| p.series.iter().map(transformed).collect())
        .collect();
    let all = || data.iter().flatten().flatten();
    let (x0, x1) = range(all().map(|p| p.0), figure.x_scale);
    let (y0, y1) = range(all().map(|p| p.1), figure.y_scale);
    let columns = columns.max(1);
    let cells = panels.len() + 1;
    let rows = cells.div_ceil(columns);
    let canvas = SVGBackend::new(
        path,
        (
            PANEL_SIZE.0 * columns as u32,
            40 + PANEL_SIZE.1 * rows as u32,
        ),
    )
    .into_drawing_area();
    canvas.fill(&WHITE)?;
    let grid = canvas.titled(figure.title, ("sans-serif", 20))?;
    let areas = grid.split_evenly((rows, columns));
    let (xs, ys) = (figure.x_scale, figure.y_scale);
    for ((panel, points), area) in panels.iter().zip(&data).zip(&areas) {
        let mut chart = ChartBuilder::on(area)
            .caption(&panel.title, ("sans-serif", 16))
            .margin(10)
            .x_label_area_size(42)
            .y_label_area_size(62)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .x_desc(figure.x_label)
            .y_desc(figure.y_label)
            .x_label_formatter(&|v| axis_label(*v, xs, x1 - x0))
            .y_label_formatter(&|v| axis_label(*v, ys, y1 - y0))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()?;
        draw_marks(&mut chart, &panel.series, points)?;
    }
    let mut entries: Vec<Series> = Vec::new();
    for s in panels.iter().flat_map(|p| &p.series) {
        if !entries.iter().any(|e| e.name == s.name) {
            entries.push(s.clone());
        }
    }
    draw_side_legend(&areas[panels.len()], &entries)?;
    canvas.present()?;
    Ok(())
}

/// Most legend entries drawn inside the plot.
const SMALL_LEGEND: usize = 6;

/// The first corner of the plot (upper right, upper left, lower right,
/// lower left) where the legend's box would cover no point of `data`
/// (transformed points, axis ranges `x` and `y`).
fn free_corner(
    series: &[Series],
    data: &[Vec<(f64, f64)>],
    x: (f64, f64),
    y: (f64, f64),
) -> Option<SeriesLabelPosition> {
    // The box in pixels (13 px text: about 7 px a character, 19 px a
    // line, the mark and margins) over the plot area's 700 x 420 px.
    let longest = series.iter().map(|s| s.name.chars().count()).max()?;
    let width = (50.0 + 7.0 * longest as f64) / 700.0;
    let height = (16.0 + 19.0 * series.len() as f64) / 420.0;
    let corners = [
        (SeriesLabelPosition::UpperRight, true, true),
        (SeriesLabelPosition::UpperLeft, false, true),
        (SeriesLabelPosition::LowerRight, true, false),
        (SeriesLabelPosition::LowerLeft, false, false),
    ];
    corners.into_iter().find_map(|(position, right, upper)| {
        let covered = data.iter().flatten().any(|&(px, py)| {
            let fx = (px - x.0) / (x.1 - x.0);
            let fy = (py - y.0) / (y.1 - y.0);
            let in_x = if right {
                fx >= 1.0 - width
            } else {
                fx <= width
            };
            let in_y = if upper {
                fy >= 1.0 - height
            } else {
                fy <= height
            };
            in_x && in_y
        });
        (!covered).then_some(position)
    })
}
/// Width of the side legend panel (px).
const SIDE_LEGEND_WIDTH: u32 = 300;

/// The legend as a column of entries in `panel`, each its series' mark in
/// its colour and its name.
fn draw_side_legend<DB: DrawingBackend>(
    panel: &DrawingArea<DB, plotters::coord::Shift>,
    series: &[Series],
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    let font = ("sans-serif", 13).into_font().color(&BLACK);
    for (k, s) in series.iter().enumerate() {
        let y = 60 + 22 * k as i32;
        let c = color(s.color);
        match s.mark {
            Mark::ThinLine | Mark::Dotted => {
                let (dash, gap) = dash_pattern(s.mark);
                panel.draw(&(EmptyElement::at((8, y)) + legend_dashes(c, dash, gap)))?
            }
            Mark::Line => {
                panel.draw(&PathElement::new([(4, y), (30, y)], c.stroke_width(2)))?;
                panel.draw(&(EmptyElement::at((17, y)) + PointShape::of(s.color).marker(c)))?
            }
            Mark::LinePoints => {
                panel.draw(&PathElement::new([(4, y), (30, y)], c.stroke_width(2)))?;
                let at = (17, y);
                match PointShape::of(s.color) {
                    PointShape::Circle => panel.draw(&Circle::new(at, 4, c.filled()))?,
                    PointShape::Triangle => panel.draw(&TriangleMarker::new(at, 5, c.filled()))?,
                    PointShape::Square => panel.draw(
                        &(EmptyElement::at(at) + Rectangle::new([(-3, -3), (3, 3)], c.filled())),
                    )?,
                    PointShape::Diamond => panel.draw(
                        &(EmptyElement::at(at)
                            + Polygon::new(vec![(0, -5), (5, 0), (0, 5), (-5, 0)], c.filled())),
                    )?,
                }
            }
            Mark::Rings => panel.draw(&Circle::new((17, y), 5, c.stroke_width(2)))?,
            Mark::Crosses => panel.draw(&Cross::new((17, y), 5, c.stroke_width(2)))?,
            Mark::Triangles => panel.draw(&TriangleMarker::new((17, y), 5, c.filled()))?,
        }
        panel.draw(&Text::new(s.name.clone(), (34, y - 7), font.clone()))?;
    }
    Ok(())
}
