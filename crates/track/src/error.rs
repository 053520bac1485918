//! The error type of the `track` crate: the engine's errors and the beam layer's, one type.

use thiserror::Error;

/// What can go wrong when setting up or running a load across the track.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TrackError {
    /// An error of the engine: a setting out of range, an unconverged or non-finite step, a solver failure.
    #[error(transparent)]
    Engine(#[from] nscd::NscdError),
    /// An error from the beam layer.
    #[error(transparent)]
    Beam(#[from] fem_beam::FemError),
    /// A rail profile or wheel flat out of range.
    #[error(transparent)]
    Irregularity(#[from] irregularity::IrregularityError),
    /// A setting of this crate refused: which (typed, so that every layer above names it by its own path, e.g. a
    /// scenario file's key), the value it was given and what is allowed.
    #[error("invalid {setting} = {value}: {allowed}")]
    Invalid {
        /// The setting.
        setting: Setting,
        /// The value refused.
        value: Refused,
        /// What is allowed.
        allowed: String,
    },
    /// The beam has no static equilibrium on its unilateral supports (nothing holds it, or the contact set does not
    /// settle).
    #[error("no static equilibrium on the unilateral foundation: {reason}")]
    NoStaticEquilibrium {
        /// Why, in words.
        reason: String,
    },
}

impl From<banded::BandedError> for TrackError {
    fn from(error: banded::BandedError) -> Self {
        TrackError::Engine(error.into())
    }
}

impl TrackError {
    /// A beam-layer error about a setting of a run (a field or a count, e.g. `foundation.subdivisions`) as this
    /// crate's own, so that the layers above name it by its place in their input as they name this crate's settings;
    /// any other beam error as it is.
    pub fn setting(error: fem_beam::FemError) -> Self {
        Self::beam_setting(error, Setting::Beam)
    }

    /// The same for the ballast friction's description (`distributed.force_per_length`, …): a key of the friction.
    pub fn friction(error: fem_beam::FemError) -> Self {
        Self::beam_setting(error, Setting::Friction)
    }

    fn beam_setting(error: fem_beam::FemError, setting: fn(&'static str) -> Setting) -> Self {
        match error {
            fem_beam::FemError::InvalidField { field, value, allowed } => {
                TrackError::Invalid { setting: setting(field), value: Refused::Number(value), allowed: allowed.into() }
            }
            fem_beam::FemError::InvalidCount { field, value, allowed } => {
                TrackError::Invalid { setting: setting(field), value: Refused::Count(value), allowed: allowed.into() }
            }
            other => other.into(),
        }
    }

    /// Whether the error is the user's input rather than a failure of the run; each layer answers for its own.
    pub fn is_invalid_input(&self) -> bool {
        match self {
            TrackError::Engine(e) => e.is_invalid_input(),
            TrackError::Beam(e) => e.is_invalid_input(),
            TrackError::Irregularity(_) | TrackError::Invalid { .. } | TrackError::NoStaticEquilibrium { .. } => true,
        }
    }
}

/// A setting of this crate out of range ([`TrackError::Invalid`]): which, its value, what is allowed.
pub(crate) fn invalid(setting: Setting, value: f64, allowed: impl Into<String>) -> TrackError {
    TrackError::Invalid { setting, value: Refused::Number(value), allowed: allowed.into() }
}

/// A count of this crate out of range.
pub(crate) fn invalid_count(setting: Setting, value: usize, allowed: impl Into<String>) -> TrackError {
    TrackError::Invalid { setting, value: Refused::Count(value), allowed: allowed.into() }
}

/// A choice of this crate that does not fit the rest of the run.
pub(crate) fn invalid_choice(setting: Setting, value: &'static str, allowed: impl Into<String>) -> TrackError {
    TrackError::Invalid { setting, value: Refused::Choice(value), allowed: allowed.into() }
}

/// A setting this crate checks, by what it is. [`Setting::name`] is this crate's own word for it; a layer above
/// names it by its place in its own input with one exhaustive match, so that a new setting cannot go unnamed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Setting {
    /// The load's speed (m/s).
    Speed,
    /// The load's speed profile (knots x m, v m/s).
    SpeedProfile,
    /// The load's constant acceleration (m/s²).
    Acceleration,
    /// The load's force (N).
    Load,
    /// Δx, the load's advance per step (m).
    LoadAdvance,
    /// The longest step (s).
    MaxStep,
    /// θ of the integrator.
    Theta,
    /// ρ∞ of the generalized-α.
    SpectralRadius,
    /// `output.acceleration_band`.
    AccelerationBand,
    /// `output.acceleration_filter`.
    AccelerationFilter,
    /// The run's end time (s).
    EndTime,
    /// The step solver's tolerance.
    Tolerance,
    /// The step solver's iteration limit.
    MaxIterations,
    /// The step solver.
    Solver,
    /// Where a static start stands the load (m).
    StaticStart,
    /// Where a steady-state start puts the load (m).
    SteadyStart,
    /// The recorded sections (m).
    RecordSections,
    /// The nodes the extremes are taken over (m).
    ExtremesNodes,
    /// The window of load positions of the window extremes (m).
    ExtremesWindow,
    /// The snapshots' times or load positions.
    Snapshots,
    /// A key of the friction placed on the beam, by its name there (`devices.count`, `distributed.subdivisions`).
    Friction(&'static str),
    /// A key of the vehicles (`vehicle.mass`, `vehicle.wheels.offset`, …).
    Vehicle(&'static str),
    /// Where the load stands in a co-moving window (m).
    CoMovingLoadAt,
    /// The track a co-moving window travels (m).
    CoMovingTrackLength,
    /// The support at the beam's left end.
    LeftSupport,
    /// The support at its right end.
    RightSupport,
    /// A setting of the beam layer, by its name there (`foundation.subdivisions`).
    Beam(&'static str),
}

impl Setting {
    /// This crate's own word for the setting.
    pub fn name(self) -> &'static str {
        match self {
            Setting::Speed => "speed",
            Setting::SpeedProfile => "speed_profile",
            Setting::Acceleration => "acceleration",
            Setting::Load => "load",
            Setting::LoadAdvance => "load_advance",
            Setting::MaxStep => "max_step",
            Setting::Theta => "integration.theta",
            Setting::SpectralRadius => "integration.spectral_radius",
            Setting::AccelerationBand => "output.acceleration_band",
            Setting::AccelerationFilter => "output.acceleration_filter",
            Setting::EndTime => "end_time",
            Setting::Tolerance => "solver.tolerance",
            Setting::MaxIterations => "solver.max_iterations",
            Setting::Solver => "solver",
            Setting::StaticStart => "initial.static_position",
            Setting::SteadyStart => "initial.position",
            Setting::RecordSections => "record_sections",
            Setting::ExtremesNodes => "extremes_nodes",
            Setting::ExtremesWindow => "extremes_window",
            Setting::Snapshots => "snapshots",
            Setting::CoMovingLoadAt => "co_moving.load_at",
            Setting::CoMovingTrackLength => "co_moving.track_length",
            Setting::LeftSupport => "supports.left",
            Setting::RightSupport => "supports.right",
            Setting::Friction(name) | Setting::Vehicle(name) | Setting::Beam(name) => name,
        }
    }
}

impl std::fmt::Display for Setting {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The value a setting was refused with: a number, a count, or a choice by its name.
#[derive(Debug, Clone, PartialEq)]
pub enum Refused {
    /// A number.
    Number(f64),
    /// A count.
    Count(usize),
    /// A choice, by its name.
    Choice(&'static str),
}

impl std::fmt::Display for Refused {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Refused::Number(x) => write!(f, "{x}"),
            Refused::Count(n) => write!(f, "{n}"),
            Refused::Choice(name) => f.write_str(name),
        }
    }
}

/// Result alias of this crate.
pub type Result<T, E = TrackError> = std::result::Result<T, E>;
