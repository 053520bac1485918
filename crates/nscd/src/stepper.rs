//! The Moreau–Jean θ-method (docs/theory.md §5) with exact discrete energy bookkeeping (docs/theory.md §6).
//!
//! With constant step h and M̂ = M + hθC + h²θ²K (SPD, banded, factored once per run), per step k → k+1:
//!
//! ```text
//! v_free  = v_k + M̂⁻¹ h [ θF_{k+1} + (1−θ)F_k − C v_k − K (q_k + hθ v_k) ]
//! v_{k+1} = v_free + M̂⁻¹ Hᵀ p,    p from the friction step (see [`crate::solver`])
//! q_{k+1} = q_k + h [ θ v_{k+1} + (1−θ) v_k ]
//! ```
//!
//! With E = ½vᵀMv + ½qᵀKq, v_θ = θv_{k+1} + (1−θ)v_k, U_θ = H v_θ and F_θ = θF_{k+1} + (1−θ)F_k, the update gives
//! the exact identity E_{k+1} − E_k = h v_θᵀF_θ − h v_θᵀC v_θ + U_θᵀp − (θ − ½)(‖Δv‖²_M + ‖Δq‖²_K), accumulated
//! term by term in [`EnergyLedger`]; its residual is at round-off level whatever the solver's tolerance.

pub use crate::integrator::{Integration, iteration_matrix};

use crate::integrator::IterationMatrix;
pub use crate::ledger::EnergyLedger;
use std::sync::Arc;

use crate::error::{NscdError, Result};
use crate::fallback::Fallbacks;
use crate::forcing::Forcing;
use crate::kernels::dot;
use crate::position::ProjectionReport;
use crate::problem::StepLaw;
use crate::solver::{InteractionProblem, InteractionSolver, SolverKind, SolverSettings, StepReport, build_solver};
use crate::system::LinearSystem;
use banded::BandDiagonals;
use friction::Law;
use friction::hertz::NEWTON_ITERATIONS;

mod rates;
mod shift;
mod terms;
use rates::{RateStep, Rates};
pub use shift::{ShiftedBlock, WindowShift};
use terms::{energies, interaction_work, spring_energy, start_residual};

/// The state and scratch of a Moreau–Jean integration; nothing allocates inside [`MoreauJean::step`].
pub struct MoreauJean {
    /// θ of the θ-method (αf of the generalized-α, which reads its coefficients from `rates`).
    theta: f64,
    h: f64,
    damped: bool,
    /// Whether some interaction is a compliant stop (whose spring energy is reported).
    varying_energy: bool,
    /// Whether every interaction is friction (the ledger's work needs no kinds).
    friction_only: bool,
    /// The integrator's M̂ and its factors (shared with the problem), for the free velocity.
    matrix: Arc<IterationMatrix>,
    problem: InteractionProblem,
    solver: Box<dyn InteractionSolver>,
    /// The solvers that take over a step the run's solver cannot solve (none for steppers made by
    /// [`MoreauJean::new`], which compare solvers).
    fallbacks: Option<Fallbacks>,
    q: Vec<f64>,
    v: Vec<f64>,
    /// Friction impulses of the last step (N·s), also the next warm start.
    pub p: Vec<f64>,
    /// Section velocities u_{k+1} = H v_{k+1} of the last step (m/s).
    pub u: Vec<f64>,
    /// Time t_k (s).
    pub time: f64,
    /// Steps taken.
    pub steps: usize,
    /// Energy terms so far.
    pub energy: EnergyLedger,
    /// The last step's solver report.
    pub last_report: StepReport,
    /// The last step's position projection (0 sweeps: none was needed or no contact is rigid).
    pub last_projection: ProjectionReport,
    v_prev: Vec<f64>,
    /// K, M, C stored by diagonals for the per-step products (see [`BandDiagonals`]).
    stiffness: BandDiagonals,
    mass: BandDiagonals,
    damping: BandDiagonals,
    /// K q_k, K v_k, C v_k, M v_k: every banded product a step needs, one product per matrix per step (K q is
    /// carried forward as K q_{k+1} = K q_k + h K v_θ, exact up to round-off).
    kq: Vec<f64>,
    kv: Vec<f64>,
    cv: Vec<f64>,
    mv: Vec<f64>,
    /// The same products of v_{k+1}, swapped into place at the end of a step.
    kv_next: Vec<f64>,
    cv_next: Vec<f64>,
    mv_next: Vec<f64>,
    work: Vec<f64>,
    work2: Vec<f64>,
    u_free: Vec<f64>,
    /// H x of the energy terms (H v_θ, H q): m.
    row_products: Vec<f64>,
    v_free: Vec<f64>,
    /// The position projection's Δq (n when some moving contact is rigid, else empty).
    dq: Vec<f64>,
    /// The generalized-α's rates (None for the θ-method).
    rates: Option<Rates>,
}

