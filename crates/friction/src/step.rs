//! What a law reads of the step (docs/theory.md §9): the scheme's weights and where the law's row stands at the
//! step's start.

/// What a law needs of the time-stepping scheme (docs/theory.md §5): the step h (s), the weight θ of U_{k+1} in the
/// step's displacement HΔq = h[(1−θ)U_k + θU_{k+1}] (U_k the scheme's start velocity), and the weight w in [0, 1] of
/// the point t_k + wh where the scheme's forces act (θ for the θ-method, αf for the generalized-α).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepWeights {
    /// h (s).
    pub step: f64,
    /// θ: the weight of U_{k+1} in the displacement.
    pub theta: f64,
    /// w: where the forces act.
    pub force: f64,
}

/// Where an interaction's row stands at a step's start (docs/theory.md §9): the gap g_k (m), the scheme's start
/// velocity U_k (m/s) from which the step's displacement HΔq = h[(1−θ)U_k + θU_{k+1}] runs, the row's velocity Hv_k
/// at t_k (m/s; the same as U_k for the θ-method, not for the generalized-α), where a dashpot's velocity
/// wU_{k+1} + (1−w)Hv_k starts as the structure's C v does, and the rheonomic velocity b_r (m/s, U = Hq̇ + b_r).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RowStart {
    /// g_k (m).
    pub gap: f64,
    /// U_k (m/s).
    pub velocity: f64,
    /// Hv_k (m/s).
    pub current: f64,
    /// b_r (m/s).
    pub rheonomic: f64,
}
