//! The track as it is built (docs/theory.md §18): the rail on discrete supports — a rail pad (spring k_p, dashpot
//! c_p, loss factor η_p) on a sleeper of mass m_s (per rail seat) on the ballast (k_b, c_b, η_b) — every `spacing` m
//! from `first`. Each sleeper is a DOF z (m, upward) under a mesh node: the pad acts on w_node − z, the ballast on z.
//! The continuous Winkler foundation is its long-wave limit, k_f ≈ (k_p k_b/(k_p + k_b))/a; the two may be used
//! together (a slab under a continuous pad, or a soil left under sleepers). Optionally the ballast is a body of its
//! own (Zhai's two-layer model, [`BallastBody`]): a mass m_b (a second DOF y under each sleeper) on a subgrade
//! (k_g, c_g, η_g); the ballast then acts on z − y and the subgrade on y.

use crate::error::{FemError, Result, non_negative, positive};
use crate::mesh::Mesh;
use crate::properties::Beam;
use crate::sleeper_exceptions::{BallastContact, SleeperException};

/// A spring–dashpot layer: stiffness (N/m), viscous damping (N·s/m), loss factor (hysteretic, frequency domain).
/// Its default, all zeros, is no layer.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Layer {
    /// k (N/m), > 0.
    pub stiffness: f64,
    /// c (N·s/m), ≥ 0.
    pub damping: f64,
    /// η ≥ 0: k → k(1 + iη) in the frequency domain.
    pub loss_factor: f64,
}

impl Layer {
    /// Its dynamic stiffness at circular frequency `omega` (rad/s): k(1 + iη) + iωc (N/m).
    pub fn dynamic_stiffness(&self, omega: f64) -> num_complex::Complex64 {
        num_complex::Complex64::new(self.stiffness, self.stiffness * self.loss_factor + omega * self.damping)
    }
}

/// The ballast as a body of its own under each sleeper (Zhai's two-layer model; Zhai, Wang & Lin 2004): the
/// vibrating ballast under a rail seat lumped as a mass on a subgrade spring–dashpot. The ballast layer then joins
/// sleeper and ballast mass; a voided or tensionless sleeper's law and its friction act between the two.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallastBody {
    /// m_b (kg per rail seat), > 0.
    pub mass: f64,
    /// The subgrade under the ballast mass (k_g > 0).
    pub subgrade: Layer,
}

impl BallastBody {
    /// The subgrade a track on a firm formation has when only the ballast mass is given: k_g = 65 MN/m,
    /// c_g = 31.15 kN·s/m per rail seat, the values of Zhai, Wang & Lin (2004).
    pub const TYPICAL_SUBGRADE: Layer = Layer { stiffness: 65e6, damping: 31.15e3, loss_factor: 0.0 };
}

