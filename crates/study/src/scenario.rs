//! The scenario file: everything docs/theory.md describes, in TOML, every key optional (defaults = the reference case of
//! docs/theory.md §2). Unknown keys are errors. [`Scenario::build`] turns it into the beam model, the contact set and the
//! run settings; [`Scenario::validate`] names the offending key by its dotted path.

use crate::error::{Result, StudyError, invalid};
use fem_beam::reference::uic60_on_soft_soil;
use fem_beam::{AbsorbingZones, BeamModel, Foundation, Mesh, Support, Supports};
use friction::{ContactSet, DeviceLayout, Devices, DistributedFriction, Quadrature};
use nscd::{InitialState, RunSettings, SolverKind};
use serde::{Deserialize, Serialize};

/// A whole case: beam, mesh, supports, foundation, load, friction, integration, sweep, output.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct Scenario {
    /// A title for reports.
    pub title: String,
    /// The rail section.
    pub beam: BeamSection,
    /// Length and elements.
    pub mesh: MeshSection,
    /// End supports.
    pub supports: SupportsSection,
    /// The soil.
    pub foundation: FoundationSection,
    /// The moving load.
    pub load: LoadSection,
    /// Friction devices and/or distributed friction.
    pub friction: FrictionSection,
    /// Time integration and the friction solver.
    pub integration: IntegrationSection,
    /// Speed range of sweeps and studies; without it, a range around the case's critical speed
    /// ([`crate::speeds::SpeedScale`]).
    pub sweep: Option<SweepSection>,
    /// What is recorded.
    pub output: OutputSection,
}

/// `[beam]`: the rail (UIC60 by default).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct BeamSection {
    /// E (Pa).
    pub youngs_modulus: f64,
    /// I (m⁴).
    pub second_moment: f64,
    /// A (m²).
    pub area: f64,
    /// ρ (kg/m³).
    pub density: f64,
}

impl Default for BeamSection {
    fn default() -> Self {
        let b = fem_beam::Beam::default();
        Self { youngs_modulus: b.youngs_modulus, second_moment: b.second_moment, area: b.area, density: b.density }
    }
}

impl BeamSection {
    /// The rail section these values describe (not yet validated).
    pub fn beam(&self) -> fem_beam::Beam {
        fem_beam::Beam {
            youngs_modulus: self.youngs_modulus,
            second_moment: self.second_moment,
            area: self.area,
            density: self.density,
        }
    }
}

/// `[mesh]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct MeshSection {
    /// Beam length L (m).
    pub length: f64,
    /// Number of equal elements.
    pub elements: usize,
}

impl Default for MeshSection {
    fn default() -> Self {
        let m = Mesh::default();
        Self { length: m.length, elements: m.elements }
    }
}

/// An end support.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum SupportKind {
    /// w = 0.
    #[default]
    Pinned,
    /// w = 0, θ = 0.
    Clamped,
    /// No constraint.
    Free,
}

impl From<SupportKind> for Support {
    fn from(kind: SupportKind) -> Self {
        match kind {
            SupportKind::Pinned => Support::Pinned,
            SupportKind::Clamped => Support::Clamped,
            SupportKind::Free => Support::Free,
        }
    }
}

/// `[supports]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct SupportsSection {
    /// Support at x = 0.
    pub left: SupportKind,
    /// Support at x = L.
    pub right: SupportKind,
}

/// `[foundation]`: Winkler stiffness and viscous damping (as a value or as a ratio of c_cr, not both).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct FoundationSection {
    /// k_f (N/m²).
    pub stiffness: f64,
    /// c_f (N·s/m²).
    pub damping: Option<f64>,
    /// ζ = c_f/c_cr.
    pub damping_ratio: Option<f64>,
    /// Damping graded up towards both ends.
    pub absorbing_zones: Option<AbsorbingZonesSection>,
}

impl Default for FoundationSection {
    fn default() -> Self {
        Self { stiffness: Foundation::default().stiffness, damping: None, damping_ratio: None, absorbing_zones: None }
    }
}

