//! The law's projection and residual, and the sparse rows the laws act on.

use friction::InteractionRow;
use friction::law::{natural_residual, project};

#[test]
fn coulomb_residual_vanishes_exactly_on_the_law() {
    let a = 2.0;
    assert_eq!(project(3.0, -a, a), 2.0);
    assert_eq!(project(-3.0, -a, a), -2.0);
    assert_eq!(project(0.5, -a, a), 0.5);
    for rho in [1e-3, 1.0, 1e3] {
        assert_eq!(natural_residual(0.0, 1.3, -a, a, rho), 0.0); // stuck, inside the bound
        assert_eq!(natural_residual(0.7, -a, -a, a, rho), 0.0); // slipping forward, impulse backward
        assert_eq!(natural_residual(-0.7, a, -a, a, rho), 0.0);
        assert!((natural_residual(0.01, 1.0, -a, a, rho) - 0.01).abs() < 1e-12 || rho * 0.01 > 3.0); // stuck but moving
        assert!(natural_residual(0.7, a, -a, a, rho) > 0.0); // impulse along the motion
        assert!(natural_residual(0.7, -1.0, -a, a, rho) > 0.0); // slipping below the bound
    }
}

/// A row longer than four entries over scattered DOFs (a wheel: four rail DOFs and its own) multiplies like the
/// dense row; rewriting it in place keeps the short fast path when it shrinks back.
#[test]
fn long_rows_multiply_like_dense_rows() {
    let v: Vec<f64> = (0..12).map(|i| 0.5 + i as f64 * 0.25).collect();
    let entries = [(11, 1.0), (2, -0.25), (3, 0.5), (4, -0.75), (5, 0.125)];
    let mut row = InteractionRow::from_entries(entries);
    assert_eq!(row.len(), 5);
    assert_eq!(row.dofs(), &[2, 3, 4, 5, 11]);
    assert!(!row.is_local());
    let dense: f64 = entries.iter().map(|(d, h)| h * v[*d]).sum();
    assert!((row.dot(&v) - dense).abs() <= 1e-15 * dense.abs());
    let mut out = vec![0.0; 12];
    row.add_transpose(2.0, &mut out);
    for (d, h) in entries {
        assert_eq!(out[d], 2.0 * h);
    }
    row.set_entries([(4, 1.0), (5, 2.0), (6, 3.0), (7, 4.0)]);
    assert!(row.is_local());
    assert_eq!(row.dot(&v), v[4] + 2.0 * v[5] + 3.0 * v[6] + 4.0 * v[7]);
}
