//! The linear critical speed of the finite reference beam.

use super::common::reference;
use track::PlacedInteractions;
use track::{RunSettings, Simulation};

#[test]
fn largest_deflection_is_near_the_critical_speed() {
    let model = reference();
    let interactions = PlacedInteractions::new();
    let v_cr = analytic::reference::uic60_on_soft_soil().infinite_beam().unwrap().critical_speed();
    let sweep: Vec<(f64, f64)> = (0..=22)
        .map(|i| {
            let speed = 150.0 + 5.0 * i as f64;
            let settings = {
                let mut s = RunSettings::default();
                s.moving.speed = speed;
                s
            };
            (
                speed,
                Simulation::new(&model, &interactions, &settings).unwrap().run().unwrap().deflection.max_downward.value,
            )
        })
        .collect();
    let (v_peak, w_peak) = sweep.iter().copied().fold((0.0, 0.0), |best, p| if p.1 > best.1 { p } else { best });
    eprintln!("linear sweep peak {w_peak:.4} m at {v_peak} m/s (v_cr = {v_cr:.2})");
    assert!((v_peak - v_cr).abs() <= 0.03 * v_cr, "peak at {v_peak} m/s");
    // Far below and above the peak the response is much smaller.
    assert!(sweep[0].1 < 0.5 * w_peak && sweep[22].1 < w_peak);
}
