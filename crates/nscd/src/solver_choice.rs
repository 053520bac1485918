//! The choice of the per-step solver and its tolerances: the one solver choice of every layer.

/// Which per-step friction solver to use: the one choice type of every layer (scenario files through the `serde`
/// feature, the command line through [`SolverKind::ALL`] and `FromStr`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "kebab-case"))]
pub enum SolverKind {
    /// Projection for a few sections (at most eight) or sections spaced wider than twice the coupling length,
    /// interior point otherwise.
    #[default]
    Auto,
    /// Nonsmooth (projected) Gauss–Seidel.
    Projection,
    /// Banded primal–dual interior point.
    InteriorPoint,
    /// Clarabel interior-point QP (feature `clarabel`).
    Clarabel,
    /// Parametric active set (homotopy) on the shifted Huber law, for fixed Coulomb friction sections.
    Homotopy,
}

impl SolverKind {
    /// Every choice, in the order they are documented.
    pub const ALL: [SolverKind; 5] = [
        SolverKind::Auto,
        SolverKind::Projection,
        SolverKind::InteriorPoint,
        SolverKind::Clarabel,
        SolverKind::Homotopy,
    ];

    /// Lower-case name, as used in scenario files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            SolverKind::Auto => "auto",
            SolverKind::Projection => "projection",
            SolverKind::InteriorPoint => "interior-point",
            SolverKind::Clarabel => "clarabel",
            SolverKind::Homotopy => "homotopy",
        }
    }
}

impl std::fmt::Display for SolverKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for SolverKind {
    type Err = String;

    /// The kind named `name` ([`SolverKind::name`]); the error lists the names.
    fn from_str(name: &str) -> Result<Self, String> {
        Self::ALL.into_iter().find(|k| k.name() == name).ok_or_else(|| {
            let names: Vec<&str> = Self::ALL.iter().map(|k| k.name()).collect();
            format!("unknown solver `{name}`, expected one of {}", names.join(", "))
        })
    }
}

/// Tolerances and limits of the friction solvers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverSettings {
    /// Solver choice. Default [`SolverKind::Auto`].
    pub kind: SolverKind,
    /// Relative tolerance on the law residual, relative to max_j |u_free,j| (m/s). Default 1e-6; in (0, 1e-2].
    /// Tighter buys no digit of a run's results: with distributed friction the outcomes scatter over tolerances
    /// 1e-12…1e-6 without a trend (stick–slip transitions move by a step under any perturbation; BENCHMARKS.md),
    /// while 1e-8 costs ~40 % more interior-point iterations than 1e-6, 1e-10 ~85 %, and the interior point stalls
    /// near 1e-12. From 1e-5 on, peaks at 200 m/s start to leave that scatter.
    pub tolerance: f64,
    /// Iteration cap per step: sweeps for projection, iterations for interior point. Default 20 000.
    pub max_iterations: usize,
    /// Let the interior point re-solve only a moving window around the sections that change (exact to the same
    /// tolerance: every section is checked; see [`crate::solver::interior_point`]). Default true.
    pub moving_window: bool,
}

impl Default for SolverSettings {
    fn default() -> Self {
        Self { kind: SolverKind::Auto, tolerance: 1e-6, max_iterations: 20_000, moving_window: true }
    }
}
