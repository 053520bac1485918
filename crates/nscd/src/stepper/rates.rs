//! The generalized-α's rates (docs/theory.md §5.4): Q ≈ q̇ and A ≈ v̇ carried from step to step with their products
//! K Q and M A, so that a step needs no banded product beyond the θ-method's three (K v, M v, C v of v_{n+1}):
//!
//! ```text
//! Q_{n+1} = [v_{n+αf} − (1−αm)Q_n]/αm          A_{n+1} = [v_{n+1} − v_n − h(1−γ)A_n]/(hγ)
//! q_{n+1} = q_n + h[(1−γ)Q_n + γQ_{n+1}]        (K Q and M A by the same recursions from K v and M v)
//! ```
//!
//! The free velocity of a step is v_free = v_n + M̂⁻¹ h[F_{n+αf} − C v_n − K q_n − αf h K e_n + c_A (αm/γ) M A_n] with
//! e_n = c_A Q_n + (γ/αm) v_n and c_A = (1 − γ) − γ(1 − αm)/αm, and the step's displacement is
//! Δq = h(d_n + θ_e v_{n+1}) with d_n = e_n − θ_e v_n: the laws see the start velocity d_n/(1 − θ_e) where the
//! θ-method's see v_n.

use crate::error::Result;
use crate::integrator::Coefficients;
use banded::SymmetricBanded;

/// The rates' state and the coefficients they follow.
pub(crate) struct Rates {
    pub(crate) c: Coefficients,
    /// θ_e = γαf/αm.
    pub(crate) theta: f64,
    /// c_A = (1 − γ) − γ(1 − αm)/αm: the weight of Q_n in e_n and of A_n in the free velocity.
    pub(crate) carry: f64,
    /// Q_n (m/s), K Q_n (N/s).
    pub(crate) q_rate: Vec<f64>,
    pub(crate) kq_rate: Vec<f64>,
    /// A_n (m/s²), M A_n (N).
    pub(crate) acceleration: Vec<f64>,
    pub(crate) m_acceleration: Vec<f64>,
    /// The laws' start velocity d_n/(1 − θ_e) (m/s; [`Rates::start_velocity`]).
    start_velocity: Vec<f64>,
    /// M until the first step sets A₀ = M⁻¹(F₀ − C v₀ − K q₀ + Hᵀr₀); None after.
    mass: Option<SymmetricBanded>,
    /// Scratch: Q_{n+1}, K Q_{n+1}, Δq.
    pub(crate) q_rate_next: Vec<f64>,
    pub(crate) kq_rate_next: Vec<f64>,
    pub(crate) dq: Vec<f64>,
}

/// What one step of the generalized-α books beyond the θ-method's terms: its numerical dissipation (J).
pub(crate) struct RateStep<'a> {
    pub(crate) h: f64,
    pub(crate) v: &'a [f64],
    pub(crate) v_prev: &'a [f64],
    pub(crate) mv: &'a [f64],
    pub(crate) mv_next: &'a [f64],
    pub(crate) kv: &'a [f64],
    pub(crate) kv_next: &'a [f64],
}

impl Rates {
    /// The rates of a scheme with coefficients `c` over n DOFs, started from Q₀ = v₀ (K Q₀ = K v₀); A₀ waits for the
    /// first step's forcing ([`Rates::start`]).
    pub(crate) fn new(c: Coefficients, v0: &[f64], kv0: &[f64], mass: SymmetricBanded) -> Self {
        let n = v0.len();
        Self {
            c,
            theta: c.position_weight(),
            carry: (1.0 - c.gamma) - c.gamma * (1.0 - c.alpha_m) / c.alpha_m,
            q_rate: v0.to_vec(),
            kq_rate: kv0.to_vec(),
            acceleration: vec![0.0; n],
            m_acceleration: vec![0.0; n],
            start_velocity: v0.to_vec(),
            mass: Some(mass),
            q_rate_next: vec![0.0; n],
            kq_rate_next: vec![0.0; n],
            dq: vec![0.0; n],
        }
    }

    /// Whether A₀ is still to be set ([`Rates::start`]).
    pub(crate) fn needs_start(&self) -> bool {
        self.mass.is_some()
    }

    /// A₀ from M A₀ = `residual` (F₀ − C v₀ − K q₀ + Hᵀr₀, N), once.
    pub(crate) fn start(&mut self, residual: &[f64]) -> Result<()> {
        if let Some(mass) = self.mass.take() {
            self.m_acceleration.copy_from_slice(residual);
            self.acceleration.copy_from_slice(residual);
            mass.factor()?.solve_in_place(&mut self.acceleration);
        }
        Ok(())
    }