impl MoreauJean {
    /// The one way to set up a run's stepper: M̂ for `integration`, its factor and the friction problem over
    /// `interactions` ([`InteractionProblem::new`]), the solver of `settings.kind` on that problem (a resolved kind, not
    /// `Auto`, which means projection here), started from
    /// (q₀, v₀) with zero impulses. The stepper owns all of it and borrows nothing.
    pub fn build(
        system: &LinearSystem,
        interactions: impl Into<crate::moving::Interactions>,
        integration: Integration,
        settings: &SolverSettings,
        q0: Vec<f64>,
        v0: Vec<f64>,
    ) -> Result<Self> {
        let problem = InteractionProblem::new(system, interactions, integration)?;
        let solver = build_solver(settings.kind, &problem, settings)?;
        let mut stepper = Self::new(system, problem, solver, q0, v0);
        stepper.fallbacks = Some(Fallbacks::new(stepper.solver.kind(), settings));
        Ok(stepper)
    }

    /// A stepper on a given problem and solver (built on that problem), for tests that compare solvers; the
    /// integration is the problem's, and there is no fallback: a step the solver cannot solve is an error.
    /// Prefer [`MoreauJean::build`].
    pub fn new(
        system: &LinearSystem,
        problem: InteractionProblem,
        solver: Box<dyn InteractionSolver>,
        q0: Vec<f64>,
        v0: Vec<f64>,
    ) -> Self {
        let integration = problem.matrix.integration;
        let coefficients = integration.coefficients();
        let n = system.dofs();
        let m = problem.interactions.len();
        let mut stepper = Self {
            theta: coefficients.alpha_f,
            h: integration.step,
            damped: system.has_damping(),
            varying_energy: problem.interactions.laws().iter().any(Law::has_spring),
            friction_only: problem.interactions.kinds().iter().all(|k| k.is_friction()),
            matrix: Arc::clone(&problem.matrix),
            problem,
            solver,
            fallbacks: None,
            q: q0,
            v: v0,
            p: vec![0.0; m],
            u: vec![0.0; m],
            time: 0.0,
            steps: 0,
            energy: EnergyLedger::default(),
            last_report: StepReport::default(),
            last_projection: ProjectionReport::default(),
            v_prev: vec![0.0; n],
            stiffness: BandDiagonals::new(&system.stiffness),
            mass: BandDiagonals::new(&system.mass),
            damping: BandDiagonals::new(&system.damping),
            kq: vec![0.0; n],
            kv: vec![0.0; n],
            cv: vec![0.0; n],
            mv: vec![0.0; n],
            kv_next: vec![0.0; n],
            cv_next: vec![0.0; n],
            mv_next: vec![0.0; n],
            work: vec![0.0; n],
            work2: vec![0.0; n],
            u_free: vec![0.0; m],
            row_products: vec![0.0; m],
            v_free: vec![0.0; n],
            dq: Vec::new(),
            rates: None,
        };
        if stepper.problem.has_projection() {
            stepper.dq = vec![0.0; n];
        }
        stepper.stiffness.mul_vec(&stepper.q, &mut stepper.kq);
        stepper.stiffness.mul_vec(&stepper.v, &mut stepper.kv);
        stepper.mass.mul_vec(&stepper.v, &mut stepper.mv);
        if stepper.damped {
            stepper.damping.mul_vec(&stepper.v, &mut stepper.cv);
        }
        stepper.v_prev.copy_from_slice(&stepper.v);
        if coefficients.has_rates() {
            stepper.rates = Some(Rates::new(coefficients, &stepper.v, &stepper.kv, system.mass.clone()));
        }
        let (kinetic, strain) = energies(&stepper.v, &stepper.mv, &stepper.q, &stepper.kq);
        stepper.energy.initial = kinetic + strain;
        stepper.energy.current = kinetic + strain;
        stepper.energy.kinetic = kinetic;
        stepper.energy.strain = strain;
        stepper.energy.spring_energy = spring_energy(&stepper.problem, &stepper.q, None, &mut stepper.row_products);
        stepper.problem.update(0.0, &stepper.q, &stepper.v);
        stepper
    }

    /// Name of the friction solver in use.
    pub fn solver_kind(&self) -> SolverKind {
        self.solver.kind()
    }

