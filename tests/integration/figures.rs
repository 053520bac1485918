//! Every figure of a study is drawn inside its frame: checked in the SVG, where each element's coordinates can be
//! read. Curves, markers and marks must lie in the plotting area (the axes' tick marks just left of and below it)
//! or in the legend column; every text must start and end inside the image (its width estimated at 0.62 em per
//! character, generous for DejaVu Sans, whose average advance is ~0.55 em). The PNG's blank margins around the
//! plotting area must stay white.

use report::plot::{Layout, PlotSpec, render};
use scenario::axis::{Axis, Shown};

/// Numbers of an attribute `name="…"` of an SVG element.
fn attribute(element: &str, name: &str) -> Option<String> {
    let start = element.find(&format!(" {name}=\""))? + name.len() + 3;
    let end = start + element[start..].find('"')?;
    Some(element[start..end].to_string())
}

fn number(element: &str, name: &str) -> f64 {
    attribute(element, name).and_then(|v| v.parse().ok()).unwrap_or(f64::NAN)
}

fn inside((left, top, right, bottom): (i32, i32, i32, i32), (x, y): (f64, f64), slack: f64) -> bool {
    let (l, t, r, b) = (f64::from(left), f64::from(top), f64::from(right), f64::from(bottom));
    x >= l - slack && x <= r + slack && y >= t - slack && y <= b + slack
}

/// Check one rendered SVG against its layout; returns the offending elements.
fn outside_elements(svg: &str, layout: &Layout) -> Vec<String> {
    let areas: Vec<(i32, i32, i32, i32)> = layout
        .panels
        .iter()
        .flat_map(|panel| {
            let (left, top, right, bottom) = panel.plot;
            let tick_zone_left = (left - 12, top, left, bottom);
            let tick_zone_below = (left, bottom, right, bottom + 12);
            [panel.plot, panel.legend, tick_zone_left, tick_zone_below]
        })
        .collect();
    let allowed = |p: (f64, f64)| areas.iter().any(|&area| inside(area, p, 1.5));
    let mut bad = Vec::new();
    for element in svg.split('<').skip(1) {
        let tag = element.split([' ', '>', '/']).next().unwrap_or_default();
        let points: Vec<(f64, f64)> = match tag {
            "polyline" | "polygon" => attribute(element, "points")
                .unwrap_or_default()
                .split_whitespace()
                .filter_map(|pair| {
                    let (x, y) = pair.split_once(',')?;
                    Some((x.parse().ok()?, y.parse().ok()?))
                })
                .collect(),
            "circle" => vec![(number(element, "cx"), number(element, "cy"))],
            "text" => {
                let (x, y) = (number(element, "x"), number(element, "y"));
                let text = element.split_once('>').map_or("", |(_, t)| t);
                let width = 0.62 * number(element, "font-size") * text.trim().chars().count() as f64;
                let (from, to) = match attribute(element, "text-anchor").as_deref() {
                    Some("middle") => (x - width / 2.0, x + width / 2.0),
                    Some("end") => (x - width, x),
                    _ => (x, x + width),
                };
                // Rotated labels (the y axis) are checked by their anchor only.
                if element.contains("rotate(") {
                    vec![(x, y)]
                } else {
                    if !(inside(layout.image, (from, y), 0.0) && inside(layout.image, (to, y), 0.0)) {
                        bad.push(format!("text {:?} spans {from:.0}–{to:.0} px", text.trim()));
                    }
                    continue;
                }
            }
            _ => continue,
        };
        let check = |p: &(f64, f64)| if tag == "text" { inside(layout.image, *p, 0.0) } else { allowed(*p) };
        if let Some(p) = points.iter().find(|p| !check(p)) {
            bad.push(format!("{tag} at ({:.0}, {:.0}): {}", p.0, p.1, &element[..element.len().min(120)]));
        }
    }
    bad
}

/// In the PNG, the blank margins around the plotting area — a strip above it and one between it and the legend
/// column — must stay white: a curve leaving its frame (as plotters' widened strokes did on dense zig-zags, a
/// bitmap-only fault) paints them. Returns the number of painted pixels.
fn painted_margin_pixels(png: &std::path::Path, layout: &Layout) -> usize {
    let image = image::open(png).unwrap().to_rgb8();
    let mut painted = 0;
    for panel in &layout.panels {
        let (left, top, right, bottom) = panel.plot;
        let above = (left..right).flat_map(|x| (top - 12..top - 2).map(move |y| (x, y)));
        let beside = (right + 2..panel.legend.0 - 1).flat_map(|x| (top..bottom).map(move |y| (x, y)));
        painted +=
            above.chain(beside).filter(|&(x, y)| image.get_pixel(x as u32, y as u32).0 != [255, 255, 255]).count();
    }
    painted
}

