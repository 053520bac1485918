//! The scenario schema: one struct per TOML section, every key optional with the reference case as default
//! (docs/theory.md §2), unknown keys refused.

pub use super::deck::DeckTrack;
pub use super::load_section::{AxleShare, LoadSection};
use crate::error::{Result, invalid};
use fem_beam::Foundation;
use nscd::SolverKind;
use serde::{Deserialize, Serialize};
use track::RunSettings;

/// `[foundation]`: Winkler stiffness and viscous damping (as a value or as a ratio of c_cr, not both), and the
/// soil's law (docs/theory.md §13).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct FoundationSection {
    /// k_f (N/m²), in compression for a nonlinear law.
    pub stiffness: f64,
    /// c_f (N·s/m²).
    pub damping: Option<f64>,
    /// ζ = c_f/c_cr.
    pub damping_ratio: Option<f64>,
    /// Linear (default), tensionless or bilinear.
    #[serde(skip_serializing_if = "FoundationLawKind::is_linear")]
    pub law: FoundationLawKind,
    /// α = k_t/k_c ∈ [0, 1] of a bilinear soil.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tension_ratio: Option<f64>,
    /// Whether the rail's weight ρA·g rests on a nonlinear soil (default true).
    #[serde(skip_serializing_if = "is_true")]
    pub self_weight: bool,
    /// Gauss sub-intervals per element of a nonlinear soil's sections (default 1: four sections per element).
    #[serde(skip_serializing_if = "is_one")]
    pub subdivisions: usize,
    /// Damping graded up towards both ends.
    pub absorbing_zones: Option<AbsorbingZonesSection>,
    /// Loss factor η_f of hysteretic damping, for the receptance (default 0; a run takes the viscous damping).
    #[serde(skip_serializing_if = "is_zero")]
    pub loss_factor: f64,
}

fn is_zero(value: &f64) -> bool {
    *value == 0.0
}

fn is_true(value: &bool) -> bool {
    *value
}

fn is_one(value: &usize) -> bool {
    *value == 1
}

impl FoundationSection {
    /// A tensionless or bilinear soil of zero stiffness: no soil at all, so its law has nothing to act on (the run
    /// places no soil sections, and says so).
    pub fn is_nonlinear_without_soil(&self) -> bool {
        self.law != FoundationLawKind::Linear && self.stiffness == 0.0
    }
}

impl Default for FoundationSection {
    fn default() -> Self {
        Self {
            stiffness: Foundation::default().stiffness,
            damping: None,
            damping_ratio: None,
            law: FoundationLawKind::Linear,
            tension_ratio: None,
            self_weight: true,
            subdivisions: 1,
            absorbing_zones: None,
            loss_factor: 0.0,
        }
    }
}

/// The soil's law as the file names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FoundationLawKind {
    /// Pushes and pulls alike.
    #[default]
    Linear,
    /// Pushes, never pulls: the rail lifts off.
    Tensionless,
    /// k_c in compression, α·k_c in tension (`tension_ratio`).
    Bilinear,
}

impl FoundationLawKind {
    fn is_linear(&self) -> bool {
        *self == FoundationLawKind::Linear
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

/// `[damping]`: damping of the structure (a bridge deck) beside the foundation's dashpots.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct DampingSection {
    /// `rayleigh = { ratio = 0.01, frequencies = [f1, f2] }` or `rayleigh = { alpha = …, beta = … }`.
    pub rayleigh: Option<RayleighSection>,
}

impl DampingSection {
    /// Whether nothing is set (the section is then left out of written scenarios).
    pub fn is_empty(&self) -> bool {
        self.rayleigh.is_none()
    }
}

/// Rayleigh damping C = αM + βK: by a ratio at two frequencies, or by α and β.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct RayleighSection {
    /// Modal damping ratio ζ at both frequencies.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ratio: Option<f64>,
    /// The two frequencies f₁ < f₂ (Hz) where the ratio holds.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub frequencies: Option<[f64; 2]>,
    /// α (1/s).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alpha: Option<f64>,
    /// β (s).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub beta: Option<f64>,
}

impl RayleighSection {
    /// The Rayleigh coefficients, from exactly one of the two forms.
    pub fn rayleigh(&self) -> crate::error::Result<fem_beam::Rayleigh> {
        match (self.ratio, self.frequencies, self.alpha, self.beta) {
            (Some(ratio), Some([f1, f2]), None, None) => Ok(fem_beam::Rayleigh::from_ratio(ratio, f1, f2)?),
            (None, None, Some(alpha), Some(beta)) => {
                let r = fem_beam::Rayleigh { mass_coefficient: alpha, stiffness_coefficient: beta };
                r.validate()?;
                Ok(r)
            }
            _ => Err(crate::error::invalid(
                "damping.rayleigh",
                format!("{self:?}"),
                "give either ratio and frequencies = [f1, f2] (Hz), or alpha (1/s) and beta (s)",
            )),
        }
    }
}

