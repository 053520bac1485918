//! The six studies of docs/theory.md §7 as named presets. Each returns its data as CSV (long format, one row per point,
//! SI units), a JSON summary (critical speeds, peaks, optimal forces) and a few human-readable summary lines.
//! All runs of a study share one rayon pool; results do not depend on the thread count.

use crate::error::{Result, invalid};
use crate::figures::{DeflectionCurve, deflection_figure, device_color, quantity_figure};
use crate::metrics::{amplification, static_midspan};
use crate::number::row;
use crate::plot::PlotSpec;
use crate::scenario::{DevicesSection, DistributedSection, Scenario};
use crate::speeds::SpeedScale;
use crate::sweep::{CriticalSpeed, Runner, SweepPoint, critical_speed, log_spaced, refine_from_scan};
use serde::Serialize;
use serde_json::{Value, json};
use std::fmt::Write as _;

/// The studies of docs/theory.md §7.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preset {
    /// 1. Critical speed with discrete devices: N ∈ {3, 7, 15, 31}, F_u ∈ {10, 50, 100} kN, and no friction.
    DiscreteSpeed,
    /// 2. Equal-cost solutions: N·F_u ∈ {3100, 1550, 310} kN for N ∈ {31, 15, 7, 3}.
    EqualCost,
    /// 3. Optimal device force at 206 m/s for N ∈ {3, 7, 15, 31}.
    OptimalForce,
    /// 4. Critical speed with distributed friction f_u ∈ {0, 1, 2, 5, 10} kN/m.
    DistributedSpeed,
    /// 5. Dynamic amplification at mid-span for v ∈ {50, 100, 150, 200} m/s, f_u ∈ {1, 2} kN/m.
    Amplification,
    /// 6. 199 devices of 1 kN against f_u = 0.995 kN/m at 150 m/s: mid-span histories.
    DiscreteVsDistributed,
}

/// How finely the studies sample speeds and forces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Resolution {
    /// 10–290 m/s by 20 m/s, 9 forces per decade-scan: quick, for tests and previews.
    Coarse,
    /// 10–300 m/s by 1 m/s, 41 forces: the paper's curves.
    Paper,
}

impl Resolution {
    /// The speeds of a study on `base`: its `[sweep]` as given, whatever the resolution; otherwise the default
    /// range around the case's critical speed ([`SpeedScale::default_range`], 10–300 m/s by 10 for the reference
    /// case) sampled every second step (coarse: 10–290 m/s by 20) or every tenth of a step (paper: 1 m/s).
    pub fn speeds(self, base: &Scenario) -> Result<Vec<f64>> {
        if let Some(sweep) = &base.sweep {
            return Ok(sweep.speeds());
        }
        let range = SpeedScale::of(base)?.default_range();
        let step = match self {
            Resolution::Coarse => 2.0 * range.step,
            Resolution::Paper => 0.1 * range.step,
        };
        let count = ((range.to - range.from) / step + 1e-9).floor() as usize + 1;
        Ok((0..count).map(|i| range.from + i as f64 * step).collect())
    }

    fn forces(self) -> usize {
        match self {
            Resolution::Coarse => 9,
            Resolution::Paper => 41,
        }
    }

    /// Name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Resolution::Coarse => "coarse",
            Resolution::Paper => "paper",
        }
    }
}

impl Preset {
    /// All six, in docs/theory.md order.
    pub const ALL: [Preset; 6] = [
        Preset::DiscreteSpeed,
        Preset::EqualCost,
        Preset::OptimalForce,
        Preset::DistributedSpeed,
        Preset::Amplification,
        Preset::DiscreteVsDistributed,
    ];

