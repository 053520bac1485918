//! Physical parameters: the rail as an Euler–Bernoulli beam and the soil as a viscoelastic Winkler foundation.
//!
//! Defaults are the reference case of docs/theory.md §2: a UIC60 rail (A = 7684 mm², I = 3055 cm⁴, ρ = 7800 kg/m³,
//! E = 210 GPa, hence EI = 6.4155 MN·m² and ρA = 59.935 kg/m) on a soil of k_f = 250 kN/m², undamped.

use crate::error::{FemError, Result, non_negative, positive};

/// Cross-section and material of the rail (an Euler–Bernoulli or Timoshenko beam). SI units. In files its keys are
/// those of `beam_keys` (with the `serde` feature).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "crate::beam_keys::BeamKeys", into = "crate::beam_keys::BeamKeys")
)]
pub struct Beam {
    /// Young's modulus E (Pa). Default 210 GPa; must be > 0.
    pub youngs_modulus: f64,
    /// Second moment of area I (m⁴). Default 3055 cm⁴ = 3.055e-5 m⁴ (UIC60); must be > 0.
    pub second_moment: f64,
    /// Cross-section area A (m²). Default 7684 mm² = 7.684e-3 m² (UIC60); must be > 0.
    pub area: f64,
    /// Density ρ (kg/m³). Default 7800 kg/m³; must be > 0.
    pub density: f64,
    /// The beam theory. Default Euler–Bernoulli.
    pub theory: BeamTheory,
    /// Loss factor η_r ≥ 0 of the rail's material, EI → EI(1 + iη_r) (and κGA): the frequency domain's (the
    /// receptance; steel 0.01–0.02); a run in time takes viscous damping. Default 0.
    pub loss_factor: f64,
}

/// How the beam deforms in bending (docs/theory.md §3, §15).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum BeamTheory {
    /// Plane sections stay normal to the axis: no shear deformation, no rotary inertia (default).
    #[default]
    EulerBernoulli,
    /// Shear deformation and rotary inertia ρI: the cross-section rotates by ψ ≠ w′, with the shear force
    /// κGA(w′ − ψ).
    Timoshenko {
        /// Shear modulus G (Pa), > 0 (steel: 81 GPa).
        shear_modulus: f64,
        /// Shear coefficient κ ∈ (0, 1] (UIC60 in vertical bending ≈ 0.4; a rectangle 5/6).
        shear_coefficient: f64,
    },
}

impl BeamTheory {
    /// The theory in words for a report: "Euler–Bernoulli", or "Timoshenko (G = 81 GPa, κ = 0.4)".
    pub fn describe(&self) -> String {
        match self {
            BeamTheory::EulerBernoulli => "Euler–Bernoulli".to_string(),
            BeamTheory::Timoshenko { shear_modulus, shear_coefficient } => {
                format!("Timoshenko (G = {} GPa, κ = {shear_coefficient})", shear_modulus / 1e9)
            }
        }
    }

    /// Whether a point force moving along the beam leaves it a bounded acceleration, so that the largest nodal
    /// acceleration of a run converges under refinement. Euler–Bernoulli: yes (the deflection is C² across the
    /// force). Timoshenko: no — the slope w′ has a kink F/(κGA − ρAv²) under the force, so a point's velocity jumps
    /// as the force passes and its acceleration there is a Dirac: the largest nodal acceleration grows as the step
    /// shrinks (docs/theory.md §10.4). A band-limited acceleration is defined on both.
    pub fn bounds_point_load_acceleration(&self) -> bool {
        matches!(self, BeamTheory::EulerBernoulli)
    }

    /// The theory in words where a report must name it: None for Euler–Bernoulli, the default.
    pub fn unless_default(&self) -> Option<String> {
        (*self != BeamTheory::EulerBernoulli).then(|| self.describe())
    }
}

impl Default for Beam {
    fn default() -> Self {
        Self {
            youngs_modulus: 210.0e9,
            second_moment: 3055.0e-8,
            area: 7684.0e-6,
            density: 7800.0,
            theory: BeamTheory::EulerBernoulli,
            loss_factor: 0.0,
        }
    }
}