/// `[foundation.absorbing_zones]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct AbsorbingZonesSection {
    /// Zone length at each end (m).
    pub length: f64,
    /// Damping reached at the ends, as a ratio of c_cr.
    pub peak_ratio: f64,
}

impl Default for AbsorbingZonesSection {
    fn default() -> Self {
        Self { length: 40.0, peak_ratio: 1.0 }
    }
}

/// `[load]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct LoadSection {
    /// Magnitude F (N), acting downward.
    pub force: f64,
    /// Speed v (m/s) of a single run.
    pub speed: f64,
}

impl Default for LoadSection {
    fn default() -> Self {
        Self { force: uic60_on_soft_soil().load, speed: 200.0 }
    }
}

/// `[friction]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct FrictionSection {
    /// `[friction.devices]`.
    pub devices: Option<DevicesSection>,
    /// `[friction.distributed]`.
    pub distributed: Option<DistributedSection>,
}

/// `[friction.devices]`: `count` evenly spaced devices or explicit `positions`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct DevicesSection {
    /// N devices at i·L/(N+1), snapped to nodes.
    pub count: Option<usize>,
    /// Device positions (m), snapped to nodes.
    pub positions: Option<Vec<f64>>,
    /// Maximal force of one device F_u (N); required.
    pub force: Option<f64>,
}

/// Quadrature of distributed friction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum QuadratureKind {
    /// Composite trapezoid.
    #[default]
    Trapezoid,
    /// Composite Simpson (even subdivisions).
    Simpson,
}

/// `[friction.distributed]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct DistributedSection {
    /// f_u (N/m).
    pub force_per_length: f64,
    /// Sub-intervals J per element.
    pub subdivisions: usize,
    /// Quadrature rule.
    pub quadrature: QuadratureKind,
}

impl Default for DistributedSection {
    fn default() -> Self {
        Self { force_per_length: 0.0, subdivisions: 4, quadrature: QuadratureKind::Trapezoid }
    }
}

/// Friction solver choice.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum SolverChoice {
    /// Projection for sparse devices, interior point for dense sections.
    #[default]
    Auto,
    /// Projected Gauss–Seidel.
    Projection,
    /// Banded interior point.
    InteriorPoint,
    /// Clarabel QP.
    Clarabel,
}

impl From<SolverChoice> for SolverKind {
    fn from(choice: SolverChoice) -> Self {
        match choice {
            SolverChoice::Auto => SolverKind::Auto,
            SolverChoice::Projection => SolverKind::Projection,
            SolverChoice::InteriorPoint => SolverKind::InteriorPoint,
            SolverChoice::Clarabel => SolverKind::Clarabel,
        }
    }
}

/// `[integration]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct IntegrationSection {
    /// θ ∈ [0.5, 1].
    pub theta: f64,
    /// Load advance per step Δx (m); h = Δx/v.
    pub load_advance: f64,
    /// Friction solver.
    pub solver: SolverChoice,
    /// Relative tolerance of the friction law.
    pub tolerance: f64,
    /// Iteration cap per step.
    pub max_iterations: usize,
    /// Interior point re-solves a moving window.
    pub moving_window: bool,
    /// Start from the analytic steady state with the load here (m) instead of at rest.
    pub steady_start: Option<f64>,
    /// Run until this time (s) instead of stopping when the load leaves.
    pub end_time: Option<f64>,
}

impl Default for IntegrationSection {
    fn default() -> Self {
        let s = RunSettings::default();
        Self {
            theta: s.theta,
            load_advance: s.load_advance,
            solver: SolverChoice::Auto,
            tolerance: s.solver.tolerance,
            max_iterations: s.solver.max_iterations,
            moving_window: s.solver.moving_window,
            steady_start: None,
            end_time: None,
        }
    }
}

/// `[sweep]`: speeds from, to, step (m/s).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SweepSection {
    /// First speed (m/s).
    pub from: f64,
    /// Last speed (m/s), included up to round-off.
    pub to: f64,
    /// Step (m/s).
    pub step: f64,
}

impl Default for SweepSection {
    fn default() -> Self {
        Self { from: 10.0, to: 300.0, step: 10.0 }
    }
}

