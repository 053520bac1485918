//! How a run is integrated (docs/theory.md §5): the scheme, the step through the load advance, the end, the solver.

use nscd::integrator::Scheme;
use nscd::solver::SolverSettings;

/// How a run is integrated: the scheme (the θ-method or the generalized-α), the step (through the load advance), the
/// end, the friction solver.
#[derive(Debug, Clone, PartialEq)]
pub struct IntegrationSettings {
    /// θ ∈ [½, 1] of the θ-method. Default ½.
    pub theta: f64,
    /// ρ∞ ∈ [0, 1]: the generalized-α of this spectral radius instead of the θ-method (θ stays ½). Default None.
    /// What a Timoshenko rail needs: θ = ½ keeps its shear modes as a sawtooth (docs/theory.md §5.4).
    pub spectral_radius: Option<f64>,
    /// Load advance per step Δx (m) > 0, so h = Δx/v. Default 0.1 m; must not exceed one element.
    pub load_advance: f64,
    /// Longest time step h_max (s) > 0: h = min(Δx/v, h_max) (see [`crate::RunSettings::time_step`]). Default None (h =
    /// Δx/v). What a sweep over a wide speed range gives its slow speeds — a vehicle's contact mode or a deck's
    /// accelerations need a step in seconds, not a distance — without shortening the step at every speed.
    pub max_step: Option<f64>,
    /// End time (s); None stops when the load leaves the beam. Must not be before that.
    pub end_time: Option<f64>,
    /// Friction solver settings.
    pub solver: SolverSettings,
}

impl Default for IntegrationSettings {
    fn default() -> Self {
        Self {
            theta: 0.5,
            spectral_radius: None,
            load_advance: 0.1,
            max_step: None,
            end_time: None,
            solver: SolverSettings::default(),
        }
    }
}

impl IntegrationSettings {
    /// The engine's scheme: the generalized-α when a spectral radius is given, else the θ-method.
    pub fn scheme(&self) -> Scheme {
        match self.spectral_radius {
            Some(spectral_radius) => Scheme::GeneralizedAlpha { spectral_radius },
            None => Scheme::Theta(self.theta),
        }
    }
}
