//! The error type of the `study` crate.

use thiserror::Error;

/// What can go wrong with a scenario or a study.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum StudyError {
    /// A scenario value is out of range; names its path in the file, the value and what is allowed.
    #[error("invalid {path} = {value}: {allowed}")]
    InvalidField {
        /// Dotted path in the scenario, e.g. `foundation.damping_ratio`.
        path: String,
        /// The offending value, as written.
        value: String,
        /// What is allowed.
        allowed: String,
    },
    /// The scenario is not valid TOML or has unknown keys / wrong types.
    #[error("{source_name}:{line}:{column}: {message}")]
    Syntax {
        /// File name (or `<string>`).
        source_name: String,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What the parser said.
        message: String,
    },
    /// A file could not be read or written.
    #[error("{path}: {message}")]
    Io {
        /// The file.
        path: String,
        /// What went wrong.
        message: String,
    },
    /// A journal of finished runs could not be opened, read or written.
    #[error("{path}: {message}")]
    Journal {
        /// The journal file.
        path: String,
        /// What is wrong.
        message: String,
    },
    /// Every run of one curve of a study failed: the study has nothing of that curve to report.
    #[error("every run of {case} failed; the first: {first}")]
    CurveFailed {
        /// The curve.
        case: String,
        /// The first run's error, as text.
        first: String,
    },
    /// The run was asked to stop (Ctrl-C) before it finished; finished runs are in the journal.
    #[error("interrupted")]
    Interrupted,
    /// An error from the beam layer.
    #[error(transparent)]
    Beam(#[from] fem_beam::FemError),
    /// An error from the stepper (invalid setting or a failed run).
    #[error(transparent)]
    Stepping(#[from] nscd::NscdError),
    /// An error of the stationary solver (a speed without a stationary wave, a singular operator).
    #[error(transparent)]
    Stationary(stationary::StationaryError),
}

impl From<irregularity::IrregularityError> for StudyError {
    fn from(error: irregularity::IrregularityError) -> Self {
        let irregularity::IrregularityError::InvalidField { field, value, allowed } = error;
        StudyError::InvalidField { path: field, value, allowed }
    }
}

impl From<track::TrackError> for StudyError {
    fn from(error: track::TrackError) -> Self {
        match error {
            track::TrackError::Engine(e) => StudyError::Stepping(e),
            track::TrackError::Beam(e) => StudyError::Beam(e),
            track::TrackError::Irregularity(e) => e.into(),
            track::TrackError::Invalid { setting, value, allowed } => {
                let value = match value {
                    track::Refused::Number(x) => crate::number::number(x),
                    track::Refused::Count(n) => n.to_string(),
                    track::Refused::Choice(name) => name.to_string(),
                };
                StudyError::InvalidField { path: path(setting), value, allowed }
            }
            track::TrackError::NoStaticEquilibrium { reason } => StudyError::InvalidField {
                path: "foundation.law".into(),
                value: "(no static equilibrium)".into(),
                allowed: reason,
            },
        }
    }
}

impl From<stationary::StationaryError> for StudyError {
    /// A stationary solve stopped by Ctrl-C is the study's interruption (exit 130, finished work kept).
    fn from(e: stationary::StationaryError) -> Self {
        match e {
            stationary::StationaryError::Interrupted => StudyError::Interrupted,
            other => StudyError::Stationary(other),
        }
    }
}

/// Where a setting the track checks is in a scenario file: one exhaustive match, so that a new setting cannot go
/// unnamed (the friction's and the vehicles' keys are theirs under `[friction]` and `[vehicle]`).
pub fn path(setting: track::Setting) -> String {
    use track::Setting as S;
    match setting {
        S::Speed => "load.speed".into(),
        S::SpeedProfile => "load.speed_profile".into(),
        S::Acceleration => "load.acceleration".into(),
        S::Load => "load.force".into(),
        S::LoadAdvance => "integration.load_advance".into(),
        S::MaxStep => "integration.max_step".into(),
        S::Theta => "integration.theta".into(),
        S::SpectralRadius => "integration.spectral_radius".into(),
        S::AccelerationBand => "output.acceleration_band".into(),
        S::AccelerationFilter => "output.acceleration_filter".into(),
        S::EndTime => "integration.end_time".into(),
        S::Tolerance => "integration.tolerance".into(),
        S::MaxIterations => "integration.max_iterations".into(),
        S::Solver => "integration.solver".into(),
        S::StaticStart => "integration.static_start".into(),
        S::SteadyStart => "integration.steady_start".into(),
        S::RecordSections => "output.sections".into(),
        S::ExtremesNodes => "output.extremes_nodes".into(),
        S::ExtremesWindow => "output.extremes_window".into(),
        S::Snapshots => "output.snapshot_times / snapshot_load_positions".into(),
        S::Friction(name) => format!("friction.{name}"),
        S::Vehicle(key) => key.into(),
        S::CoMovingLoadAt => "co_moving.load_at".into(),
        S::CoMovingTrackLength => "co_moving.track_length".into(),
        S::LeftSupport => "supports.left".into(),
        S::RightSupport => "supports.right".into(),
        S::Beam(name) => name.into(),
    }
}

impl StudyError {
    /// Whether the error is the user's input (exit code 2) rather than a runtime failure; a lower layer's error
    /// answers for itself.
    pub fn is_invalid_input(&self) -> bool {
        match self {
            StudyError::InvalidField { .. } | StudyError::Syntax { .. } | StudyError::Journal { .. } => true,
            StudyError::Io { .. } | StudyError::CurveFailed { .. } | StudyError::Interrupted => false,
            StudyError::Beam(e) => e.is_invalid_input(),
            StudyError::Stepping(e) => e.is_invalid_input(),
            StudyError::Stationary(e) => e.is_invalid_input(),
        }
    }
}

/// Result alias of this crate.
pub type Result<T, E = StudyError> = std::result::Result<T, E>;

/// An `InvalidField` error: the field (dotted path or command-line option), its value, what is allowed.
pub fn invalid(path: &str, value: impl std::fmt::Display, allowed: impl Into<String>) -> StudyError {
    StudyError::InvalidField { path: path.into(), value: value.to_string(), allowed: allowed.into() }
}
