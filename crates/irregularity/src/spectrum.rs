//! One-sided power spectral densities of vertical track irregularity S(Ω) in m²/(rad/m), Ω = 2π/λ (docs/theory.md
//! §11), each with its closed-form antiderivative, so that the variance in a band, ∫S dΩ, is exact:
//!
//! - German (ORE B176): S = A_v Ω_c² / ((Ω² + Ω_r²)(Ω² + Ω_c²)), Ω_c = 0.8246, Ω_r = 0.0206 rad/m, A_v = 4.032e-7
//!   (low irregularity) or 1.080e-6 m·rad (high); usual band 0.5–80 m. With a = Ω_r, b = Ω_c:
//!   ∫S dΩ = A_v b²/(b² − a²)·(atan(Ω/a)/a − atan(Ω/b)/b).
//! - FRA class k = 1 … 6: S = 0.25·A_v Ω_c² / (Ω²(Ω² + Ω_c²)), Ω_c = 0.8245 rad/m, A_v = 1.2107, 1.0181, 0.6816,
//!   0.5376, 0.2095, 0.0339 cm²·rad/m (× 1e-4 for m²·rad/m); band 1.5–300 m. ∫S dΩ = 0.25·A_v(−1/Ω − atan(Ω/Ω_c)/Ω_c).
//!
//! Some codes' "class 5" carries other factors of 2π and 4: these are the formulas used, quoted with every result.

use crate::error::{Result, invalid};

/// FRA A_v of classes 1 … 6 (cm²·rad/m).
const FRA_AV: [f64; 6] = [1.2107, 1.0181, 0.6816, 0.5376, 0.2095, 0.0339];

/// A track-quality spectrum.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spectrum {
    /// German (ORE B176) spectrum, low irregularity (high-speed lines).
    GermanLow,
    /// German spectrum, high irregularity.
    GermanHigh,
    /// FRA class 1 (worst) … 6 (best).
    Fra(u8),
}

impl Spectrum {
    /// Every spectrum, by name.
    pub const NAMES: [&'static str; 8] =
        ["german-low", "german-high", "fra-1", "fra-2", "fra-3", "fra-4", "fra-5", "fra-6"];

    /// The spectrum called `name` (one of [`Spectrum::NAMES`]).
    pub fn from_name(name: &str) -> Result<Self> {
        match name {
            "german-low" => Ok(Spectrum::GermanLow),
            "german-high" => Ok(Spectrum::GermanHigh),
            _ => name
                .strip_prefix("fra-")
                .and_then(|k| k.parse::<u8>().ok())
                .filter(|k| (1..=6).contains(k))
                .map(Spectrum::Fra)
                .ok_or_else(|| invalid("spectrum", name, format!("must be one of {}", Self::NAMES.join(", ")))),
        }
    }

    /// Its name.
    pub fn name(self) -> String {
        match self {
            Spectrum::GermanLow => "german-low".into(),
            Spectrum::GermanHigh => "german-high".into(),
            Spectrum::Fra(k) => format!("fra-{k}"),
        }
    }

    /// The usual band of wavelengths (m): (shortest, longest).
    pub fn default_band(self) -> (f64, f64) {
        match self {
            Spectrum::GermanLow | Spectrum::GermanHigh => (0.5, 80.0),
            Spectrum::Fra(_) => (1.5, 300.0),
        }
    }

    /// S(Ω) (m²/(rad/m)) at Ω > 0 (rad/m).
    pub fn density(self, omega: f64) -> f64 {
        let w2 = omega * omega;
        match self {
            Spectrum::GermanLow | Spectrum::GermanHigh => {
                let (a_v, c, r) = self.german();
                a_v * c * c / ((w2 + r * r) * (w2 + c * c))
            }
            Spectrum::Fra(_) => {
                let (a_v, c) = self.fra();
                0.25 * a_v * c * c / (w2 * (w2 + c * c))
            }
        }
    }

    /// ∫_{Ω₁}^{Ω₂} S dΩ (m²), from the antiderivative.
    pub fn variance(self, from: f64, to: f64) -> f64 {
        self.antiderivative(to) - self.antiderivative(from)
    }

    fn antiderivative(self, omega: f64) -> f64 {
        match self {
            Spectrum::GermanLow | Spectrum::GermanHigh => {
                let (a_v, b, a) = self.german();
                a_v * b * b / (b * b - a * a) * ((omega / a).atan() / a - (omega / b).atan() / b)
            }
            Spectrum::Fra(_) => {
                let (a_v, c) = self.fra();
                0.25 * a_v * (-1.0 / omega - (omega / c).atan() / c)
            }
        }
    }

    /// (A_v m·rad, Ω_c, Ω_r) of the German spectra.
    fn german(self) -> (f64, f64, f64) {
        let a_v = if self == Spectrum::GermanLow { 4.032e-7 } else { 1.080e-6 };
        (a_v, 0.8246, 0.0206)
    }

    /// (A_v m²·rad/m, Ω_c) of an FRA class.
    fn fra(self) -> (f64, f64) {
        let Spectrum::Fra(k) = self else { unreachable!("FRA only") };
        (FRA_AV[usize::from(k) - 1] * 1e-4, 0.8245)
    }
}

#[cfg(test)]
mod tests {
    use super::Spectrum;

    /// The antiderivatives against a composite Simpson rule of S on a fine log grid (relative 1e-9: Simpson with
    /// 20 000 panels per decade of a smooth rational function).
    #[test]
    fn band_variance_matches_quadrature() {
        for name in Spectrum::NAMES {
            let s = Spectrum::from_name(name).unwrap();
            let (short, long) = s.default_band();
            let (a, b) = (std::f64::consts::TAU / long, std::f64::consts::TAU / short);
            // Simpson in u = ln Ω: ∫S dΩ = ∫S(e^u) e^u du.
            let n = 100_000;
            let (u0, u1) = (a.ln(), b.ln());
            let h = (u1 - u0) / n as f64;
            let f = |u: f64| s.density(u.exp()) * u.exp();
            let mut sum = f(u0) + f(u1);
            for i in 1..n {
                sum += f(u0 + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
            }
            let simpson = sum * h / 3.0;
            let exact = s.variance(a, b);
            assert!((exact / simpson - 1.0).abs() < 1e-9, "{name}: {exact} vs {simpson}");
            assert_eq!(Spectrum::from_name(&s.name()).unwrap(), s);
        }
        assert!(Spectrum::from_name("fra-7").is_err() && Spectrum::from_name("german").is_err());
    }

    /// Orders of magnitude the literature quotes: German low irregularity over 0.5–80 m has σ ≈ 1.5 mm… a few
    /// mm; FRA class 6 is smoother than class 1 by A_v's ratio.
    #[test]
    fn spectra_rank_as_expected() {
        let tau = std::f64::consts::TAU;
        let sigma = |s: Spectrum| {
            let (short, long) = s.default_band();
            s.variance(tau / long, tau / short).sqrt()
        };
        let low = sigma(Spectrum::GermanLow);
        assert!(low > 1e-3 && low < 1e-2, "German low σ = {low} m");
        assert!((sigma(Spectrum::GermanHigh) / low - (1.080e-6f64 / 4.032e-7).sqrt()).abs() < 1e-12);
        assert!((sigma(Spectrum::Fra(1)) / sigma(Spectrum::Fra(6)) - (1.2107f64 / 0.0339).sqrt()).abs() < 1e-12);
    }
}
