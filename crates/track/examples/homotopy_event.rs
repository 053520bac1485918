//! What one homotopy event costs if the factor is brought up to date in place (issue 53, step 1): on the reference
//! run with 5 kN/m of ballast friction (200 elements, 799 sections, 200 m/s, θ = ½), at step `STEP` (the load at
//! mid-beam) the sections strictly inside their impulse interval form the band, B = M̂ + Σ_band γ_j h_j h_jᵀ with
//! γ_j = a_j/ε, ε = 0.4·10⁻⁶·U (the homotopy's own scale, U = max|u| of the step). Each event flips one section
//! near the edges of the stuck zones: γ h hᵀ added or taken away, the factor rows from the section's first DOF on
//! recomputed until they stop changing (`BandedLdlt::refactor_rows_from`, drop 1e-14), the direction's correction
//! B⁻¹h solved locally (`solve_local`, drop 1e-13), the rates of the sections that correction reaches updated, and
//! each of their next event times recomputed and queued (a binary heap with versions, as the homotopy keeps it).
//!
//! `cargo run -p track --example homotopy_event -- EVENTS` (the dev profile is optimised) prints the rows refactored and the DOFs solved
//! per event; the instructions an event are (count with EVENTS − count with 0) / EVENTS, from
//! `valgrind --tool=callgrind target/debug/examples/homotopy_event EVENTS` (`EVENTS algebra`: without the rates
//! and the event times).

use analytic::reference::uic60_on_soft_soil;
use banded::LocalVector;
use track::{BallastOnBeam, DistributedFriction, RunSettings, Simulation};

/// The step whose partition is taken: t = 0.5 s, the load at 100 m.
const STEP: usize = 1000;

/// An event time in the queue (earliest first), stale once its section's version has moved on.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Pending {
    time: f64,
    section: usize,
    version: u32,
}

impl Eq for Pending {}

impl Ord for Pending {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        other.time.total_cmp(&self.time).then(other.section.cmp(&self.section))
    }
}

