//! Line plots of results, as PNG and SVG, drawn with plotters and a bundled DejaVu font (no system fonts, no Python
//! or gnuplot).
//!
//! One convention for every figure: a colour-blind-safe palette (Okabe & Ito 2008, without its yellow, which
//! vanishes on white) where a colour index always means the same configuration across a study's figures (0 = no
//! friction, black); markers on sampled points, so a coarse grid is not mistaken for a sharp resonance; solid and
//! dashed strokes for the two quantities of one configuration (e.g. downward and upward deflection magnitudes), each
//! configuration once in the legend; refined optima marked with a triangle; the legend outside the data, in a column
//! to the right; tick labels rounded to the axis' own resolution (no `-0.000000000000000111022`).

use crate::axis_grid::{self, GridAxis};
pub use crate::palette::{GREY, Palette, color};
use crate::plot_text::{LEGEND_SIZE, fitting_size, legend_lines, subtitle_lines};
use plotters::coord::Shift;
use plotters::prelude::*;
use scenario::axis::Axis;
use scenario::error::{Result, StudyError};
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::sync::Once;

/// How a curve is stroked.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
pub enum Stroke {
    /// A solid line.
    #[default]
    Solid,
    /// A dashed line.
    Dashed,
}

/// One curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Series {
    /// Legend text; `None` keeps the curve out of the legend (e.g. the dashed twin of a configuration).
    pub label: Option<String>,
    /// Colour index in the palette: one configuration, one index, in every figure of a study.
    pub color: usize,
    /// Solid or dashed.
    pub stroke: Stroke,
    /// Draw a marker at every point.
    pub markers: bool,
    /// (x, y) in plot units.
    pub points: Vec<(f64, f64)>,
}

impl Series {
    /// A reference line (a limit, a threshold, a speed where a curve ends) from `from` to `to`, dashed grey.
    pub fn reference(label: impl Into<String>, from: (f64, f64), to: (f64, f64)) -> Self {
        Series {
            label: Some(label.into()),
            color: GREY,
            stroke: Stroke::Dashed,
            markers: false,
            points: vec![from, to],
        }
    }
}

/// A marked point (a refined critical speed or optimum), drawn as a triangle in its configuration's colour.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Mark {
    /// Colour index.
    pub color: usize,
    /// (x, y) in plot units.
    pub point: (f64, f64),
}

/// One figure.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlotSpec {
    /// File name without extension.
    pub stem: String,
    /// Title.
    pub title: String,
    /// A second title line (e.g. the reference values a ratio is taken against), or empty.
    pub subtitle: String,
    /// x-axis label with unit.
    pub x_label: String,
    /// y-axis label with unit.
    pub y_label: String,
    /// Logarithmic x axis (x must be > 0).
    pub log_x: bool,
    /// Logarithmic y axis (y must be > 0); labels at 1-2-5 values (see [`crate::axis_grid`]).
    pub log_y: bool,
    /// The curves, drawn in this order.
    pub series: Vec<Series>,
    /// Marked points.
    pub marks: Vec<Mark>,
    /// What the strokes mean, shown in black after the curves in the legend (e.g. "downward" for solid).
    pub key: Vec<(Stroke, String)>,
    /// Legend text for the marks, or empty.
    pub mark_label: String,
    /// How colour indices map to colours.
    pub palette: Palette,
    /// Panels stacked top to bottom under this figure's title and subtitle, each drawn as a figure of its own (its
    /// title a heading, its legend beside it), its x and y ranges as [`PanelY`] says; when there are
    /// any, this figure's own series and marks are not drawn.
    pub panels: Vec<PlotSpec>,
    /// How the panels' y ranges are chosen.
    pub panel_y: PanelY,
}

/// The y ranges of a figure's panels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
pub enum PanelY {
    /// Common among panels of the same y label (the same quantity compares at a glance).
    #[default]
    SharedPerQuantity,
    /// Each panel its own x and y ranges (one quantity at scales that differ tenfold, e.g. a wave below and at
    /// resonance, whose domains differ fourfold too).
    EachOwn,
}

impl PlotSpec {
    /// A figure with no curves yet, its axes labelled from the quantities they show ([`Axis`]).
    pub fn new(stem: impl Into<String>, title: impl Into<String>, x: &Axis, y: &Axis) -> Self {
        Self {
            stem: stem.into(),
            title: title.into(),
            subtitle: String::new(),
            x_label: x.label().into(),
            y_label: y.label().into(),
            log_x: false,
            log_y: false,
            series: Vec::new(),
            marks: Vec::new(),
            key: Vec::new(),
            mark_label: String::new(),
            palette: Palette::Categorical,
            panels: Vec::new(),
            panel_y: PanelY::SharedPerQuantity,
        }
    }
}

