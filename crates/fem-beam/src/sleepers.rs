//! The track as it is built (docs/theory.md §18): the rail on discrete supports — a rail pad (spring k_p, dashpot
//! c_p, loss factor η_p) on a sleeper of mass m_s (per rail seat) on the ballast (k_b, c_b, η_b) — every `spacing` m
//! from `first`. Each sleeper is a DOF z (m, upward) under a mesh node: the pad acts on w_node − z, the ballast on z.
//! The continuous Winkler foundation is its long-wave limit, k_f ≈ (k_p k_b/(k_p + k_b))/a; the two may be used
//! together (a slab under a continuous pad, or a soil left under sleepers).

use crate::error::{FemError, Result, non_negative, positive};
use crate::mesh::Mesh;
use crate::properties::Beam;
use crate::sleeper_exceptions::{BallastContact, SleeperException};

/// A spring–dashpot layer: stiffness (N/m), viscous damping (N·s/m), loss factor (hysteretic, frequency domain).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Layer {
    /// k (N/m), > 0.
    pub stiffness: f64,
    /// c (N·s/m), ≥ 0.
    pub damping: f64,
    /// η ≥ 0: k → k(1 + iη) in the frequency domain.
    pub loss_factor: f64,
}

/// The lumped resonances of a bay (Hz), [`Sleepers::bay_resonances`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BayResonances {
    /// The whole track bouncing on the ballast.
    pub track: f64,
    /// The rail on its pads, the sleeper against it.
    pub rail_on_pads: f64,
}

/// Sleepers under the rail, per rail seat. Defaults: typical values of a ballasted track (Knothe & Grassie 1993):
/// a = 0.6 m, m_s = 150 kg, pads k_p = 200 MN/m, c_p = 30 kN·s/m, ballast k_b = 100 MN/m, c_b = 50 kN·s/m, no
/// exceptions.
#[derive(Debug, Clone, PartialEq)]
pub struct Sleepers {
    /// a (m), > 0.
    pub spacing: f64,
    /// Where the first sleeper sits (m), ≥ 0; default half a spacing.
    pub first: f64,
    /// m_s (kg per rail seat), > 0.
    pub mass: f64,
    /// The rail pad between rail and sleeper.
    pub pad: Layer,
    /// The ballast under the sleeper.
    pub ballast: Layer,
    /// Sleepers that differ from the rest, later entries over earlier ones ([`Sleepers::support`]).
    pub exceptions: Vec<SleeperException>,
}

impl Default for Sleepers {
    fn default() -> Self {
        Self {
            spacing: 0.6,
            first: 0.3,
            mass: 150.0,
            pad: Layer { stiffness: 200e6, damping: 30e3, loss_factor: 0.0 },
            ballast: Layer { stiffness: 100e6, damping: 50e3, loss_factor: 0.0 },
            exceptions: Vec::new(),
        }
    }
}

impl Sleepers {
    /// Check every value; the error names the key.
    pub fn validate(&self) -> Result<()> {
        positive("sleepers.spacing", self.spacing)?;
        non_negative("sleepers.first", self.first)?;
        positive("sleepers.mass", self.mass)?;
        let layers = [
            (&self.pad, ["sleepers.pad.stiffness", "sleepers.pad.damping", "sleepers.pad.loss_factor"]),
            (&self.ballast, ["sleepers.ballast.stiffness", "sleepers.ballast.damping", "sleepers.ballast.loss_factor"]),
        ];
        for (layer, [stiffness, damping, loss]) in layers {
            positive(stiffness, layer.stiffness)?;
            non_negative(damping, layer.damping)?;
            non_negative(loss, layer.loss_factor)?;
        }
        Ok(())
    }

    /// The equivalent continuous support (N/m²): the pad and ballast in series, spread over a spacing.
    pub fn equivalent_stiffness(&self) -> f64 {
        let (kp, kb) = (self.pad.stiffness, self.ballast.stiffness);
        kp * kb / (kp + kb) / self.spacing
    }

    /// The sleepers' mass spread over their spacing, m_s/a (kg/m).
    pub fn mass_per_length(&self) -> f64 {
        self.mass / self.spacing
    }

    /// The equivalent continuous track of `beam` on these sleepers and a soil `k_f` (N/m²): the beam carrying the
    /// sleepers' mass spread as the long wave moves it, on k_f + [`Self::equivalent_stiffness`]. Well below the
    /// bay's resonances ([`Self::bay_resonances`]) a sleeper follows its rail node quasi-statically,
    /// z = w·k_p/(k_p + k_b), so its kinetic energy is that of a mass m_s (k_p/(k_p + k_b))² moving with the rail:
    /// ρ → ρ + m_s (k_p/(k_p + k_b))²/(aA) — 0.44 m_s for the typical pads and ballast.
    pub fn equivalent_track(&self, beam: &Beam, k_f: f64) -> (Beam, f64) {
        let ratio = self.pad.stiffness / (self.pad.stiffness + self.ballast.stiffness);
        let density = beam.density + self.mass_per_length() * ratio * ratio / beam.area;
        (Beam { density, ..*beam }, k_f + self.equivalent_stiffness())
    }

