//! Two independent methods for the wave on a nonlinear soil: the stationary solve in moving coordinates
//! (`stationary`) and a run of the load across a long finite track in time through the interaction engine (`track`,
//! with absorbing zones), read in its middle third when the load is at the middle (docs/theory.md §13, §14).

use scenario::Scenario;
use stationary::Domain;
use track::Simulation;

/// The finite track's deflection at the nodes (x, w) when the load is at `at` (m), and the stationary wave there.
fn both(toml: &str, speed: f64, at: f64) -> (Vec<(f64, f64)>, stationary::StationaryWave) {
    let snapshot = finite(toml, speed, at);
    let scenario = Scenario::from_toml(toml, "case.toml").unwrap();
    let problem = scenario.stationary_problem(speed, Domain::default()).unwrap();
    (snapshot, stationary::solve(&problem).unwrap())
}

/// The finite track's deflection at the nodes (x, w) when the load is at `at` (m).
fn finite(toml: &str, speed: f64, at: f64) -> Vec<(f64, f64)> {
    let scenario = Scenario::from_toml(toml, "case.toml").unwrap();
    let case = scenario.build().unwrap();
    let mut settings = case.settings.clone();
    settings.moving.speed = speed;
    let simulation = Simulation::new(&case.model, &case.interactions, &settings).unwrap();
    let mut snapshot = Vec::new();
    let model = &case.model;
    simulation
        .run_observed(&mut |view| {
            if (view.load_position - at).abs() < 1e-6 {
                let full = model.dofs().expand(view.displacement);
                snapshot = (0..model.mesh().nodes()).map(|i| (model.mesh().node_x(i), full[2 * i])).collect();
                return false;
            }
            true
        })
        .unwrap();
    assert!(!snapshot.is_empty(), "the load never stood at {at} m");
    snapshot
}

/// max |w_finite − W| over ±30 m around the load at `at` (m), relative to the wave's peak.
fn disagreement(toml: &str, speed: f64, at: f64) -> f64 {
    let (finite, wave) = both(toml, speed, at);
    assert!(wave.convergence.is_converged(), "{:?}", wave.convergence);
    assert!(!wave.lift_off.is_empty(), "the rail must leave the soil for this to test anything");
    let peak = wave.max_downward().value;
    let mut worst: f64 = 0.0;
    for (x, w) in finite.iter().filter(|(x, _)| (x - at).abs() <= 30.0) {
        let i = wave.s.iter().position(|t| (t - (x - at)).abs() < 1e-9).expect("a node of the moving domain");
        worst = worst.max((w - wave.deflection[i]).abs());
    }
    worst / peak
}

/// A 200 m track of 0.25 m elements with absorbing zones of 40 m, the load starting static at 30 m: what it carries
/// around the load approaches the stationary wave as the start's transient dies away. Measured (bilinear α = ½ at
/// 140 m/s, ζ = 0.1): 1.9e-2 of the peak at 80 m, 9.5e-3 at 100 m, 4.1e-3 at 120 m, 1.8e-3 at 140 m, the same
/// with half the step (the time step's share is below 1e-4); tensionless at 80 m/s: 5e-4 at 100 m.
#[test]
fn the_stationary_wave_is_what_a_long_track_carries_around_the_load() {
    let toml = |law: &str| {
        format!(
            "[mesh]\nelements = 800\n[foundation]\ndamping_ratio = 0.1\n{law}\n[foundation.absorbing_zones]\n\
             length = 40.0\npeak_ratio = 1.0\n[integration]\nstatic_start = 30.0\n"
        )
    };
    let bilinear = toml("law = \"bilinear\"\ntension_ratio = 0.5");
    let (early, late) = (disagreement(&bilinear, 140.0, 100.0), disagreement(&bilinear, 140.0, 140.0));
    assert!(late <= 3e-3 && late < early / 3.0, "bilinear: {early:e} at 100 m, {late:e} at 140 m");
    let tensionless = disagreement(&toml("law = \"tensionless\""), 80.0, 100.0);
    assert!(tensionless <= 1e-3, "tensionless: {tensionless:e}");
}