/// Where a figure was drawn: pixel rectangles (left, top, right, bottom) of the whole image and of each panel's
/// plotting area (inside the axes) and legend column. Every curve, marker and mark lies in a plotting area; legend
/// samples in a legend column.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// The image.
    pub image: (i32, i32, i32, i32),
    /// Each panel, top to bottom (one for a figure without panels).
    pub panels: Vec<PanelLayout>,
}

/// Where one panel was drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PanelLayout {
    /// Inside the axes.
    pub plot: (i32, i32, i32, i32),
    /// The legend column.
    pub legend: (i32, i32, i32, i32),
}

const SIZE: (u32, u32) = (1200, 800);
/// Height of each panel of a figure with panels (px).
const PANEL_HEIGHT: u32 = 340;
/// A curve of more points than this is drawn without markers, whatever its series asks.
pub const MAX_MARKED_POINTS: usize = 60;
const LEGEND_WIDTH: u32 = 300;

static FONTS: Once = Once::new();

fn register_fonts() {
    FONTS.call_once(|| {
        // The bundled font is valid by construction; should it ever fail, text falls back to nothing drawn.
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular());
        let _ = plotters::style::register_font("sans-serif", FontStyle::Bold, dejavu::sans::bold());
    });
}

fn plot_error(path: &Path, e: impl std::fmt::Display) -> StudyError {
    StudyError::Io { path: path.display().to_string(), message: format!("plotting failed: {e}") }
}

impl PlotSpec {
    /// This figure with every text it draws typeset ([`crate::typeset::text`]): title, subtitle, axis labels,
    /// legend labels, key, marks, panels.
    pub fn typeset(&self) -> PlotSpec {
        let text = crate::typeset::text;
        let mut out = self.clone();
        (out.title, out.subtitle) = (text(&self.title), text(&self.subtitle));
        (out.x_label, out.y_label, out.mark_label) = (text(&self.x_label), text(&self.y_label), text(&self.mark_label));
        for s in &mut out.series {
            s.label = s.label.as_deref().map(text);
        }
        for (_, key) in &mut out.key {
            *key = text(key);
        }
        out.panels = self.panels.iter().map(PlotSpec::typeset).collect();
        out
    }
}

/// The image size of `spec`: 1200×800, or taller by [`PANEL_HEIGHT`] a panel beyond two.
fn size(spec: &PlotSpec) -> (u32, u32) {
    let extra = spec.panels.len().saturating_sub(2) as u32;
    (SIZE.0, SIZE.1 + extra * PANEL_HEIGHT)
}

/// Draw `spec` into `folder` as `<stem>.png` (1200×800, taller with more than two panels) and `<stem>.svg`;
/// returns both paths and the layout.
pub fn render(spec: &PlotSpec, folder: &Path) -> Result<(PathBuf, PathBuf, Layout)> {
    register_fonts();
    let spec = &spec.typeset();
    let png = folder.join(format!("{}.png", spec.stem));
    let svg = folder.join(format!("{}.svg", spec.stem));
    // Only regular files are replaced: a link, device or FIFO in the output folder is refused, never written through.
    for path in [&png, &svg] {
        if std::fs::symlink_metadata(path).is_ok_and(|meta| !meta.is_file()) {
            return Err(scenario::error::invalid("figure", path.display(), "exists and is not a regular file"));
        }
    }
    let layout = {
        let root = BitMapBackend::new(&png, size(spec)).into_drawing_area();
        let layout = draw(&root, spec).map_err(|e| plot_error(&png, e))?;
        root.present().map_err(|e| plot_error(&png, e))?;
        layout
    };
    {
        let root = SVGBackend::new(&svg, size(spec)).into_drawing_area();
        draw(&root, spec).map_err(|e| plot_error(&svg, e))?;
        root.present().map_err(|e| plot_error(&svg, e))?;
    }
    Ok((png, svg, layout))
}

/// The drawn coordinate of a value on a log axis (`log`: its log₁₀) or a linear one.
fn transform(log: bool) -> impl Fn(f64) -> f64 + Copy {
    move |v: f64| if log { v.log10() } else { v }
}