/// The lumped resonances of a bay (Hz), [`Sleepers::bay_resonances`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BayResonances {
    /// The whole track bouncing on the ballast (on the subgrade where the ballast is a body).
    pub track: f64,
    /// Where the ballast is a body: the sleeper on the ballast, the ballast mass against it.
    pub sleeper_on_ballast: Option<f64>,
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
    /// The ballast as a mass on the subgrade (two layers), or None: the ballast stands on rigid ground.
    pub ballast_body: Option<BallastBody>,
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
            ballast_body: None,
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
        let subgrade = self.ballast_body.map(|body| {
            (
                body.subgrade,
                ["sleepers.subgrade.stiffness", "sleepers.subgrade.damping", "sleepers.subgrade.loss_factor"],
            )
        });
        for (layer, [stiffness, damping, loss]) in layers.iter().map(|(l, keys)| (**l, *keys)).chain(subgrade) {
            positive(stiffness, layer.stiffness)?;
            non_negative(damping, layer.damping)?;
            if !(layer.loss_factor.is_finite() && (0.0..=1.0).contains(&layer.loss_factor)) {
                return Err(FemError::InvalidField {
                    field: loss,
                    value: layer.loss_factor,
                    allowed: "must lie in [0, 1]: rail pads and ballast have η of 0.1–0.5, and no solid damps above 1",
                });
            }
        }
        if let Some(body) = self.ballast_body {
            positive("sleepers.ballast.mass", body.mass)?;
        }
        Ok(())
    }

    /// DOFs per sleeper: z, and the ballast mass's y where the ballast is a body.
    pub fn dofs_per_sleeper(&self) -> usize {
        if self.ballast_body.is_some() { 2 } else { 1 }
    }

    /// The layers' compliances from the rail down (m/N): 1/k_p, 1/k_b and, under a ballast body, 1/k_g.
    fn compliances(&self) -> [f64; 3] {
        let subgrade = self.ballast_body.map_or(0.0, |b| 1.0 / b.subgrade.stiffness);
        [1.0 / self.pad.stiffness, 1.0 / self.ballast.stiffness, subgrade]
    }

    /// The equivalent continuous support (N/m²): the pad, ballast (and subgrade) in series, spread over a spacing.
    pub fn equivalent_stiffness(&self) -> f64 {
        1.0 / self.compliances().iter().sum::<f64>() / self.spacing
    }

    /// The equivalent continuous dashpot (N·s/m²): the layers' Kelvin–Voigt pairs in series to first order in ω,
    /// Σ 1/(k_i + iωc_i) ≈ Σ 1/k_i − iω Σ c_i/k_i², so c_eq = k_s² Σ c_i/k_i² / a with k_s = 1/Σ 1/k_i — for pad and
    /// ballast (c_p k_b² + c_b k_p²)/((k_p + k_b)² a), exact when every layer has the same c/k.
    pub fn equivalent_damping(&self) -> f64 {
        let subgrade = self.ballast_body.map(|b| b.subgrade);
        let layers = [Some(self.pad), Some(self.ballast), subgrade];
        let series = self.equivalent_stiffness() * self.spacing;
        let sum: f64 = layers.iter().flatten().map(|l| l.damping / (l.stiffness * l.stiffness)).sum();
        series * series * sum / self.spacing
    }

    /// The sleepers' mass spread over their spacing, m_s/a (kg/m).
    pub fn mass_per_length(&self) -> f64 {
        self.mass / self.spacing
    }

    /// The long-wave twin in the frequency domain: the sleepers' dynamic stiffness spread over their spacing
    /// (N/m²) at circular frequency `omega` — the pad in series with the sleeper's mass on the ballast,
    /// k̃_p(k̃_b − ω²m_s)/(k̃_p + k̃_b − ω²m_s)/a with k̃ = k(1 + iη) + iωc ([`Layer::dynamic_stiffness`]).
    pub fn dynamic_stiffness_per_metre(&self, omega: f64) -> num_complex::Complex64 {
        let (pad, below) =
            (self.pad.dynamic_stiffness(omega), self.ballast.dynamic_stiffness(omega) - omega * omega * self.mass);
        pad * below / (pad + below) / self.spacing
    }

    /// The equivalent continuous track of `beam` on these sleepers and a soil `k_f` (N/m²): the beam carrying the
    /// sleepers' (and ballast bodies') mass spread as the long wave moves it, on k_f + [`Self::equivalent_stiffness`].
    /// Well below the bay's resonances ([`Self::bay_resonances`]) the layers follow the rail node quasi-statically,
    /// each mass moving with the share of w in the compliances below it — z = w·(1/k_b + 1/k_g)/Σ1/k,
    /// y = w·(1/k_g)/Σ1/k — so their kinetic energy is that of m_s (z/w)² + m_b (y/w)² moving with the rail:
    /// ρ → ρ + (m_s (z/w)² + m_b (y/w)²)/(aA) — 0.44 m_s for the typical pads on rigidly founded ballast.
    pub fn equivalent_track(&self, beam: &Beam, k_f: f64) -> (Beam, f64) {
        let [pad, ballast, subgrade] = self.compliances();
        let total = pad + ballast + subgrade;
        let (sleeper, body) = ((ballast + subgrade) / total, subgrade / total);
        let body_mass = self.ballast_body.map_or(0.0, |b| b.mass);
        let moved = self.mass * sleeper * sleeper + body_mass * body * body;
        let density = beam.density + moved / self.spacing / beam.area;
        (Beam { density, ..*beam }, k_f + self.equivalent_stiffness())
    }

    /// The resonances of one bay lumped (Hz): the rail's mass over a spacing ρA·a on the pad, on the sleeper on
    /// the ballast (on the ballast mass on the subgrade) — the lowest the whole track bouncing, the highest the rail
    /// on its pads (the sleeper moving against it) and, under a ballast body, the sleeper on the ballast (the mode
    /// the rail moves least in). The eigenvalues of the chain's M⁻¹K. Estimates that name the peaks of a receptance; the rail's bending
    /// shifts them.
    pub fn bay_resonances(&self, rail_mass_per_length: f64) -> BayResonances {
        let hz = |omega2: f64| omega2.max(0.0).sqrt() / std::f64::consts::TAU;
        let (m1, m2) = (rail_mass_per_length * self.spacing, self.mass);
        let (k1, k2) = (self.pad.stiffness, self.ballast.stiffness);
        let Some(body) = self.ballast_body else {
            // m1 m2 ω⁴ − (m1 (k1 + k2) + m2 k1) ω² + k1 k2 = 0.
            let (a, b, c) = (m1 * m2, m1 * (k1 + k2) + m2 * k1, k1 * k2);
            let root = (b * b - 4.0 * a * c).max(0.0).sqrt();
            return BayResonances {
                track: hz(2.0 * c / (b + root)),
                sleeper_on_ballast: None,
                rail_on_pads: hz((b + root) / (2.0 * a)),
            };
        };
        let (m3, k3) = (body.mass, body.subgrade.stiffness);
        // M^{-1/2} K M^{-1/2} of the chain rail–pad–sleeper–ballast–ballast mass–subgrade: symmetric, same ω²; in
        // its eigenvector v the kinetic energy's share of mass i is v_i².
        let s = [m1.sqrt(), m2.sqrt(), m3.sqrt()];
        let k = nalgebra::Matrix3::new(k1, -k1, 0.0, -k1, k1 + k2, -k2, 0.0, -k2, k2 + k3);
        let eigen = nalgebra::Matrix3::from_fn(|i, j| k[(i, j)] / (s[i] * s[j])).symmetric_eigen();
        let mut modes: Vec<(f64, f64)> =
            (0..3).map(|i| (eigen.eigenvalues[i], eigen.eigenvectors[(0, i)].powi(2))).collect();
        modes.sort_by(|a, b| a.0.total_cmp(&b.0));
        // The lowest is the track bouncing; of the other two, the rail on its pads is the one the rail's mass
        // carries more of (for typical layers the highest; on a stiff subgrade the ballast mass's own is higher).
        let (rail, other) = if modes[2].1 >= modes[1].1 { (modes[2], modes[1]) } else { (modes[1], modes[2]) };
        BayResonances { track: hz(modes[0].0), sleeper_on_ballast: Some(hz(other.0)), rail_on_pads: hz(rail.0) }
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
        // The spacing first: a first sleeper off the nodes is often the default spacing/2 of a misfit spacing.
        let off_node = |x: f64| (x / l - (x / l).round()).abs() > 1e-9 * (1.0 + (x / l).round());
        for (field, value) in [("sleepers.spacing", self.spacing), ("sleepers.first", self.first)] {
            if off_node(value) {
                return Err(FemError::InvalidField {
                    field,
                    value,
                    allowed: "must be a multiple of the element length (mesh.length / mesh.elements), so that every \
                              sleeper sits on a mesh node",
                });
            }
        }
        (0..count).map(|i| ((self.first + i as f64 * self.spacing) / l).round() as usize).map(Ok).collect()
    }
}

