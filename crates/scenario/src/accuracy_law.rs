//! The law of the ballast friction a refinement runs (`run --accuracy`, docs/theory.md §6.2): the cheapest for an
//! accuracy, by the measured table of the laws' accuracy against cost (BENCHMARKS.md, "The friction laws").
//!
//! Where the friction is light against the foundation's reaction under an axle — ρ_f = 2f_u/(βF) ≤
//! [`ONE_SECTION_A_NODE_UP_TO`], f_u the friction per metre, F the heaviest axle on the rail and Fβ/2 the foundation's
//! peak reaction per metre under it (Hetényi 1946) — one section a node (J = 1) is as accurate as four sections an
//! element (J = 4) at every resolution measured, and cheaper — a fifth to a tenth of the cost to 800 elements, half at
//! 1600: the error is the mesh's and the step's, not the law's. Heavier friction (ρ_f ≈ 1.5 measured) converges smoothly with J = 4 and wanders with
//! J = 1, which saves little there, so the law given is kept. A law the scenario sets (J ≠ 4 or Simpson) is kept too.

use crate::Scenario;
use crate::sections::{DistributedSection, QuadratureKind};
use crate::speeds::SpeedScale;
use serde::Serialize;

/// The largest friction share ρ_f at which a refinement runs one section a node: the reference case's 5 kN/m has
/// ρ_f = 0.38 (J = 1 as accurate as J = 4), its 20 kN/m ρ_f = 1.53 (J = 4 the cheaper to a given accuracy).
pub const ONE_SECTION_A_NODE_UP_TO: f64 = 0.4;

/// The law a refinement runs its ballast friction with.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AccuracyLaw {
    /// Sub-intervals J an element.
    pub subdivisions: usize,
    /// The quadrature.
    pub quadrature: QuadratureKind,
    /// ρ_f = 2f_u/(βF); None without a foundation or a load.
    pub friction_share: Option<f64>,
    /// Whether the refinement chose it (false: the scenario's own).
    pub chosen: bool,
}

impl Scenario {
    /// ρ_f = 2f_u/(βF) of this scenario's ballast friction, F (N) the heaviest axle its run puts on the rail (read
    /// from its run settings: no model is built, no ground fitted); None without ballast friction, a foundation (β)
    /// or a load.
    pub fn friction_share(&self) -> Option<f64> {
        let f_u = self.friction.distributed.as_ref()?.force_per_length;
        let beta = SpeedScale::of(self).ok()?.bending_wavenumber.filter(|&b| b > 0.0)?;
        let train = self.run_settings(self.load.speed).ok()?.moving.load.train();
        let heaviest = train.axles.iter().map(|a| a.force.abs()).fold(0.0, f64::max);
        (heaviest > 0.0).then(|| 2.0 * f_u / (beta * heaviest))
    }

    /// The scenario a refinement runs and its friction law, where it has ballast friction (None without): one
    /// section a node where the law is the default (J = 4, trapezoid) and ρ_f ≤ [`ONE_SECTION_A_NODE_UP_TO`], else
    /// the scenario as it is.
    pub fn with_accuracy_law(&self) -> Option<(Scenario, AccuracyLaw)> {
        let law = self.friction.distributed.as_ref()?;
        let friction_share = self.friction_share();
        let default = DistributedSection::default();
        let light = friction_share.is_some_and(|share| share <= ONE_SECTION_A_NODE_UP_TO);
        let chosen = light && law.subdivisions == default.subdivisions && law.quadrature == default.quadrature;
        let mut scenario = self.clone();
        if chosen {
            let distributed = scenario.friction.distributed.as_mut().expect("ballast friction");
            distributed.subdivisions = 1;
        }
        let ran = scenario.friction.distributed.as_ref().expect("ballast friction");
        let (subdivisions, quadrature) = (ran.subdivisions, ran.quadrature);
        Some((scenario, AccuracyLaw { subdivisions, quadrature, friction_share, chosen }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sections::DistributedSection;

    fn with_friction(force_per_length: f64, subdivisions: usize) -> Scenario {
        let mut s = Scenario::default();
        s.friction.distributed = Some(DistributedSection { force_per_length, subdivisions, ..Default::default() });
        s
    }

    #[test]
    fn the_reference_case_s_friction_share_is_twice_f_u_over_beta_times_its_force() {
        // β = 0.31417 1/m, F = 83.4 kN (docs/theory.md §2): 5 kN/m is ρ_f = 0.3816.
        let s = with_friction(5000.0, 4);
        let share = s.friction_share().unwrap();
        assert!((share - 2.0 * 5000.0 / (0.31417 * 83_400.0)).abs() < 1e-4, "{share}");
        assert_eq!(Scenario::default().friction_share(), None);
    }

    #[test]
    fn light_friction_on_the_default_law_runs_one_section_a_node_and_any_other_keeps_its_law() {
        let light = with_friction(5000.0, 4);
        let (ran, law) = light.with_accuracy_law().unwrap();
        assert_eq!((law.subdivisions, law.chosen), (1, true));
        assert_eq!(ran.friction.distributed.unwrap().subdivisions, 1);
        let heavy = with_friction(20_000.0, 4);
        let (ran, law) = heavy.with_accuracy_law().unwrap();
        assert_eq!((law.subdivisions, law.chosen), (4, false));
        assert!(law.friction_share.unwrap() > ONE_SECTION_A_NODE_UP_TO);
        assert_eq!(ran, heavy);
        let given = with_friction(5000.0, 2);
        let (_, law) = given.with_accuracy_law().unwrap();
        assert_eq!((law.subdivisions, law.chosen), (2, false));
        assert!(Scenario::default().with_accuracy_law().is_none());
    }
}