impl SweepSection {
    /// Check the range (`path` prefixes the field names in errors).
    pub fn validate(&self, path: &str) -> Result<()> {
        let (from, to, step) = (self.from, self.to, self.step);
        if !(from.is_finite() && from > 0.0) {
            return Err(invalid(&format!("{path}.from"), from, "must be finite and > 0 (m/s)"));
        }
        if !(to.is_finite() && to >= from) {
            return Err(invalid(&format!("{path}.to"), to, format!("must be finite and ≥ from = {from} (m/s)")));
        }
        if !(step.is_finite() && step > 0.0) {
            return Err(invalid(&format!("{path}.step"), step, "must be finite and > 0 (m/s)"));
        }
        if (to - from) / step > 1e6 {
            return Err(invalid(&format!("{path}.step"), step, "gives more than a million speeds"));
        }
        Ok(())
    }

    /// The speeds from, from + step, … ≤ to (up to round-off).
    pub fn speeds(&self) -> Vec<f64> {
        let count = ((self.to - self.from) / self.step + 1e-9).floor() as usize + 1;
        (0..count).map(|i| self.from + i as f64 * self.step).collect()
    }
}

/// `[output]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct OutputSection {
    /// Positions (m) whose histories are recorded in single runs.
    pub sections: Vec<f64>,
    /// Load positions [A, B] (m) over which the "window" extremes are taken besides the whole-run ones; default the
    /// middle third of the beam, [L/3, 2L/3], away from the entry and exit transients.
    pub extremes_window: Option<[f64; 2]>,
    /// Times (s) of whole-beam snapshots (`run --out`).
    pub snapshot_times: Vec<f64>,
    /// Load positions (m) of whole-beam snapshots (`run --out`); with neither list, L/4, L/2 and 3L/4.
    pub snapshot_load_positions: Vec<f64>,
}

impl OutputSection {
    /// The snapshot requests for a beam of length `length` (m): the times and load positions given, or the load at
    /// L/4, L/2 and 3L/4.
    pub fn snapshots(&self, length: f64) -> Vec<nscd::SnapshotAt> {
        use nscd::SnapshotAt;
        let mut requests: Vec<SnapshotAt> = self.snapshot_times.iter().map(|&t| SnapshotAt::Time(t)).collect();
        requests.extend(self.snapshot_load_positions.iter().map(|&x| SnapshotAt::LoadPosition(x)));
        if requests.is_empty() {
            requests = [0.25, 0.5, 0.75].iter().map(|f| SnapshotAt::LoadPosition(f * length)).collect();
        }
        requests
    }

    /// The window of load positions (m) for a beam of length `length` (m): the one given, or the middle third.
    pub fn extremes_window(&self, length: f64) -> (f64, f64) {
        self.extremes_window.map_or((length / 3.0, 2.0 * length / 3.0), |[a, b]| (a, b))
    }
}

/// A scenario turned into what the stepper runs.
#[derive(Debug, Clone)]
pub struct Case {
    /// The assembled beam.
    pub model: BeamModel,
    /// All friction sections.
    pub contacts: ContactSet,
    /// Run settings (speed from `[load]`).
    pub settings: RunSettings,
    /// Identifies what a run of this case at a given speed computes: a hash (64-bit FNV-1a) of the frictrack version
    /// and the scenario without its title, load speed, recorded sections and sweep range. Keys journal entries.
    pub fingerprint: u64,
}

fn finite_positive(path: &str, value: f64, unit: &str) -> Result<()> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(invalid(path, value, format!("must be finite and > 0 ({unit})")))
    }
}

fn finite_non_negative(path: &str, value: f64, unit: &str) -> Result<()> {
    if value.is_finite() && value >= 0.0 {
        Ok(())
    } else {
        Err(invalid(path, value, format!("must be finite and ≥ 0 ({unit})")))
    }
}

