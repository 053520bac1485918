//! Ralph's path search (1994) for the stationary friction wave: the globalisation the κ continuation
//! ([`crate::continuation`]) takes where a stage's Newton iteration does not settle. The residual F of the wave with
//! Jenkins friction is piecewise affine in W (and continuous: the play operator is), so from a start W₀ the path
//! F(W(t)) = (1 − t) F(W₀) is a chain of line segments, one a set of section states, joined where one section
//! flips: W + σ e in each piece with e = ±A_P⁻¹(−F(W₀)) (A_P the sets' matrix: one factorisation a flip), to the
//! first section whose force (stuck) or trial force (slipping) reaches its bound, e's sign the one that leads into
//! the next piece. Followed to t = 1 it ends at the wave with no line search.
//!
//! Measured on the undamped reference track with 1 kN/m (BENCHMARKS.md, "Ralph's path search"): from the last
//! stage's wave at the same speed the path takes 11–223 flips where Newton at 10× the stiffness fails within 100
//! iterations; from another speed's wave it takes thousands and may cycle among flips of no length, so it starts
//! only from a settled stage, and gives up after [`PATH_FLIPS`] flips.

use crate::control::Control;
use crate::error::Result;
use crate::friction::{FrictionSections, FrictionState, SectionState};
use crate::operator::MovingFrame;
use crate::sets::{SetSystem, Sets, residual};

/// The most flips a path may pass before it gives up (each a factorisation): above the 11–223 of every path from a
/// settled stage that arrived in the measurements, far below the > 100 000 of one that wandered.
pub const PATH_FLIPS: usize = 300;

/// What a path search did.
#[derive(Debug, Clone)]
pub(crate) struct PathOutcome {
    /// Where it ended.
    pub(crate) w: Vec<f64>,
    /// The t it reached (1: the wave, to the round-off the flips left).
    pub(crate) t: f64,
    /// Section flips passed.
    pub(crate) events: usize,
    /// Flips that passed no length of path (two sections on their bounds at once, or a flip undone).
    pub(crate) degenerate: usize,
    /// Flips after which t runs the other way.
    pub(crate) reversals: usize,
    /// Distinct sections flipped.
    pub(crate) flipped: usize,
}

/// Each section's force and trial force as α + β σ along W + σ e: (α, β) for all sections.
struct Rates {
    force: (Vec<f64>, Vec<f64>),
    trial: (Vec<f64>, Vec<f64>),
}

impl Rates {
    /// The rates along −e: the slopes negated.
    fn turned(mut self) -> Self {
        self.force.1.iter_mut().chain(self.trial.1.iter_mut()).for_each(|b| *b = -*b);
        self
    }
}

/// The march of [`FrictionSections::march_by`] along W + σ e, the states held in `slipping` (a sign where a section
/// slips, 0 where it sticks): affine in σ until a section flips.
fn rates(friction: &FrictionSections, slipping: &[f64], w: &[f64], e: &[f64]) -> Rates {
    let n = slipping.len();
    let k = friction.stiffness;
    let mut out = Rates { force: (vec![0.0; n], vec![0.0; n]), trial: (vec![0.0; n], vec![0.0; n]) };
    let (mut a, mut b, mut d_prev, mut e_prev) = (0.0, 0.0, friction.rest, 0.0);
    for i in (0..n).rev() {
        let (d, de) = (friction.sections[i].deflection(w), friction.sections[i].deflection(e));
        let (ta, tb) = (a + k * (d - d_prev), b + k * (de - e_prev));
        (out.trial.0[i], out.trial.1[i]) = (ta, tb);
        (a, b) = match slipping[i] {
            0.0 => (ta, tb),
            sign => (sign * friction.capacity, 0.0),
        };
        (out.force.0[i], out.force.1[i]) = (a, b);
        (d_prev, e_prev) = (d, de);
    }
    out
}