/// The data range of the figure (after the log transforms), padded by 2 % in x and 5 % in y so that markers at the
/// ends stay inside the frame.
fn ranges(spec: &PlotSpec) -> Option<((f64, f64), (f64, f64))> {
    let (tx, ty) = (transform(spec.log_x), transform(spec.log_y));
    let curves = spec.series.iter().flat_map(|s| s.points.iter());
    let marks = spec.marks.iter().map(|m| &m.point);
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for &(x, y) in curves.chain(marks) {
        let (x, y) = (tx(x), ty(y));
        if x.is_finite() && y.is_finite() {
            (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
        }
    }
    if !(x0.is_finite() && y0.is_finite()) {
        return None;
    }
    if x1 <= x0 {
        x1 = x0 + 1.0;
    }
    let pad = if y1 > y0 { 0.05 * (y1 - y0) } else { 1.0 };
    let x_pad = 0.02 * (x1 - x0);
    Some(((x0 - x_pad, x1 + x_pad), (y0 - pad, y1 + pad)))
}

fn draw<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, spec: &PlotSpec) -> std::result::Result<Layout, String> {
    let err = |e: &dyn std::fmt::Display| e.to_string();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    // Titles shrink to fit the width (20 px margins) rather than run off the image; subtitles wrap onto lines.
    let width = f64::from(SIZE.0 - 40);
    let subtitle = subtitle_lines(root, &spec.subtitle, width);
    let height = match subtitle.len() {
        0 => 50,
        n => 56 + 22 * n as u32,
    };
    let (titled, body) = root.split_vertically(height);
    let title_size = fitting_size(&titled, &spec.title, 28.0, width);
    titled
        .draw(&Text::new(spec.title.as_str(), (20, 12), ("sans-serif", title_size).into_font()))
        .map_err(|e| err(&e))?;
    for (k, (line, size)) in subtitle.iter().enumerate() {
        let style = ("sans-serif", *size).into_font().color(&RGBColor(60, 60, 60));
        titled.draw(&Text::new(line.as_str(), (20, 48 + 22 * k as i32), style)).map_err(|e| err(&e))?;
    }
    let (w, h) = root.dim_in_pixel();
    let image = (0, 0, w as i32, h as i32);
    if spec.panels.is_empty() {
        let range = ranges(spec).ok_or("nothing to plot")?;
        return Ok(Layout { image, panels: vec![draw_panel(&body, spec, range)?] });
    }
    // Common ranges, so that the panels compare at a glance: x for all, y among panels of the same quantity (the
    // same y label; a moment's kN·m has nothing to share with a deflection's mm).
    let found: Vec<_> = spec.panels.iter().filter_map(|p| ranges(p).map(|r| (p.y_label.as_str(), r))).collect();
    let union = |a: (f64, f64), b: (f64, f64)| (a.0.min(b.0), a.1.max(b.1));
    let x = found.iter().map(|(_, (x, _))| *x).reduce(union).ok_or("nothing to plot")?;
    let mut panels = Vec::with_capacity(spec.panels.len());
    for (area, panel) in body.split_evenly((spec.panels.len(), 1)).iter().zip(&spec.panels) {
        let (heading, rest) = area.split_vertically(30);
        let style = ("sans-serif", fitting_size(&heading, &panel.title, 20.0, width)).into_font();
        heading.draw(&Text::new(panel.title.as_str(), (20, 8), style)).map_err(|e| err(&e))?;
        let own = ranges(panel);
        let same = found.iter().filter(|(label, _)| *label == panel.y_label).map(|(_, (_, y))| *y);
        let (x, y) = match spec.panel_y {
            PanelY::SharedPerQuantity => (x, same.reduce(union).unwrap_or((-1.0, 1.0))),
            PanelY::EachOwn => own.unwrap_or((x, (-1.0, 1.0))),
        };
        panels.push(draw_panel(&rest, panel, (x, y))?);
    }
    Ok(Layout { image, panels })
}

