//! Bad input returns a typed error naming the field — never a panic.

use analytic::reference::uic60_on_soft_soil;
use fem_beam::{Beam, BeamModel, Discretisation, FemError, Foundation, LoadVector, Mesh};

fn field_of(err: FemError) -> &'static str {
    match err {
        FemError::InvalidField { field, .. } | FemError::InvalidCount { field, .. } => field,
        other => panic!("expected a field error, got {other}"),
    }
}

#[test]
fn bad_parameters_name_their_field() {
    let case = uic60_on_soft_soil();
    let build = |beam: Beam, foundation: Foundation, mesh: Mesh| {
        BeamModel::new(beam, foundation, mesh, case.supports).map(|_| ()).unwrap_err()
    };
    let b = case.beam;
    let f = case.foundation;
    let m = case.mesh;
    let bilinear = |tension_ratio| fem_beam::FoundationLaw::Bilinear { tension_ratio };
    let cases: Vec<(FemError, &str)> = vec![
        (build(b, f, Mesh { length: 0.0, ..m }), "mesh.length"),
        (build(b, f, Mesh { length: -5.0, ..m }), "mesh.length"),
        (build(b, f, Mesh { length: f64::NAN, ..m }), "mesh.length"),
        (build(b, f, Mesh { elements: 0, ..m }), "mesh.elements"),
        (build(Beam { youngs_modulus: 0.0, ..b }, f, m), "beam.youngs_modulus"),
        (build(Beam { second_moment: -1.0, ..b }, f, m), "beam.second_moment"),
        (build(Beam { area: f64::NAN, ..b }, f, m), "beam.area"),
        (build(Beam { density: f64::INFINITY, ..b }, f, m), "beam.density"),
        (build(b, Foundation { stiffness: -1.0, ..f }, m), "foundation.stiffness"),
        (build(b, Foundation { damping: f64::NAN, ..f }, m), "foundation.damping"),
        (build(b, Foundation { law: bilinear(1.5), ..f }, m), "foundation.tension_ratio"),
        (build(b, Foundation { law: bilinear(-0.1), ..f }, m), "foundation.tension_ratio"),
        (build(b, Foundation { law: bilinear(f64::NAN), ..f }, m), "foundation.tension_ratio"),
        (LoadVector::point_force(&Discretisation::euler_bernoulli(m), 200.5, 1.0).unwrap_err(), "position"),
        (LoadVector::point_force(&Discretisation::euler_bernoulli(m), -0.1, 1.0).unwrap_err(), "position"),
        (LoadVector::point_force(&Discretisation::euler_bernoulli(m), f64::NAN, 1.0).unwrap_err(), "position"),
        (LoadVector::point_force(&Discretisation::euler_bernoulli(m), 3.0, f64::NAN).unwrap_err(), "force"),
        (f.with_damping_ratio(-0.1, &b).unwrap_err(), "foundation.damping_ratio"),
    ];
    for (err, field) in cases {
        let text = err.to_string();
        assert_eq!(field_of(err), field, "{text}");
        assert!(text.contains(field), "message should name the field: {text}");
    }
}

#[test]
fn bad_requests_on_a_valid_model_are_errors() {
    let case = uic60_on_soft_soil();
    let model = case.model().unwrap();
    assert!(matches!(model.natural_frequencies(0), Err(FemError::InvalidCount { .. })));
    assert!(matches!(model.natural_frequencies(10_000), Err(FemError::InvalidCount { .. })));
    assert!(matches!(model.deflection_at(&[0.0; 3], 1.0), Err(FemError::LengthMismatch { .. })));
    let q = vec![0.0; model.dofs().full_len()];
    assert_eq!(field_of(model.deflection_at(&q, 201.0).unwrap_err()), "position");
    let inf = case.infinite_beam().unwrap();
    assert_eq!(field_of(inf.steady_state(-1.0, case.load).unwrap_err()), "speed");
    assert_eq!(field_of(inf.steady_state(f64::NAN, case.load).unwrap_err()), "speed");
    let no_soil = Foundation::linear(0.0, 0.0);
    assert_eq!(
        field_of(analytic::reference::InfiniteBeam::new(&case.beam, &no_soil).unwrap_err()),
        "foundation.stiffness"
    );
}