/// On a tensionless soil a co-moving window (time stepping through the interaction engine, docs/theory.md §15) and
/// the stationary solve in moving coordinates (a Newton iteration on the stationary equation, §14) — two independent
/// methods — give the same wave around the load after 600 m: measured 1.2e-5 of the peak (bound 1e-4: the window's
/// soil is settled against its clamped front and its absorbing zones damp more than c_f, both far from the load).
#[test]
fn a_co_moving_window_carries_the_stationary_wave_of_a_tensionless_soil() {
    use analytic::reference::uic60_on_soft_soil;
    use fem_beam::{AbsorbingZones, BeamModel, Foundation, FoundationLaw, Mesh, Support, Supports};
    use track::co_moving::{CoMovingSettings, run_co_moving};
    let case = uic60_on_soft_soil();
    let foundation =
        Foundation { law: FoundationLaw::Tensionless, ..case.foundation.with_damping_ratio(0.05, &case.beam).unwrap() };
    let mesh = Mesh::new(120.0, 480).unwrap();
    let zones = AbsorbingZones { length: 30.0, peak_damping: foundation.critical_damping(&case.beam) };
    let damping = zones.element_damping(&mesh, foundation.damping).unwrap();
    let supports = Supports { left: Support::Free, right: Support::Clamped };
    let model = BeamModel::with_element_damping(case.beam, foundation, mesh, supports, damping).unwrap();
    let soil = track::FoundationSections::default().interactions(&model).unwrap();
    let mut settings = track::RunSettings::default();
    settings.moving.speed = 80.0;
    settings.integration.load_advance = 0.05;
    let window = CoMovingSettings { load_at: 60.0, track_length: 600.0, middle: (30.0, 90.0) };
    let run = run_co_moving(&model, &soil, &settings, &window).unwrap();
    let problem = stationary::StationaryProblem {
        beam: case.beam,
        foundation,
        load: 83.4e3,
        speed: 80.0,
        self_weight: true,
        friction: fem_beam::DistributedFriction::default(),
        domain: Domain::default(),
    };
    let wave = stationary::solve(&problem).unwrap();
    assert!(wave.convergence.is_converged() && !wave.lift_off.is_empty());
    let peak = wave.max_downward().value;
    let mut worst: f64 = 0.0;
    for (s, w) in run.wave.iter().filter(|(s, _)| s.abs() <= 30.0) {
        let i = wave.s.iter().position(|t| (t - s).abs() < 1e-6).expect("the same nodes");
        worst = worst.max((w - wave.deflection[i]).abs());
    }
    assert!(worst <= 1e-4 * peak, "{:e} of the peak", worst / peak);
    let e = &run.energy;
    assert!(e.residual().abs() <= 1e-9 * e.load_work, "{:e} of {:e}", e.residual(), e.load_work);
}

