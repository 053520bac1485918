//! The energy ledger of a run (docs/theory.md §6): every term of the discrete energy identity of the Moreau–Jean
//! step, accumulated by [`crate::MoreauJean`], so that E_now − E₀ − (the terms) is a residual at round-off.

/// Cumulative energy terms of a run (J).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EnergyLedger {
    /// Energy E₀ at the start.
    pub initial: f64,
    /// Energy E = ½vᵀMv + ½qᵀKq now.
    pub current: f64,
    /// Kinetic part of `current`.
    pub kinetic: f64,
    /// Strain part of `current` (bending + foundation).
    pub strain: f64,
    /// Σ h v_θᵀF_θ: work of the external load.
    pub load_work: f64,
    /// Σ h v_θᵀC v_θ ≥ 0: dissipated by the foundation dashpots.
    pub viscous_dissipation: f64,
    /// Σ U_θᵀp over the friction interactions: work of the friction impulses (≤ 0 for θ = 1; report as is
    /// otherwise).
    pub friction_work: f64,
    /// Σ U_θᵀp over the contacts (rigid or compliant): the work of the contact impulses, which a compliant contact
    /// partly stores in its spring ([`EnergyLedger::spring_energy`]).
    pub contact_work: f64,
    /// Σ U_θᵀp over the unilateral supports of the structure.
    pub support_work: f64,
    /// ½k_c⟨δ⟩₊² summed over the compliant interactions now (J): not part of `current`, whose balance the impulses'
    /// work closes; reported so that the stops' own loss, −(contact + support work) − Δspring energy, can be told.
    pub spring_energy: f64,
    /// Σ over the moving contacts (wheels) of what each lost in a step (J):
    /// [`crate::InteractionProblem::moving_contact_loss`] — landing impacts and the implicit spring — less the
    /// rigid contacts' [`EnergyLedger::projection_work`]. Apart from
    /// `contact_work`, which also carries the work a wheel's rolling along a moving rail does (its rheonomic part).
    pub contact_loss: f64,
    /// Σ over the steps of the strain energy the position projection of rigid moving contacts changed
    /// (J, either sign; [`crate::position`]): ½(q + Δq)ᵀK(q + Δq) − ½qᵀKq.
    pub projection_work: f64,
    /// Σ (θ − ½)(‖Δv‖²_M + ‖Δq‖²_K) ≥ 0: numerical dissipation of the scheme.
    pub numerical_dissipation: f64,
    /// Σ over the shifts of a co-moving window of E after − E before (J, ≤ 0 as a rule): the energy the dropped
    /// rear element carried out of the window ([`crate::MoreauJean::shift`]); 0 on a fixed domain.
    pub transported: f64,
    /// Largest |per-step residual| seen (J).
    pub max_step_residual: f64,
}

impl EnergyLedger {
    /// E_now − E₀ − (load work − viscous + interactions − numerical + projection + transported): zero up to
    /// round-off.
    pub fn residual(&self) -> f64 {
        self.current
            - self.initial
            - (self.load_work - self.viscous_dissipation + self.interaction_work() - self.numerical_dissipation
                + self.projection_work
                + self.transported)
    }

    /// Work of all interaction impulses (J): friction, contact and supports.
    pub fn interaction_work(&self) -> f64 {
        self.friction_work + self.contact_work + self.support_work
    }

    /// Energy removed by friction and viscous damping (positive).
    pub fn dissipated(&self) -> f64 {
        self.viscous_dissipation - self.friction_work
    }
}

/// The energy balance of a run as it is reported (J): the ledger's terms a reader checks the identity with, the same
/// object for a run, each point of a sweep and the co-moving window.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(deny_unknown_fields))]
pub struct EnergyBalance {
    /// Work of the loads (J).
    pub load_work: f64,
    /// Work of the friction impulses (J, ≤ 0 at θ = 1).
    pub friction_work: f64,
    /// What friction removed, −friction work (J).
    pub friction_dissipation: f64,
    /// What the viscous dashpots removed (J, ≥ 0).
    pub viscous_dissipation: f64,
    /// Friction plus viscous dissipation (J).
    pub dissipated: f64,
    /// The θ-method's numerical dissipation (J; 0 at θ = ½).
    pub numerical_dissipation: f64,
    /// What the shifts of a co-moving window carried out of it (J; 0 on a fixed domain).
    pub transported: f64,
    /// What the discrete energy identity leaves over (J; round-off).
    pub residual: f64,
}

impl EnergyBalance {
    /// A balance none of whose terms is known (NaN, a missing value): what a file that holds only some of them
    /// reads back into, those filled in.
    pub fn unknown() -> Self {
        let n = f64::NAN;
        Self {
            load_work: n,
            friction_work: n,
            friction_dissipation: n,
            viscous_dissipation: n,
            dissipated: n,
            numerical_dissipation: n,
            transported: n,
            residual: n,
        }
    }
}

impl EnergyLedger {
    /// The balance a report shows.
    pub fn balance(&self) -> EnergyBalance {
        EnergyBalance {
            load_work: self.load_work,
            friction_work: self.friction_work,
            // 0 − W, not −W: no "-0" in a report without friction.
            friction_dissipation: 0.0 - self.friction_work,
            viscous_dissipation: self.viscous_dissipation,
            dissipated: self.dissipated(),
            numerical_dissipation: self.numerical_dissipation,
            transported: self.transported,
            residual: self.residual(),
        }
    }
}