    /// The two resonances of one bay lumped (Hz): the rail's mass over a spacing ρA·a on the pad, on the sleeper on
    /// the ballast — the lower the whole track bouncing on the ballast, the upper the rail on its pads (the sleeper
    /// moving against it). Estimates that name the peaks of a receptance; the rail's bending shifts them.
    pub fn bay_resonances(&self, rail_mass_per_length: f64) -> BayResonances {
        let (m1, m2) = (rail_mass_per_length * self.spacing, self.mass);
        let (k1, k2) = (self.pad.stiffness, self.ballast.stiffness);
        // m1 m2 ω⁴ − (m1 (k1 + k2) + m2 k1) ω² + k1 k2 = 0.
        let (a, b, c) = (m1 * m2, m1 * (k1 + k2) + m2 * k1, k1 * k2);
        let root = (b * b - 4.0 * a * c).max(0.0).sqrt();
        let hz = |omega2: f64| omega2.sqrt() / std::f64::consts::TAU;
        BayResonances { track: hz(2.0 * c / (b + root)), rail_on_pads: hz((b + root) / (2.0 * a)) }
    }

    /// The mesh node under each sleeper, first to last: every sleeper on the beam must sit on a node (within 1e-9 of
    /// an element), else the error names the keys that place them.
    pub fn nodes(&self, mesh: &Mesh) -> Result<Vec<usize>> {
        self.validate()?;
        let l = mesh.element_length();
        if self.first > mesh.length {
            return Err(FemError::InvalidField {
                field: "sleepers.first",
                value: self.first,
                allowed: "must lie on the beam (≤ its length)",
            });
        }
        let count = ((mesh.length - self.first) / self.spacing * (1.0 + 1e-12)).floor() as usize + 1;
        if count > Mesh::MAX_ELEMENTS {
            return Err(FemError::InvalidCount {
                field: "sleepers.spacing",
                value: count,
                allowed: "must leave at most one sleeper per node of the largest mesh (1 000 000)",
            });
        }
        for (index, exception) in self.exceptions.iter().enumerate() {
            exception.validate(index, count)?;
        }
        (0..count)
            .map(|i| {
                let x = self.first + i as f64 * self.spacing;
                let node = (x / l).round();
                if (x / l - node).abs() > 1e-9 * (1.0 + node) {
                    let field = if i == 0 { "sleepers.first" } else { "sleepers.spacing" };
                    let value = if i == 0 { self.first } else { self.spacing };
                    return Err(FemError::InvalidField {
                        field,
                        value,
                        allowed: "must put every sleeper on a mesh node: first and spacing multiples of the element \
                                  length (mesh.length / mesh.elements)",
                    });
                }
                Ok(node as usize)
            })
            .collect()
    }
}

impl Sleepers {
    /// What the sleepers under `nodes` add to a matrix over the free DOFs of `dofs` (a map with their DOFs,
    /// [`crate::supports::DofMap::with_sleepers`]), as entries (i, j ≤ i) of its lower triangle: on z the sleeper's `mass` term and both
    /// layers, on (w, z) the pad as [[1, −1], [−1, 1]] (on z alone where a support holds w). `layers` gives what a
    /// sleeper's pad and ballast contribute, from its [`SleeperSupport`] — their k for K (the ballast's where bonded),
    /// c for C, k(1 + iη) + iωc for a dynamic stiffness — and `mass` what m_s does (m_s for M, −ω²m_s for a dynamic
    /// stiffness, 0 for K and C).
    pub fn entries<T>(
        &self,
        dofs: &crate::supports::DofMap,
        nodes: &[usize],
        layers: impl Fn(&SleeperSupport) -> (T, T),
        mass: impl Fn(f64) -> T,
    ) -> Vec<(usize, usize, T)>
    where
        T: Copy + std::ops::Add<Output = T> + std::ops::Neg<Output = T>,
    {
        let mut out = Vec::with_capacity(3 * nodes.len());
        for (s, &node) in nodes.iter().enumerate() {
            let (pad, ballast) = layers(&self.support(s));
            let z = dofs.sleeper(s);
            out.push((z, z, mass(self.mass) + pad + ballast));
            if let Some(w) = dofs.free_index(2 * node) {
                out.push((w, w, pad));
                out.push((z.max(w), z.min(w), -pad));
            }
        }
        out
    }
}

/// What holds one sleeper, the exceptions applied: its pad and ballast layers (stiffnesses scaled), how the ballast
/// holds it, its friction force (N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SleeperSupport {
    /// The pad (stiffness scaled).
    pub pad: Layer,
    /// The ballast (stiffness scaled).
    pub ballast: Layer,
    /// Bonded or unilateral.
    pub contact: BallastContact,
    /// F (N), 0 for none.
    pub friction: f64,
}