    /// Name on the command line and of the output files.
    pub fn name(self) -> &'static str {
        match self {
            Preset::DiscreteSpeed => "discrete-speed",
            Preset::EqualCost => "equal-cost",
            Preset::OptimalForce => "optimal-force",
            Preset::DistributedSpeed => "distributed-speed",
            Preset::Amplification => "amplification",
            Preset::DiscreteVsDistributed => "discrete-vs-distributed",
        }
    }

    /// The preset called `name`.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL.into_iter().find(|p| p.name() == name).ok_or_else(|| {
            let names: Vec<&str> = Self::ALL.iter().map(|p| p.name()).collect();
            invalid("preset", name, format!("must be one of {}", names.join(", ")))
        })
    }

    /// What the study sets itself on top of the base scenario (the friction set-ups it compares, the speeds of
    /// fixed-speed studies, the recorded section).
    pub fn sets(self) -> &'static [&'static str] {
        match self {
            Preset::DiscreteSpeed => &["friction: none, and N ∈ {3, 7, 15, 31} devices of F_u ∈ {10, 50, 100} kN"],
            Preset::EqualCost => &["friction: N·F_u ∈ {3100, 1550, 310} kN shared by N ∈ {31, 15, 7, 3} devices"],
            Preset::OptimalForce => &[
                "friction: N ∈ {3, 7, 15, 31} devices, F_u scanned over 1 kN–10 MN",
                "load.speed: the critical speed v_cr rounded (206 m/s for the reference case)",
            ],
            Preset::DistributedSpeed => &["friction: distributed f_u ∈ {0, 1, 2, 5, 10} kN/m, no devices"],
            Preset::Amplification => &[
                "friction: distributed f_u ∈ {1, 2} kN/m, no devices",
                "load.speed: ¼, ½, ¾ and 1 × v_cr rounded (50, 100, 150, 200 m/s for the reference case)",
                "output.sections: mid-span",
            ],
            Preset::DiscreteVsDistributed => &[
                "friction: 199 devices of 1 kN, and distributed 0.995 kN/m",
                "load.speed: ¾ v_cr rounded (150 m/s for the reference case)",
                "output.sections: mid-span",
            ],
        }
    }

    /// The parts of `base` that this study replaces with its own (see [`Preset::sets`]), one sentence each; empty
    /// when the base scenario leaves them at their defaults.
    pub fn overrides(self, base: &Scenario) -> Vec<String> {
        let mut notes = Vec::new();
        let f = &base.friction;
        if f.devices.is_some() || f.distributed.is_some() {
            notes.push(format!(
                "the scenario's [friction] is not used: the study compares its own set-ups ({})",
                self.sets()[0].trim_start_matches("friction: ")
            ));
        }
        if !self.sweeps_speed() && base.sweep.is_some() {
            notes.push("the scenario's [sweep] is not used: this study runs at fixed speeds".into());
        }
        notes
    }

    /// Whether the study sweeps the load speed (the others run at fixed speeds).
    pub fn sweeps_speed(self) -> bool {
        matches!(self, Preset::DiscreteSpeed | Preset::EqualCost | Preset::DistributedSpeed)
    }

    /// A one-line title.
    pub fn title(self) -> &'static str {
        match self {
            Preset::DiscreteSpeed => "Critical speed with discrete friction devices",
            Preset::EqualCost => "Equal-cost device solutions (N·F_u constant)",
            Preset::OptimalForce => "Optimal device force at 206 m/s",
            Preset::DistributedSpeed => "Critical speed with distributed friction",
            Preset::Amplification => "Dynamic amplification at mid-span",
            Preset::DiscreteVsDistributed => "199 devices × 1 kN against 0.995 kN/m distributed friction",
        }
    }
}

/// What a study produces.
#[derive(Debug, Clone, Serialize)]
pub struct StudyData {
    /// Preset name.
    pub name: &'static str,
    /// Title.
    pub title: &'static str,
    /// Resolution name.
    pub resolution: &'static str,
    /// The data, CSV with a header line.
    #[serde(skip)]
    pub csv: String,
    /// Machine-readable summary (critical speeds, peaks, optimal forces…).
    pub summary: Value,
    /// Human-readable summary lines, one per curve or case.
    pub lines: Vec<String>,
    /// Two sentences saying what the study shows, for reports.
    pub headline: Vec<String>,
    /// The figures.
    pub plots: Vec<PlotSpec>,
    /// Number of simulations run.
    pub runs: usize,
    /// Mean friction-solver iterations per step over the study's sweep runs (solver statistics).
    pub mean_iterations: f64,
    /// The CSV's columns with their units, in order.
    pub columns: Vec<(String, &'static str)>,
}

/// The unit of a column of a study's CSV (SI; "1" for counts and ratios).
fn unit_of(column: &str) -> &'static str {
    match column {
        "speed" => "m/s",
        "device_force" | "cost" => "N",
        "force_per_length" => "N/m",
        "dissipated_energy" => "J",
        "global_norm" => "m²",
        "time" => "s",
        "impulse" => "N·s",
        "model" => "text",
        "devices" | "tau" | "phi_w" | "phi_m" => "1",
        _ => "m",
    }
}