impl Beam {
    /// Check every field; the error names the first bad one.
    pub fn validate(&self) -> Result<()> {
        positive("beam.youngs_modulus", self.youngs_modulus)?;
        positive("beam.second_moment", self.second_moment)?;
        positive("beam.area", self.area)?;
        positive("beam.density", self.density)?;
        non_negative("beam.loss_factor", self.loss_factor)?;
        if let BeamTheory::Timoshenko { shear_modulus, shear_coefficient } = self.theory {
            positive("beam.shear_modulus", shear_modulus)?;
            if !(shear_coefficient > 0.0 && shear_coefficient <= 1.0) {
                return Err(FemError::InvalidField {
                    field: "beam.shear_coefficient",
                    value: shear_coefficient,
                    allowed: "must lie in (0, 1] (UIC60 in vertical bending ≈ 0.4, a rectangle 5/6)",
                });
            }
        }
        Ok(())
    }

    /// The bar wave speed √(E/ρ) (m/s; 5.2 km/s in steel, 3.7 km/s in concrete): no beam theory holds for a load
    /// moving faster.
    pub fn bar_wave_speed(&self) -> f64 {
        (self.youngs_modulus / self.density).sqrt()
    }

    /// The speed (m/s) a load moving along this beam must stay below for its moving-frame equations to keep their
    /// type: the bar wave √(E/ρ) for Euler–Bernoulli, the (slower) shear wave √(κGA/ρA) for Timoshenko (≈ 2 km/s
    /// for a rail).
    pub fn wave_speed_limit(&self) -> f64 {
        self.shear_stiffness().map_or(self.bar_wave_speed(), |g| (g / self.mass_per_length()).sqrt())
    }

    /// Shear stiffness κGA (N) of a Timoshenko beam; None for Euler–Bernoulli (infinite).
    pub fn shear_stiffness(&self) -> Option<f64> {
        match self.theory {
            BeamTheory::EulerBernoulli => None,
            BeamTheory::Timoshenko { shear_modulus, shear_coefficient } => {
                Some(shear_coefficient * shear_modulus * self.area)
            }
        }
    }

    /// Rotary inertia per unit length ρI (kg·m): a Timoshenko beam's; 0 for Euler–Bernoulli, which neglects it.
    pub fn rotary_inertia(&self) -> f64 {
        match self.theory {
            BeamTheory::EulerBernoulli => 0.0,
            BeamTheory::Timoshenko { .. } => self.density * self.second_moment,
        }
    }

    /// Bending stiffness EI (N·m²).
    pub fn bending_stiffness(&self) -> f64 {
        self.youngs_modulus * self.second_moment
    }

    /// Mass per unit length ρA (kg/m).
    pub fn mass_per_length(&self) -> f64 {
        self.density * self.area
    }
}

/// How the soil resists deflection w (upward positive) per unit length (docs/theory.md §13): linearly, or in
/// compression only, or with a softer tension branch. The assembled K holds the linear part, k_t = α·k_c
/// ([`Foundation::tension_stiffness`]); the rest, (k_c − k_t)⟨−w⟩₊, is a compliant unilateral law at the sections
/// of the track's foundation layout.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum FoundationLaw {
    /// Force −k_f·w: pushes and pulls alike (default).
    #[default]
    Linear,
    /// Force k_c⟨−w⟩₊: pushes, never pulls (the rail lifts off the soil).
    Tensionless,
    /// Force −k_c·w in compression (w < 0), −α·k_c·w in tension.
    Bilinear {
        /// α = k_t/k_c ∈ [0, 1].
        tension_ratio: f64,
    },
}

impl FoundationLaw {
    /// α = k_t/k_c: 1 linear, 0 tensionless.
    pub fn tension_ratio(&self) -> f64 {
        match *self {
            FoundationLaw::Linear => 1.0,
            FoundationLaw::Tensionless => 0.0,
            FoundationLaw::Bilinear { tension_ratio } => tension_ratio,
        }
    }

    /// Its name in scenario files and reports: "linear", "tensionless" or "bilinear".
    pub fn name(&self) -> &'static str {
        match self {
            FoundationLaw::Linear => "linear",
            FoundationLaw::Tensionless => "tensionless",
            FoundationLaw::Bilinear { .. } => "bilinear",
        }
    }

    /// The law in words for a report: its name, with the tension ratio of a bilinear soil ("bilinear, k_t = 0.5 k_c").
    pub fn describe(&self) -> String {
        match self {
            FoundationLaw::Bilinear { tension_ratio } => format!("bilinear, k_t = {tension_ratio} k_c"),
            law => law.name().to_string(),
        }
    }

    /// Whether the law is linear (k_t = k_c), whatever its name.
    pub fn is_linear(&self) -> bool {
        self.tension_ratio() == 1.0
    }
}