impl SleeperSupport {
    /// The ballast's stiffness K holds (N/m): all of it where bonded, none where a unilateral law carries it.
    pub fn bonded_stiffness(&self) -> f64 {
        match self.contact {
            BallastContact::Bonded => self.ballast.stiffness,
            BallastContact::Unilateral { .. } => 0.0,
        }
    }

    /// Whether this sleeper is linear (bonded, no friction).
    pub fn is_linear(&self) -> bool {
        self.contact == BallastContact::Bonded && self.friction == 0.0
    }
}

impl Sleepers {
    /// What holds sleeper `s`: the typical layers, changed by the last exception that names it.
    pub fn support(&self, s: usize) -> SleeperSupport {
        let typical =
            SleeperSupport { pad: self.pad, ballast: self.ballast, contact: BallastContact::Bonded, friction: 0.0 };
        match self.exceptions.iter().rev().find(|e| e.covers(s)) {
            None => typical,
            Some(e) => SleeperSupport {
                pad: Layer { stiffness: self.pad.stiffness * e.pad_scale, ..self.pad },
                ballast: Layer { stiffness: self.ballast.stiffness * e.ballast_scale, ..self.ballast },
                contact: e.contact,
                friction: e.friction,
            },
        }
    }

    /// Whether an exception names sleeper `s` (it differs from the rest).
    pub fn differs(&self, s: usize) -> bool {
        self.exceptions.iter().any(|e| e.covers(s))
    }

    /// Whether every sleeper is linear (no unilateral ballast, no friction): what the receptance needs.
    pub fn is_linear(&self) -> bool {
        self.exceptions.iter().all(|e| e.contact == BallastContact::Bonded && e.friction == 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sleepers_sit_on_nodes_or_are_refused_by_key() {
        let mesh = Mesh::new(6.0, 40).unwrap(); // l = 0.15 m: a = 0.6 m is four elements
        let nodes = Sleepers::default().nodes(&mesh).unwrap();
        assert_eq!(nodes, vec![2, 6, 10, 14, 18, 22, 26, 30, 34, 38]);
        let off = Sleepers { first: 0.25, ..Sleepers::default() }.nodes(&mesh).unwrap_err().to_string();
        assert!(off.contains("sleepers.first = 0.25") && off.contains("element length"), "{off}");
        let spacing = Sleepers { first: 0.0, spacing: 0.5, ..Sleepers::default() }.nodes(&mesh).unwrap_err();
        assert!(spacing.to_string().contains("sleepers.spacing = 0.5"), "{spacing}");
        let soft = Sleepers { pad: Layer { stiffness: -1.0, ..Sleepers::default().pad }, ..Sleepers::default() };
        assert!(soft.validate().unwrap_err().to_string().contains("sleepers.pad.stiffness = -1"));
        assert!((Sleepers::default().equivalent_stiffness() - 200e6 * 100e6 / 300e6 / 0.6).abs() < 1e-3);
    }

    #[test]
    fn a_bay_lumped_has_the_two_mass_resonances_and_the_span_its_pinned_pinned_one() {
        // Two masses on two springs: the product of ω² is k1k2/(m1m2), their sum (k1 + k2)/m2 + k1/m1.
        let s = Sleepers::default();
        let r = s.bay_resonances(60.0);
        let (w1, w2) = ((r.track * std::f64::consts::TAU).powi(2), (r.rail_on_pads * std::f64::consts::TAU).powi(2));
        let (m1, m2, k1, k2) = (36.0, 150.0, 200e6, 100e6);
        assert!((w1 * w2 / (k1 * k2 / (m1 * m2)) - 1.0).abs() < 1e-12);
        assert!(((w1 + w2) / ((k1 + k2) / m2 + k1 / m1) - 1.0).abs() < 1e-12);
        assert!(r.track < r.rail_on_pads);
        // Euler–Bernoulli: π/(2a²)·√(EI/ρA), 1428 Hz for UIC60 at a = 0.6 m.
        let beam = Beam::default();
        let closed = std::f64::consts::PI / (2.0 * 0.36) * (beam.bending_stiffness() / beam.mass_per_length()).sqrt();
        assert!((crate::dispersion::pinned_pinned(&beam, s.spacing) / closed - 1.0).abs() < 1e-12);
        let (smeared, k) = s.equivalent_track(&beam, 1e6);
        // 150 kg every 0.6 m moving with (2/3) of the rail's deflection: 250 kg/m × 4/9.
        assert!((smeared.mass_per_length() - beam.mass_per_length() - 250.0 * 4.0 / 9.0).abs() < 1e-9);
        assert!((k - 1e6 - s.equivalent_stiffness()).abs() < 1e-6);
    }
}