/// Run `preset` on top of `base` (normally the reference case).
pub fn run_preset(preset: Preset, resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let data = match preset {
        Preset::DiscreteSpeed => discrete_speed(resolution, base, runner)?,
        Preset::EqualCost => equal_cost(resolution, base, runner)?,
        Preset::OptimalForce => optimal_force(resolution, base, runner)?,
        Preset::DistributedSpeed => distributed_speed(resolution, base, runner)?,
        Preset::Amplification => amplification_study(base, runner)?,
        Preset::DiscreteVsDistributed => discrete_vs_distributed(base, runner)?,
    };
    let headline = headline(preset, &data.summary);
    let header = data.csv.lines().next().unwrap_or_default();
    let columns = header.split(',').map(|c| (c.to_string(), unit_of(c))).collect();
    Ok(StudyData {
        columns,
        name: preset.name(),
        title: preset.title(),
        resolution: resolution.name(),
        headline,
        ..data
    })
}

fn number(v: &Value, key: &str) -> f64 {
    v.get(key).and_then(Value::as_f64).unwrap_or(f64::NAN)
}

/// Two sentences on what a study shows, from its summary.
fn headline(preset: Preset, summary: &Value) -> Vec<String> {
    let empty = Vec::new();
    let items = summary.get("curves").or_else(|| summary.get("optima")).and_then(Value::as_array).unwrap_or(&empty);
    let find = |pred: &dyn Fn(&Value) -> bool| items.iter().find(|v| pred(v)).cloned().unwrap_or(Value::Null);
    let curve_text = |v: &Value| {
        let (speed, peak) = (number(v, "critical_speed"), 1e3 * number(v, "peak_max_downward_deflection"));
        match v.get("critical_speed_location").and_then(Value::as_str) {
            Some("upper-end") => format!("at or above {speed:.1} m/s, the top of the range (peak there {peak:.0} mm)"),
            Some("lower-end") => {
                format!("at or below {speed:.1} m/s, the bottom of the range (peak there {peak:.0} mm)")
            }
            _ => format!("{speed:.1} m/s with a peak of {peak:.0} mm"),
        }
    };
    match preset {
        Preset::DiscreteSpeed => {
            let none = find(&|v| number(v, "devices") == 0.0);
            let best = items
                .iter()
                .min_by(|a, b| {
                    number(a, "peak_max_downward_deflection").total_cmp(&number(b, "peak_max_downward_deflection"))
                })
                .cloned()
                .unwrap_or(Value::Null);
            let cut =
                1.0 - number(&best, "peak_max_downward_deflection") / number(&none, "peak_max_downward_deflection");
            vec![
                format!("Without friction the track's critical speed is {}.", curve_text(&none)),
                format!(
                    "The best set, {} devices of {:.0} kN, cuts that peak by {:.0} % (critical speed {}).",
                    number(&best, "devices"),
                    number(&best, "device_force") / 1e3,
                    100.0 * cut,
                    curve_text(&best)
                ),
            ]
        }
        Preset::EqualCost => {
            let mut text = Vec::new();
            for cost in [3100e3, 1550e3, 310e3] {
                let group: Vec<&Value> = items.iter().filter(|v| number(v, "cost") == cost).collect();
                let best = group.iter().min_by(|a, b| {
                    number(a, "peak_max_downward_deflection").total_cmp(&number(b, "peak_max_downward_deflection"))
                });
                if let Some(b) = best {
                    text.push(format!(
                        "{:.0} kN: {} × {:.0} kN (peak {:.0} mm)",
                        cost / 1e3,
                        number(b, "devices"),
                        number(b, "device_force") / 1e3,
                        1e3 * number(b, "peak_max_downward_deflection")
                    ));
                }
            }
            vec![
                "For a given total friction capacity N·F_u, the lowest resonance peak comes from:".into(),
                format!("{}.", text.join("; ")),
            ]
        }
        Preset::OptimalForce => {
            let text: Vec<String> = items
                .iter()
                .map(|v| {
                    format!(
                        "N = {}: {:.0} kN ({:.0} mm)",
                        number(v, "devices"),
                        number(v, "optimal_device_force") / 1e3,
                        1e3 * number(v, "max_downward_deflection")
                    )
                })
                .collect();
            vec![
                format!(
                    "At {} m/s the max downward deflection is smallest for an intermediate device force:",
                    number(summary, "speed")
                ),
                format!("{}.", text.join("; ")),
            ]
        }
        Preset::DistributedSpeed => {
            let none = find(&|v| number(v, "force_per_length") == 0.0);
            let strong = find(&|v| number(v, "force_per_length") == 10e3);
            vec![
                format!("Without ballast friction the critical speed is {}.", curve_text(&none)),
                format!("With f_u = 10 kN/m it is {}.", curve_text(&strong)),
            ]
        }
        Preset::Amplification => {
            let top = items.iter().map(|v| number(v, "speed")).fold(0.0, f64::max);
            let at = |f: f64| find(&|v| number(v, "force_per_length") == f && number(v, "speed") == top);
            vec![
                "Mid-span amplification grows with speed towards the critical speed.".into(),
                format!(
                    "At {top} m/s: max φ_w {:.2} and φ_M {:.2} with f_u = 1 kN/m, {:.2} and {:.2} with 2 kN/m.",
                    number(&at(1e3), "max_phi_w"),
                    number(&at(1e3), "max_phi_m"),
                    number(&at(2e3), "max_phi_w"),
                    number(&at(2e3), "max_phi_m")
                ),
            ]
        }
        Preset::DiscreteVsDistributed => vec![
            format!(
                "With equal capacity, 199 devices of 1 kN and f_u = 0.995 kN/m give mid-span histories within {:.2} mm of each other on a {:.1} mm peak.",
                1e3 * number(summary, "max_history_gap"),
                1e3 * number(summary, "peak_midspan_deflection")
            ),
            format!(
                "They dissipate {:.0} J and {:.0} J.",
                number(summary, "dissipated_devices"),
                number(summary, "dissipated_distributed")
            ),
        ],
    }
}

