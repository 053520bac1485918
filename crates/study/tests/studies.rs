//! Scenarios and studies.

use study::StudyError;
use study::scenario::{Scenario, TEMPLATE};
use study::sweep::{critical_speed, optimal_device_force, speed_sweep, write_csv};

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
    assert!(case.contacts.is_empty());
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
    assert_eq!(case.contacts.len(), 31 + 799);
    assert!((case.model.foundation().damping_ratio(case.model.beam()) - 0.05).abs() < 1e-12);
    assert_eq!(case.settings.speed, 150.0);
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
        ("[friction.devices]\ncount = 500\nforce = 1.0", "devices.count"),
        ("[friction.devices]\npositions = [300.0]\nforce = 1.0", "friction.devices.positions"),
        (
            "[friction.distributed]\nforce_per_length = 1.0\nsubdivisions = 3\nquadrature = \"simpson\"",
            "distributed.subdivisions",
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
        let points = speed_sweep(&case, &speeds, jobs, &|_| {}).unwrap();
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
    let sweep = speed_sweep(&case, &speeds, 0, &|_| {}).unwrap();
    let critical = critical_speed(&case, &sweep, 0.05).unwrap();
    let v_cr = fem_beam::reference::uic60_on_soft_soil().infinite_beam().unwrap().critical_speed();
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
    let best = optimal_device_force(&s, 206.0, (1e3, 1e7), 9, 0.05).unwrap();
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
    for entry in std::fs::read_dir(&folder).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let scenario = Scenario::from_path(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            scenario.build().unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            assert!(!scenario.title.is_empty(), "{}", path.display());
            count += 1;
        }
    }
    assert_eq!(count, 6, "one example per study");
}