impl PartialOrd for Pending {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

/// The band's matrix at step STEP of the reference run with 5 kN/m, and what the events need of that step.
struct Partition {
    /// B = M̂ + Σ_band γ_j h_j h_jᵀ.
    b: banded::SymmetricBanded,
    /// The sections' rows.
    placed: track::PlacedInteractions,
    /// Each section's half-width a_j (N·s) and whether it is strictly inside its interval.
    half: Vec<f64>,
    in_band: Vec<bool>,
    /// The step's section velocities u (m/s) and ε (m/s).
    u: Vec<f64>,
    epsilon: f64,
}

/// Run the reference with 5 kN/m to step STEP and build its band matrix.
fn partition() -> Partition {
    let model = uic60_on_soft_soil().model().expect("reference model");
    let placed = DistributedFriction::new(5e3).interactions(&model).expect("friction");
    let settings = RunSettings::default();
    let mut state = None;
    Simulation::new(&model, &placed, &settings)
        .and_then(|s| {
            s.run_observed(&mut |view| {
                if view.step == STEP {
                    let half: Vec<f64> =
                        view.law.lower.iter().zip(&view.law.upper).map(|(lo, hi)| 0.5 * (hi - lo)).collect();
                    let centre = view.law.lower.iter().zip(&view.law.upper).map(|(lo, hi)| 0.5 * (hi + lo));
                    let inside =
                        view.impulses.iter().zip(centre).zip(&half).map(|((p, c), a)| (p - c).abs() < a * (1.0 - 1e-9));
                    state = Some((half.clone(), inside.collect::<Vec<bool>>(), view.section_velocities.to_vec()));
                }
                view.step < STEP
            })
        })
        .expect("the reference run");
    let (half, in_band, u) = state.expect("the run reached the step");
    let system = track::system::beam_system(&model);
    let mut b = nscd::integrator::iteration_matrix(&system, nscd::Integration::theta(0.5, settings.time_step()));
    let epsilon = 0.4e-6 * u.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for (j, row) in placed.interactions().rows().iter().enumerate().filter(|(j, _)| in_band[*j]) {
        b.add_outer(row.dofs(), row.values(), half[j] / epsilon);
    }
    Partition { b, placed, half, in_band, u, epsilon }
}

fn main() {
    let events: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(100);
    // `… EVENTS algebra`: the refactor and the local solve alone, to price the bookkeeping apart.
    let algebra_only = std::env::args().nth(2).as_deref() == Some("algebra");
    let Partition { mut b, placed, half, in_band, u, epsilon } = partition();
    let rows = placed.interactions().rows();
    let mut factor = b.factor().expect("B is SPD");
    // Events happen where a section changes side: at the edges of the band's runs.
    let edges: Vec<usize> = (1..rows.len()).filter(|&j| in_band[j] != in_band[j - 1]).collect();
    let band_count = in_band.iter().filter(|&&x| x).count();
    println!(
        "step {STEP}: {band_count} of {} sections in the band, {} edges, ε = {epsilon:.3e} m/s",
        rows.len(),
        edges.len()
    );
    if edges.is_empty() || events == 0 {
        return;
    }
    let (mut refactored, mut solved, mut touched) = (0usize, 0usize, 0usize);
    let (mut y, mut scratch) = (LocalVector::default(), Vec::new());
    let mut rates: Vec<f64> = u.iter().map(|x| 1e-3 * x).collect();
    let mut versions = vec![0u32; rows.len()];
    let mut queue = std::collections::BinaryHeap::new();
    let mut flipped = in_band.clone();
    for e in 0..events {
        let j = edges[e % edges.len()];
        let row = &rows[j];
        let sign = if flipped[j] { -1.0 } else { 1.0 };
        flipped[j] = !flipped[j];
        b.add_outer(row.dofs(), row.values(), sign * half[j] / epsilon);
        let (first, last) = (row.dofs()[0], *row.dofs().last().unwrap());
        let end = factor.refactor_rows_from(&b, first, last, 1e-14).expect("B stays SPD");
        refactored += end - first;
        let entries: Vec<(usize, f64)> = row.entries().collect();
        factor.solve_local(&entries, 1e-13, &mut y, &mut scratch);
        solved += y.values.len();
        if algebra_only {
            continue;
        }
        // The rates of the sections y reaches, du_k = h_k · y (rows in order of their first DOF, each spanning ≤ 4).
        let from = rows.partition_point(|r| r.dofs()[0] + 4 <= y.start);
        let to = rows.partition_point(|r| r.dofs()[0] < y.end());
        for (k, other) in rows.iter().enumerate().take(to).skip(from) {
            rates[k] += y.dot_consecutive(other.dofs()[0], other.values());
            // Its next event: a band section reaching an edge of its band (|u| = 2ε), a bound one its velocity's zero.
            let target = if flipped[k] { (2.0 * epsilon).copysign(rates[k]) } else { 0.0 };
            let time = (target - u[k]) / rates[k];
            versions[k] += 1;
            if time > 0.0 && time <= 1.0 {
                queue.push(Pending { time, section: k, version: versions[k] });
            }
        }
        touched += to - from;
        // The next event is the earliest current one (stale entries, whose section moved on, are dropped).
        while queue.peek().is_some_and(|top: &Pending| top.version != versions[top.section]) {
            queue.pop();
        }
    }
    // The factor kept up to date event by event against B's factor afresh: solves of a smooth right-hand side.
    let rhs: Vec<f64> = (0..b.order()).map(|i| (i as f64 * 0.01).sin()).collect();
    let (kept, fresh) = (factor.solve(&rhs), b.factor().expect("B is SPD").solve(&rhs));
    let size = fresh.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let gap = kept.iter().zip(&fresh).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / size;
    println!("B⁻¹r by the kept factor against a fresh one: {gap:.1e} of its largest entry");
    let n = events as f64;
    println!(
        "{events} events: {:.1} rows refactored, {:.1} DOFs solved, {:.1} section rates updated per event (Σ rate {:.3e}, {} queued)",
        refactored as f64 / n,
        solved as f64 / n,
        touched as f64 / n,
        rates.iter().sum::<f64>(),
        queue.len()
    );
}