impl Sleepers {
    /// What the sleepers under `nodes` add to a matrix over the free DOFs of `dofs` (a map with their DOFs,
    /// [`crate::supports::DofMap::with_sleepers`]), as entries (i, j ≤ i) of its lower triangle: each layer a
    /// spring [[1, −1], [−1, 1]] between the DOFs it joins — the pad between w and z (on z alone where a support
    /// holds w), the ballast between z and what is under it ([`crate::supports::DofMap::under_ballast`]: the ground,
    /// a ballast body's y or an embankment's w_e), the subgrade between a ballast body's y and
    /// the ground — and the masses on z and y. `layers` gives what a sleeper's pad, ballast and subgrade contribute,
    /// from its [`SleeperSupport`] — their k for K (the ballast's where bonded), c for C, k(1 + iη) + iωc for a
    /// dynamic stiffness — and `mass` what m_s and m_b do (m for M, −ω²m for a dynamic stiffness, 0 for K and C).
    pub fn entries<T>(
        &self,
        dofs: &crate::supports::DofMap,
        nodes: &[usize],
        layers: impl Fn(&SleeperSupport) -> [T; 3],
        mass: impl Fn(f64) -> T,
    ) -> Vec<(usize, usize, T)>
    where
        T: Copy + std::ops::Neg<Output = T>,
    {
        // A layer joining DOFs a and b (None: held, or the ground).
        fn spring<T: Copy + std::ops::Neg<Output = T>>(
            out: &mut Vec<(usize, usize, T)>,
            a: Option<usize>,
            b: Option<usize>,
            k: T,
        ) {
            out.extend([a, b].into_iter().flatten().map(|d| (d, d, k)));
            if let (Some(a), Some(b)) = (a, b) {
                out.push((a.max(b), a.min(b), -k));
            }
        }
        let mut out = Vec::with_capacity(5 * self.dofs_per_sleeper() * nodes.len());
        for (s, &node) in nodes.iter().enumerate() {
            let [pad, ballast, subgrade] = layers(&self.support(s));
            let z = dofs.sleeper(s);
            out.push((z, z, mass(self.mass)));
            spring(&mut out, dofs.free_index(2 * node), Some(z), pad);
            spring(&mut out, Some(z), dofs.under_ballast(s, node), ballast);
            if let (Some(y), Some(body)) = (dofs.ballast_body(s), self.ballast_body) {
                out.push((y, y, mass(body.mass)));
                spring(&mut out, Some(y), None, subgrade);
            }
        }
        out
    }
}