fn with_devices(base: &Scenario, count: usize, force: f64) -> Scenario {
    let mut s = base.clone();
    s.friction.devices =
        (count > 0).then_some(DevicesSection { count: Some(count), positions: None, force: Some(force) });
    s.friction.distributed = None;
    s
}

fn with_distributed(base: &Scenario, force_per_length: f64) -> Scenario {
    let mut s = base.clone();
    s.friction.devices = None;
    s.friction.distributed =
        (force_per_length > 0.0).then(|| DistributedSection { force_per_length, ..DistributedSection::default() });
    s
}

fn blank(runs: usize) -> StudyData {
    StudyData {
        name: "",
        title: "",
        resolution: "",
        csv: String::new(),
        summary: Value::Null,
        lines: Vec::new(),
        headline: Vec::new(),
        plots: Vec::new(),
        runs,
        mean_iterations: 0.0,
        columns: Vec::new(),
    }
}

fn mean_iterations<'a>(points: impl Iterator<Item = &'a SweepPoint>) -> f64 {
    let (sum, count) = points.fold((0.0, 0usize), |(s, c), p| (s + p.mean_iterations, c + 1));
    if count > 0 { sum / count as f64 } else { 0.0 }
}

/// A labelled family of speed sweeps with the critical speed of each curve.
struct Curves {
    labels: Vec<Vec<(String, f64)>>,
    points: Vec<Vec<SweepPoint>>,
    critical: Vec<CriticalSpeed>,
    runs: usize,
}

fn sweep_curves(scenarios: Vec<(Vec<(String, f64)>, Scenario)>, speeds: &[f64], runner: &Runner) -> Result<Curves> {
    let cases = scenarios.iter().map(|(_, s)| s.build()).collect::<Result<Vec<_>>>()?;
    let points = runner.sweep_many(&cases, speeds)?;
    let step = speeds[1] - speeds[0];
    let curves: Vec<usize> = (0..cases.len()).collect();
    let refined = runner.silent().map(&curves, |&c| critical_speed(&cases[c], &points[c], 0.02 * step, runner))?;
    let runs = cases.len() * speeds.len() + refined.iter().map(|c| c.evaluations.len()).sum::<usize>();
    Ok(Curves { labels: scenarios.into_iter().map(|(l, _)| l).collect(), points, critical: refined, runs })
}

impl Curves {
    /// Max downward and upward deflection magnitudes vs speed for the curves `members`, coloured by `color`, with
    /// each interior critical speed marked.
    fn deflection_plot(
        &self,
        stem: &str,
        title: &str,
        members: &[usize],
        legend: &dyn Fn(usize) -> String,
        color: &dyn Fn(usize) -> usize,
    ) -> PlotSpec {
        let curves = members
            .iter()
            .map(|&c| DeflectionCurve {
                label: legend(c),
                color: color(c),
                downward: self.points[c].iter().map(|q| (q.speed, q.max_downward_deflection)).collect(),
                upward: self.points[c].iter().map(|q| (q.speed, q.max_upward_deflection)).collect(),
                optimum: Some(&self.critical[c])
                    .filter(|k| k.is_interior())
                    .map(|k| (k.speed, k.max_downward_deflection)),
            })
            .collect();
        deflection_figure(stem, title, "load speed v (m/s)", curves, "refined critical speed")
    }