    /// The law of the last step (bounds in N·s: ±h·F_j for friction; compliance and drift).
    pub fn law(&self) -> &StepLaw {
        &self.problem.law
    }

    /// Step size h (s).
    pub fn step_size(&self) -> f64 {
        self.h
    }

    /// Displacement q_k of the free DOFs (m, rad).
    pub fn q(&self) -> &[f64] {
        &self.q
    }

    /// Velocity v_k of the free DOFs (m/s, rad/s).
    pub fn v(&self) -> &[f64] {
        &self.v
    }

    /// Velocity v_{k−1} before the last step (m/s, rad/s; v₀ before the first step).
    pub fn previous_v(&self) -> &[f64] {
        &self.v_prev
    }

    /// The free velocity v_free of the next step (no friction impulse), without advancing:
    /// v_free = v_k + M̂⁻¹ h [θF_{k+1} + (1−θ)F_k − C v_k − K(q_k + hθ v_k)] for the θ-method (the generalized-α's
    /// in docs/theory.md §5.4).
    pub fn free_velocity(&mut self, forcing: &dyn Forcing) -> &[f64] {
        let (h, theta) = (self.h, self.theta);
        let (t0, t1) = (self.time, self.time + h);
        if let Some(rates) = &self.rates {
            rates.free_rhs(h, (&self.kq, &self.kv, &self.cv), &mut self.work);
        } else {
            // −h [C v_k + K(q_k + hθ v_k)] from the cached products (C v stays zero without damping).
            for (((w, kq), kv), cv) in self.work.iter_mut().zip(&self.kq).zip(&self.kv).zip(&self.cv) {
                *w = -h * (kq + h * theta * kv + cv);
            }
        }
        forcing.add_to(t1, h * theta, &mut self.work);
        forcing.add_to(t0, h * (1.0 - theta), &mut self.work);
        self.matrix.factor.solve_in_place(&mut self.work);
        for ((f, v), w) in self.v_free.iter_mut().zip(&self.v).zip(&self.work) {
            *f = v + w;
        }
        &self.v_free
    }

    /// Advance one step under `forcing`. Errors (without changing the state's meaning) if the friction solver does
    /// not converge or a value becomes non-finite.
    pub fn step(&mut self, forcing: &dyn Forcing) -> Result<StepReport> {
        let (h, theta) = (self.h, self.theta);
        let (t0, t1) = (self.time, self.time + h);
        self.update_phase(forcing, t0)?;
        self.free_velocity(forcing);
        // v_prev ← v_k, v ← v_free; the stale vector left in v_free is overwritten by the next free velocity.
        std::mem::swap(&mut self.v_prev, &mut self.v);
        std::mem::swap(&mut self.v, &mut self.v_free);
        let report = self.impulse_phase(t1)?;
        // work = v_θ, where the forces act (θ is the generalized-α's αf). The θ-method's step moves q by h v_θ; the
        // generalized-α's by h[(1−γ)Q_n + γQ_{n+1}].
        for ((w, v), v_prev) in self.work.iter_mut().zip(&self.v).zip(&self.v_prev) {
            *w = theta * v + (1.0 - theta) * v_prev;
        }
        match self.rates.as_mut() {
            Some(rates) => rates.advance_position(h, &self.work, &mut self.q),
            None => self.q.iter_mut().zip(&self.work).for_each(|(q, w)| *q += h * w),
        }
        let projection = if self.problem.has_projection() {
            let projection = self.problem.project_positions(t1, (&self.q, &self.v), &self.p, &mut self.dq);
            if !projection.converged() {
                return Err(NscdError::ProjectionUnconverged {
                    step: self.steps + 1,
                    time: t1,
                    violation: projection.violation,
                    sweeps: projection.sweeps,
                });
            }
            projection
        } else {
            ProjectionReport::default()
        };
        // The step's energy before the projection, then the projection's own.
        self.book_energy(forcing, t0, t1)?;
        if projection.sweeps > 0 {
            self.apply_projection();
        }
        if !self.problem.interactions.is_empty() {
            self.problem.velocities(&self.v, &mut self.u);
        }
        self.time = t1;
        self.steps += 1;
        self.last_report = report;
        self.last_projection = projection;
        Ok(report)
    }

