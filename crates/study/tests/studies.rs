//! Scenarios and studies.

use runner::{Runner, critical_speed, optimal_device_force, write_csv};
use scenario::StudyError;
use scenario::{Scenario, TEMPLATE};

fn path_of(err: StudyError) -> String {
    match err {
        StudyError::InvalidField { path, .. } => path,
        other => panic!("expected a field error, got {other}"),
    }
}

#[test]
fn template_is_the_reference_case() {
    let parsed = Scenario::from_toml(TEMPLATE, "template.toml").unwrap();
    assert_eq!(parsed, Scenario::default());
    let case = parsed.build().unwrap();
    assert_eq!(case.model.mesh().elements, 200);
    assert!(case.interactions.is_empty());
    // Round trip through the serialiser.
    assert_eq!(Scenario::from_toml(&parsed.to_toml(), "x").unwrap(), parsed);
}

#[test]
fn a_scenario_lists_only_what_differs() {
    let s = Scenario::from_toml(
        "[friction.devices]\ncount = 31\nforce = 50e3\n[friction.distributed]\nforce_per_length = 1000.0\n\
         [foundation]\ndamping_ratio = 0.05\n[load]\nspeed = 150.0\n",
        "s.toml",
    )
    .unwrap();
    let case = s.build().unwrap();
    assert_eq!(case.interactions.len(), 31 + 799);
    assert!((case.model.foundation().damping_ratio(case.model.beam()) - 0.05).abs() < 1e-12);
    assert_eq!(case.settings.moving.speed, 150.0);
}

#[test]
fn syntax_errors_and_unknown_keys_give_line_and_column() {
    let err = Scenario::from_toml("[foundation]\nstifness = 1.0\n", "bad.toml").unwrap_err();
    match &err {
        StudyError::Syntax { source_name, line, column, message } => {
            assert_eq!((source_name.as_str(), *line, *column), ("bad.toml", 2, 1));
            assert!(message.contains("stifness"), "{message}");
        }
        other => panic!("{other}"),
    }
    assert!(err.is_invalid_input());
    let err = Scenario::from_toml("[load]\nspeed = \"fast\"\n", "bad.toml").unwrap_err();
    assert!(matches!(err, StudyError::Syntax { line: 2, .. }), "{err}");
}

#[test]
fn bad_values_name_their_path() {
    let cases = [
        ("[mesh]\nelements = 0", "mesh.elements"),
        ("[beam]\ndensity = -1.0", "beam.density"),
        ("[foundation]\ndamping = 1.0\ndamping_ratio = 0.1", "foundation.damping_ratio"),
        ("[foundation]\ndamping_ratio = -0.1", "foundation.damping_ratio"),
        ("[load]\nspeed = 0.0", "load.speed"),
        ("[load]\nforce = -5.0", "load.force"),
        ("[integration]\ntheta = 0.3", "integration.theta"),
        ("[integration]\nload_advance = 2.0", "integration.load_advance"),
        ("[integration]\ntolerance = 0.5", "integration.tolerance"),
        ("[integration]\nsteady_start = 250.0", "integration.steady_start"),
        ("[friction.devices]\ncount = 3\npositions = [1.0]\nforce = 1.0", "friction.devices.count"),
        ("[friction.devices]\ncount = 500\nforce = 1.0", "friction.devices.count"),
        ("[friction.devices]\npositions = [300.0]\nforce = 1.0", "friction.devices.positions"),
        (
            "[friction.distributed]\nforce_per_length = 1.0\nsubdivisions = 3\nquadrature = \"simpson\"",
            "friction.distributed.subdivisions",
        ),
        ("[sweep]\nfrom = 100.0\nto = 50.0", "sweep.to"),
        ("[output]\nsections = [201.0]", "output.sections"),
    ];
    for (text, path) in cases {
        let err = Scenario::from_toml(text, "s.toml").unwrap().build().unwrap_err();
        assert!(err.is_invalid_input(), "{text}: {err}");
        let message = err.to_string();
        assert!(message.contains(path), "{text}: expected {path} in «{message}»");
        if let StudyError::InvalidField { .. } = err {
            assert_eq!(path_of(err), path);
        }
    }
}