    /// One quantity vs speed for every curve.
    fn quantity_plot(
        &self,
        stem: &str,
        title: &str,
        y_label: &str,
        value: fn(&SweepPoint) -> f64,
        legend: &dyn Fn(usize) -> String,
        color: &dyn Fn(usize) -> usize,
    ) -> PlotSpec {
        let curves = (0..self.points.len())
            .map(|c| (legend(c), color(c), self.points[c].iter().map(|q| (q.speed, value(q))).collect()))
            .collect();
        quantity_figure(stem, title, "load speed v (m/s)", y_label, curves, true)
    }

    fn csv(&self) -> String {
        let mut out = String::new();
        let label_names: Vec<&str> = self.labels[0].iter().map(|(n, _)| n.as_str()).collect();
        let _ = writeln!(
            out,
            "{},speed,max_downward_deflection,max_upward_deflection,dissipated_energy,global_norm,\
             window_max_downward_deflection,window_max_upward_deflection",
            label_names.join(",")
        );
        for (labels, points) in self.labels.iter().zip(&self.points) {
            let prefix: Vec<f64> = labels.iter().map(|(_, v)| *v).collect();
            for p in points {
                let values = [
                    p.speed,
                    p.max_downward_deflection,
                    p.max_upward_deflection,
                    p.dissipated_energy,
                    p.global_norm,
                    p.window_max_downward_deflection,
                    p.window_max_upward_deflection,
                ];
                let _ = writeln!(out, "{},{}", row(&prefix), row(&values));
            }
        }
        out
    }

    fn summary(&self) -> (Value, Vec<String>) {
        let mut items = Vec::new();
        let mut lines = Vec::new();
        for ((labels, points), critical) in self.labels.iter().zip(&self.points).zip(&self.critical) {
            let upward = points.iter().fold(0.0f64, |m, p| m.max(p.max_upward_deflection));
            let window = points.iter().fold(0.0f64, |m, p| m.max(p.window_max_downward_deflection));
            let mut item = serde_json::Map::new();
            for (name, value) in labels {
                item.insert(name.clone(), json!(value));
            }
            item.insert("critical_speed".into(), json!(critical.speed));
            item.insert("critical_speed_location".into(), json!(critical.location));
            item.insert("peak_max_downward_deflection".into(), json!(critical.max_downward_deflection));
            item.insert("peak_max_upward_deflection_sampled".into(), json!(upward));
            item.insert("peak_window_max_downward_deflection_sampled".into(), json!(window));
            items.push(Value::Object(item));
            let label: Vec<String> = labels.iter().map(|(n, v)| format!("{n} = {v}")).collect();
            let text = if critical.is_interior() {
                format!(
                    "critical speed {:.1} m/s ({:.0} km/h), peak max downward deflection {:.1} mm",
                    critical.speed,
                    critical.speed * 3.6,
                    critical.max_downward_deflection * 1e3
                )
            } else {
                critical.describe()
            };
            lines.push(format!("{}: {text}", label.join(", ")));
        }
        (json!({ "curves": items }), lines)
    }
}

fn discrete_speed(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let mut scenarios = vec![(vec![("device_force".into(), 0.0), ("devices".into(), 0.0)], with_devices(base, 0, 0.0))];
    for force in [10e3, 50e3, 100e3] {
        for count in [3usize, 7, 15, 31] {
            scenarios.push((
                vec![("device_force".into(), force), ("devices".into(), count as f64)],
                with_devices(base, count, force),
            ));
        }
    }
    let mut data = curves_study(scenarios, &resolution.speeds(base)?, runner, &|curves| {
        let legend =
            |c: usize| if c == 0 { "no friction".to_string() } else { format!("N = {}", [3, 7, 15, 31][(c - 1) % 4]) };
        [10, 50, 100]
            .iter()
            .enumerate()
            .map(|(i, kn)| {
                let members: Vec<usize> = std::iter::once(0).chain((1 + 4 * i)..(5 + 4 * i)).collect();
                curves.deflection_plot(
                    &format!("discrete-speed-{kn}kN"),
                    &format!("Discrete devices, F_u = {kn} kN: max deflection vs speed"),
                    &members,
                    &legend,
                    &|c| if c == 0 { 0 } else { device_color([3, 7, 15, 31][(c - 1) % 4]) },
                )
            })
            .collect()
    })?;
    data.lines.insert(0, "Discrete devices: critical speed and peak of each curve (refined on fresh runs).".into());
    Ok(data)
}