    /// The step's start: the generalized-α's rates at the first step, and the update phase of a varying problem.
    fn update_phase(&mut self, forcing: &dyn Forcing, t0: f64) -> Result<()> {
        if let Some(rates) = self.rates.as_mut()
            && rates.needs_start()
        {
            start_residual(&self.problem, forcing, t0, (&self.q, &self.v, &self.kq, &self.cv), &mut self.work);
            rates.start(&self.work)?;
        }
        if self.problem.is_varying() {
            // The update phase: moving rows and the step's law from (t_k, q_k, v_k), the warm start brought into
            // the new bounds, the solver told of the new rows. The generalized-α's laws see its start velocity.
            match self.rates.as_mut() {
                Some(rates) => self.problem.update_from(self.time, &self.q, rates.start_velocity(&self.v), &self.v),
                None => self.problem.update(self.time, &self.q, &self.v),
            }
            self.problem.clamp_to_bounds(&mut self.p);
            if self.problem.has_moving() {
                self.solver.refresh(&self.problem)?;
            }
        }
        Ok(())
    }

    /// The impulse phase: the interaction problem at the free velocity solved (with Hertz contacts' Newton updates),
    /// then v = v_free + M̂⁻¹Hᵀp written back; nothing to solve without interactions.
    fn impulse_phase(&mut self, t1: f64) -> Result<StepReport> {
        if self.problem.interactions.is_empty() {
            return Ok(StepReport::default());
        }
        self.problem.velocities(&self.v, &mut self.u_free);
        let mut report = self.solve_interactions(t1)?;
        // Hertz contacts: Newton on their tangent, one more solve per update (docs/theory.md §9).
        let mut newton = 0;
        while newton < NEWTON_ITERATIONS && self.problem.newton_step(&self.p) {
            self.solver.refresh(&self.problem)?;
            let (iterations, fallback) = (report.iterations, report.fallback);
            report = self.solve_interactions(t1)?;
            report.iterations += iterations;
            report.fallback = report.fallback.or(fallback);
            newton += 1;
        }
        // Write back the solver's v when it formed it, else v = v_free + M̂⁻¹Hᵀp here.
        let formed = match (&self.fallbacks, report.fallback) {
            (Some(fallbacks), Some(_)) => fallbacks.velocity(&report),
            _ => self.solver.velocity(),
        };
        match formed {
            Some(v) => self.v.copy_from_slice(v),
            None => self.problem.add_response(&self.p, &mut self.v, &mut self.work),
        }
        Ok(report)
    }

    /// One solve of the step's interaction problem by the run's solver, and by the fallbacks when it fails
    /// (unconverged, or an error of its own); an error naming the run's solver when none converges. `t1` is the
    /// step's end time (s), for the error.
    fn solve_interactions(&mut self, t1: f64) -> Result<StepReport> {
        // During a hand-over (the run's solver failed steps in a row) the fallbacks go first; should they all fail,
        // the run's solver still gets the step.
        if let Some(fallbacks) = self.fallbacks.as_mut()
            && fallbacks.takes_the_step()
            && let Some(report) = fallbacks.solve(&self.problem, &self.v, &self.u_free, &mut self.p, None)
        {
            return Ok(report);
        }
        let attempt = self.solver.solve(&self.problem, &self.v, &self.u_free, &mut self.p);
        let solved = matches!(&attempt, Ok(report) if report.converged());
        if let Some(fallbacks) = self.fallbacks.as_mut() {
            match solved {
                true => fallbacks.solver_succeeded(),
                false => fallbacks.solver_failed(),
            }
        }
        if solved {
            return attempt;
        }
        if let Some(fallbacks) = self.fallbacks.as_mut()
            && let Some(report) =
                fallbacks.solve(&self.problem, &self.v, &self.u_free, &mut self.p, attempt.as_ref().ok())
        {
            return Ok(report);
        }
        let report = attempt?;
        Err(NscdError::Unconverged {
            solver: self.solver.kind(),
            status: report.status,
            step: self.steps + 1,
            time: t1,
            residual: report.residual,
            iterations: report.iterations,
            tolerance: report.tolerance,
            fallbacks: self.fallbacks.as_ref().map(|_| Fallbacks::order(self.solver.kind())),
        })
    }

    /// q ← q + Δq of the position projection; K q and the strain energy follow, the change booked as
    /// [`EnergyLedger::projection_work`]: ½(q + Δq)ᵀK(q + Δq) − ½qᵀKq = Δqᵀ(Kq + ½KΔq).
    fn apply_projection(&mut self) {
        self.stiffness.mul_vec(&self.dq, &mut self.work2);
        let change = dot(&self.dq, &self.kq) + 0.5 * dot(&self.dq, &self.work2);
        for ((q, dq), (kq, kdq)) in self.q.iter_mut().zip(&self.dq).zip(self.kq.iter_mut().zip(&self.work2)) {
            *q += dq;
            *kq += kdq;
        }
        let e = &mut self.energy;
        e.strain += change;
        e.current += change;
        e.projection_work += change;
        // Part of the rigid contacts' loss: while a wheel presses on a moving rail, the step's −p·Ū and the
        // projection's change are each the O(h) drift and cancel (docs/theory.md §9).
        e.contact_loss -= change;
    }

