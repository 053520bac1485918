//! Trains on the track (docs/theory.md §10): without friction a train's run is the sum of time-shifted single-axle
//! runs; the energy identity closes with many axles, with and without friction; the steady-state start of a train
//! superposes its axles'.

use super::common::beam;
use fem_beam::{Axle, Train};
use track::Devices;
use track::Load;
use track::PlacedInteractions;
use track::{RunSettings, Simulation};

fn train(offsets: &[f64], forces: &[f64]) -> Train {
    let axles = offsets.iter().zip(forces).map(|(&offset, &force)| Axle { offset, force }).collect();
    Train { name: "test".into(), axles, patches: Vec::new() }
}

/// Linear superposition in time: each axle is the unit single-axle run scaled by P_i and delayed by d_i/v (a whole
/// number of steps: offsets are multiples of the load advance). Deflection, velocity, acceleration and moment
/// histories at three sections and the final state agree to 1e-10 of their scale (round-off: the accumulated times
/// of the two runs differ in their last bits).
#[test]
fn a_train_is_the_sum_of_time_shifted_single_axle_runs() {
    let model = beam(60.0, 60);
    let none = PlacedInteractions::new();
    for (offsets, forces) in [
        (vec![0.0, 2.5], vec![170e3, 120e3]),
        (vec![0.0, 3.0, 14.0, 17.0, 20.5], vec![170e3, 170e3, 200e3, 200e3, 90e3]),
    ] {
        let train = train(&offsets, &forces);
        let mut settings = RunSettings::default();
        settings.moving.speed = 120.0;
        settings.record.sections = vec![15.0, 30.0, 44.0];
        let mut single = settings.clone();
        settings.moving.load = Load::Train(train.clone());
        let whole = Simulation::new(&model, &none, &settings).unwrap().run().unwrap();
        // The unit axle, run as long as the train's crossing.
        single.moving.load = Load::Force(1.0);
        single.integration.end_time = Some(settings.crossing_time(60.0));
        let unit = Simulation::new(&model, &none, &single).unwrap().run().unwrap();
        let shifts: Vec<usize> =
            offsets.iter().map(|d| (d / settings.integration.load_advance).round() as usize).collect();
        for (history, reference) in whole.histories.iter().zip(&unit.histories) {
            let n = history.deflection.len();
            assert!(n > 500, "histories over the whole crossing: {n} samples");
            assert!(reference.deflection.len() >= n, "the unit run covers the train's");
            for (series, unit_series) in [
                (&history.deflection, &reference.deflection),
                (&history.velocity, &reference.velocity),
                (&history.acceleration, &reference.acceleration),
                (&history.moment, &reference.moment),
            ] {
                let sum = |k: usize| -> f64 {
                    shifts.iter().zip(&forces).filter(|(s, _)| k >= **s).map(|(s, f)| f * unit_series[k - s]).sum()
                };
                let scale = series.iter().fold(0.0f64, |m, x| m.max(x.abs()));
                for k in 0..n {
                    assert!(
                        (series[k] - sum(k)).abs() <= 1e-10 * scale,
                        "{} axles, section {} step {k}: {} vs {}",
                        offsets.len(),
                        history.position,
                        series[k],
                        sum(k)
                    );
                }
            }
        }
        assert_eq!(whole.histories.len(), 3);
        assert!(whole.deflection.max_downward.value > 0.0);
    }
}

/// The discrete energy identity closes to round-off with all 50 axles of HSLM-A1 crossing, without friction and with
/// 31 devices (the load's work summed over every axle on the beam).
#[test]
fn energy_closes_with_many_axles() {
    let model = beam(60.0, 60);
    let train = Train::hslm_a(1);
    for interactions in [PlacedInteractions::new(), Devices::uniform(31, 50e3).interactions(&model).unwrap()] {
        let mut settings = RunSettings::default();
        settings.moving.speed = 150.0;
        settings.integration.load_advance = 0.2;
        settings.moving.load = Load::Train(train.clone());
        let r = Simulation::new(&model, &interactions, &settings).unwrap().run().unwrap();
        let e = r.energy;
        // The whole train crosses: (60 + 397.525) m at 0.2 m per step.
        assert_eq!(r.statistics.steps, ((60.0 + train.length()) / 0.2_f64).round() as usize);
        assert!(e.load_work > 0.0);
        assert!(e.residual().abs() <= 1e-9 * e.load_work, "residual {:e} of {:e}", e.residual(), e.load_work);
        if !interactions.is_empty() {
            assert!(e.friction_work < 0.0);
        }
    }
}

/// Extremes over a range of nodes: a train longer than the beam leaves its largest deflection next to a support,
/// where its axles leave; over the middle third the extremes sit inside it, are no larger than the whole beam's,
/// and the static envelope over the same nodes gives a consistent amplification. A range holding every node gives
/// the whole-beam results bit for bit (the same pass, every node counted); a range without a free node is refused.
#[test]
fn extremes_over_a_range_of_nodes() {
    let model = beam(60.0, 60);
    let none = PlacedInteractions::new();
    let train = train(&[0.0, 3.0, 14.0, 17.0, 40.0, 43.0, 54.0, 57.0, 80.0, 83.0], &[170e3; 10]);
    let mut settings = RunSettings::default();
    settings.moving.speed = 100.0;
    settings.moving.load = Load::Train(train.clone());
    let whole = Simulation::new(&model, &none, &settings).unwrap().run().unwrap();
    settings.record.extremes_nodes = Some((0.0, 60.0));
    let all = Simulation::new(&model, &none, &settings).unwrap().run().unwrap();
    assert_eq!(all.deflection.max_downward, whole.deflection.max_downward);
    assert_eq!(all.max_acceleration, whole.max_acceleration);
    settings.record.extremes_nodes = Some((20.0, 40.0));
    let middle = Simulation::new(&model, &none, &settings).unwrap().run().unwrap();
    for e in [middle.deflection.max_downward, middle.deflection.max_upward, middle.max_acceleration.unwrap()] {
        assert!(e.position.is_some_and(|x| (20.0..=40.0).contains(&x)), "{e:?}");
    }
    assert!(middle.deflection.max_downward.value <= whole.deflection.max_downward.value);
    assert!(middle.max_acceleration.unwrap().value <= whole.max_acceleration.unwrap().value);
    assert_eq!(middle.global_norm, whole.global_norm, "W̄ stays a whole-beam norm");
    let statics =
        track::statics::static_envelope(&model, &track::PlacedInteractions::new(), &train, 0.1, Some((20.0, 40.0)))
            .unwrap();
    assert!((20.0..=40.0).contains(&statics.position));
    let daf = middle.deflection.max_downward.value / statics.max_downward;
    assert!(daf > 1.0 && daf < 1.5, "amplification {daf} at 100 m/s, well below v_cr = 206 m/s");
    settings.record.extremes_nodes = Some((20.2, 20.8));
    assert!(Simulation::new(&model, &none, &settings).is_err(), "no node between 20.2 and 20.8 m");
}
