//! A layered visco-elastic ground: layers from the surface down over a half-space, each an isotropic material with
//! shear- and compression-wave speeds C_s, C_p (m/s), density ρ (kg/m³) and hysteretic damping ξ, whose complex
//! moduli are μ* = ρC_s²(1 + 2iξ sgn ω) and λ* + 2μ* = ρC_p²(1 + 2iξ sgn ω) (docs/theory.md §19).

use fem_beam::FemError;
use fem_beam::error::Result;
use num_complex::Complex64;

/// The most layers a profile may have: a site's profile has a few to a few tens; thousands are a mistake.
pub const MAX_LAYERS: usize = 200;

/// An isotropic visco-elastic material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoilMaterial {
    /// C_s (m/s), > 0.
    pub shear_wave_speed: f64,
    /// C_p (m/s), > C_s·√(4/3): the Poisson ratio ([`SoilMaterial::poisson_ratio`]) then lies in (−1, ½), reaching
    /// ½ only as C_p → ∞.
    pub compression_wave_speed: f64,
    /// ρ (kg/m³), > 0.
    pub density: f64,
    /// ξ ≥ 0, the hysteretic damping ratio.
    pub damping_ratio: f64,
}

/// One layer: a material and its thickness.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoilLayer {
    /// h (m), > 0.
    pub thickness: f64,
    /// Its material.
    pub material: SoilMaterial,
}

/// The half-space under the last layer.
pub type HalfSpace = SoilMaterial;

/// Layers from the surface down over a half-space.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundProfile {
    /// The layers, from the surface down (may be empty: a homogeneous half-space).
    pub layers: Vec<SoilLayer>,
    /// What lies below them.
    pub half_space: HalfSpace,
}

impl SoilMaterial {
    /// ν = (C_p² − 2C_s²)/(2(C_p² − C_s²)).
    pub fn poisson_ratio(&self) -> f64 {
        let (p2, s2) = (self.compression_wave_speed.powi(2), self.shear_wave_speed.powi(2));
        (p2 - 2.0 * s2) / (2.0 * (p2 - s2))
    }

    /// The complex shear modulus μ* = ρC_s²(1 + 2iξ sgn ω) (Pa) at circular frequency `omega` (rad/s).
    pub fn shear_modulus(&self, omega: f64) -> Complex64 {
        self.density * self.shear_wave_speed.powi(2) * self.damping(omega)
    }

    /// The complex P-wave modulus λ* + 2μ* = ρC_p²(1 + 2iξ sgn ω) (Pa) at circular frequency `omega` (rad/s).
    pub fn p_wave_modulus(&self, omega: f64) -> Complex64 {
        self.density * self.compression_wave_speed.powi(2) * self.damping(omega)
    }

    /// The complex wave speeds squared (C_s*², C_p*²) = (μ*/ρ, (λ* + 2μ*)/ρ) (m²/s²) at `omega` (rad/s).
    pub fn wave_speeds_squared(&self, omega: f64) -> (Complex64, Complex64) {
        (self.shear_modulus(omega) / self.density, self.p_wave_modulus(omega) / self.density)
    }

    /// 1 + 2iξ sgn ω: hysteretic damping, real at rest.
    fn damping(&self, omega: f64) -> Complex64 {
        let sign = if omega == 0.0 { 0.0 } else { omega.signum() };
        Complex64::new(1.0, 2.0 * self.damping_ratio * sign)
    }

    /// Each value in range, named under `path` (e.g. `ground.layers[2]`).
    pub fn validate(&self, path: &str) -> Result<()> {
        let bad = |key: &str, value: f64, allowed: &str| FemError::InvalidGround {
            path: format!("{path}.{key}"),
            value,
            allowed: allowed.to_string(),
        };
        let (cs, cp) = (self.shear_wave_speed, self.compression_wave_speed);
        if !(cs.is_finite() && cs > 0.0) {
            return Err(bad("shear_wave_speed", cs, "must be finite and > 0 (m/s)"));
        }
        // ν = (C_p² − 2C_s²)/(2(C_p² − C_s²)) is −1 at C_p² = (4/3)C_s² and tends to ½ as C_p → ∞.
        if !(cp.is_finite() && cp * cp > 4.0 / 3.0 * cs * cs) {
            return Err(bad(
                "compression_wave_speed",
                cp,
                &format!(
                    "must be finite and above C_s·√(4/3) = {:.1} m/s (a Poisson ratio above −1)",
                    cs * (4.0f64 / 3.0).sqrt()
                ),
            ));
        }
        if !(self.density.is_finite() && self.density > 0.0) {
            return Err(bad("density", self.density, "must be finite and > 0 (kg/m³)"));
        }
        if !(self.damping_ratio.is_finite() && (0.0..0.5).contains(&self.damping_ratio)) {
            return Err(bad("damping_ratio", self.damping_ratio, "must lie in [0, 0.5) (hysteretic ξ)"));
        }
        Ok(())
    }
}

impl GroundProfile {
    /// A homogeneous half-space of `material`.
    pub fn half_space(material: SoilMaterial) -> Self {
        Self { layers: Vec::new(), half_space: material }
    }

    /// Every material, from the surface down, the half-space's last.
    pub fn materials(&self) -> impl Iterator<Item = &SoilMaterial> {
        self.layers.iter().map(|layer| &layer.material).chain(std::iter::once(&self.half_space))
    }

    /// The material at the surface: the first layer's, or the half-space's if there is none.
    pub fn top(&self) -> &SoilMaterial {
        self.layers.first().map_or(&self.half_space, |layer| &layer.material)
    }

    /// Every material's C_s and C_p (m/s), top down: where k = ω/C the ground's response has a kink.
    pub fn wave_speeds(&self) -> Vec<f64> {
        self.materials().flat_map(|m| [m.shear_wave_speed, m.compression_wave_speed]).collect()
    }

    /// The least shear-wave speed C_s of any material (m/s).
    pub fn slowest_shear_wave_speed(&self) -> f64 {
        self.materials().map(|m| m.shear_wave_speed).fold(f64::INFINITY, f64::min)
    }

    /// The same profile without damping (ξ = 0 everywhere): the elastic ground whose dispersion curves are drawn.
    pub fn undamped(&self) -> Self {
        let mut elastic = self.clone();
        for layer in &mut elastic.layers {
            layer.material.damping_ratio = 0.0;
        }
        elastic.half_space.damping_ratio = 0.0;
        elastic
    }

    /// Every layer and the half-space in range, each named by its key (`ground.layers[i].…`,
    /// `ground.half_space.…`); at most [`MAX_LAYERS`] layers.
    pub fn validate(&self) -> Result<()> {
        if self.layers.len() > MAX_LAYERS {
            return Err(FemError::InvalidGround {
                path: "ground.layers".into(),
                value: self.layers.len() as f64,
                allowed: format!("at most {MAX_LAYERS} layers (a site's profile has a few to a few tens)"),
            });
        }
        for (i, layer) in self.layers.iter().enumerate() {
            let h = layer.thickness;
            if !(h.is_finite() && h > 0.0) {
                return Err(FemError::InvalidGround {
                    path: format!("ground.layers[{i}].thickness"),
                    value: h,
                    allowed: "must be finite and > 0 (m)".into(),
                });
            }
            layer.material.validate(&format!("ground.layers[{i}]"))?;
        }
        self.half_space.validate("ground.half_space")
    }
}
