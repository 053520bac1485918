//! Line plots of study results, as PNG and SVG, drawn with plotters and a bundled DejaVu font (no system fonts,
//! no Python or gnuplot). Axes are labelled with units; every plot has a title and a legend.

use crate::error::{Result, StudyError};
use plotters::prelude::*;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::sync::Once;

/// One curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Series {
    /// Legend text.
    pub label: String,
    /// Colour index in the palette (curves of one configuration share it).
    pub color: usize,
    /// (x, y) in plot units.
    pub points: Vec<(f64, f64)>,
}

/// One figure.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlotSpec {
    /// File name without extension.
    pub stem: String,
    /// Title.
    pub title: String,
    /// x-axis label with unit.
    pub x_label: String,
    /// y-axis label with unit.
    pub y_label: String,
    /// Logarithmic x axis (x must be > 0).
    pub log_x: bool,
    /// The curves.
    pub series: Vec<Series>,
}

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

/// Draw `spec` into `folder` as `<stem>.png` (1200×800) and `<stem>.svg`; returns both paths.
pub fn render(spec: &PlotSpec, folder: &Path) -> Result<(PathBuf, PathBuf)> {
    register_fonts();
    let png = folder.join(format!("{}.png", spec.stem));
    let svg = folder.join(format!("{}.svg", spec.stem));
    {
        let root = BitMapBackend::new(&png, (1200, 800)).into_drawing_area();
        draw(&root, spec).map_err(|e| plot_error(&png, e))?;
        root.present().map_err(|e| plot_error(&png, e))?;
    }
    {
        let root = SVGBackend::new(&svg, (1200, 800)).into_drawing_area();
        draw(&root, spec).map_err(|e| plot_error(&svg, e))?;
        root.present().map_err(|e| plot_error(&svg, e))?;
    }
    Ok((png, svg))
}

fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, plotters::coord::Shift>,
    spec: &PlotSpec,
) -> std::result::Result<(), String> {
    let err = |e: &dyn std::fmt::Display| e.to_string();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let tx = |x: f64| if spec.log_x { x.log10() } else { x };
    let points = spec.series.iter().flat_map(|s| s.points.iter()).filter(|(x, y)| x.is_finite() && y.is_finite());
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for &(x, y) in points {
        x0 = x0.min(tx(x));
        x1 = x1.max(tx(x));
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if !(x0.is_finite() && y0.is_finite()) {
        return Err("nothing to plot".into());
    }
    if x1 <= x0 {
        x1 = x0 + 1.0;
    }
    let pad = if y1 > y0 { 0.05 * (y1 - y0) } else { 1.0 };
    let (y0, y1) = (y0 - pad, y1 + pad);
    let mut chart = ChartBuilder::on(root)
        .caption(&spec.title, ("sans-serif", 30))
        .margin(20)
        .x_label_area_size(60)
        .y_label_area_size(90)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| err(&e))?;
    let log_x = spec.log_x;
    let x_format = move |x: &f64| if log_x { format!("{:.0e}", 10f64.powf(*x)) } else { tick(*x) };
    let y_format = |y: &f64| tick(*y);
    chart
        .configure_mesh()
        .x_desc(spec.x_label.as_str())
        .y_desc(spec.y_label.as_str())
        .x_label_formatter(&x_format)
        .y_label_formatter(&y_format)
        .label_style(("sans-serif", 18))
        .axis_desc_style(("sans-serif", 22))
        .draw()
        .map_err(|e| err(&e))?;
    for s in &spec.series {
        let color = Palette99::pick(s.color).mix(0.9);
        let line: Vec<(f64, f64)> =
            s.points.iter().map(|&(x, y)| (tx(x), y)).filter(|(x, y)| x.is_finite() && y.is_finite()).collect();
        chart
            .draw_series(LineSeries::new(line, color.stroke_width(2)))
            .map_err(|e| err(&e))?
            .label(s.label.as_str())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(3)));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 18))
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(|e| err(&e))?;
    Ok(())
}

/// A tick label: the value rounded to six significant digits, without float noise (0.30000000000000004 → 0.3).
fn tick(value: f64) -> String {
    if value == 0.0 || !value.is_finite() {
        return format!("{value}");
    }
    let digits = 5 - value.abs().log10().floor() as i32;
    let scale = 10f64.powi(digits.clamp(-300, 300));
    format!("{}", (value * scale).round() / scale)
}