/// A viscoelastic Winkler foundation: a distributed spring k_f and dashpot c_f per unit length of beam.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Foundation {
    /// Stiffness k_f (N/m², force per unit length per unit deflection), in compression k_c for a nonlinear law.
    /// Default 250 kN/m²; must be ≥ 0.
    pub stiffness: f64,
    /// Viscous damping c_f (N·s/m²). Default 0; must be ≥ 0. See [`Foundation::critical_damping`].
    pub damping: f64,
    /// The soil's law. Default linear.
    pub law: FoundationLaw,
    /// Loss factor η_f ≥ 0 of hysteretic damping, k_f → k_f(1 + iη_f): the frequency domain's (the receptance); a
    /// run in time takes the viscous c_f. Default 0.
    pub loss_factor: f64,
}

impl Default for Foundation {
    fn default() -> Self {
        Self::linear(250.0e3, 0.0)
    }
}

impl Foundation {
    /// A linear foundation of stiffness k_f (N/m²) and damping c_f (N·s/m²).
    pub fn linear(stiffness: f64, damping: f64) -> Self {
        Self { stiffness, damping, law: FoundationLaw::Linear, loss_factor: 0.0 }
    }

    /// Check every field; the error names the first bad one.
    pub fn validate(&self) -> Result<()> {
        non_negative("foundation.stiffness", self.stiffness)?;
        non_negative("foundation.damping", self.damping)?;
        non_negative("foundation.loss_factor", self.loss_factor)?;
        let ratio = self.law.tension_ratio();
        if !(0.0..=1.0).contains(&ratio) {
            return Err(FemError::InvalidField {
                field: "foundation.tension_ratio",
                value: ratio,
                allowed: "must lie in [0, 1]: the tension stiffness k_t = α·k_c cannot exceed the compression \
                          stiffness",
            });
        }
        Ok(())
    }

    /// k_t = α·k_c (N/m²): the stiffness in tension, the linear part the assembled K holds.
    pub fn tension_stiffness(&self) -> f64 {
        self.law.tension_ratio() * self.stiffness
    }

    /// k_c − k_t (N/m²): the stiffness of the unilateral part (k_c − k_t)⟨−w⟩₊ that acts beside the linear k_t
    /// (0 on a linear soil).
    pub fn unilateral_stiffness(&self) -> f64 {
        self.stiffness - self.tension_stiffness()
    }

    /// The soil's reaction on the rail per unit length at deflection w (m, upward positive), in N/m, upward positive:
    /// −k_t·w + (k_c − k_t)⟨−w⟩₊ — −k_f·w on a linear soil, k_c⟨−w⟩₊ on a tensionless one (docs/theory.md §13).
    pub fn reaction(&self, w: f64) -> f64 {
        -self.tension_stiffness() * w + self.unilateral_stiffness() * (-w).max(0.0)
    }

    /// The energy stored in the soil per unit length at deflection w (J/m), the potential of [`Foundation::reaction`]:
    /// ½k_t w² + ½(k_c − k_t) min(w, 0)².
    pub fn potential(&self, w: f64) -> f64 {
        0.5 * self.tension_stiffness() * w * w + 0.5 * self.unilateral_stiffness() * w.min(0.0).powi(2)
    }

    /// The rail's settlement under its own weight far from supports, ρA·g/k_f (m, downward); 0 without a soil.
    pub fn settlement(&self, beam: &Beam) -> f64 {
        match self.stiffness > 0.0 {
            true => beam.mass_per_length() * crate::GRAVITY / self.stiffness,
            false => 0.0,
        }
    }

    /// The soil's dynamic stiffness at circular frequency `omega` (rad/s): k_f(1 + iη_f) + iωc_f (N/m²).
    pub fn dynamic_stiffness(&self, omega: f64) -> num_complex::Complex64 {
        num_complex::Complex64::new(self.stiffness, self.stiffness * self.loss_factor + omega * self.damping)
    }

    /// Critical damping c_cr = 2√(k_f ρA) (N·s/m²); ≈ 7742 N·s/m² for the reference case.
    pub fn critical_damping(&self, beam: &Beam) -> f64 {
        2.0 * (self.stiffness * beam.mass_per_length()).sqrt()
    }

