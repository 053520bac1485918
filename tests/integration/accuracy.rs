//! `run --accuracy TOL` (docs/theory.md §6.2): the run refined until every outcome's estimated error is within TOL —
//! and, where the next resolution costs more than allowed, stopped with the outcomes that did not reach it named.

use report::resolution_check::accuracy::{AccuracyStatus, Target, refine};
use scenario::Scenario;

fn coarse() -> Scenario {
    let mut s = Scenario::default();
    s.mesh.elements = 50;
    s.integration.load_advance = 0.8;
    s
}

#[test]
fn a_refinement_that_reaches_its_tolerance_reports_the_finest_run_within_it() {
    let target = Target { tolerance: 0.05, level_seconds: 60.0 };
    let refined = refine(&coarse(), target, &|_, _| Vec::new(), None, &mut |_| {}, &|_| {}).unwrap();
    let accuracy = refined.summary.accuracy.as_ref().unwrap();
    assert_eq!(accuracy.status, AccuracyStatus::Reached);
    let check = refined.summary.resolution_check.as_ref().unwrap();
    assert_eq!(check.run, 2, "the answer is the finest of the last three");
    let finest = accuracy.resolutions.last().unwrap();
    assert_eq!(finest.elements, refined.scenario.mesh.elements);
    assert_eq!(check.resolutions[2].elements, finest.elements);
    assert!(accuracy.resolutions.len() >= 3);
    for pair in accuracy.resolutions.windows(2) {
        assert_eq!(pair[1].elements, 2 * pair[0].elements, "each resolution halves the elements");
        assert_eq!(pair[1].load_advance, 0.5 * pair[0].load_advance, "and the load advance");
    }
    for o in &check.outcomes {
        let error = o.error.unwrap_or_else(|| panic!("{} undefined in a reached refinement", o.name));
        assert!(error <= 0.05 * o.values[2].abs(), "{}: {error} against {:?}", o.name, o.values);
    }
    // The summary is the finest run's own.
    let window = &refined.summary.extremes.window_deflection.max_downward.extreme;
    let checked = check.outcomes.iter().find(|o| o.name == "window_max_downward_deflection").unwrap();
    assert_eq!(window.value, checked.values[2]);
}

#[test]
fn a_refinement_beyond_its_budget_stops_and_names_what_did_not_reach_the_tolerance() {
    // 1e-5 cannot be reached before a resolution estimated beyond 0.05 s.
    let target = Target { tolerance: 1e-5, level_seconds: 0.05 };
    let refined = refine(&coarse(), target, &|_, _| Vec::new(), None, &mut |_| {}, &|_| {}).unwrap();
    let accuracy = refined.summary.accuracy.unwrap();
    let AccuracyStatus::NotReached { why, outcomes } = &accuracy.status else { panic!("{:?}", accuracy.status) };
    assert!(why.contains("would take") && why.contains("beyond 0.05 s"), "{why}");
    assert!(!outcomes.is_empty());
}

#[test]
fn a_tolerance_outside_zero_to_one_is_refused_by_key() {
    for bad in [0.0, -0.01, 1.0, 2.0, f64::NAN, f64::INFINITY] {
        let target = Target { tolerance: bad, level_seconds: 1.0 };
        let Err(e) = refine(&coarse(), target, &|_, _| Vec::new(), None, &mut |_| {}, &|_| {}) else {
            panic!("{bad} taken")
        };
        assert!(e.to_string().contains("invalid accuracy"), "{e}");
    }
}

/// The main job at `--accuracy 0.01`, as docs/theory.md §6.2 quotes it: 100 to 6400 elements, the whole run's peak
/// settled to 513.4 mm, the window's to 292.55 and 203.75 mm.
#[test]
#[ignore = "15 s: cargo test -p frictrack-tests --test integration the_main_job_at_one_per_cent -- --ignored"]
fn the_main_job_at_one_per_cent() {
    let target = Target { tolerance: 0.01, level_seconds: 1200.0 };
    let refined = refine(&Scenario::default(), target, &|_, _| Vec::new(), None, &mut |_| {}, &|_| {}).unwrap();
    let accuracy = refined.summary.accuracy.as_ref().unwrap();
    assert_eq!(accuracy.status, AccuracyStatus::Reached);
    let elements: Vec<usize> = accuracy.resolutions.iter().map(|r| r.elements).collect();
    assert_eq!(elements, [100, 200, 400, 800, 1600, 3200, 6400]);
    let x = &refined.summary.extremes;
    // Quoted in mm to four or five digits.
    assert!((x.deflection.max_downward.value * 1e3 - 513.4).abs() < 0.05);
    assert!((x.window_deflection.max_downward.extreme.value * 1e3 - 292.55).abs() < 0.005);
    assert!((x.window_deflection.max_upward.extreme.value * 1e3 - 203.75).abs() < 0.005);
}