/// Render every figure of `plots` into a fresh folder and check each SVG and PNG.
pub fn assert_drawn_inside(plots: &[PlotSpec], name: &str) {
    let folder = std::env::temp_dir().join(format!("frictrack-figures-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    std::fs::create_dir_all(&folder).unwrap();
    assert!(!plots.is_empty(), "{name}: no figure");
    for spec in plots {
        let (png, svg, layout) = render(spec, &folder).unwrap();
        let painted = painted_margin_pixels(&png, &layout);
        assert_eq!(painted, 0, "{}: {painted} pixels painted in the PNG's margins", spec.stem);
        let bad = outside_elements(&std::fs::read_to_string(&svg).unwrap(), &layout);
        assert!(
            bad.is_empty(),
            "{}: {} elements outside their area, e.g. {:?}",
            spec.stem,
            bad.len(),
            &bad[..3.min(bad.len())]
        );
    }
    let _ = std::fs::remove_dir_all(&folder);
}

#[test]
fn a_curve_out_of_its_frame_is_caught() {
    // A layout whose plotting area misses the data: the checker must report the curve.
    let mut spec =
        PlotSpec::new("probe", "probe", &Axis::new("x", "x", Shown::Si), &Axis::new("y", "deflection", Shown::Si));
    spec.series.push(report::plot::Series {
        label: Some("probe".into()),
        color: 1,
        stroke: report::plot::Stroke::Solid,
        markers: true,
        points: vec![(0.0, 0.0), (1.0, 1.0)],
    });
    let folder = std::env::temp_dir().join(format!("frictrack-figures-probe-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let (_, svg, mut layout) = render(&spec, &folder).unwrap();
    let svg = std::fs::read_to_string(svg).unwrap();
    assert!(outside_elements(&svg, &layout).is_empty());
    layout.panels[0].plot.1 += 200;
    assert!(!outside_elements(&svg, &layout).is_empty());
    let _ = std::fs::remove_dir_all(&folder);
}

/// A train of three quarter cars draws its wheel forces a panel per vehicle: three panels, each inside its frame,
/// each headed by its vehicle, on one image taller than a single chart.
#[test]
fn wheel_forces_are_drawn_a_panel_per_vehicle() {
    let text = "[mesh]\nlength = 60.0\nelements = 120\n[load]\nspeed = 30.0\n[integration]\nload_advance = 0.05\n[vehicle]\nkind = \"quarter-car\"\n\
                [[vehicle.behind]]\noffset = 10.0\nkind = \"quarter-car\"\ncount = 2\nspacing = 10.0\n";
    let scenario = scenario::Scenario::from_toml(text, "three-cars.toml").unwrap();
    let case = scenario.build().unwrap();
    let result = runner::Runner::new(1).unwrap().simulate(&case, &case.settings).unwrap();
    let spec = report::vehicle_output::wheel_plot(result.vehicles.as_ref().unwrap(), "three cars", (0.0, 60.0));
    assert_eq!(spec.panels.len(), 3);
    assert!(spec.panels.iter().all(|p| p.series.len() == 1), "one wheel in each quarter car");
    assert_drawn_inside(std::slice::from_ref(&spec), "wheel-panels");
    let folder = std::env::temp_dir().join(format!("frictrack-figures-wheel-panels-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let (_, svg, layout) = render(&spec, &folder).unwrap();
    assert_eq!(layout.panels.len(), 3);
    assert!(layout.image.3 > 800, "taller than one chart: {:?}", layout.image);
    assert!(layout.panels.windows(2).all(|w| w[0].plot.3 < w[1].plot.1), "stacked top to bottom");
    let svg = std::fs::read_to_string(svg).unwrap();
    assert!(svg.contains("vehicle 3 (quarter car), wheel 3"), "each panel is headed by its vehicle and wheels");
    // One static wheel load, said once under the title rather than in every legend entry.
    assert!(svg.contains("static wheel load Q₀ =") && !svg.contains("wheel 1 (Q₀"));
    let _ = std::fs::remove_dir_all(&folder);
}

/// A legend label too long for its column wraps onto more lines at the legend's one font size: nothing is painted in
/// the image's rightmost 4 px (a label running off the image paints there — the 11 px single line this replaced
/// did), and the long label's lines and the short one are written at the same size (a long label shrunk to 13 px
/// beside 17 px ones read as two legends).
#[test]
fn long_legend_labels_wrap_instead_of_running_off_the_image() {
    let mut spec = PlotSpec::new(
        "long-legend",
        "long legend",
        &Axis::new("x", "x", Shown::Si),
        &Axis::new("w", "deflection", Shown::Milli),
    );
    for (i, label) in ["wheel 1 (vehicle 1, Q₀ = 61.7 kN) over the dipped joint at 100 m", "short"].iter().enumerate()
    {
        spec.series.push(report::plot::Series {
            label: Some(label.to_string()),
            color: 1 + i,
            stroke: report::plot::Stroke::Solid,
            markers: false,
            points: vec![(0.0, i as f64), (1.0, 1.0 + i as f64)],
        });
    }
    let folder = std::env::temp_dir().join(format!("frictrack-figures-long-legend-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let (png, svg, _) = render(&spec, &folder).unwrap();
    let image = image::open(&png).unwrap().to_rgb8();
    let (width, height) = image.dimensions();
    let painted = (width - 4..width)
        .flat_map(|x| (0..height).map(move |y| (x, y)))
        .filter(|&(x, y)| image.get_pixel(x, y).0 != [255, 255, 255])
        .count();
    assert_eq!(painted, 0, "the legend reaches the image's edge");
    let svg = std::fs::read_to_string(svg).unwrap();
    let texts: Vec<&str> = svg.split("<text").skip(1).collect();
    let legend: Vec<&&str> =
        texts.iter().filter(|t| ["wheel 1", "joint at", "\nshort\n"].iter().any(|w| t.contains(w))).collect();
    assert!(legend.len() >= 3, "the long label on two lines or more, and the short one: {legend:?}");
    let size = |t: &str| attribute(&format!("<text{t}"), "font-size");
    assert!(legend.iter().all(|t| size(t) == size(legend[0])), "one font size: {legend:?}");
    assert!(svg.contains("at 100 m"), "a number kept with its unit");
    let _ = std::fs::remove_dir_all(&folder);
}

/// A y label written upward never runs past its panel's plot: on three stacked snapshot panels (their plots ~200 px
/// high) "deflection w (mm, upward > 0)" at 21 px was ~300 px long and reached into the heading above; it is set
/// smaller to fit (its width estimated at 0.55 em a character, DejaVu Sans's average advance: the 0.62 em above is a
/// bound for text that must stay inside the image, too generous to compare a fitted length with).
#[test]
fn a_panels_y_label_fits_its_panel() {
    let axis = |name: &str, quantity: &str| Axis::new(name, quantity, Shown::Milli);
    let mut figure = PlotSpec::new("panels", "three panels", &axis("x", "x"), &axis("deflection w", "deflection"));
    for i in 0..3 {
        let mut panel = PlotSpec::new(format!("p{i}"), format!("panel {i}"), &axis("x", "x"), &figure_y());
        panel.series.push(report::plot::Series {
            label: Some("curve".into()),
            color: 1,
            stroke: report::plot::Stroke::Solid,
            markers: false,
            points: vec![(0.0, 0.0), (1.0, -1.0)],
        });
        figure.panels.push(panel);
    }
    let folder = std::env::temp_dir().join(format!("frictrack-figures-panels-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let (_, svg, layout) = render(&figure, &folder).unwrap();
    let svg = std::fs::read_to_string(svg).unwrap();
    let label = figure.panels[0].y_label.clone();
    let sizes: Vec<f64> = svg
        .split("<text")
        .filter(|t| t.split_once('>').is_some_and(|(_, text)| text.trim().starts_with(&label.replace('>', "&gt;"))))
        .map(|t| number(&format!("<text{t}"), "font-size"))
        .collect();
    assert_eq!(sizes.len(), 3, "{label}");
    for (size, panel) in sizes.iter().zip(&layout.panels) {
        let height = f64::from(panel.plot.3 - panel.plot.1);
        let length = 0.55 * size * label.chars().count() as f64;
        assert!(length <= height, "{length:.0} px of label beside {height} px of plot");
    }
    let _ = std::fs::remove_dir_all(&folder);
}

/// The snapshots' y axis: the deflection, upward positive.
fn figure_y() -> Axis {
    Axis::noted("deflection w", "deflection", Shown::Milli, "upward > 0")
}