    /// Damping ratio ζ = c_f / c_cr (0 when c_cr = 0).
    pub fn damping_ratio(&self, beam: &Beam) -> f64 {
        let critical = self.critical_damping(beam);
        if critical > 0.0 { self.damping / critical } else { 0.0 }
    }

    /// The same foundation with c_f = ζ·c_cr. Errors if ζ is negative or not finite.
    pub fn with_damping_ratio(self, ratio: f64, beam: &Beam) -> Result<Self> {
        non_negative("foundation.damping_ratio", ratio)?;
        Ok(Self { damping: ratio * self.critical_damping(beam), ..self })
    }
}

/// Rayleigh damping C_R = α M + β K of the structure (docs/theory.md §10), beside the foundation's dashpots: the
/// damping of a bridge deck. The modal damping ratio at circular frequency ω is ζ(ω) = (α/ω + βω)/2.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Rayleigh {
    /// α (1/s), ≥ 0. Default 0.
    pub mass_coefficient: f64,
    /// β (s), ≥ 0. Default 0.
    pub stiffness_coefficient: f64,
}

impl Rayleigh {
    /// The coefficients giving damping ratio `ratio` at the two frequencies f₁ < f₂ (Hz):
    /// α = 2ζω₁ω₂/(ω₁ + ω₂), β = 2ζ/(ω₁ + ω₂) (between them the ratio is a little lower, outside higher).
    pub fn from_ratio(ratio: f64, f1: f64, f2: f64) -> Result<Self> {
        non_negative("damping.rayleigh.ratio", ratio)?;
        positive("damping.rayleigh.frequencies[0]", f1)?;
        positive("damping.rayleigh.frequencies[1]", f2)?;
        if f2 <= f1 {
            return Err(FemError::InvalidField {
                field: "damping.rayleigh.frequencies[1]",
                value: f2,
                allowed: "must exceed the first frequency (Hz)",
            });
        }
        let (w1, w2) = (2.0 * std::f64::consts::PI * f1, 2.0 * std::f64::consts::PI * f2);
        Ok(Self { mass_coefficient: 2.0 * ratio * w1 * w2 / (w1 + w2), stiffness_coefficient: 2.0 * ratio / (w1 + w2) })
    }

    /// ζ at circular frequency ω (rad/s).
    pub fn ratio_at(&self, omega: f64) -> f64 {
        0.5 * (self.mass_coefficient / omega + self.stiffness_coefficient * omega)
    }

    /// Whether both coefficients are zero.
    pub fn is_zero(&self) -> bool {
        self.mass_coefficient == 0.0 && self.stiffness_coefficient == 0.0
    }

    /// Check α and β: finite and ≥ 0.
    pub fn validate(&self) -> Result<()> {
        non_negative("damping.rayleigh.alpha", self.mass_coefficient)?;
        non_negative("damping.rayleigh.beta", self.stiffness_coefficient)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::{Foundation, FoundationLaw};

    /// The soil's reaction is −dP/dw of its potential on every law (central differences: the branches are quadratic,
    /// so the difference is exact to round-off away from w = 0), and each law's reaction is the one its name says.
    #[test]
    fn the_reaction_is_the_potentials_derivative_and_each_law_says_what_it_is() {
        let laws = [FoundationLaw::Linear, FoundationLaw::Tensionless, FoundationLaw::Bilinear { tension_ratio: 0.5 }];
        for law in laws {
            let soil = Foundation { stiffness: 2.5e5, law, ..Foundation::default() };
            for w in [-3e-3, -1e-4, 2e-4, 5e-3] {
                let d = 1e-7;
                let slope = (soil.potential(w + d) - soil.potential(w - d)) / (2.0 * d);
                assert!((soil.reaction(w) + slope).abs() <= 1e-9 * soil.stiffness * w.abs(), "{law:?} at {w}");
            }
            let (pressed, lifted) = (soil.reaction(-1e-3), soil.reaction(1e-3));
            assert_eq!(pressed, 2.5e5 * 1e-3, "{law:?}: k_c in compression");
            assert_eq!(lifted, -law.tension_ratio() * 2.5e5 * 1e-3, "{law:?}: α·k_c in tension");
            assert_eq!(soil.unilateral_stiffness(), (1.0 - law.tension_ratio()) * 2.5e5);
        }
    }
}