/// Friction in the ballast (2 kN/m, 100 m/s, ζ = 5 %) on the infinite track, three ways: a co-moving window over 600 m
/// of track and a 200 m finite track with absorbing zones read ±20 m around the load at 140 m, both through the
/// interaction engine but on different domains (one shifting with a clamped front, one fixed with pinned ends),
/// and the stationary solve in moving coordinates (a Newton iteration on the play operator, no time stepping).
/// Measured: window vs finite track 6.6e-4 of the peak (bound 2e-3: the finite track's start transient after
/// 110 m, 1.8e-3 in the bilinear case above); window vs stationary 2.05e-3 at Δx = 0.05 m and 1.06e-3 at 0.0125 m
/// (the time stepping's error of stick–slip, first order: halved by a quarter step; behind the load −3.13 → −3.19
/// mm against the stationary −3.23 mm), asserted as ≤ 3e-3 and a fall by 0.6 at least.
#[test]
fn friction_on_a_co_moving_window_and_on_a_long_track() {
    let toml = "[mesh]\nelements = 800\n[load]\nspeed = 100.0\n[foundation]\ndamping_ratio = 0.05\n[friction.distributed]\n\
                force_per_length = 2000.0\n[foundation.absorbing_zones]\nlength = 40.0\npeak_ratio = 1.0\n\
                [integration]\nstatic_start = 30.0\nload_advance = 0.05\n[co_moving]\nwindow = 120.0\n\
                track_length = 600.0\nzones = 30.0\n";
    let scenario = Scenario::from_toml(toml, "case.toml").unwrap();
    let finite =
        finite(&toml.replace("[co_moving]\nwindow = 120.0\ntrack_length = 600.0\nzones = 30.0\n", ""), 100.0, 140.0);
    let section = scenario.co_moving.clone().unwrap();
    let (_, run) = study::co_moving::output::run(&scenario, &section).unwrap();
    let peak = run.wave.iter().fold(0.0f64, |m, (_, w)| m.max(w.abs()));
    let mut worst: f64 = 0.0;
    for (x, w) in finite.iter().filter(|(x, _)| (x - 140.0).abs() <= 20.0) {
        let s = x - 140.0;
        let (_, v) = run.wave.iter().min_by(|a, b| (a.0 - s).abs().total_cmp(&(b.0 - s).abs())).unwrap();
        worst = worst.max((w - v).abs());
    }
    assert!(worst <= 2e-3 * peak, "{:e} of the peak", worst / peak);
    // The third method: the stationary solve, which the window approaches as its step falls.
    let problem = scenario.stationary_problem(100.0, Domain::default()).unwrap();
    let wave = stationary::solve(&problem).unwrap();
    assert!(wave.convergence.is_converged(), "{:?}", wave.convergence);
    let apart = |run: &track::co_moving::CoMovingResult| {
        let mut worst: f64 = 0.0;
        for (s, w) in run.wave.iter().filter(|(s, _)| s.abs() <= 40.0) {
            let i = wave.s.iter().position(|t| (t - s).abs() < 1e-6).expect("the same nodes");
            worst = worst.max((w - wave.deflection[i]).abs());
        }
        worst / wave.max_downward().value
    };
    let fine = Scenario::from_toml(&toml.replace("load_advance = 0.05", "load_advance = 0.0125"), "case.toml").unwrap();
    let (_, fine_run) = study::co_moving::output::run(&fine, &section).unwrap();
    let (coarse, fine) = (apart(&run), apart(&fine_run));
    assert!(coarse <= 3e-3 && fine <= 0.6 * coarse, "stationary vs co-moving: {coarse:e} (Δx 0.05), {fine:e} (0.0125)");
    assert!(run.energy.friction_work < 0.0 && run.energy.residual().abs() <= 1e-9 * run.energy.load_work);
}