impl Scenario {
    /// Parse TOML; `source_name` (a file name) prefixes syntax errors with line and column.
    pub fn from_toml(text: &str, source_name: &str) -> Result<Self> {
        toml::from_str(text).map_err(|e| {
            let offset = e.span().map_or(0, |span| span.start);
            let (line, column) = line_column(text, offset);
            let message = e.message().trim();
            let message = match key_path(text, offset) {
                Some(path) => format!("{path}: {message}{}", did_you_mean(message)),
                None => format!("{message}{}", did_you_mean(message)),
            };
            StudyError::Syntax { source_name: source_name.into(), line, column, message }
        })
    }

    /// Read and parse a file.
    pub fn from_path(path: &std::path::Path) -> Result<Self> {
        // A scenario that cannot be read is the user's input error (exit code 2), not a failure of the run.
        let text = std::fs::read_to_string(path)
            .map_err(|e| invalid("scenario file", path.display(), format!("cannot be read: {e}")))?;
        Self::from_toml(&text, &path.display().to_string())
    }

    /// The scenario as TOML (all keys, defaults included).
    pub fn to_toml(&self) -> String {
        toml::to_string(self).expect("a scenario always serialises")
    }

    /// Check every value that the lower layers do not already name by its path.
    pub fn validate(&self) -> Result<()> {
        self.build().map(|_| ())
    }

    /// The assembled beam model (beam, mesh, foundation with its damping and absorbing zones, supports), checked;
    /// refuses degenerate meshes and mechanisms ([`crate::diagnostics::refuse_degenerate`]).
    pub fn model(&self) -> Result<BeamModel> {
        let beam = self.beam.beam();
        beam.validate()?;
        let mesh = Mesh::new(self.mesh.length, self.mesh.elements)?;
        let f = &self.foundation;
        let mut foundation = Foundation { stiffness: f.stiffness, damping: 0.0 };
        foundation.validate()?;
        match (f.damping, f.damping_ratio) {
            (Some(_), Some(ratio)) => {
                return Err(invalid(
                    "foundation.damping_ratio",
                    ratio,
                    "give foundation.damping or damping_ratio, not both",
                ));
            }
            (Some(c), None) => {
                finite_non_negative("foundation.damping", c, "N·s/m²")?;
                foundation.damping = c;
            }
            (None, Some(ratio)) => {
                finite_non_negative("foundation.damping_ratio", ratio, "ratio of c_cr")?;
                foundation = foundation.with_damping_ratio(ratio, &beam)?;
            }
            (None, None) => {}
        }
        let supports = Supports { left: self.supports.left.into(), right: self.supports.right.into() };
        let damping = match &f.absorbing_zones {
            Some(z) => {
                finite_positive("foundation.absorbing_zones.length", z.length, "m")?;
                finite_non_negative("foundation.absorbing_zones.peak_ratio", z.peak_ratio, "ratio of c_cr")?;
                let zones = AbsorbingZones {
                    length: z.length,
                    peak_damping: z.peak_ratio * foundation.critical_damping(&beam),
                };
                zones.element_damping(&mesh, foundation.damping).map_err(|e| under("foundation", e.into()))?
            }
            None => vec![foundation.damping; mesh.elements],
        };
        let model = BeamModel::with_element_damping(beam, foundation, mesh, supports, damping)?;
        crate::diagnostics::refuse_degenerate(&model)?;
        Ok(model)
    }

    /// Build the model, contact set and run settings, checking every value on the way.
    pub fn build(&self) -> Result<Case> {
        let model = self.model()?;
        let contacts = self.contacts(&model).map_err(|e| under("friction", e))?;
        finite_non_negative("load.force", self.load.force, "N")?;
        finite_positive("load.speed", self.load.speed, "m/s")?;
        if let Some([a, b]) = self.output.extremes_window {
            let length = model.mesh().length;
            if !(a.is_finite() && b.is_finite() && 0.0 <= a && a < b && b <= length) {
                return Err(invalid(
                    "output.extremes_window",
                    format!("[{a}, {b}]"),
                    format!("needs load positions 0 ≤ A < B ≤ L = {length} m"),
                ));
            }
        }
        let settings = self.run_settings(self.load.speed);
        settings.validate(&model).map_err(scenario_path)?;
        if let Some(sweep) = &self.sweep {
            sweep.validate("sweep")?;
        }
        Ok(Case { model, contacts, settings, fingerprint: self.fingerprint() })
    }