/// One chart with its legend column in `area`, over `range` (after the log transforms): the plotting area's and
/// legend's pixel rectangles.
fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    spec: &PlotSpec,
    ((x0, x1), (y0, y1)): ((f64, f64), (f64, f64)),
) -> std::result::Result<PanelLayout, String> {
    let err = |e: &dyn std::fmt::Display| e.to_string();
    let (chart_area, legend_area) = area.split_horizontally(SIZE.0 - LEGEND_WIDTH);
    let (tx, ty) = (transform(spec.log_x), transform(spec.log_y));
    let (log_x, log_y) = (spec.log_x, spec.log_y);
    let grid =
        |log: bool, lo: f64, hi: f64| if log { axis_grid::logarithmic(lo, hi) } else { axis_grid::linear(lo, hi) };
    let (x_grid, y_grid) = (grid(log_x, x0, x1), grid(log_y, y0, y1));
    let (x_step, y_step, x_plain, y_plain) = (x_grid.step, y_grid.step, x_grid.plain, y_grid.plain);
    let mut chart = ChartBuilder::on(&chart_area)
        .margin(15)
        .x_label_area_size(60)
        .y_label_area_size(95)
        .build_cartesian_2d(GridAxis::new(x0..x1, x_grid), GridAxis::new(y0..y1, y_grid))
        .map_err(|e| err(&e))?;
    let label = |log: bool, step: f64, plain: bool| {
        move |v: &f64| if log { axis_grid::log_tick(*v, plain) } else { axis_grid::tick(*v, step) }
    };
    let (x_format, y_format) = (label(log_x, x_step, x_plain), label(log_y, y_step, y_plain));
    // The axes' descriptions at 21 px, smaller where the y one (written upward) would run past a short panel's plot
    // (a stacked snapshot's: "deflection w (mm, upward > 0)" was taller than its 200 px).
    let plot_height = f64::from(chart.plotting_area().dim_in_pixel().1);
    let description = fitting_size(&chart_area, &spec.y_label, 21.0, 0.95 * plot_height);
    chart
        .configure_mesh()
        .x_desc(spec.x_label.as_str())
        .y_desc(spec.y_label.as_str())
        .x_label_formatter(&x_format)
        .y_label_formatter(&y_format)
        .label_style(("sans-serif", 18))
        .axis_desc_style(("sans-serif", description))
        .light_line_style(RGBColor(235, 235, 235))
        .bold_line_style(RGBColor(205, 205, 205))
        .draw()
        .map_err(|e| err(&e))?;
    // The plot's own width in pixels (inside the axes' labels and margins).
    let columns = chart.plotting_area().dim_in_pixel().0 as usize;
    // Colour 0, "no friction" in every study, is drawn last: the reference stays visible where the curves with
    // friction coincide with it or cross it.
    let reference = |s: &&Series| spec.palette == Palette::Categorical && s.color == 0;
    let order = spec.series.iter().filter(|s| !reference(s)).chain(spec.series.iter().filter(reference));
    for s in order {
        // Segments of 2 px or less: a 1 px stroke. plotters' bitmap backend widens a thicker stroke segment by
        // segment, and on dense zig-zags (a friction force chattering every step, a wheel force ringing after a
        // dipped joint: 900 points over 750 px) the widened segments shoot out of the frame.
        // Otherwise 3: plotters draws a stroke wider than 1 px as a polygon whose corners it offsets by ±width/2
        // across the segment, truncated to whole pixels — at width 2 the offsets of a steep or diagonal segment
        // (|±1·sin| < 1) truncate to 0 and it came out 1 px thin beside its 2 px neighbours; at 3 every direction
        // keeps 2 px or more.
        // A dense but smooth curve (a wave of a few hundred extrema sampled every step) is thinned to its extrema
        // and every k-th point in between, and drawn 3 px like the rest.
        let line: Vec<(f64, f64)> =
            s.points.iter().map(|&(x, y)| (tx(x), ty(y))).filter(|(x, y)| x.is_finite() && y.is_finite()).collect();
        let line = thinned(line, columns);
        let width = if 2 * line.len() > columns { 1 } else { 3 };
        let style = spec.palette.color(s.color).stroke_width(width);
        match s.stroke {
            Stroke::Solid => chart.draw_series(LineSeries::new(line.clone(), style)).map(|_| ()),
            Stroke::Dashed => chart.draw_series(DashedLineSeries::new(line.clone(), 9, 6, style)).map(|_| ()),
        }
        .map_err(|e| err(&e))?;
        // Markers show where a curve was sampled; past MAX_MARKED_POINTS (a 2 km/h sweep) they only blot it.
        if s.markers && line.len() <= MAX_MARKED_POINTS {
            let marker = |p: (f64, f64)| Circle::new(p, 3, spec.palette.color(s.color).filled());
            chart.draw_series(line.into_iter().map(marker)).map_err(|e| err(&e))?;
        }
    }
    let triangle = |p: (f64, f64), c: usize| TriangleMarker::new(p, 9, spec.palette.color(c).filled());
    let marks = spec.marks.iter().map(|m| triangle((tx(m.point.0), ty(m.point.1)), m.color));
    chart.draw_series(marks).map_err(|e| err(&e))?;
    let (px, py) = chart.plotting_area().get_pixel_range();
    draw_legend(&legend_area, spec).map_err(|e| err(&e))?;
    let (lx, ly) = legend_area.get_pixel_range();
    Ok(PanelLayout { plot: (px.start, py.start, px.end, py.end), legend: (lx.start, ly.start, lx.end, ly.end) })
}