/// What holds one sleeper, the exceptions applied: its pad (stiffness scaled) and ballast (stiffness and dashpot
/// scaled) layers, how the ballast holds it, its friction force (N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SleeperSupport {
    /// The pad (stiffness scaled).
    pub pad: Layer,
    /// The ballast (stiffness and dashpot scaled).
    pub ballast: Layer,
    /// The subgrade under a ballast body ([`BallastBody`]), or None.
    pub subgrade: Option<Layer>,
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

    /// The ballast's dashpot C holds (N·s/m): all of it where bonded, none where unilateral — there the law carries
    /// it in contact only (a dashpot does not pull a hanging sleeper nor act across an open gap).
    pub fn bonded_damping(&self) -> f64 {
        match self.contact {
            BallastContact::Bonded => self.ballast.damping,
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
        let typical = SleeperSupport {
            pad: self.pad,
            ballast: self.ballast,
            subgrade: self.ballast_body.map(|b| b.subgrade),
            contact: BallastContact::Bonded,
            friction: 0.0,
        };
        match self.exceptions.iter().rev().find(|e| e.covers(s)) {
            None => typical,
            Some(e) => SleeperSupport {
                pad: Layer { stiffness: self.pad.stiffness * e.pad_scale, ..self.pad },
                ballast: Layer {
                    stiffness: self.ballast.stiffness * e.ballast_scale,
                    damping: self.ballast.damping * e.ballast_scale,
                    ..self.ballast
                },
                contact: e.contact,
                friction: e.friction,
                ..typical
            },
        }
    }

    /// Whether an exception names sleeper `s` (it differs from the rest).
    pub fn differs(&self, s: usize) -> bool {
        self.exceptions.iter().any(|e| e.covers(s))
    }

    /// Whether some sleeper's ballast cannot pull (tensionless or voided).
    pub fn has_unilateral_ballast(&self) -> bool {
        self.exceptions.iter().any(|e| e.contact != BallastContact::Bonded)
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
    fn a_bay_lumped_has_the_two_mass_resonances_and_its_long_wave_twin() {
        // Two masses on two springs: the product of ω² is k1k2/(m1m2), their sum (k1 + k2)/m2 + k1/m1.
        let s = Sleepers::default();
        let r = s.bay_resonances(60.0);
        let (w1, w2) = ((r.track * std::f64::consts::TAU).powi(2), (r.rail_on_pads * std::f64::consts::TAU).powi(2));
        let (m1, m2, k1, k2) = (36.0, 150.0, 200e6, 100e6);
        assert!((w1 * w2 / (k1 * k2 / (m1 * m2)) - 1.0).abs() < 1e-12);
        assert!(((w1 + w2) / ((k1 + k2) / m2 + k1 / m1) - 1.0).abs() < 1e-12);
        assert!(r.track < r.rail_on_pads);
        let beam = Beam::default();
        let (smeared, k) = s.equivalent_track(&beam, 1e6);
        // 150 kg every 0.6 m moving with (2/3) of the rail's deflection: 250 kg/m × 4/9.
        assert!((smeared.mass_per_length() - beam.mass_per_length() - 250.0 * 4.0 / 9.0).abs() < 1e-9);
        assert!((k - 1e6 - s.equivalent_stiffness()).abs() < 1e-6);
    }

    #[test]
    fn a_ballast_body_adds_a_third_resonance_and_its_share_of_the_long_wave() {
        // Three masses on three springs: Σω² = tr(M⁻¹K) = k1/m1 + (k1 + k2)/m2 + (k2 + k3)/m3 and
        // Πω² = det K/det M = k1k2k3/(m1m2m3).
        let body = BallastBody { mass: 500.0, subgrade: BallastBody::TYPICAL_SUBGRADE };
        let s = Sleepers { ballast: Layer { stiffness: 180e6, ..Sleepers::default().ballast }, ..Sleepers::default() };
        let s = Sleepers { ballast_body: Some(body), ..s };
        let r = s.bay_resonances(60.0);
        let w2 = |f: f64| (f * std::f64::consts::TAU).powi(2);
        let middle = r.sleeper_on_ballast.unwrap();
        let (m1, m2, m3, k1, k2, k3) = (36.0, 150.0, 500.0, 200e6, 180e6, 65e6);
        let sum = w2(r.track) + w2(middle) + w2(r.rail_on_pads);
        assert!((sum / (k1 / m1 + (k1 + k2) / m2 + (k2 + k3) / m3) - 1.0).abs() < 1e-12);
        let product = w2(r.track) * w2(middle) * w2(r.rail_on_pads);
        assert!((product / (k1 * k2 * k3 / (m1 * m2 * m3)) - 1.0).abs() < 1e-10);
        assert!(r.track < middle && middle < r.rail_on_pads, "{r:?}");
        // In series: 1/k_eq a = 1/k_p + 1/k_b + 1/k_g; in the long wave z = w(1/k_b + 1/k_g)/Σ, y = w(1/k_g)/Σ.
        let total = 1.0 / k1 + 1.0 / k2 + 1.0 / k3;
        assert!((s.equivalent_stiffness() * 0.6 * total - 1.0).abs() < 1e-12);
        let beam = Beam::default();
        let (zr, yr) = ((1.0 / k2 + 1.0 / k3) / total, (1.0 / k3) / total);
        let (smeared, _) = s.equivalent_track(&beam, 0.0);
        let added = (150.0 * zr * zr + 500.0 * yr * yr) / 0.6;
        assert!((smeared.mass_per_length() - beam.mass_per_length() - added).abs() < 1e-9);
        // Every layer with c/k = τ: the series is one layer of the same τ.
        let tau = 1e-4;
        let same = |l: Layer| Layer { damping: tau * l.stiffness, ..l };
        let body_same = BallastBody { subgrade: same(body.subgrade), ..body };
        let uniform =
            Sleepers { pad: same(s.pad), ballast: same(s.ballast), ballast_body: Some(body_same), ..s.clone() };
        assert!((uniform.equivalent_damping() / (tau * uniform.equivalent_stiffness()) - 1.0).abs() < 1e-12);
        let error = Sleepers { ballast_body: Some(BallastBody { mass: 0.0, ..body }), ..s.clone() }.validate();
        assert!(error.unwrap_err().to_string().contains("sleepers.ballast.mass = 0"));
        let soft = BallastBody { subgrade: Layer { stiffness: -1.0, ..body.subgrade }, ..body };
        let error = Sleepers { ballast_body: Some(soft), ..s }.validate().unwrap_err().to_string();
        assert!(error.contains("sleepers.subgrade.stiffness = -1"), "{error}");
    }
}