/// The first flip along W + σ e: (σ, section), skipping `skip`.
fn first_event(friction: &FrictionSections, slipping: &[f64], r: &Rates, skip: Option<usize>) -> Option<(f64, usize)> {
    let f_u = friction.capacity;
    let mut best: Option<(f64, usize)> = None;
    for i in 0..slipping.len() {
        if Some(i) == skip {
            continue;
        }
        let sigma = match slipping[i] {
            0.0 => {
                let (a, b) = (r.force.0[i], r.force.1[i]);
                if b > 0.0 {
                    (f_u - a) / b
                } else if b < 0.0 {
                    (-f_u - a) / b
                } else {
                    continue;
                }
            }
            s => {
                let (a, b) = (r.trial.0[i], r.trial.1[i]);
                if s * b < 0.0 { (f_u - s * a) / (s * b) } else { continue }
            }
        };
        let sigma = sigma.max(0.0);
        if best.is_none_or(|(bs, _)| sigma < bs) {
            best = Some((sigma, i));
        }
    }
    best
}

/// The path from `w` to t = 1 on `frame` (friction, no soil sections), at most `limit` flips, each booked with
/// `control` (the path stops where it says so).
pub(crate) fn path_search(
    frame: &MovingFrame,
    speed: f64,
    mut w: Vec<f64>,
    limit: usize,
    control: &Control<'_>,
) -> Result<PathOutcome> {
    let friction = frame.friction.as_ref().expect("a frame with friction");
    let start = friction.march(&w);
    let f0 = residual(frame, &w, Some(&start.force));
    let mut slipping: Vec<f64> = start
        .states
        .iter()
        .map(|s| match s {
            SectionState::Slipping { sign } => *sign,
            SectionState::Stuck { .. } => 0.0,
        })
        .collect();
    let direction = |state: FrictionState| -> Result<Vec<f64>> {
        let system = SetSystem::new(frame, &Sets { pressed: Vec::new(), friction: Some(state) }, speed)?;
        let mut d: Vec<f64> = f0.iter().map(|f| -f).collect();
        system.solve_in_place(&mut d);
        Ok(d)
    };
    let mut e = direction(start)?;
    let mut r = rates(friction, &slipping, &w, &e);
    let mut seen = vec![false; slipping.len()];
    let (mut t, mut delta, mut skip) = (0.0, 1.0, None);
    let mut out = PathOutcome { w: Vec::new(), t, events: 0, degenerate: 0, reversals: 0, flipped: 0 };
    while out.events < limit && control.next_iteration(w.len())? {
        let to_end = if delta > 0.0 { 1.0 - t } else { f64::INFINITY };
        let Some((sigma, i)) = first_event(friction, &slipping, &r, skip).filter(|&(sigma, _)| sigma < to_end) else {
            if delta > 0.0 {
                w.iter_mut().zip(&e).for_each(|(w, e)| *w += to_end * e);
                t = 1.0;
            }
            break;
        };
        w.iter_mut().zip(&e).for_each(|(w, e)| *w += sigma * e);
        t += delta * sigma;
        let was = slipping[i];
        slipping[i] = if was == 0.0 { (r.force.0[i] + sigma * r.force.1[i]).signum() } else { 0.0 };
        let d = direction(friction.march_by(&w, |j, _| (slipping[j] != 0.0).then_some(slipping[j])))?;
        let next = rates(friction, &slipping, &w, &d);
        // Into the new piece: a new slip's trial force grows past f_u, a new stick's force falls inside.
        let inward = match slipping[i] {
            0.0 => was * next.force.1[i] < 0.0,
            s => s * next.trial.1[i] > 0.0,
        };
        let turned = if inward { 1.0 } else { -1.0 };
        out.reversals += usize::from(turned != delta);
        out.degenerate += usize::from(sigma == 0.0);
        delta = turned;
        e = d.into_iter().map(|x| delta * x).collect();
        // The rates along e are those along d, their slopes turned with it (negation is exact).
        r = if delta > 0.0 { next } else { next.turned() };
        out.events += 1;
        (skip, seen[i]) = (Some(i), true);
    }
    out.flipped = seen.iter().filter(|s| **s).count();
    Ok(PathOutcome { w, t, ..out })
}

#[cfg(test)]
#[path = "path_search_tests.rs"]
mod tests;
