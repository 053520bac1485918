//! Load vectors and element matrices: totals, symmetry, definiteness, no double counting.

use analytic::reference::uic60_on_soft_soil;
use fem_beam::element::hermite;
use fem_beam::{Beam, BeamModel, Discretisation, Foundation, LoadVector, Mesh, Support, Supports};

#[test]
fn uniform_load_sums_to_total() {
    let mesh = Mesh::new(200.0, 200).unwrap();
    let q = -Beam::default().mass_per_length() * fem_beam::GRAVITY;
    let load = LoadVector::uniform(&mesh, q).unwrap();
    let total: f64 = load.to_full(&mesh).iter().step_by(2).sum();
    assert!((total - q * 200.0).abs() < 1e-12 * (q * 200.0).abs());
    assert!((load.total_force() - q * 200.0).abs() < 1e-12 * (q * 200.0).abs());
    // Interior nodal moments cancel; only the end ones remain (±q l²/12).
    let full = load.to_full(&mesh);
    assert!(full[101].abs() < 1e-9);
    assert!((full[1] - q / 12.0).abs() < 1e-12 * q.abs());
}

#[test]
fn point_load_on_a_node_is_counted_once() {
    let mesh = Mesh::new(200.0, 200).unwrap();
    let beam = Discretisation::euler_bernoulli(mesh);
    for x in [0.0, 50.0, 100.0, 200.0, 100.3] {
        let load = LoadVector::point_force(&beam, x, -83.4e3).unwrap();
        assert_eq!(load.contributions().len(), 1);
        assert!((load.total_force() + 83.4e3).abs() < 1e-9, "x = {x}");
        let full = load.to_full(&mesh);
        let total: f64 = full.iter().step_by(2).sum();
        assert!((total + 83.4e3).abs() < 1e-9);
        // Static equivalence: the nodal set has the moment of the point load about x = 0.
        let moment: f64 = (0..mesh.nodes()).map(|i| full[2 * i] * mesh.node_x(i) + full[2 * i + 1]).sum();
        assert!((moment + 83.4e3 * x).abs() < 1e-6 * 83.4e3 * 200.0);
    }
    let on_node = LoadVector::point_force(&beam, 100.0, 1.0).unwrap().to_full(&mesh);
    assert_eq!(on_node[200], 1.0);
    assert_eq!(on_node.iter().filter(|v| **v != 0.0).count(), 1);
}

#[test]
fn point_moment_is_a_pure_couple() {
    let mesh = Mesh::new(10.0, 10).unwrap();
    let beam = Discretisation::euler_bernoulli(mesh);
    let mut load = LoadVector::new();
    load.add_point_moment(&beam, 3.7, 250.0).unwrap();
    let full = load.to_full(&mesh);
    let force: f64 = full.iter().step_by(2).sum();
    let moment: f64 = (0..mesh.nodes()).map(|i| full[2 * i] * mesh.node_x(i) + full[2 * i + 1]).sum();
    assert!(force.abs() < 1e-12);
    assert!((moment - 250.0).abs() < 1e-10);
}

#[test]
fn element_matrices_are_symmetric_and_rigid_modes_are_free() {
    let l = 0.73;
    for m in [hermite::consistent_mass(59.9, l), hermite::bending_stiffness(6.4e6, l)] {
        for i in 0..4 {
            for j in 0..4 {
                assert!((m[i][j] - m[j][i]).abs() <= 1e-15 * m[i][i].abs().max(m[j][j].abs()));
            }
        }
    }
    // Rigid translation and rotation cost no bending energy; the mass-pattern integrates ∫N = l.
    let kb = hermite::bending_stiffness(6.4e6, l);
    for mode in [[1.0, 0.0, 1.0, 0.0], [0.0, 1.0, l, 1.0]] {
        let f = hermite::apply(&kb, &mode);
        assert!(f.iter().all(|v| v.abs() < 1e-6));
    }
    let me = hermite::consistent_mass(1.0, l);
    let translation = hermite::apply(&me, &[1.0, 0.0, 1.0, 0.0]);
    assert!((translation[0] + translation[2] - l).abs() < 1e-14);
}

