//! The whole static deflection line of the reference beam against the closed-form infinite-beam shape
//! w(x) = −w₀·e^{−β|x−x₀|}(cos β(x−x₀) + sin β|x−x₀|), not only its peak.

use analytic::reference::uic60_on_soft_soil;
use fem_beam::LoadVector;

#[test]
fn static_deflection_line_matches_infinite_beam_everywhere() {
    let case = uic60_on_soft_soil();
    let model = case.model().unwrap();
    let inf = case.infinite_beam().unwrap();
    let (w0, beta) = (inf.static_deflection(case.load), inf.beta());
    let x0 = 100.0;
    let load = LoadVector::point_force(&model.discretisation(), x0, -case.load).unwrap();
    let q = model.static_solve(&load).unwrap();
    let zero_speed = inf.steady_state(0.0, case.load).unwrap();
    let mut worst: f64 = 0.0;
    for i in 0..=2000 {
        let x = 0.1 * i as f64;
        let xi = beta * (x - x0);
        let exact = -w0 * (-xi.abs()).exp() * (xi.cos() + xi.abs().sin());
        assert!((zero_speed.deflection(x - x0) - exact).abs() < 1e-12 * w0);
        worst = worst.max((model.deflection_at(&q, x).unwrap() - exact).abs());
    }
    // Cubic interpolation of a shape with wavelength 2π/β = 20 m on 1 m elements: ~(βl)⁴/384 ≈ 3e-5 relative,
    // plus the O(l³) kink error at the load; the pinned ends at βL/2 ≈ 31 decay lengths are invisible.
    assert!(worst < 1e-4 * w0, "worst deviation {worst} m");
}