fn equal_cost(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let mut scenarios = Vec::new();
    for cost in [3100e3, 1550e3, 310e3] {
        for count in [31usize, 15, 7, 3] {
            let force = cost / count as f64;
            let labels = vec![("cost".into(), cost), ("devices".into(), count as f64), ("device_force".into(), force)];
            scenarios.push((labels, with_devices(base, count, force)));
        }
    }
    curves_study(scenarios, &resolution.speeds(base)?, runner, &|curves| {
        [3100, 1550, 310]
            .iter()
            .enumerate()
            .map(|(i, cost)| {
                let legend = |c: usize| {
                    let n = [31, 15, 7, 3][c % 4];
                    format!("N = {n}, F_u = {:.1} kN", f64::from(*cost) / f64::from(n))
                };
                curves.deflection_plot(
                    &format!("equal-cost-{cost}kN"),
                    &format!("Equal cost N·F_u = {cost} kN: max deflection vs speed"),
                    &((4 * i)..(4 * i + 4)).collect::<Vec<_>>(),
                    &legend,
                    &|c| device_color([31, 15, 7, 3][c % 4]),
                )
            })
            .collect()
    })
}

fn distributed_speed(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let scenarios = [0.0, 1e3, 2e3, 5e3, 10e3]
        .into_iter()
        .map(|f| (vec![("force_per_length".into(), f)], with_distributed(base, f)))
        .collect();
    curves_study(scenarios, &resolution.speeds(base)?, runner, &|curves| {
        let legend = |c: usize| match c {
            0 => "no friction".to_string(),
            _ => format!("f_u = {} kN/m", [0, 1, 2, 5, 10][c]),
        };
        // f_u = 0 is "no friction", black as in every study; 1–10 kN/m take the next colours in order.
        let color = |c: usize| c;
        vec![
            curves.deflection_plot(
                "distributed-speed-deflection",
                "Distributed friction: max deflection vs speed",
                &(0..5).collect::<Vec<_>>(),
                &legend,
                &color,
            ),
            curves.quantity_plot(
                "distributed-speed-global-norm",
                "Distributed friction: global norm vs speed",
                "global norm (1/t_on)∫∫|w| dx dt (m²)",
                |q| q.global_norm,
                &legend,
                &color,
            ),
            curves.quantity_plot(
                "distributed-speed-dissipated",
                "Distributed friction: dissipated energy vs speed",
                "energy dissipated by friction and damping (kJ)",
                |q| q.dissipated_energy / 1e3,
                &legend,
                &color,
            ),
        ]
    })
}

fn curves_study(
    scenarios: Vec<(Vec<(String, f64)>, Scenario)>,
    speeds: &[f64],
    runner: &Runner,
    plots: &dyn Fn(&Curves) -> Vec<PlotSpec>,
) -> Result<StudyData> {
    let curves = sweep_curves(scenarios, speeds, runner)?;
    let (summary, lines) = curves.summary();
    Ok(StudyData {
        csv: curves.csv(),
        summary,
        lines,
        plots: plots(&curves),
        mean_iterations: mean_iterations(curves.points.iter().flatten()),
        ..blank(curves.runs)
    })
}

fn optimal_force(resolution: Resolution, base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let speed = SpeedScale::of(base)?.near_critical(206.0);
    let forces = log_spaced(1e3, 1e7, resolution.forces());
    let counts = [3usize, 7, 15, 31];
    let scenarios: Vec<Scenario> = counts
        .iter()
        .flat_map(|&n| forces.iter().map(move |&f| (n, f)))
        .map(|(n, f)| with_devices(base, n, f))
        .collect();
    let points = runner.map(&scenarios, |s| runner.point(&s.build()?, speed))?;
    let mut csv =
        String::from("devices,device_force,speed,max_downward_deflection,max_upward_deflection,dissipated_energy\n");
    let mut items = Vec::new();
    let mut lines = Vec::new();
    let mut runs = points.len();
    let mut figure_curves = Vec::new();
    for (i, &n) in counts.iter().enumerate() {
        let curve = &points[i * forces.len()..(i + 1) * forces.len()];
        let kn = |f: &f64| f / 1e3;
        for (f, p) in forces.iter().zip(curve) {
            let values = [n as f64, *f, speed, p.max_downward_deflection, p.max_upward_deflection, p.dissipated_energy];
            let _ = writeln!(csv, "{}", row(&values));
        }
        let values: Vec<f64> = curve.iter().map(|p| p.max_downward_deflection).collect();
        let refined = refine_from_scan(&with_devices(base, n, 1.0), speed, &forces, &values, 0.02, runner)?;
        runs += refined.explored.len();
        figure_curves.push(DeflectionCurve {
            label: format!("N = {n}"),
            color: device_color(n),
            downward: forces.iter().zip(curve).map(|(f, p)| (kn(f), p.max_downward_deflection)).collect(),
            upward: forces.iter().zip(curve).map(|(f, p)| (kn(f), p.max_upward_deflection)).collect(),
            optimum: Some((kn(&refined.force), refined.max_downward_deflection)),
        });
        items.push(json!({ "devices": n, "optimal_device_force": refined.force, "max_downward_deflection": refined.max_downward_deflection }));
        lines.push(format!(
            "N = {n}: optimal F_u {:.1} kN gives max downward deflection {:.1} mm at {speed} m/s",
            refined.force / 1e3,
            refined.max_downward_deflection * 1e3
        ));
    }
    let mut plot = deflection_figure(
        "optimal-force",
        &format!("Max deflection vs device force at {speed} m/s"),
        "device force F_u (kN, log scale)",
        figure_curves,
        "refined optimal force",
    );
    plot.log_x = true;
    Ok(StudyData {
        csv,
        summary: json!({ "speed": speed, "optima": items }),
        lines,
        plots: vec![plot],
        mean_iterations: mean_iterations(points.iter()),
        ..blank(runs)
    })
}