/// A quarter car over a 3 mm dipped joint at 60 m/s (ζ = 5 %), two ways: riding a co-moving window (its wheel's row
/// moving back an element in the window at every shift while the rail's profile is read where the wheel is on the
/// track) and crossing a 400 m finite track with absorbing zones. The wheel meets the dip 80 m after its static start
/// in both. Measured: the wheel forces ±20 m around the dip agree to 4.9e-3 of the static load Q₀ (bound 1e-2), the
/// extremes 54.9/112.1 kN in both. What differs is the impact's high-frequency waves (~1 km/s at the contact's
/// 160 Hz) coming back from the domains' ends a few metres of travel later: 5.8e-2 with a 120 m window and a 200 m
/// track, 1.75e-2 with a 240 m window, 4.9e-3 with the track doubled too (before the dip, 2.4e-3 with the 120 m
/// window: its wave still settling from the static start).
/// The window's energy identity closes at round-off with the vehicle's contact work in it.
#[test]
fn a_vehicle_rides_a_co_moving_window_over_an_irregular_rail() {
    let common = "[mesh]\nelements = 800\n[foundation]\ndamping_ratio = 0.05\n[load]\nspeed = 60.0\n[vehicle]\n\
                  kind = \"quarter-car\"\n[integration]\nload_advance = 0.05\n";
    let dip = |x: f64| {
        format!("[[rail.irregularities]]\nkind = \"dipped-joint\"\nposition = {x}\ndepth = 3e-3\nlength = 1.0\n")
    };
    // The window: the wheel starts 60 m into it, so the dip 80 m ahead is at 140 m of track.
    let window = format!("{common}{}[co_moving]\nwindow = 240.0\ntrack_length = 110.0\nzones = 80.0\n", dip(200.0));
    let scenario = Scenario::from_toml(&window, "window.toml").unwrap();
    let (summary, run) = study::co_moving::output::run(&scenario, scenario.co_moving.as_ref().unwrap()).unwrap();
    let riding = &run.vehicles.as_ref().expect("the vehicle's results").wheels[0];
    assert!(run.energy.residual().abs() <= 1e-9 * run.energy.viscous_dissipation, "{:e}", run.energy.residual());
    // The finite track: a static start at 30 m, the dip at 110 m.
    let finite = format!("{common}{}[foundation.absorbing_zones]\nlength = 80.0\n", dip(180.0))
        .replace("[mesh]\nelements = 800\n", "[mesh]\nlength = 400.0\nelements = 1600\n")
        .replace("load_advance = 0.05\n", "load_advance = 0.05\nstatic_start = 100.0\n");
    let case = Scenario::from_toml(&finite, "finite.toml").unwrap().build().unwrap();
    let result = Simulation::new(&case.model, &case.interactions, &case.settings).unwrap().run().unwrap();
    let crossing = &result.vehicles.as_ref().expect("the vehicle's results").wheels[0];
    let around = |w: &track::simulation::WheelResult, dip: f64| -> Vec<(i64, f64)> {
        let h = &w.history;
        h.position
            .iter()
            .zip(&h.force)
            .filter(|(x, _)| (*x - dip).abs() <= 20.0)
            .map(|(x, f)| (((x - dip) / 0.05).round() as i64, *f))
            .collect()
    };
    let (a, b) = (around(riding, 200.0), around(crossing, 180.0));
    assert!(a.len() > 700 && a.len() == b.len(), "{} and {} steps around the dip", a.len(), b.len());
    let q0 = riding.static_force;
    let worst = a.iter().zip(&b).map(|((i, f), (j, g))| {
        assert_eq!(i, j, "the same places");
        (f - g).abs()
    });
    let worst = worst.fold(0.0f64, f64::max) / q0;
    eprintln!(
        "window vs finite track: {worst:e} of Q0; extremes {:?} vs {:?}",
        (riding.min_force, riding.max_force),
        (crossing.min_force, crossing.max_force)
    );
    assert!(worst <= 1e-2, "{worst:e} of Q₀");
    assert!(summary.vehicles.as_ref().is_some_and(|v| v.max_wheel_force > 1.3 * q0), "the dip loads the wheel");
}

/// The same two methods for a Timoshenko rail (κ = 0.4, G = 81 GPa) on the tensionless soil at 80 m/s: the long
/// track's Timoshenko elements in time against the stationary solve with its moving-frame Timoshenko operator and
/// transparent ends (docs/theory.md §16). Measured 5.0e-4 of the peak at 100 m, as for Euler–Bernoulli (5e-4): the start's transient, not the rail.
#[test]
fn a_timoshenko_rail_carries_its_stationary_wave_too() {
    let toml = "[mesh]\nelements = 800\n[beam]\ntheory = \"timoshenko\"\nshear_modulus = 81e9\nshear_coefficient = 0.4\n\
                [foundation]\ndamping_ratio = 0.1\nlaw = \"tensionless\"\n[foundation.absorbing_zones]\nlength = 40.0\n\
                peak_ratio = 1.0\n[integration]\nstatic_start = 30.0\n";
    let difference = disagreement(toml, 80.0, 100.0);
    assert!(difference <= 1e-3, "{difference:e}");
}