/// `[[load.axles]]`: one axle.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AxleSection {
    /// Offset behind the first axle (m), ≥ 0.
    pub offset: f64,
    /// Static force (N, downward), ≥ 0.
    pub force: f64,
}

/// `[[load.patches]]`: one uniform load patch.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PatchSection {
    /// Offset of its front behind the first axle (m), ≥ 0.
    pub offset: f64,
    /// Length (m), > 0.
    pub length: f64,
    /// Load per length (N/m, downward), ≥ 0.
    pub intensity: f64,
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

impl FrictionSection {
    /// The friction in words — "31 devices × 50 kN", "f_u = 2 kN/m", both joined by " + " — or None without any.
    pub fn describe(&self) -> Option<String> {
        let mut parts = Vec::new();
        if let Some(d) = &self.devices {
            parts.push(devices_text(d.requested(), d.force.unwrap_or(f64::NAN)));
        }
        if let Some(d) = &self.distributed {
            parts.push(format!("f_u = {} kN/m", d.force_per_length / 1e3));
        }
        (!parts.is_empty()).then(|| parts.join(" + "))
    }
}

/// "1 device × 50 kN", "31 devices × 50 kN": `count` devices of `force` (N).
pub fn devices_text(count: usize, force: f64) -> String {
    format!("{count} device{} × {} kN", if count == 1 { "" } else { "s" }, force / 1e3)
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

impl DevicesSection {
    /// How many devices are asked for: `count`, else the positions given (0 with neither).
    pub fn requested(&self) -> usize {
        self.count.or(self.positions.as_ref().map(Vec::len)).unwrap_or(0)
    }
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

/// `[integration]`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct IntegrationSection {
    /// θ ∈ [0.5, 1] of the θ-method; None: the default scheme ([`IntegrationSection::scheme`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub theta: Option<f64>,
    /// ρ∞ ∈ [0, 1]: the generalized-α instead of the θ-method.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spectral_radius: Option<f64>,
    /// Load advance per step Δx (m); h = Δx/v.
    pub load_advance: f64,
    /// Longest time step (s): h = min(Δx/v, max_step).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_step: Option<f64>,
    /// Friction solver.
    pub solver: SolverKind,
    /// Relative tolerance of the friction law.
    pub tolerance: f64,
    /// Iteration cap per step.
    pub max_iterations: usize,
    /// Interior point re-solves a moving window.
    pub moving_window: bool,
    /// Start from the analytic steady state with the load here (m) instead of at rest.
    pub steady_start: Option<f64>,
    /// Start at rest in the static equilibrium of the loads (and vehicles) standing with the first one here (m).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub static_start: Option<f64>,
    /// Run until this time (s) instead of stopping when the load leaves.
    pub end_time: Option<f64>,
    /// A single run's accuracy: refine until every outcome's estimated error is within this relative tolerance
    /// ([`crate::accuracy_key`]; a run's `--accuracy` in the scenario).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub accuracy: Option<f64>,
}

impl Default for IntegrationSection {
    fn default() -> Self {
        let s = RunSettings::default();
        Self {
            theta: None,
            spectral_radius: None,
            load_advance: s.integration.load_advance,
            max_step: None,
            solver: SolverKind::Auto,
            tolerance: s.integration.solver.tolerance,
            max_iterations: s.integration.solver.max_iterations,
            moving_window: s.integration.solver.moving_window,
            steady_start: None,
            static_start: None,
            end_time: None,
            accuracy: None,
        }
    }
}

/// The spectral radius ρ∞ of the generalized-α that integrates a Timoshenko rail when the scenario names neither θ nor
/// ρ∞: ½ damps the rail's unresolved shear modes (the sawtooth θ = ½ keeps) and stays second order — on UIC60 over
/// sleepers the largest pad force stays within 0.2 % from 4 to 64 elements a bay where θ = ½ drifts +1.7 %
/// (docs/theory.md §5.4); ρ∞ = 0.8 sat between the two.
pub const TIMOSHENKO_SPECTRAL_RADIUS: f64 = 0.5;

impl IntegrationSection {
    /// The scheme `(θ, ρ∞)` this section chooses for a rail of shear flexibility `timoshenko` carrying (or not) a
    /// `rigid_contact` wheel: what the scenario names wins (ρ∞ with θ left at ½, or θ alone); without either, a
    /// Timoshenko rail takes the generalized-α of [`TIMOSHENKO_SPECTRAL_RADIUS`] — except under a rigid wheel–rail
    /// contact, whose impact law needs the θ-method — and everything else the run's default θ (½, the trapezoidal
    /// rule: [`track::simulation::IntegrationSettings`]).
    pub fn scheme(&self, timoshenko: bool, rigid_contact: bool) -> (f64, Option<f64>) {
        let default_theta = RunSettings::default().integration.theta;
        match (self.theta, self.spectral_radius) {
            (theta, Some(rho)) => (theta.unwrap_or(default_theta), Some(rho)),
            (Some(theta), None) => (theta, None),
            (None, None) if timoshenko && !rigid_contact => (default_theta, Some(TIMOSHENKO_SPECTRAL_RADIUS)),
            (None, None) => (default_theta, None),
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
        if (to - from) / step > crate::speeds::MAX_SPEEDS as f64 {
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
    /// Positions [a, b] (m) of the nodes over which the extremes (deflections and acceleration) are taken; default
    /// every node. On a finite track, [L/3, 2L/3] leaves out the transients at the ends, where the loads enter and
    /// leave over the supports.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub extremes_nodes: Option<[f64; 2]>,
    /// Times (s) of whole-beam snapshots (`run --out`).
    pub snapshot_times: Vec<f64>,
    /// Load positions (m) of whole-beam snapshots (`run --out`); with neither list, L/4, L/2 and 3L/4.
    pub snapshot_load_positions: Vec<f64>,
    /// The track on a bridge deck, which sets the EN 1990 deck-acceleration limit the train study checks a span
    /// against: ballasted (3.5 m/s², the default) or direct fastening (5 m/s²).
    #[serde(skip_serializing_if = "DeckTrack::is_default")]
    pub deck_track: DeckTrack,
    /// f_max (Hz) of the band-limited acceleration a run reports beside the nodal one: the accelerations' part in
    /// the beam's modes at or below it (docs/theory.md §10.4). Default: on a span (pinned ends, no foundation, no
    /// sleepers) EN 1990 A2's max(30 Hz, 1.5 f₁, f₃); elsewhere none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub acceleration_band: Option<f64>,
    /// The band (Hz) of the acceleration a run reports filtered in time, on a model of any size: the velocity's
    /// difference over 0.443/band s, the filter's −3 dB point at the band (docs/theory.md §10.4). Default: on a
    /// Timoshenko rail (whose nodal acceleration is undefined under a point force) 1000 Hz; elsewhere none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub acceleration_filter: Option<f64>,
}

impl OutputSection {
    /// The snapshot requests for a run whose first axle travels from `start` to `end` (m; from the run's start
    /// position — 0 from rest — to the beam's length plus the train's): the times and load positions given, or the
    /// first axle at ¼, ½ and ¾ of its travel (L/4, L/2, 3L/4 for a single load from rest).
    pub fn snapshots(&self, (start, end): (f64, f64)) -> Vec<track::SnapshotAt> {
        use track::SnapshotAt;
        let mut requests: Vec<SnapshotAt> = self.snapshot_times.iter().map(|&t| SnapshotAt::Time(t)).collect();
        requests.extend(self.snapshot_load_positions.iter().map(|&x| SnapshotAt::LoadPosition(x)));
        if requests.is_empty() {
            requests = [0.25, 0.5, 0.75].iter().map(|f| SnapshotAt::LoadPosition(start + f * (end - start))).collect();
        }
        requests
    }

    /// The window of load positions (m) for a beam of length `length` (m): the one given, or the middle third.
    pub fn extremes_window(&self, length: f64) -> (f64, f64) {
        self.extremes_window.map_or((length / 3.0, 2.0 * length / 3.0), |[a, b]| (a, b))
    }
}

/// `[co_moving]`: the load crosses `track_length` m of endless track through a window of `window` m that travels
/// with it (docs/theory.md §15), the load at `load_at` m from the window's rear end, absorbing zones of `zones` m at
/// both ends; the mesh's element length and the scenario's soil and friction.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CoMovingSection {
    /// Window length (m). Default: 120 m, or longer where the wave at the run's speed needs it (four times its 1 %
    /// decay length on the longer side, rounded up to 10 m, so that it fades between the load in the middle and the
    /// zones of a quarter of the window).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub window: Option<f64>,
    /// Track travelled (m). Default 1000.
    pub track_length: f64,
    /// The load's place in the window (m from its rear end); default the middle.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_at: Option<f64>,
    /// Absorbing zone at each end (m, damping graded up to c_cr); default a quarter of the window.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub zones: Option<f64>,
}

impl Default for CoMovingSection {
    fn default() -> Self {
        Self { window: None, track_length: 1000.0, load_at: None, zones: None }
    }
}