    /// See [`Case::fingerprint`].
    pub fn fingerprint(&self) -> u64 {
        let mut physics = self.clone();
        physics.title.clear();
        physics.load.speed = 0.0;
        physics.output.sections.clear();
        physics.output.snapshot_times.clear();
        physics.output.snapshot_load_positions.clear();
        physics.sweep = None;
        fnv1a(
            format!("frictrack {} results {RESULT_FORMAT}\n{}", env!("CARGO_PKG_VERSION"), physics.to_toml())
                .as_bytes(),
        )
    }

    /// The scenario's beam, foundation (with its damping), mesh, supports and load force as the closed-form
    /// reference case (`frictrack reference` and `analytic` on a scenario).
    pub fn reference_case(&self) -> Result<fem_beam::reference::ReferenceCase> {
        finite_non_negative("load.force", self.load.force, "N")?;
        let model = self.model()?;
        Ok(fem_beam::reference::ReferenceCase {
            beam: *model.beam(),
            foundation: *model.foundation(),
            mesh: *model.mesh(),
            supports: model.supports(),
            load: self.load.force,
        })
    }

    /// The speeds of a sweep: `[sweep]` if given, else the default range around the critical speed.
    pub fn speed_range(&self) -> Result<SweepSection> {
        match &self.sweep {
            Some(sweep) => Ok(sweep.clone()),
            None => Ok(crate::speeds::SpeedScale::of(self)?.default_range()),
        }
    }

    fn contacts(&self, model: &BeamModel) -> Result<ContactSet> {
        let mut contacts = ContactSet::new();
        if let Some(d) = &self.friction.devices {
            let layout = match (d.count, &d.positions) {
                (Some(count), None) => DeviceLayout::Uniform { count },
                (None, Some(positions)) => {
                    if let Some(&x) =
                        positions.iter().find(|x| !(x.is_finite() && (0.0..=model.mesh().length).contains(*x)))
                    {
                        return Err(invalid("friction.devices.positions", x, "every position must lie on the beam"));
                    }
                    DeviceLayout::Positions(positions.clone())
                }
                (Some(count), Some(_)) => {
                    return Err(invalid(
                        "friction.devices.count",
                        count,
                        "give friction.devices.count or positions, not both",
                    ));
                }
                (None, None) => return Err(invalid("friction.devices", "{}", "give count or positions")),
            };
            // The layout's own checks (e.g. the count against the mesh) come first, then the force.
            let mut devices = Devices { layout, force: 0.0 };
            devices.validate(model)?;
            devices.force = d.force.ok_or_else(|| {
                invalid("friction.devices.force", "missing", "give the maximal force of one device F_u (N)")
            })?;
            finite_non_negative("friction.devices.force", devices.force, "N")?;
            contacts.extend(devices.contact_set(model)?);
        }
        if let Some(d) = &self.friction.distributed {
            let quadrature = match d.quadrature {
                QuadratureKind::Trapezoid => Quadrature::Trapezoid,
                QuadratureKind::Simpson => Quadrature::Simpson,
            };
            let distributed =
                DistributedFriction { force_per_length: d.force_per_length, subdivisions: d.subdivisions, quadrature };
            contacts.extend(distributed.contact_set(model)?);
        }
        Ok(contacts)
    }

    /// Run settings for a load speed `speed` (m/s), not yet validated (see [`Scenario::build`]).
    pub fn run_settings(&self, speed: f64) -> RunSettings {
        let i = &self.integration;
        let mut settings = RunSettings {
            speed,
            load: self.load.force,
            theta: i.theta,
            load_advance: i.load_advance,
            end_time: i.end_time,
            record_sections: self.output.sections.clone(),
            extremes_window: Some(self.output.extremes_window(self.mesh.length)),
            ..RunSettings::default()
        };
        settings.solver.kind = i.solver.into();
        settings.solver.tolerance = i.tolerance;
        settings.solver.max_iterations = i.max_iterations;
        settings.solver.moving_window = i.moving_window;
        if let Some(position) = i.steady_start {
            settings.initial = InitialState::SteadyState { position };
        }
        settings
    }
}