fn amplification_study(base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let reference = static_midspan(&with_distributed(base, 0.0).build()?)?;
    let scale = SpeedScale::of(base)?;
    let speeds = [(0.25, 50.0), (0.5, 100.0), (0.75, 150.0), (1.0, 200.0)].map(|(f, v)| scale.fraction(f, v));
    let combos: Vec<(f64, f64)> = [1e3, 2e3].into_iter().flat_map(|f| speeds.map(|v| (f, v))).collect();
    let results = runner.map(&combos, |&(f, v)| {
        let mut s = with_distributed(base, f);
        s.load.speed = v;
        s.output.sections = vec![s.mesh.length / 2.0];
        let case = s.build()?;
        let samples = runner.cached(&format!("{:016x}@{v}/midspan-amplification", case.fingerprint), || {
            let r = runner.simulate(&case, &case.settings)?;
            Ok(amplification(&r.histories[0], reference, case.model.mesh().length))
        })?;
        Ok((f, v, samples))
    })?;
    let mut csv = String::from("force_per_length,speed,tau,phi_w,phi_m\n");
    let mut items = Vec::new();
    let mut lines = Vec::new();
    for (f, v, samples) in &results {
        for a in samples {
            let _ = writeln!(csv, "{}", row(&[*f, *v, a.tau, a.deflection, a.moment]));
        }
        let max_w = samples.iter().fold(f64::NEG_INFINITY, |m, a| m.max(a.deflection));
        let max_m = samples.iter().fold(f64::NEG_INFINITY, |m, a| m.max(a.moment));
        items.push(json!({ "force_per_length": f, "speed": v, "max_phi_w": max_w, "max_phi_m": max_m }));
        lines.push(format!("f_u = {:.0} kN/m, v = {v} m/s: max φ_w {max_w:.3}, max φ_M {max_m:.3}", f / 1e3));
    }
    let subtitle = format!(
        "w_sta = {:.2} mm, M_sta = {:.2} kN·m: mid-span static deflection and moment, load at mid-span, no friction",
        reference.deflection.abs() * 1e3,
        reference.moment.abs() / 1e3
    );
    let mut plots = Vec::new();
    for (f, kn) in [(1e3, 1), (2e3, 2)] {
        for (which, symbol, value) in [
            (
                "deflection",
                "φ_w = w/w_sta",
                (|a: &crate::metrics::Amplification| a.deflection) as fn(&crate::metrics::Amplification) -> f64,
            ),
            ("moment", "φ_M = M/M_sta", |a| a.moment),
        ] {
            // Fastest first, so that the slower, smaller curves are drawn on top and stay visible.
            let curves = results
                .iter()
                .enumerate()
                .filter(|(_, (ff, _, _))| *ff == f)
                .rev()
                .map(|(i, (_, v, samples))| {
                    let points = samples.iter().map(|a| (a.tau, value(a))).collect();
                    (format!("v = {v} m/s"), 1 + i % speeds.len(), points)
                })
                .collect();
            let mut plot = quantity_figure(
                &format!("amplification-{which}-{kn}kN"),
                &format!("Mid-span {which} amplification, f_u = {kn} kN/m"),
                "load position τ = x_c/L (-)",
                &format!("{symbol} (-)"),
                curves,
                false,
            );
            plot.subtitle = subtitle.clone();
            plots.push(plot);
        }
    }
    Ok(StudyData { csv, summary: json!({ "curves": items }), lines, plots, ..blank(results.len()) })
}