#[test]
fn sweeps_do_not_depend_on_thread_count() {
    let s =
        Scenario::from_toml("[mesh]\nlength = 60.0\nelements = 60\n[friction.devices]\ncount = 7\nforce = 20e3", "s")
            .unwrap();
    let case = s.build().unwrap();
    let speeds = [120.0, 150.0, 180.0, 210.0];
    let csv = |jobs| {
        let points = Runner::new(jobs).unwrap().speed_sweep(&case, &speeds).unwrap();
        let mut out = Vec::new();
        write_csv(&points, &mut out).unwrap();
        String::from_utf8(out).unwrap()
    };
    let one = csv(1);
    assert_eq!(one, csv(2));
    assert_eq!(one.lines().count(), 5);
    assert!(one.starts_with("speed,max_downward_deflection,max_upward_deflection,dissipated_energy,global_norm"));
}

/// The refined critical speed of the friction-free reference case is within 1 % of v_cr = 205.6 m/s.
#[test]
fn refined_linear_critical_speed() {
    let case = Scenario::default().build().unwrap();
    let speeds: Vec<f64> = (0..=11).map(|i| 150.0 + 10.0 * i as f64).collect();
    let sweep = Runner::new(0).unwrap().speed_sweep(&case, &speeds).unwrap();
    let critical = critical_speed(&case, &sweep, 0.05, &Runner::new(0).unwrap()).unwrap();
    let v_cr = analytic::reference::uic60_on_soft_soil().infinite_beam().unwrap().critical_speed();
    eprintln!(
        "critical speed {:.2} m/s, peak {:.4} m (sweep max at {:?}), {} refinement runs",
        critical.speed,
        critical.max_downward_deflection,
        critical.sweep_maximum,
        critical.evaluations.len()
    );
    assert!((critical.speed - v_cr).abs() < 0.01 * v_cr, "{critical:?}");
    assert!(critical.max_downward_deflection >= critical.sweep_maximum.1);
}

/// Too weak a device does nothing, too strong a device locks the rail into a stiffer system that resonates at a
/// higher speed: at 206 m/s the best F_u for 7 devices lies strictly inside the bounds.
#[test]
fn optimal_device_force_is_interior() {
    let s = Scenario::from_toml("[friction.devices]\ncount = 7\nforce = 1.0", "s").unwrap();
    let best = optimal_device_force(&s, 206.0, (1e3, 1e7), 9, 0.05, &Runner::new(0).unwrap()).unwrap();
    let first = best.explored[0].1;
    let last = best.explored[8].1;
    eprintln!(
        "optimal F_u {:.1} kN: {:.4} m (ends {:.4}, {:.4} m), {} runs",
        best.force / 1e3,
        best.max_downward_deflection,
        first,
        last,
        best.explored.len()
    );
    assert!(best.force > 1e3 && best.force < 1e7);
    assert!(best.max_downward_deflection < first && best.max_downward_deflection < last);
    assert!(best.explored.iter().all(|&(_, w)| w >= best.max_downward_deflection));
}