/// A field error of a lower layer, whose name is relative to the scenario section `section` (e.g. `devices.count` in
/// `[friction]`), renamed to its full path; other errors unchanged.
fn under(section: &str, error: StudyError) -> StudyError {
    use fem_beam::FemError as F;
    use friction::FrictionError as R;
    match error {
        StudyError::Friction(R::InvalidField { field, value, allowed }) => {
            invalid(&format!("{section}.{field}"), value, allowed)
        }
        StudyError::Friction(R::InvalidCount { field, value, allowed }) => {
            invalid(&format!("{section}.{field}"), value, allowed)
        }
        StudyError::Beam(F::InvalidField { field, value, allowed }) => {
            invalid(&format!("{section}.{field}"), value, allowed)
        }
        StudyError::Beam(F::InvalidCount { field, value, allowed }) => {
            invalid(&format!("{section}.{field}"), value, allowed)
        }
        other => other,
    }
}

/// Rename a run-setting error's field to its path in the scenario file.
fn scenario_path(error: nscd::NscdError) -> StudyError {
    match error {
        nscd::NscdError::InvalidField { field, value, allowed } => {
            let path = match field {
                "speed" => "load.speed",
                "load" => "load.force",
                "load_advance" => "integration.load_advance",
                "integration.step" => "integration.load_advance",
                "solver.tolerance" => "integration.tolerance",
                "solver.max_iterations" => "integration.max_iterations",
                "initial.position" => "integration.steady_start",
                "end_time" => "integration.end_time",
                "record_sections" => "output.sections",
                other => other,
            };
            invalid(path, value, allowed)
        }
        other => other.into(),
    }
}

/// Version of what a run reports ([`crate::SweepPoint`]'s fields), part of every fingerprint so that journals of
/// an older format are never read back as results of this one.
const RESULT_FORMAT: u32 = 2;

/// 64-bit FNV-1a hash: stable across platforms, Rust versions and runs (unlike `std`'s `DefaultHasher`).
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

/// The dotted path of the key at byte `offset`: the enclosing `[table]` header and the key on that line (or the
/// header itself when the offset is inside one). `None` for a syntax error not on a key.
fn key_path(text: &str, offset: usize) -> Option<String> {
    let offset = offset.min(text.len());
    let line_start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let line = text[line_start..].lines().next().unwrap_or("").trim();
    let header = |l: &str| l.trim_start_matches('[').split(']').next().map(|h| h.trim().replace(' ', ""));
    if line.starts_with('[') {
        return header(line).filter(|h| !h.is_empty());
    }
    let key = line.split_once('=')?.0.trim().trim_matches('"');
    if key.is_empty() {
        return None;
    }
    let table = text[..line_start].lines().rev().map(str::trim).find(|l| l.starts_with('[')).and_then(header);
    Some(match table {
        Some(t) if !t.is_empty() => format!("{t}.{key}"),
        _ => key.to_string(),
    })
}

/// For serde's "unknown field `x`, expected `a`, `b`…" (or variant): ", did you mean `a`?" when one of the
/// expected names is within a third of its length in edit distance, else nothing.
fn did_you_mean(message: &str) -> String {
    let Some(rest) = message.strip_prefix("unknown field `").or_else(|| message.strip_prefix("unknown variant `"))
    else {
        return String::new();
    };
    let Some((given, expected)) = rest.split_once('`') else { return String::new() };
    let candidates = expected.split('`').skip(1).step_by(2);
    let best = candidates.map(|c| (strsim::damerau_levenshtein(given, c), c)).min();
    match best {
        Some((distance, name)) if distance <= (name.chars().count() / 3).max(1) => format!("; did you mean `{name}`?"),
        _ => String::new(),
    }
}

/// 1-based line and column of byte `offset` in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// A documented scenario template: every key with its default, unit and meaning (`frictrack init`).
pub const TEMPLATE: &str = include_str!("template.toml");