/// `line` as drawn over `columns` px: unchanged where it has at most columns/2 points or is not smooth (more than
/// columns/8 extrema: a chattering force, which only a 1 px stroke draws faithfully); else its first and last
/// points, every extremum and every k-th point between, k such that at most columns/2 points remain — the peaks
/// kept to the bit.
fn thinned(line: Vec<(f64, f64)>, columns: usize) -> Vec<(f64, f64)> {
    let extremum = |i: usize| {
        let (before, after) = (line[i].1 - line[i - 1].1, line[i + 1].1 - line[i].1);
        before * after < 0.0
    };
    let extrema = (1..line.len().saturating_sub(1)).filter(|&i| extremum(i)).count();
    if 2 * line.len() <= columns || 8 * extrema > columns {
        return line;
    }
    // Room for the stride's points beside the extrema, the ends and the rounding of the stride.
    let room = (columns / 2).saturating_sub(extrema + 3).max(2);
    let stride = line.len().div_ceil(room).max(1);
    let last = line.len() - 1;
    (0..line.len()).filter(|&i| i == 0 || i == last || i % stride == 0 || extremum(i)).map(|i| line[i]).collect()
}

/// The legend column: one entry per labelled curve (its stroke and marker), then the key of strokes and marks (a
/// triangle in each of the marks' colours), every text at one size.
fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    spec: &PlotSpec,
) -> std::result::Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let room = f64::from(area.dim_in_pixel().0) - 64.0;
    const LINE: i32 = 18;
    // The text beside a sample at `y`, on as many lines as it needs; the extra height it took (px).
    let write = |text: &str, y: i32| -> std::result::Result<i32, DrawingAreaErrorKind<DB::ErrorType>> {
        let lines = legend_lines(area, text, room);
        for (k, line) in lines.iter().enumerate() {
            let at = (58, y - 8 + LINE * k as i32);
            area.draw(&Text::new(line.as_str(), at, ("sans-serif", LEGEND_SIZE).into_font()))?;
        }
        Ok(LINE * (lines.len().max(1) as i32 - 1))
    };
    let sample = |y: i32, stroke: Stroke| -> Vec<Vec<(i32, i32)>> {
        match stroke {
            Stroke::Solid => vec![vec![(10, y), (50, y)]],
            Stroke::Dashed => vec![vec![(10, y), (20, y)], vec![(26, y), (36, y)], vec![(42, y), (50, y)]],
        }
    };
    let mut y = 30;
    for s in spec.series.iter().filter(|s| s.label.is_some()) {
        for segment in sample(y, s.stroke) {
            area.draw(&PathElement::new(segment, spec.palette.color(s.color).stroke_width(3)))?;
        }
        if s.markers {
            area.draw(&Circle::new((30, y), 3, spec.palette.color(s.color).filled()))?;
        }
        y += 26 + write(s.label.as_deref().unwrap_or_default(), y)?;
    }
    y += 10;
    for (stroke, text) in &spec.key {
        for segment in sample(y, *stroke) {
            area.draw(&PathElement::new(segment, BLACK.stroke_width(2)))?;
        }
        y += 26 + write(text, y)?;
    }
    if !spec.marks.is_empty() && !spec.mark_label.is_empty() {
        // The marks' colours in order of first appearance, a triangle each (up to three side by side).
        let mut colors: Vec<usize> = Vec::new();
        for m in &spec.marks {
            if !colors.contains(&m.color) {
                colors.push(m.color);
            }
        }
        let count = colors.len().min(3) as i32;
        for (k, &c) in colors.iter().take(3).enumerate() {
            let x = 30 + 14 * k as i32 - 7 * (count - 1);
            area.draw(&TriangleMarker::new((x, y), 9, spec.palette.color(c).filled()))?;
        }
        write(&spec.mark_label, y)?;
    }
    Ok(())
}
