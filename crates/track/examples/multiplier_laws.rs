//! Ballast friction with one unknown a node or an element against the sections, under space–time refinement (issue
//! 53 route 2, "a friction law without redundant multipliers"): `cargo run --release -p track --example
//! multiplier_laws` (~25 s). The 5 kN/m reference run (200 m, 200 m/s) on 200, 400 and 800 elements, once at the
//! reference's load advance of 0.1 m a step (the mesh refined alone: each law's own error) and once with the advance
//! refined with the mesh (0.1, 0.05, 0.025 m: the error of a whole run at each resolution), for:
//!
//! - `sections`: the default law, five sections an element (J = 4; 799 rows on 400 DOFs, W of rank 400);
//! - `nodal`: one section a node (J = 1, trapezoid: the product's law with `subdivisions = 1`);
//! - `element-mean`: one unknown an element, its row the element's mean velocity (1/l)∫N dx and its bound f_u·l —
//!   piecewise-constant multipliers, orthogonal and so their own dual basis;
//! - `nodal-dual`: one unknown a node with the dual (biorthogonal) basis of the linear hats, ψ_i = 2φ_i − φ_{i±1} on
//!   each element (∫ψ_iφ_j = δ_ij D_i, D_i = ∫φ_i): row (1/D_i)∫ψ_i N dx over the node's two elements (six DOFs,
//!   outside M̂'s band, so solved by projection), bound f_u·D_i (Wohlmuth 2000; Hüeber, Stadler & Wohlmuth 2008).
//!
//! The extremes are the middle third's (the load between 66.7 and 133.3 m, away from the entry and exit transients)
//! and the friction dissipation of the whole run; each is printed as its relative difference from the sections at
//! the finest resolution. These rows are built here, not in the product: they are the measurement behind
//! BENCHMARKS.md's table, not a law users can choose.

use analytic::reference::uic60_on_soft_soil;
use fem_beam::BeamModel;
use fem_beam::element::hermite::GAUSS_4;
use friction::{InteractionRow, Law};
use nscd::SolverKind;
use track::{BallastOnBeam, DistributedFriction, PlacedInteractions, RunSettings, SectionKind, Simulation};

const FORCE_PER_LENGTH: f64 = 5e3;

fn main() {
    println!("The mesh refined alone, at the reference's load advance of 0.1 m a step (the laws' own error):");
    series(&[(200, 0.1), (400, 0.1), (800, 0.1)]);
    println!("\nThe mesh and the step refined together (the error of a run at each resolution):");
    series(&[(200, 0.1), (400, 0.05), (800, 0.025)]);
}

/// Every law at each resolution (elements, load advance in m), as relative differences from the sections at the last.
fn series(resolutions: &[(usize, f64)]) {
    let laws = ["sections", "nodal", "element-mean", "nodal-dual"];
    let mut rows = Vec::new();
    for &(elements, advance) in resolutions {
        for law in laws {
            // The one-unknown-an-element and dual laws are measured at the two coarser resolutions: projection on
            // the dense W of 800 unknowns is minutes a run, and the two coarser ones decide.
            if elements == 800 && matches!(law, "element-mean" | "nodal-dual") {
                continue;
            }
            rows.push(run(law, elements, advance));
        }
    }
    let &(elements, advance) = resolutions.last().expect("a resolution");
    let finest = rows.iter().find(|r| r.law == "sections" && r.elements == elements && r.advance == advance);
    let finest = finest.expect("the finest sections").clone();
    println!("law           elements  advance  unknowns  solver          its/step  window down  window up  dissipated");
    for r in &rows {
        let d = |a: f64, b: f64| (a - b) / b;
        println!(
            "{:<13} {:>8}  {:>7}  {:>8}  {:<14} {:>9.2}  {:>+11.2e}  {:>+9.2e}  {:>+10.2e}",
            r.law,
            r.elements,
            r.advance,
            r.unknowns,
            r.solver,
            r.iterations,
            d(r.down, finest.down),
            d(r.up, finest.up),
            d(r.dissipated, finest.dissipated)
        );
    }
    println!(
        "finest sections: window down {:.9} m, up {:.9} m, dissipated {:.3} J",
        finest.down, finest.up, finest.dissipated
    );
}

