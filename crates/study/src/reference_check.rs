//! The reference check of a scenario: its static response under one load at mid-span and its lowest natural
//! frequencies, each beside its closed form (docs/theory.md §2, §8): the deflection and moment of the infinite beam
//! under a static load, v_cr, and the pinned beam's ω_n.

use fem_beam::LoadVector;
use fem_beam::section::Motion;
use scenario::Scenario;
use scenario::error::{Result, invalid};
use serde::Serialize;

/// One natural frequency beside its closed form.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModeCheck {
    /// Mode number n (1-based).
    pub n: usize,
    /// ω_n of the finite-element model (rad/s).
    pub omega: f64,
    /// ω_n of the pinned beam on its foundation (rad/s; Timoshenko's frequency equation for a Timoshenko rail).
    pub omega_closed_form: f64,
}

/// The reference check's numbers: the finite-element results beside the closed forms.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReferenceCheck {
    /// The scenario's title, or the reference case's name.
    pub title: String,
    /// The rail where it is not Euler–Bernoulli's ("Timoshenko (G = 81 GPa, κ = 0.4)").
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rail_theory: Option<String>,
    /// Beam length L (m).
    pub length: f64,
    /// The end supports, `left/right`.
    pub supports: String,
    /// Elements.
    pub elements: usize,
    /// Free DOFs.
    pub dofs: usize,
    /// The static load F at mid-span (N, downward).
    pub load: f64,
    /// w under the load (m, upward > 0) and the infinite beam's −F β/(2k).
    pub midspan_deflection: f64,
    /// The infinite beam's deflection under the load (m).
    pub midspan_deflection_closed_form: f64,
    /// M under the load (N·m) and the infinite beam's F/(4β).
    pub midspan_moment: f64,
    /// The infinite beam's moment under the load (N·m).
    pub midspan_moment_closed_form: f64,
    /// v_cr (m/s).
    pub critical_speed: f64,
    /// The lowest natural frequencies.
    pub modes: Vec<ModeCheck>,
}

impl ReferenceCheck {
    /// The check of `scenario` with its lowest `modes` natural frequencies. Refused for a scenario whose loads are a
    /// train or vehicles (one load at mid-span is checked: the single load's force would silently answer another
    /// question), and for `modes` outside [1, free DOFs] (field `modes`).
    pub fn of(scenario: &Scenario, modes: usize) -> Result<Self> {
        let load = &scenario.load;
        let (field, value) = match (&scenario.vehicle, &load.train, load.axles.len(), load.patches.len()) {
            (Some(_), _, _, _) => ("vehicle", "given".to_string()),
            (None, Some(train), _, _) => ("load.train", train.clone()),
            (None, None, axles, _) if axles > 0 => ("load.axles", format!("{axles} axles")),
            (None, None, _, patches) if patches > 0 => ("load.patches", format!("{patches} patches")),
            _ => ("", String::new()),
        };
        if !field.is_empty() {
            return Err(invalid(
                field,
                value,
                "`frictrack reference` checks one load of [load] force at mid-span against its closed form; for this \
                 scenario's loads use `frictrack analytic SCENARIO --speed V` (a train's steady state) or `frictrack run`",
            ));
        }
        let case = scenario.reference_case()?;
        let model = case.model()?;
        let inf = analytic::moving_beam::MovingBeam::new(&case.beam, &case.foundation)?;
        let mid = case.mesh.length / 2.0;
        let load = LoadVector::point_force(&model.discretisation(), mid, -case.load)?;
        let q = model.static_solve(&load)?;
        let moments = model.nodal_moments(&q, &load, Motion::default())?;
        let free = model.dofs().free_len();
        if modes == 0 || modes > free {
            return Err(invalid(
                "modes",
                modes,
                format!("must lie in [1, {free}], the number of free DOFs of this mesh"),
            ));
        }
        let omega = model.natural_frequencies(modes)?;
        Ok(Self {
            title: if scenario.title.is_empty() {
                "reference case: UIC60 rail on soft soil".into()
            } else {
                scenario.title.clone()
            },
            rail_theory: case.beam.theory.unless_default(),
            length: case.mesh.length,
            supports: format!("{:?}/{:?}", case.supports.left, case.supports.right).to_lowercase(),
            elements: case.mesh.elements,
            dofs: free,
            load: case.load,
            midspan_deflection: model.deflection_at(&q, mid)?,
            midspan_deflection_closed_form: -inf.static_deflection(case.load)?,
            midspan_moment: moments.at(mid),
            midspan_moment_closed_form: inf.static_moment(case.load)?,
            critical_speed: inf.critical_speed(),
            modes: omega
                .iter()
                .enumerate()
                .map(|(i, &w)| ModeCheck {
                    n: i + 1,
                    omega: w,
                    omega_closed_form: analytic::dispersion::pinned_natural_frequency(
                        &case.beam,
                        case.foundation.stiffness,
                        case.mesh.length,
                        i + 1,
                    ),
                })
                .collect(),
        })
    }
}