/// The commented example scenarios shipped in `examples/` are valid.
#[test]
fn example_scenarios_are_valid() {
    let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut count = 0;
    // The examples and those in a folder of their own (a case with its data: examples/ledsgard).
    let files = std::fs::read_dir(&folder).unwrap().map(|e| e.unwrap().path()).flat_map(|path| match path.is_dir() {
        true => std::fs::read_dir(&path).unwrap().map(|e| e.unwrap().path()).collect(),
        false => vec![path],
    });
    for path in files {
        if path.extension().is_some_and(|e| e == "toml") {
            let scenario = Scenario::from_path(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            scenario.validate().unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            assert!(!scenario.title.is_empty(), "{}", path.display());
            count += 1;
        }
    }
    // One per study, the HSLM bridge, the rail cars, and one per further feature (flat, random rail, measured rail,
    // matrices vehicle, vehicle groups, CSV train, axles and patches, a vehicle on ballast friction, a tensionless
    // soil, vehicles through a co-moving window, a Timoshenko rail, a receptance, a track on sleepers, voided
    // sleepers, ballast bodies on the subgrade, a track on a layered ground, Ledsgård's X2000 on its site as a
    // composite beam and as a rail on sleepers over the embankment).
    assert_eq!(count, 26, "one example per study and per feature");
}

fn small_case() -> scenario::Case {
    Scenario::from_toml("[mesh]\nlength = 60.0\nelements = 60\n[friction.devices]\ncount = 7\nforce = 20e3", "s")
        .unwrap()
        .build()
        .unwrap()
}

fn temporary(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("frictrack-study-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A sweep stopped half-way and resumed from its journal gives the same points, bit for bit, as one uninterrupted
/// sweep, and runs only the missing speeds; a line cut short by a kill is dropped.
#[test]
fn journal_resumes_a_stopped_sweep_exactly() {
    use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
    let case = small_case();
    let speeds = [100.0, 130.0, 160.0, 190.0, 220.0, 250.0];
    let whole = Runner::new(1).unwrap().speed_sweep(&case, &speeds).unwrap();

    let path = temporary("journal").join("sweep.journal");
    // A journal left without a finished run (a command refused before its first run) does not block the next one.
    drop(runner::Journal::open(&path, false).unwrap());
    let journal = runner::Journal::open(&path, false).unwrap();
    let stop = AtomicBool::new(false);
    let done = AtomicUsize::new(0);
    let progress = |n: usize| {
        done.store(n, Ordering::Relaxed);
        if n == 3 {
            stop.store(true, Ordering::Relaxed);
        }
    };
    let runner = Runner::new(1).unwrap().with_progress(&progress).with_journal(Some(&journal)).with_stop(&stop);
    assert_eq!(runner.speed_sweep(&case, &speeds), Err(scenario::StudyError::Interrupted));
    drop(journal);
    // Simulate a kill while a line was being written.
    let mut bytes = std::fs::read(&path).unwrap();
    assert_eq!(bytes.iter().filter(|&&b| b == b'\n').count(), 1 + 3, "header + three finished points");
    bytes.extend_from_slice(b"{\"key\":\"cut sh");
    std::fs::write(&path, &bytes).unwrap();

    assert!(runner::Journal::open(&path, false).is_err(), "an existing journal needs --resume");
    let journal = runner::Journal::open(&path, true).unwrap();
    assert_eq!(journal.resumed(), 3);
    let resumed = Runner::new(2).unwrap().with_journal(Some(&journal)).speed_sweep(&case, &speeds).unwrap();
    assert_eq!(resumed, whole, "bit-identical points after resume");
    drop(journal);
    let text = std::fs::read_to_string(&path).unwrap();
    assert_eq!(text.lines().count(), 1 + speeds.len(), "the cut line is gone, each speed once:\n{text}");
    assert!(text.ends_with('\n'));
}

/// A journal of another case does not feed this one: the key holds the case fingerprint.
#[test]
fn journal_keys_hold_the_case_fingerprint() {
    let case = small_case();
    let mut other =
        Scenario::from_toml("[mesh]\nlength = 60.0\nelements = 60\n[friction.devices]\ncount = 7\nforce = 21e3", "s")
            .unwrap();
    assert_ne!(other.fingerprint(), Scenario::default().fingerprint());
    let path = temporary("fingerprint").join("j");
    let journal = runner::Journal::open(&path, false).unwrap();
    let runner = Runner::new(1).unwrap().with_journal(Some(&journal));
    let a = runner.point(&case, 150.0).unwrap();
    let b = runner.point(&other.build().unwrap(), 150.0).unwrap();
    assert_ne!(a, b);
    // Title, speed, recorded sections and sweep range do not change what a point computes.
    other.title = "renamed".into();
    other.load.speed = 17.0;
    other.output.sections = vec![3.0];
    other.sweep = Some(scenario::SweepSection { step: 1.0, ..Default::default() });
    assert_eq!(other.fingerprint(), other.build().unwrap().fingerprint);
    let mut same = other.clone();
    same.title.clear();
    assert_eq!(same.fingerprint(), other.fingerprint());
}

/// On a stiff soil (k_f = 10 MN/m², v_cr ≈ 517 m/s) the discrete-speed study samples around v_cr (25–725 m/s at
/// coarse resolution) and finds every curve's critical speed inside its range, the friction-free one within 10 % of
/// v_cr (a finite pinned beam started from rest peaks near, not at, the infinite beam's v_cr; 3 % on the reference
/// soil). A fixed 10–290 m/s grid used to report 290 m/s, its top, for every curve.
#[test]
fn stiff_soil_discrete_speed_study_finds_interior_critical_speeds() {
    let mut stiff = Scenario::default();
    stiff.foundation.stiffness = 1e7;
    let speeds = study::presets::Resolution::Coarse.speeds(&stiff).unwrap();
    assert_eq!((speeds[0], *speeds.last().unwrap(), speeds.len()), (25.0, 725.0, 15));
    let data = study::presets::run_preset(
        study::presets::Preset::DiscreteSpeed,
        study::presets::Resolution::Coarse,
        &stiff,
        &Runner::new(0).unwrap(),
    )
    .unwrap();
    let summary = data.summary_json();
    let curves = summary["curves"].as_array().unwrap();
    assert_eq!(curves.len(), 13);
    for curve in curves {
        assert_eq!(curve["critical_speed_location"], "interior", "{curve}");
    }
    let v_cr = scenario::speeds::SpeedScale::of(&stiff).unwrap().critical_speed.unwrap();
    let free = curves[0]["critical_speed"].as_f64().unwrap();
    assert!((free - v_cr).abs() < 0.1 * v_cr, "friction-free critical speed {free} vs v_cr {v_cr}");
}

/// A journal borrows another's finished runs (reproduce: the stationary-wave study's finite-beam curves are the
/// distributed-speed study's): a sweep over them runs nothing, gives the same points, and writes nothing to either.
#[test]
fn a_journal_borrows_the_finished_runs_of_another() {
    use std::sync::atomic::AtomicBool;
    let case = small_case();
    let speeds = [100.0, 150.0, 200.0];
    let folder = temporary("borrow");
    let (first, second) = (folder.join("first.journal"), folder.join("second.journal"));
    let journal = runner::Journal::open(&first, false).unwrap();
    let whole = Runner::new(1).unwrap().with_journal(Some(&journal)).speed_sweep(&case, &speeds).unwrap();
    drop(journal);
    let before = std::fs::read(&first).unwrap();
    let mut borrowing = runner::Journal::open(&second, false).unwrap();
    assert_eq!(borrowing.borrow_from(&first).unwrap(), 3);
    assert_eq!(borrowing.borrow_from(&folder.join("absent.journal")).unwrap(), 0);
    // A stop raised before any run: only runs taken from a journal can finish.
    let stop = AtomicBool::new(true);
    let runner = Runner::new(1).unwrap().with_journal(Some(&borrowing)).with_stop(&stop);
    assert_eq!(runner.speed_sweep(&case, &speeds).unwrap(), whole, "every point from the other journal");
    drop(borrowing);
    assert_eq!(std::fs::read(&first).unwrap(), before, "the other journal is only read");
    assert_eq!(std::fs::read_to_string(&second).unwrap().lines().count(), 1, "nothing copied: the header alone");
}
