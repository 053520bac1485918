//! A `[ground]` outside what a soil is: values the model computes with but no site has — each warned of with the
//! limit it crosses, before any spectrum is computed (the ground's other checks refuse what cannot be computed at
//! all). The limits are wide on purpose: they flag typing errors and units (ρ in g/cm³, C_s in km/s), not unusual
//! sites.
//!
//! - Density 1 000–3 500 kg/m³: peat and organic clay from ~1 050, dense rock to ~3 000 (Kramer, *Geotechnical
//!   Earthquake Engineering*, 1996, tables 6-1 and 6-2).
//! - Shear wave speed 10–4 000 m/s: the softest peats ~15–40 m/s, hard rock ~3 500 m/s.
//! - Layer thickness 0.05–1 000 m: thinner than a ballast stone, or deeper than any site's profile.
//! - An embankment of no mass: the two-beam track's embankment carries 5–20 t/m; of none, it is a spring.

use crate::Scenario;
use crate::number::number;
use crate::warning::Warning;

/// ρ (kg/m³) of a soil or rock lies in this range.
pub const DENSITY: (f64, f64) = (1_000.0, 3_500.0);
/// C_s (m/s) of a soil or rock lies in this range.
pub const SHEAR_WAVE_SPEED: (f64, f64) = (10.0, 4_000.0);
/// A layer's thickness (m) lies in this range.
pub const THICKNESS: (f64, f64) = (0.05, 1_000.0);

impl Scenario {
    /// Warnings for a `[ground]` (and the two-beam track's `[embankment]` on it) outside what a site is; none
    /// without a ground.
    pub fn ground_warnings(&self) -> Vec<Warning> {
        let Some(ground) = &self.ground else { return Vec::new() };
        let mut out = Vec::new();
        let materials = ground
            .layers
            .iter()
            .enumerate()
            .map(|(i, layer)| (format!("ground.layers[{i}]"), layer))
            .chain(ground.half_space.iter().map(|h| ("ground.half_space".to_string(), h)));
        for (path, soil) in materials {
            let checks = [
                ("density", soil.density, DENSITY, "kg/m³", "of a soil or rock"),
                ("shear_wave_speed", soil.shear_wave_speed, SHEAR_WAVE_SPEED, "m/s", "of a soil or rock"),
                ("thickness", soil.thickness, THICKNESS, "m", "of a site's layer"),
            ];
            for (key, value, (low, high), unit, what) in checks {
                let Some(value) = value.filter(|v| v.is_finite() && !(low..=high).contains(v)) else { continue };
                out.push(Warning {
                    field: format!("{path}.{key}"),
                    value: format!("{} {unit}", number(value)),
                    message: format!(
                        "lies outside {} – {} {unit}, the range {what}: check its unit; the numbers are the \
                         model's, not a site's",
                        number(low),
                        number(high)
                    ),
                });
            }
        }
        if let Some(embankment) = self.embankment.as_ref().filter(|e| e.mass_per_length == 0.0) {
            out.push(Warning {
                field: "embankment.mass_per_length".into(),
                value: number(embankment.mass_per_length),
                message: "an embankment of no mass only spreads the load (a real one carries 5–20 t/m, which moves \
                          with the track and lowers its critical speed)"
                    .into(),
            });
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use crate::Scenario;

    /// The soft-ground example gives no warning; ρ in g/cm³, C_s in km/s and a layer of a nanometre each give one,
    /// naming the key.
    #[test]
    fn a_ground_outside_what_a_site_is_is_warned_of() {
        let site = include_str!("../../../examples/soft-ground.toml");
        let warned = |text: &str| -> Vec<String> {
            let scenario = Scenario::from_toml(text, "site.toml").unwrap();
            scenario.ground_warnings().iter().map(ToString::to_string).collect()
        };
        assert!(warned(site).is_empty(), "{:?}", warned(site));
        let grams = warned(&site.replace("density = 1500.0", "density = 1.5"));
        assert!(grams.len() == 1 && grams[0].starts_with("ground.layers[0].density = 1.5 kg/m³"), "{grams:?}");
        let km = warned(&site.replace("shear_wave_speed = 110.0", "shear_wave_speed = 0.11"));
        assert!(km.len() == 1 && km[0].starts_with("ground.half_space.shear_wave_speed = 0.11 m/s"), "{km:?}");
        let thin = warned(&site.replace("thickness = 4.0", "thickness = 1e-9"));
        assert!(thin.len() == 1 && thin[0].starts_with("ground.layers[1].thickness = 1e-9 m"), "{thin:?}");
    }
}