/// One run's outcome.
#[derive(Debug, Clone)]
struct Outcome {
    law: &'static str,
    elements: usize,
    advance: f64,
    unknowns: usize,
    solver: String,
    iterations: f64,
    down: f64,
    up: f64,
    dissipated: f64,
}

fn run(law: &'static str, elements: usize, advance: f64) -> Outcome {
    let mut case = uic60_on_soft_soil();
    case.mesh.elements = elements;
    let model = case.model().expect("reference model");
    let interactions = match law {
        "sections" => DistributedFriction::new(FORCE_PER_LENGTH).interactions(&model).expect("sections"),
        "nodal" => DistributedFriction { subdivisions: 1, ..DistributedFriction::new(FORCE_PER_LENGTH) }
            .interactions(&model)
            .expect("sections"),
        "element-mean" => element_means(&model),
        _ => nodal_duals(&model),
    };
    let mut settings = RunSettings::default();
    settings.integration.load_advance = advance;
    let length = model.mesh().length;
    settings.record.extremes_window = Some((length / 3.0, 2.0 * length / 3.0));
    if law == "nodal-dual" {
        settings.integration.solver.kind = SolverKind::Projection;
    }
    let result = Simulation::new(&model, &interactions, &settings).and_then(|s| s.run()).expect("run");
    let window = result.window.expect("the middle third set above").deflection;
    Outcome {
        law,
        elements,
        advance,
        unknowns: interactions.len(),
        solver: result.statistics.solver_name().to_string(),
        iterations: result.statistics.mean_iterations,
        down: window.max_downward.value,
        up: window.max_upward.value,
        dissipated: -result.energy.friction_work,
    }
}

/// ∫ over element `e` of weight(ξ)·N(ξ) dx by four-point Gauss (exact: degree ≤ 4 here), on its free DOFs.
fn weighted_shape_integral(model: &BeamModel, e: usize, weight: impl Fn(f64) -> f64) -> Vec<(usize, f64)> {
    let l = model.mesh().element_length();
    let mut integral = [0.0; 4];
    for &(t, w) in &GAUSS_4 {
        let n = model.element().shape(t);
        for k in 0..4 {
            integral[k] += w * l * weight(t) * n[k];
        }
    }
    model.dofs().element_free(e).into_iter().zip(integral).filter_map(|(d, v)| d.map(|d| (d, v))).collect()
}

/// One unknown an element: row (1/l)∫_e N dx, bound f_u·l.
fn element_means(model: &BeamModel) -> PlacedInteractions {
    let (elements, l) = (model.mesh().elements, model.mesh().element_length());
    let mut set = PlacedInteractions::new();
    for e in 0..elements {
        let entries = weighted_shape_integral(model, e, |_| 1.0 / l);
        let law = Law::Coulomb { capacity: FORCE_PER_LENGTH * l };
        set.push(InteractionRow::from_entries(entries), law, (e as f64 + 0.5) * l, SectionKind::Ballast);
    }
    set
}

/// One unknown a node with the dual basis of the hats: row (1/D_i)∫ψ_i N dx, bound f_u·D_i.
fn nodal_duals(model: &BeamModel) -> PlacedInteractions {
    let (elements, l) = (model.mesh().elements, model.mesh().element_length());
    let mut set = PlacedInteractions::new();
    for node in 0..=elements {
        let mut entries: Vec<(usize, f64)> = Vec::new();
        let mut length = 0.0;
        // ψ_i = 2φ_i − φ_other on each element of the node: 3ξ − 1 where the node is the element's right end,
        // 2 − 3ξ where it is the left.
        let left = (node > 0).then(|| weighted_shape_integral(model, node - 1, |t| 3.0 * t - 1.0));
        let right = (node < elements).then(|| weighted_shape_integral(model, node, |t| 2.0 - 3.0 * t));
        for part in [left, right].into_iter().flatten() {
            length += 0.5 * l;
            for (dof, value) in part {
                match entries.iter_mut().find(|(d, _)| *d == dof) {
                    Some(entry) => entry.1 += value,
                    None => entries.push((dof, value)),
                }
            }
        }
        let row = InteractionRow::from_entries(entries.into_iter().map(|(d, v)| (d, v / length)));
        set.push(row, Law::Coulomb { capacity: FORCE_PER_LENGTH * length }, node as f64 * l, SectionKind::Ballast);
    }
    set
}