    /// The laws' start velocity d_n/(1 − θ_e) from v_n, with d_n = c_A Q_n + (γ(1 − αf)/αm) v_n.
    pub(crate) fn start_velocity(&mut self, v: &[f64]) -> &[f64] {
        let Coefficients { alpha_m, alpha_f, gamma } = self.c;
        let (a, b) = (self.carry / (1.0 - self.theta), gamma * (1.0 - alpha_f) / alpha_m / (1.0 - self.theta));
        for ((s, q), v) in self.start_velocity.iter_mut().zip(&self.q_rate).zip(v) {
            *s = a * q + b * v;
        }
        &self.start_velocity
    }

    /// −h[C v + K q + αf h K e_n] + h c_A (αm/γ) M A_n into `out` (the free velocity's right side without the load),
    /// from K q_n, K v_n and C v_n.
    pub(crate) fn free_rhs(&self, h: f64, (kq, kv, cv): (&[f64], &[f64], &[f64]), out: &mut [f64]) {
        let Coefficients { alpha_m, alpha_f, gamma } = self.c;
        let (ke_q, ke_v) = (alpha_f * h * self.carry, alpha_f * h * gamma / alpha_m);
        let ma = h * self.carry * alpha_m / gamma;
        for i in 0..out.len() {
            out[i] = -h * (kq[i] + cv[i] + ke_q * self.kq_rate[i] + ke_v * kv[i]) + ma * self.m_acceleration[i];
        }
    }

    /// Q_{n+1} from `v_alpha` = v_{n+αf}, and q ← q + Δq, Δq = h[(1−γ)Q_n + γQ_{n+1}] (kept in `dq`).
    pub(crate) fn advance_position(&mut self, h: f64, v_alpha: &[f64], q: &mut [f64]) {
        let Coefficients { alpha_m, gamma, .. } = self.c;
        for i in 0..q.len() {
            self.q_rate_next[i] = (v_alpha[i] - (1.0 - alpha_m) * self.q_rate[i]) / alpha_m;
            self.dq[i] = h * ((1.0 - gamma) * self.q_rate[i] + gamma * self.q_rate_next[i]);
            q[i] += self.dq[i];
        }
    }

    /// Carry the rates to n+1 and K q forward (`kq` ← K q_{n+1}), returning the step's numerical dissipation
    /// (αf − ½)(‖Δv‖²_M + ‖Δq‖²_K) − h(γ − αm)(ΔAᵀM v_{n+αf} + ΔQᵀK q_{n+αf}) (docs/theory.md §6).
    pub(crate) fn finish_step(&mut self, s: RateStep<'_>, kq: &mut [f64]) -> f64 {
        let Coefficients { alpha_m, alpha_f, gamma } = self.c;
        let h = s.h;
        let (mut kinetic, mut strain, mut rates) = (0.0, 0.0, 0.0);
        for i in 0..kq.len() {
            let kv_alpha = (1.0 - alpha_f) * s.kv[i] + alpha_f * s.kv_next[i];
            self.kq_rate_next[i] = (kv_alpha - (1.0 - alpha_m) * self.kq_rate[i]) / alpha_m;
            let kdq = h * ((1.0 - gamma) * self.kq_rate[i] + gamma * self.kq_rate_next[i]);
            let kq_alpha = kq[i] + alpha_f * kdq;
            kq[i] += kdq;
            let dv = s.v[i] - s.v_prev[i];
            let a_next = (dv - h * (1.0 - gamma) * self.acceleration[i]) / (h * gamma);
            let ma_next = (s.mv_next[i] - s.mv[i] - h * (1.0 - gamma) * self.m_acceleration[i]) / (h * gamma);
            let mv_alpha = (1.0 - alpha_f) * s.mv[i] + alpha_f * s.mv_next[i];
            kinetic += dv * (s.mv_next[i] - s.mv[i]);
            strain += self.dq[i] * kdq;
            rates += (a_next - self.acceleration[i]) * mv_alpha + (self.q_rate_next[i] - self.q_rate[i]) * kq_alpha;
            self.acceleration[i] = a_next;
            self.m_acceleration[i] = ma_next;
        }
        std::mem::swap(&mut self.q_rate, &mut self.q_rate_next);
        std::mem::swap(&mut self.kq_rate, &mut self.kq_rate_next);
        (alpha_f - 0.5) * (kinetic + strain) - h * (gamma - alpha_m) * rates
    }
}
