//! The per-step linear algebra of the time stepper: factor M̂ = M + hθC + h²θ²K once, solve many times.
//!
//! Compares the hand-written banded LDLᵀ of `fem-beam` with nalgebra-sparse's `CscCholesky` and nalgebra's dense
//! Cholesky, on the reference beam (pinned, h = 0.1 m / 200 m/s, θ = ½) with 200 and 2000 elements
//! (400 and 4000 free DOFs). Run with `cargo bench -p frictrack-benches --bench linear_solve`.

use analytic::reference::uic60_on_soft_soil;
use banded::{BandDiagonals, SymmetricBanded};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fem_beam::{BeamModel, Mesh};
use nalgebra::DVector;
use nalgebra_sparse::{CscMatrix, factorization::CscCholesky};
use std::hint::black_box;

fn iteration_matrix(elements: usize) -> SymmetricBanded {
    let mut case = uic60_on_soft_soil();
    case.mesh = Mesh::new(case.mesh.length, elements).unwrap();
    let model: BeamModel = case.model().unwrap();
    let h = case.mesh.element_length() / 200.0;
    let theta = 0.5;
    SymmetricBanded::linear_combination(&[
        (1.0, model.mass()),
        (h * theta, model.damping()),
        (h * h * theta * theta, model.stiffness()),
    ])
}

fn linear_solve(c: &mut Criterion) {
    let mut group = c.benchmark_group("linear_solve");
    for elements in [200usize, 2000] {
        let m_hat = iteration_matrix(elements);
        let n = m_hat.order();
        let rhs: Vec<f64> = (0..n).map(|i| ((i * 7919) % 1000) as f64 / 1000.0 - 0.5).collect();
        let dense = m_hat.to_dense();
        let csc = CscMatrix::from(&dense);

        group.bench_function(BenchmarkId::new("banded_ldlt_factor", n), |b| {
            b.iter(|| black_box(&m_hat).factor().unwrap())
        });
        let ldlt = m_hat.factor().unwrap();
        let mut x = rhs.clone();
        group.bench_function(BenchmarkId::new("banded_ldlt_solve", n), |b| {
            b.iter(|| {
                x.copy_from_slice(&rhs);
                ldlt.solve_in_place(black_box(&mut x));
            })
        });

        // The stepper's other per-step kernel: one product with a banded matrix, in both storage layouts.
        let mut y = vec![0.0; n];
        group.bench_function(BenchmarkId::new("product_row_band", n), |b| {
            b.iter(|| m_hat.mul_vec(black_box(&rhs), &mut y))
        });
        let diagonals = BandDiagonals::new(&m_hat);
        group.bench_function(BenchmarkId::new("product_by_diagonals", n), |b| {
            b.iter(|| diagonals.mul_vec(black_box(&rhs), &mut y))
        });

        group.bench_function(BenchmarkId::new("csc_cholesky_factor", n), |b| {
            b.iter(|| CscCholesky::factor(black_box(&csc)).unwrap())
        });
        let chol = CscCholesky::factor(&csc).unwrap();
        let mut xm = nalgebra::DMatrix::from_column_slice(n, 1, &rhs);
        group.bench_function(BenchmarkId::new("csc_cholesky_solve", n), |b| {
            b.iter(|| {
                xm.copy_from_slice(&rhs);
                chol.solve_mut(black_box(&mut xm));
            })
        });

        if n <= 500 {
            group.bench_function(BenchmarkId::new("dense_cholesky_factor", n), |b| {
                b.iter(|| black_box(dense.clone()).cholesky().unwrap())
            });
            let dense_chol = dense.clone().cholesky().unwrap();
            let mut xd = DVector::from_vec(rhs.clone());
            group.bench_function(BenchmarkId::new("dense_cholesky_solve", n), |b| {
                b.iter(|| {
                    xd.copy_from_slice(&rhs);
                    dense_chol.solve_mut(black_box(&mut xd));
                })
            });
        }
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).warm_up_time(std::time::Duration::from_millis(500)).measurement_time(std::time::Duration::from_secs(2));
    targets = linear_solve
}
criterion_main!(benches);
