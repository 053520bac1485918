//! The set-ups the studies share: friction by devices or distributed, a long track standing for an infinite one,
//! a blank result to fill, the mean solver iterations of a family of runs.

use super::study_data::{StudyData, StudySummary};
use runner::SweepPoint;
use scenario::{AbsorbingZonesSection, DevicesSection, DistributedSection, Scenario};

/// On a track, what stands for an infinite one under long loads (`what`, e.g. "the trains"): absorbing zones of
/// min(40 m, L/5) at the ends unless the scenario has its own (an undamped track keeps the waves trapped between its
/// pinned ends), and the extremes over the nodes of the middle third unless `[output] extremes_nodes` is given (loads
/// entering and leaving over a support set off transients there); a sentence in `notes` for each change.
pub(super) fn as_long_track(s: &mut Scenario, notes: &mut Vec<String>, what: &str) {
    let length = s.mesh.length;
    if s.foundation.absorbing_zones.is_none() {
        let zones = AbsorbingZonesSection { length: (length / 5.0).min(40.0), ..Default::default() };
        notes.push(format!(
            "on a track the study adds absorbing zones of {:.1} m at the ends (damping up to {} × c_cr) so that \
             {what}' waves leave the beam as on an infinite track (give [foundation.absorbing_zones], with \
             peak_ratio = 0 for none)",
            zones.length, zones.peak_ratio
        ));
        s.foundation.absorbing_zones = Some(zones);
    }
    if s.output.extremes_nodes.is_none() {
        s.output.extremes_nodes = Some([length / 3.0, 2.0 * length / 3.0]);
        notes.push(format!(
            "on a track the extremes are taken over the nodes of the middle third, {:.1}–{:.1} m, away from the \
             transients where {what} enter and leave over the supports ([output] extremes_nodes sets another range)",
            length / 3.0,
            2.0 * length / 3.0
        ));
    }
}

pub(super) fn with_devices(base: &Scenario, count: usize, force: f64) -> Scenario {
    let mut s = base.clone();
    s.friction.devices =
        (count > 0).then_some(DevicesSection { count: Some(count), positions: None, force: Some(force) });
    s.friction.distributed = None;
    s
}

pub(super) fn with_distributed(base: &Scenario, force_per_length: f64) -> Scenario {
    let mut s = base.clone();
    s.friction.devices = None;
    s.friction.distributed =
        (force_per_length > 0.0).then(|| DistributedSection { force_per_length, ..DistributedSection::default() });
    s
}

pub(super) fn blank(runs: usize) -> StudyData {
    StudyData {
        name: "",
        title: "",
        resolution: "",
        csv: String::new(),
        summary: StudySummary::none(),
        lines: Vec::new(),
        headline: Vec::new(),
        plots: Vec::new(),
        runs,
        mean_iterations: 0.0,
        columns: Vec::new(),
        failures: Vec::new(),
        ran_on: Vec::new(),
    }
}

pub(super) fn mean_iterations<'a>(points: impl Iterator<Item = &'a SweepPoint>) -> f64 {
    let (sum, count) = points.fold((0.0, 0usize), |(s, c), p| (s + p.mean_iterations, c + 1));
    if count > 0 { sum / count as f64 } else { 0.0 }
}