#[test]
fn assembled_matrices_are_positive_definite_for_every_support() {
    let case = uic60_on_soft_soil();
    let mesh = Mesh::new(30.0, 30).unwrap();
    let supports = [Support::Pinned, Support::Clamped, Support::Free];
    for left in supports {
        for right in supports {
            let s = Supports { left, right };
            let model = BeamModel::new(case.beam, case.foundation, mesh, s).unwrap();
            let dense_m = model.mass().to_dense();
            let dense_k = model.stiffness().to_dense();
            assert_eq!(dense_m, dense_m.transpose());
            assert_eq!(dense_k, dense_k.transpose());
            let mass = model.mass().factor().unwrap();
            let stiffness = model.stiffness().factor().unwrap();
            assert!(mass.pivots().all(|d| d > 0.0) && stiffness.pivots().all(|d| d > 0.0), "{s:?}");
            assert!(dense_m.cholesky().is_some() && dense_k.cholesky().is_some());
            let removed = [left, right].into_iter().map(|s| match s {
                Support::Pinned => 1,
                Support::Clamped => 2,
                Support::Free => 0,
            });
            assert_eq!(model.dofs().free_len(), 2 * mesh.nodes() - removed.sum::<usize>());
        }
    }
    // Without foundation, a free–free K is singular: the factorisation reports it.
    let bare = BeamModel::new(case.beam, Foundation::linear(0.0, 0.0), mesh, Supports::both(Support::Free)).unwrap();
    assert!(bare.stiffness().factor().is_err());
}

/// A uniform patch over whole elements gives the standard consistent loads; over partial elements it is the limit
/// of n equal point loads q·ℓ/n at the midpoints of n equal parts (the composite midpoint rule on the piecewise
/// cubic Ψ: error O(1/n²), so each doubling of n divides it by about 4); its total is q·ℓ for the part on the beam.
#[test]
fn patch_loads_are_the_limit_of_point_loads() {
    let mesh = Mesh::new(20.0, 20).unwrap();
    let beam = Discretisation::euler_bernoulli(mesh);
    let q = -2.5e4;
    let mut whole = LoadVector::new();
    whole.add_patch(&beam, 4.0, 6.0, q).unwrap();
    assert_eq!(whole.contributions().len(), 2);
    for c in whole.contributions() {
        for (a, b) in c.nodal.iter().zip(hermite::uniform_load(q, 1.0)) {
            assert!((a - b).abs() <= 1e-12 * q.abs(), "{a} vs {b}");
        }
    }
    let (a, b) = (3.3, 7.85);
    let mut patch = LoadVector::new();
    patch.add_patch(&beam, a, b, q).unwrap();
    let exact = patch.to_full(&mesh);
    assert!((patch.total_force() - q * (b - a)).abs() <= 1e-12 * (q * (b - a)).abs());
    let mut errors = Vec::new();
    for n in [10, 20, 40, 80] {
        let mut points = LoadVector::new();
        let width = (b - a) / n as f64;
        for i in 0..n {
            points.add_point_force(&beam, a + (i as f64 + 0.5) * width, q * width).unwrap();
        }
        let approx = points.to_full(&mesh);
        let scale = exact.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        errors.push(exact.iter().zip(&approx).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / scale);
    }
    for pair in errors.windows(2) {
        assert!(pair[1] <= pair[0] / 3.5, "not second order: {errors:?}");
    }
    // Off the beam: only the covered part counts.
    let mut hanging = LoadVector::new();
    hanging.add_patch(&beam, 18.5, 25.0, q).unwrap();
    assert!((hanging.total_force() - q * 1.5).abs() <= 1e-12 * (q * 1.5).abs());
    let mut missing = LoadVector::new();
    missing.add_patch(&beam, 21.0, 25.0, q).unwrap();
    assert!(missing.contributions().is_empty());
}