    /// Book the energy terms of the step just taken (`work` holds v_θ, the generalized-α's v_{n+αf}) and carry the
    /// products forward. A
    /// non-finite energy — some displacement or velocity overflowed or became NaN, which the quadratic forms
    /// ½vᵀMv and ½qᵀKq always propagate (M has a positive diagonal) — stops the run before the ledger changes.
    fn book_energy(&mut self, forcing: &dyn Forcing, t0: f64, t1: f64) -> Result<()> {
        let (h, theta) = (self.h, self.theta);
        // The products of v_{k+1}: the only banded products of a step.
        self.stiffness.mul_vec(&self.v, &mut self.kv_next);
        self.mass.mul_vec(&self.v, &mut self.mv_next);
        if self.damped {
            self.damping.mul_vec(&self.v, &mut self.cv_next);
        }
        let numerical = if let Some(rates) = self.rates.as_mut() {
            let step = RateStep {
                h,
                v: &self.v,
                v_prev: &self.v_prev,
                mv: &self.mv,
                mv_next: &self.mv_next,
                kv: &self.kv,
                kv_next: &self.kv_next,
            };
            rates.finish_step(step, &mut self.kq)
        } else {
            // work2 = K v_θ, so that K Δq = h K v_θ; then K q_{k+1} = K q_k + h K v_θ.
            for (((w, kv_next), kv), kq) in
                self.work2.iter_mut().zip(&self.kv_next).zip(&self.kv).zip(self.kq.iter_mut())
            {
                *w = theta * kv_next + (1.0 - theta) * kv;
                *kq += h * *w;
            }
            if theta > 0.5 {
                // (θ − ½)[ΔvᵀMΔv + ΔqᵀKΔq] with MΔv = Mv_{k+1} − Mv_k, Δq = h v_θ and KΔq = h K v_θ.
                let kinetic: f64 =
                    (0..self.v.len()).map(|i| (self.v[i] - self.v_prev[i]) * (self.mv_next[i] - self.mv[i])).sum();
                (theta - 0.5) * (kinetic + h * h * dot(&self.work, &self.work2))
            } else {
                0.0
            }
        };
        let (kinetic, strain) = energies(&self.v, &self.mv_next, &self.q, &self.kq);
        if !(kinetic + strain).is_finite() {
            return Err(NscdError::NonFinite {
                step: self.steps + 1,
                time: t1,
                what: "displacement or velocity",
                hint: "check the inputs for extreme values; try θ > 0.5",
            });
        }
        let load = h * (theta * forcing.power(t1, &self.work) + (1.0 - theta) * forcing.power(t0, &self.work));
        let viscous = if self.damped {
            // h v_θᵀ C v_θ with C v_θ = θ C v_{k+1} + (1 − θ) C v_k.
            h * (theta * dot(&self.work, &self.cv_next) + (1.0 - theta) * dot(&self.work, &self.cv))
        } else {
            0.0
        };
        let work = interaction_work(&self.problem, self.friction_only, (&self.p, &self.work), &mut self.row_products);
        std::mem::swap(&mut self.kv, &mut self.kv_next);
        std::mem::swap(&mut self.mv, &mut self.mv_next);
        std::mem::swap(&mut self.cv, &mut self.cv_next);
        let before = self.energy.current;
        let e = &mut self.energy;
        e.kinetic = kinetic;
        e.strain = strain;
        e.current = kinetic + strain;
        e.load_work += load;
        e.viscous_dissipation += viscous;
        e.friction_work += work.friction;
        e.contact_work += work.contact;
        e.support_work += work.support;
        e.numerical_dissipation += numerical;
        if self.varying_energy {
            e.spring_energy = spring_energy(&self.problem, &self.q, Some(&self.p), &mut self.row_products);
        }
        if self.varying_energy || self.problem.has_projection() {
            for j in self.problem.fixed_len()..self.p.len() {
                e.contact_loss += self.problem.moving_contact_loss(j, self.p[j], &self.work).unwrap_or(0.0);
            }
        }
        let step_residual = e.current - before - (load - viscous + work.total() - numerical);
        e.max_step_residual = e.max_step_residual.max(step_residual.abs());
        Ok(())
    }
}
