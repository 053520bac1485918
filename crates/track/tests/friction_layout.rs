//! Friction placed on a beam mesh: devices snapping and merging, distributed capacities (exact), rows that
//! interpolate the deflection.

use analytic::reference::uic60_on_soft_soil;
use fem_beam::{BeamModel, Support, Supports};
use friction::InteractionKind;
use track::{
    BallastOnBeam, DeviceLayout, Devices, DistributedFriction, Quadrature, Refused, SectionKind, Setting, TrackError,
};

fn model(supports: Supports) -> BeamModel {
    let case = uic60_on_soft_soil();
    BeamModel::new(case.beam, case.foundation, case.mesh, supports).unwrap()
}

#[test]
fn devices_snap_to_nearest_node_ties_going_right() {
    let m = model(Supports::default());
    // N = 15 on 1 m elements: x_i = 12.5·i → ties at every odd i go to the larger node.
    let devices = Devices::uniform(15, 50e3);
    let snapped = devices.snapped_positions(&m).unwrap();
    assert_eq!(snapped.len(), 15);
    assert_eq!(snapped[0], 13.0);
    assert_eq!(snapped[1], 25.0);
    assert_eq!(snapped[2], 38.0);
    let set = devices.interactions(&m).unwrap();
    assert_eq!(set.len(), 15);
    assert_eq!(set.interactions().total_capacity(), 15.0 * 50e3);
    assert!(set.interactions().rows().iter().all(|r| r.len() == 1));
    assert!(set.kinds().iter().all(|k| *k == SectionKind::Device));
    assert!(set.interactions().kinds().iter().all(|k| *k == InteractionKind::Friction));
    // 199 devices on 200 elements sit on every interior node.
    let all = Devices::uniform(199, 1e3).interactions(&m).unwrap();
    assert_eq!(all.len(), 199);
    assert_eq!(all.positions()[0], 1.0);
    assert_eq!(all.interactions().total_capacity(), 199.0 * 1e3);
}

#[test]
fn devices_on_one_node_merge_and_too_many_are_rejected() {
    let m = model(Supports::default());
    let devices = Devices { layout: DeviceLayout::Positions(vec![10.2, 9.9, 50.0]), force: 1e3 };
    let set = devices.interactions(&m).unwrap();
    assert_eq!(set.len(), 2);
    assert_eq!([set.interactions().capacity(0), set.interactions().capacity(1)], [2e3, 1e3]);
    assert_eq!(set.positions(), &[10.0, 50.0]);
    let err = Devices::uniform(200, 1e3).interactions(&m).unwrap_err();
    let TrackError::Invalid { setting, value, .. } = &err else { panic!("{err}") };
    assert_eq!((setting, value), (&Setting::Friction("devices.count"), &Refused::Count(200)), "{err}");
    let err = Devices::uniform(3, -1.0).interactions(&m).unwrap_err();
    assert!(err.to_string().contains("devices.force"), "{err}");
    let err = Devices { layout: DeviceLayout::Positions(vec![250.0]), force: 1.0 }.interactions(&m).unwrap_err();
    assert!(err.to_string().contains("position"), "{err}");
}

#[test]
fn distributed_capacity_is_exact() {
    let free = model(Supports::both(Support::Free));
    for quadrature in [Quadrature::Trapezoid, Quadrature::Simpson] {
        for j in [2usize, 4, 6] {
            let fu = 995.0;
            let d = DistributedFriction { force_per_length: fu, subdivisions: j, quadrature };
            let set = d.interactions(&free).unwrap();
            assert_eq!(set.len(), j * 200 + 1);
            // Sums of l/J-type weights: exact up to the round-off of ~800 additions.
            assert!(
                (set.interactions().total_capacity() - fu * 200.0).abs() < 1e-12 * fu * 200.0,
                "{quadrature:?}, J = {j}"
            );
            assert!(set.positions().windows(2).all(|w| w[1] > w[0]));
        }
    }
    // Pinned ends: the two end sections cannot move and are dropped with their bounds.
    let pinned = model(Supports::default());
    let set = DistributedFriction::new(1000.0).interactions(&pinned).unwrap();
    assert_eq!(set.len(), 4 * 200 - 1);
    assert!((set.interactions().dropped_capacity() - 2.0 * 1000.0 * 0.125).abs() < 1e-9);
    assert!((set.interactions().total_capacity() + set.interactions().dropped_capacity() - 200e3).abs() < 1e-7);
}

#[test]
fn distributed_rows_interpolate_the_deflection() {
    let m = model(Supports::default());
    let set = DistributedFriction::new(1.0).interactions(&m).unwrap();
    // A velocity field that is a cubic on the element is reproduced exactly at every section.
    let full: Vec<f64> = (0..m.dofs().full_len())
        .map(|d| {
            let x = m.mesh().node_x(d / 2);
            if d % 2 == 0 { (0.05 * x).sin() } else { 0.05 * (0.05 * x).cos() }
        })
        .collect();
    let free = m.dofs().reduce(&full);
    let full = m.dofs().expand(&free); // constrained DOFs (pinned w at the ends) are zero
    let mut u = vec![0.0; set.len()];
    set.interactions().velocities(&free, &mut u);
    for (j, &x) in set.positions().iter().enumerate() {
        let w = m.deflection_at(&full, x).unwrap();
        assert!((u[j] - w).abs() < 1e-14, "section {j} at {x}");
    }
}

#[test]
fn simpson_needs_even_subdivisions() {
    let m = model(Supports::default());
    let d = DistributedFriction { force_per_length: 1.0, subdivisions: 3, quadrature: Quadrature::Simpson };
    let err = d.interactions(&m).unwrap_err();
    assert!(err.to_string().contains("distributed.subdivisions"), "{err}");
    assert!(DistributedFriction { force_per_length: f64::NAN, ..Default::default() }.validate().is_err());
}
