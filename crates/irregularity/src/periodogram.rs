//! The periodogram of a sampled profile, the estimate of its one-sided PSD (docs/theory.md §11):
//! P(Ω) = |Δx Σ_i r_i e^{−iΩx_i}|² / (πL), L = nΔx, in m²/(rad/m). A harmonic A cos(Ωx + φ) of a whole number of
//! periods in L gives P = A²L/(4π) at its Ω: times the bin width 2π/L, its variance A²/2.

use crate::trig::sin_cos;

/// P(Ω) at each of `wavenumbers` (rad/m) of `samples` taken every `spacing` m from x = 0.
pub fn periodogram(samples: &[f64], spacing: f64, wavenumbers: &[f64]) -> Vec<f64> {
    let length = samples.len() as f64 * spacing;
    wavenumbers
        .iter()
        .map(|&omega| {
            let (re, im) = samples.iter().enumerate().fold((0.0, 0.0), |(re, im), (i, &r)| {
                let (s, c) = sin_cos(omega * i as f64 * spacing);
                (re + r * c, im - r * s)
            });
            spacing * spacing * (re * re + im * im) / (std::f64::consts::PI * length)
        })
        .collect()
}

/// Means of `values` over logarithmic bins of Ω, `per_decade` bins a decade: (geometric centre of the bin's Ω, mean)
/// for each non-empty bin, by rising Ω. A raw periodogram scatters by 100 % (two degrees of freedom per Ω); a bin of
/// m of them by 1/√m.
pub fn log_bins(wavenumbers: &[f64], values: &[f64], per_decade: usize) -> Vec<(f64, f64)> {
    let per_decade = per_decade.max(1) as f64;
    let mut bins: Vec<(i64, f64, f64, usize)> = Vec::new();
    for (&omega, &value) in wavenumbers.iter().zip(values) {
        let bin = (omega.log10() * per_decade).floor() as i64;
        match bins.last_mut() {
            Some(last) if last.0 == bin => {
                last.1 += omega.ln();
                last.2 += value;
                last.3 += 1;
            }
            _ => bins.push((bin, omega.ln(), value, 1)),
        }
    }
    bins.into_iter().map(|(_, log_sum, sum, n)| ((log_sum / n as f64).exp(), sum / n as f64)).collect()
}