fn discrete_vs_distributed(base: &Scenario, runner: &Runner) -> Result<StudyData> {
    let speed = SpeedScale::of(base)?.fraction(0.75, 150.0);
    let mut devices = with_devices(base, 199, 1e3);
    let mut distributed = with_distributed(base, 995.0);
    for s in [&mut devices, &mut distributed] {
        s.load.speed = speed;
        s.output.sections = vec![s.mesh.length / 2.0];
    }
    // Each run with the capacity F_j (N) of its friction section at mid-span, to compare what each mobilises.
    let runs = runner.map(&[&devices, &distributed], |s| {
        let case = s.build()?;
        let middle = case.contacts.positions().iter().position(|&x| (x - s.mesh.length / 2.0).abs() < 1e-9);
        let capacity = middle.map_or(f64::NAN, |j| case.contacts.bounds()[j]);
        Ok((runner.simulate(&case, &case.settings)?, capacity))
    })?;
    let (capacities, runs): (Vec<f64>, Vec<_>) = runs.into_iter().map(|(r, c)| (c, r)).unzip();
    let mut csv = String::from("model,time,load_position,deflection,impulse\n");
    for (name, r) in ["devices", "distributed"].iter().zip(&runs) {
        let h = &r.histories[0];
        let impulse = h.impulse.as_deref().unwrap_or(&[]);
        for k in 0..h.time.len() {
            let values = [h.time[k], h.load_position[k], h.deflection[k], impulse.get(k).copied().unwrap_or(0.0)];
            let _ = writeln!(csv, "{name},{}", row(&values));
        }
    }
    let (a, b) = (&runs[0].histories[0], &runs[1].histories[0]);
    let peak = a.deflection.iter().fold(0.0f64, |m, w| m.max(w.abs()));
    let gap = a.deflection.iter().zip(&b.deflection).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    let lines = vec![
        format!(
            "mid-span deflection histories differ by at most {:.2} mm on a {:.1} mm peak ({:.2} %)",
            gap * 1e3,
            peak * 1e3,
            100.0 * gap / peak
        ),
        format!(
            "dissipated energy {:.0} J (199 devices) vs {:.0} J (distributed)",
            runs[0].energy.dissipated(),
            runs[1].energy.dissipated()
        ),
    ];
    let summary = json!({
        "speed": speed,
        "max_history_gap": gap,
        "peak_midspan_deflection": peak,
        "dissipated_devices": runs[0].energy.dissipated(),
        "dissipated_distributed": runs[1].energy.dissipated(),
    });
    let history = |i: usize, value: &dyn Fn(&nscd::simulation::SectionHistory, usize) -> f64| -> Vec<(f64, f64)> {
        let h = &runs[i].histories[0];
        (0..h.time.len()).map(|k| (h.time[k], value(h, k))).collect()
    };
    let labels = ["199 devices × 1 kN", "f_u = 0.995 kN/m"];
    let colors = [4, 5];
    let h = runs[0].step;
    let deflection = (0..2).map(|i| (labels[i].to_string(), colors[i], history(i, &|s, k| s.deflection[k] * 1e3)));
    let mobilised = (0..2).map(|i| {
        let fraction = &|s: &nscd::simulation::SectionHistory, k: usize| {
            s.impulse.as_ref().map_or(0.0, |p| p[k] / (h * capacities[i]))
        };
        (labels[i].to_string(), colors[i], history(i, fraction))
    });
    let plots = vec![
        quantity_figure(
            "discrete-vs-distributed-deflection",
            &format!("Mid-span deflection at {speed} m/s, equal friction capacity"),
            "time t (s)",
            "mid-span deflection w (mm, upward > 0)",
            deflection.collect(),
            false,
        ),
        {
            let mut plot = quantity_figure(
                "discrete-vs-distributed-mobilised",
                &format!("Friction mobilised at mid-span, {speed} m/s"),
                "time t (s)",
                "friction force / capacity of the section (-1 … 1)",
                mobilised.collect(),
                false,
            );
            plot.subtitle = format!(
                "capacity at mid-span: a device of {:.0} N against a section of {:.0} N (0.995 kN/m × 0.25 m)",
                capacities[0], capacities[1]
            );
            plot
        },
    ];
    Ok(StudyData { csv, summary, lines, plots, ..blank(2) })
}
