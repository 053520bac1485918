//! What the studies of the discrete track share (docs/theory.md §18): a mesh with a node over every sleeper and four
//! elements a bay, and the continuous track a discrete one stands for.

use scenario::Scenario;
use scenario::sleepers::SleepersSection;

/// Elements a bay the time-domain studies run with: half a pinned–pinned wavelength in four.
pub(super) const ELEMENTS_PER_BAY: usize = 4;

/// Where `s` has no `[sleepers]`, put its rail on `sleepers` (`what` they are, in words) in place of its soil; a
/// sentence in `notes` when it does.
pub(super) fn sleepers_unless_given(s: &mut Scenario, sleepers: SleepersSection, what: &str, notes: &mut Vec<String>) {
    if s.sleepers.is_some() {
        return;
    }
    s.sleepers = Some(sleepers);
    s.foundation.stiffness = 0.0;
    s.foundation.damping = None;
    s.foundation.damping_ratio = None;
    notes.push(format!("the scenario has no [sleepers]: the study puts its rail on {what} in place of its soil"));
}

/// The typical ballasted track's sleepers, in words for [`sleepers_unless_given`].
pub(super) const TYPICAL: &str =
    "the typical ballasted track (pads 200 MN/m on 150 kg sleepers every 0.6 m on ballast of 100 MN/m)";

/// Make `s`'s mesh put a node over every sleeper with at least `per_bay` elements a bay, if it does not: whole bays
/// of the track's length, `per_bay` elements each; a sentence in `notes` when it changes.
pub(super) fn fit_mesh(s: &mut Scenario, per_bay: usize, notes: &mut Vec<String>) {
    let Some(sleepers) = &s.sleepers else { return };
    let a = sleepers.spacing;
    let first = sleepers.first.unwrap_or(0.5 * a);
    let l = s.mesh.length / s.mesh.elements as f64;
    let on_nodes = |x: f64| (x / l - (x / l).round()).abs() <= 1e-9 * (1.0 + x / l);
    if on_nodes(a) && on_nodes(first) && a / l >= per_bay as f64 - 1e-9 {
        return;
    }
    let bays = (s.mesh.length / a + 1e-9).floor();
    // Whole bays, rounded to a nanometre so that the length reads as it is meant (199.8 m, not 199.799…).
    s.mesh.length = (bays * a * 1e9).round() / 1e9;
    s.mesh.elements = per_bay * bays as usize;
    if let Some(section) = s.sleepers.as_mut() {
        section.first = Some(0.5 * a);
    }
    notes.push(format!(
        "mesh: {} m in {} elements — whole bays of {a} m, {per_bay} elements each, a node over every sleeper (the first \
         at {} m)",
        s.mesh.length,
        s.mesh.elements,
        0.5 * a
    ));
}

/// Sleepers every 0.6 m holding `s`'s soil in their stead: pad and ballast k = 2k_f a, c = 2c_f a each (in series,
/// the soil's spring and dashpot per sleeper), a light sleeper of a tenth of the rail's mass over a bay.
pub(super) fn sleepers_for_soil(s: &Scenario) -> scenario::error::Result<SleepersSection> {
    let a = 0.6;
    let foundation = *s.model()?.foundation();
    let layer = scenario::sleepers::LayerSection {
        stiffness: Some(2.0 * foundation.stiffness * a),
        damping: Some(2.0 * foundation.damping * a),
        loss_factor: None,
    };
    Ok(SleepersSection {
        spacing: a,
        first: None,
        mass: 0.1 * s.beam.mass_per_length() * a,
        pad: layer,
        ballast: scenario::sleepers::BallastSection {
            stiffness: layer.stiffness,
            damping: layer.damping,
            loss_factor: None,
            mass: None,
        },
        subgrade: None,
        self_weight: true,
        exceptions: Vec::new(),
    })
}
