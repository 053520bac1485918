//! Tests of the HSLM study's set-up: what it changes in the scenario, its friction set-ups, resonance speeds.
use super::super::resonances::resonances;
use super::super::results::millimetres;
use super::{friction_setups, prepared};
use scenario::{AbsorbingZonesSection, DevicesSection, DistributedSection, Scenario};

/// On a track the study adds absorbing zones and takes the extremes over the middle third, unless the scenario
/// sets them; on a span it reduces the load advance to v_min/(20 f_max) and touches nothing else.
#[test]
fn what_the_study_changes() {
    let speeds = [40.0, 80.0, 116.0];
    let track = Scenario::default();
    let (s, notes) = prepared(&track, &speeds).unwrap();
    assert_eq!(s.foundation.absorbing_zones, Some(AbsorbingZonesSection { length: 40.0, peak_ratio: 1.0 }));
    assert_eq!(s.output.extremes_nodes, Some([200.0 / 3.0, 400.0 / 3.0]));
    assert_eq!((notes.len(), s.integration.load_advance), (2, track.integration.load_advance));
    let mut own = track.clone();
    own.foundation.absorbing_zones = Some(AbsorbingZonesSection { length: 10.0, peak_ratio: 0.0 });
    own.output.extremes_nodes = Some([0.0, 200.0]);
    let (s, notes) = prepared(&own, &speeds).unwrap();
    assert_eq!((s, notes.len()), (own, 0));

    let mut span = Scenario::default();
    span.mesh.length = 20.0;
    span.mesh.elements = 40;
    span.foundation.stiffness = 0.0;
    // A 20 m rail span: f_max = 30 Hz, so 40 m/s needs Δx ≤ 0.0667 m, below the default 0.1 m.
    let (s, notes) = prepared(&span, &speeds).unwrap();
    let model = span.model().unwrap();
    let (f_max, _) = scenario::diagnostics::deck_frequency(&model).unwrap();
    assert_eq!(s.integration.load_advance, 40.0 / (20.0 * f_max));
    assert_eq!((s.foundation.absorbing_zones, s.output.extremes_nodes, notes.len()), (None, None, 1));
}

/// The set-up without friction has none, whatever the scenario gives; the other is the scenario's own, or the
/// fallback devices at 31 per 200 m.
#[test]
fn the_two_friction_setups() {
    let mut base = Scenario::default();
    let (none, with, text) = friction_setups(&base);
    assert!(none.friction.devices.is_none() && none.friction.distributed.is_none());
    assert_eq!(with.friction.devices.as_ref().and_then(|d| d.count), Some(31));
    assert_eq!(text, "31 devices × 50 kN");
    base.mesh.length = 20.0;
    assert_eq!(friction_setups(&base).2, "3 devices × 50 kN");
    base.mesh.length = 5.0;
    assert_eq!(friction_setups(&base).2, "1 device × 50 kN");
    base.friction.devices = Some(DevicesSection { count: Some(1), positions: None, force: Some(20e3) });
    base.friction.distributed = Some(DistributedSection { force_per_length: 2e3, ..DistributedSection::default() });
    let (none, with, text) = friction_setups(&base);
    assert!(none.friction.devices.is_none() && none.friction.distributed.is_none());
    assert_eq!(with.friction, base.friction);
    assert_eq!(text, "1 device × 20 kN + f_u = 2 kN/m");
}

#[test]
fn resonance_speeds_are_the_harmonics_inside_the_range() {
    let r = resonances(&[10.0, 40.0], 20.0, (40.0, 120.0));
    let speeds: Vec<(usize, usize, f64)> = r.iter().map(|r| (r.mode, r.order, r.speed)).collect();
    // f₁D = 200 m/s: i = 2, 3, 4, 5 give 100, 66.7, 50, 40; f₂D = 800 m/s: i = 7 … 20 fall in [40, 120].
    assert_eq!(&speeds[..4], &[(1, 2, 100.0), (1, 3, 200.0 / 3.0), (1, 4, 50.0), (1, 5, 40.0)]);
    assert_eq!(speeds.len(), 4 + 14);
    assert_eq!(speeds[4], (2, 7, 800.0 / 7.0));
    // A frequency within 1 % of a lower one adds nothing.
    let crowded = resonances(&[10.0, 10.05, 40.0], 20.0, (40.0, 120.0));
    assert_eq!(crowded.len(), 18);
    assert!(crowded.iter().all(|r| r.mode != 2));
}

#[test]
fn millimetres_keep_three_significant_digits() {
    assert_eq!(millimetres(1.2461e-3), "1.25 mm");
    assert_eq!(millimetres(0.32645), "326 mm");
    assert_eq!(millimetres(4.2e-5), "0.0420 mm");
}
