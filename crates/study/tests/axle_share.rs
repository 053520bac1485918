//! What the beam carries of a train's axles (`[load] carries`): one rail's half on a foundation or on sleepers,
//! whole axles on a span, as given otherwise; the single load is the beam's own.

use scenario::AxleShare;
use scenario::Scenario;

fn scenario(toml: &str) -> Scenario {
    Scenario::from_toml(toml, "test.toml").unwrap()
}

/// The forces of the run's train (N), first axle and total.
fn train_forces(s: &Scenario) -> (f64, f64) {
    let settings = s.run_settings(100.0).unwrap();
    let train = settings.moving.load.axles().cloned().expect("a train");
    (train.axles[0].force, train.total_force())
}

#[test]
fn a_rail_carries_half_of_each_axle_and_a_deck_all_of_it() {
    // HSLM-A1: 50 axles of 170 kN, 8 500 kN in all.
    let track = scenario("[load]\ntrain = \"hslm-a1\"\n");
    assert_eq!(track.axle_share(), AxleShare::OneRail);
    assert_eq!(train_forces(&track), (85e3, 4250e3));
    let deck = scenario("[load]\ntrain = \"hslm-a1\"\n[foundation]\nstiffness = 0.0\n");
    assert_eq!(deck.axle_share(), AxleShare::WholeAxle);
    assert_eq!(train_forces(&deck), (170e3, 8500e3));
    // A rail on sleepers (no soil) is a track too: one rail's half (it put whole axles on the rail before).
    let sleepers = scenario(
        "[load]\ntrain = \"hslm-a1\"\n[foundation]\nstiffness = 0.0\n[mesh]\nlength = 199.8\nelements = 1332\n[sleepers]\n",
    );
    assert_eq!(sleepers.axle_share(), AxleShare::OneRail);
    assert_eq!(train_forces(&sleepers), (85e3, 4250e3));
    let whole = scenario("[load]\ntrain = \"hslm-a1\"\ncarries = \"whole-axle\"\n");
    assert_eq!(train_forces(&whole), (170e3, 8500e3));
    let half_deck = scenario("[load]\ntrain = \"hslm-a1\"\ncarries = \"one-rail\"\n[foundation]\nstiffness = 0.0\n");
    assert_eq!(train_forces(&half_deck), (85e3, 4250e3));
    // Axles given one by one are axle loads too.
    let axles =
        scenario("[load]\n[[load.axles]]\noffset = 0.0\nforce = 200e3\n[[load.axles]]\noffset = 3.0\nforce = 200e3\n");
    assert_eq!(train_forces(&axles), (100e3, 200e3));
    // The catalogue's `single` is the single load, the beam's own force: never scaled.
    let single = scenario("[load]\ntrain = \"single\"\nforce = 83.4e3\n");
    assert_eq!(train_forces(&single), (83.4e3, 83.4e3));
    // A bad value names the key and what is allowed.
    let bad = Scenario::from_toml("[load]\ncarries = \"both-rails\"\n", "bad.toml").unwrap_err().to_string();
    assert!(bad.contains("carries") && bad.contains("one-rail") && bad.contains("whole-axle"), "{bad}");
}

#[test]
fn catalogue_names_are_taken_in_any_case() {
    let upper = scenario("[load]\ntrain = \"HSLM-A3\"\n[foundation]\nstiffness = 0.0\n");
    let settings = upper.run_settings(100.0).unwrap();
    assert_eq!(settings.moving.load.axles().unwrap().name, "hslm-a3");
}
