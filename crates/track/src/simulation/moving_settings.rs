//! What moves on the beam (docs/theory.md §10.5): the load, its speed — constant, or changing through a speed
//! profile over position — and where it starts.

use super::settings::{InitialState, Load};
use crate::error::{Result, Setting, invalid};
use fem_beam::Motion;

/// What moves on the beam: the load, its speed and where it starts.
#[derive(Debug, Clone, PartialEq)]
pub struct MovingLoadSettings {
    /// Load speed v (m/s) > 0. Default 200. With a speed `profile`, the speed it gives at x = 0
    /// ([`MovingLoadSettings::with_profile`] sets both).
    pub speed: f64,
    /// The speed profile: knots (x m, v m/s) of the first axle's speed over its position, v² linear in x between them
    /// and held outside ([`Motion::through`]); empty: the constant `speed`. Default empty.
    pub profile: Vec<(f64, f64)>,
    /// The constant acceleration a (m/s²) the profile was made from ([`MovingLoadSettings::with_acceleration`]),
    /// so that the run can be set at another speed ([`MovingLoadSettings::at_speed`]); None for a given profile.
    pub acceleration: Option<f64>,
    /// What crosses. Default one force of 83.4 kN.
    pub load: Load,
    /// Initial state (and with it the first axle's start position). Default rest, the load entering at x = 0.
    pub initial: InitialState,
    /// The speed every speed of the run must stay below. Default the beam's own bar wave.
    pub speed_limit: SpeedLimit,
}

/// The speed a load must stay below (docs/theory.md §2, §19).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum SpeedLimit {
    /// The beam's bar wave speed √(E/ρ) (5.2 km/s in steel, 3.7 km/s in concrete): beyond it no beam theory holds,
    /// and the step h = Δx/v would shrink towards round-off.
    #[default]
    BarWave,
    /// The fastest wave (m/s) of a ground under a composite track-and-embankment beam, whose E and ρ are a section
    /// convention (only EI and ρA are its own, so √(E/ρ) moves as EI is split): beyond every wave of the model no
    /// load is meant.
    FastestGroundWave(f64),
}

impl SpeedLimit {
    /// The limit (m/s) on `beam`, and what it is, in words.
    pub fn on(self, beam: &fem_beam::Beam) -> (f64, String) {
        match self {
            SpeedLimit::BarWave => (beam.bar_wave_speed(), "the beam's bar wave speed √(E/ρ)".into()),
            SpeedLimit::FastestGroundWave(speed) => {
                (speed, "the ground's fastest wave (its largest compression wave speed C_p)".into())
            }
        }
    }
}

impl Default for MovingLoadSettings {
    fn default() -> Self {
        Self {
            speed: 200.0,
            profile: Vec::new(),
            acceleration: None,
            load: Load::default(),
            initial: InitialState::Rest,
            speed_limit: SpeedLimit::BarWave,
        }
    }
}

impl MovingLoadSettings {
    /// The settings with the speed `profile` (knots (x m, v m/s)) and `speed` its speed at x = 0; refused by key
    /// ([`fem_beam::motion::check_knots`]) if a knot is bad.
    pub fn with_profile(mut self, profile: Vec<(f64, f64)>) -> Result<Self> {
        self.speed = Motion::through(0.0, &profile)?.speed(0.0);
        self.profile = profile;
        Ok(self)
    }

    /// The settings with a constant acceleration `a` (m/s², negative brakes; 0 keeps the constant speed), `speed`
    /// being the speed at x = 0: the profile v² = speed² + 2a·x over the first axle's travel `(start, end)` (m).
    /// Refused by key where the load would stop before `end` (braking) or would have been at rest after `start`.
    pub fn with_acceleration(mut self, a: f64, (start, end): (f64, f64)) -> Result<Self> {
        if !a.is_finite() {
            return Err(invalid(Setting::Acceleration, a, "must be finite (m/s²)"));
        }
        if a == 0.0 {
            return Ok(self);
        }
        let speed = self.speed;
        let squared = |x: f64| speed * speed + 2.0 * a * x;
        let stop = -speed * speed / (2.0 * a);
        if a < 0.0 && squared(end) <= 0.0 {
            let allowed = format!(
                "brings the load to rest at x = {stop:.1} m, but the run needs it moving until its first axle reaches \
                 {end:.1} m (where the last axle has left the beam): brake less, or start faster"
            );
            return Err(invalid(Setting::Acceleration, a, allowed));
        }
        if a > 0.0 && squared(start) <= 0.0 {
            let allowed = format!(
                "means the load was at rest at x = {stop:.1} m, after its start at {start:.1} m: accelerate less, or \
                 start the load further on"
            );
            return Err(invalid(Setting::Acceleration, a, allowed));
        }
        self = self.with_profile(vec![(start, squared(start).sqrt()), (end, squared(end).sqrt())])?;
        (self.speed, self.acceleration) = (speed, Some(a));
        Ok(self)
    }

    /// The same run at `speed` (m/s): its constant speed, or with a constant acceleration the speed at x = 0 over the
    /// same travel; refused by key for a given speed profile, which sets the speeds itself.
    pub fn at_speed(&self, speed: f64) -> Result<Self> {
        let moved = Self { speed, profile: Vec::new(), acceleration: None, ..self.clone() };
        match (self.acceleration, self.profile.first().zip(self.profile.last())) {
            (_, None) => Ok(moved),
            (Some(a), Some((&(start, _), &(end, _)))) => moved.with_acceleration(a, (start, end)),
            (None, Some(_)) => Err(invalid(
                Setting::SpeedProfile,
                speed,
                "a speed profile sets the speeds itself: a run at another speed (a sweep's) does not take it; leave \
                 the profile out to sweep speeds, or give a constant acceleration",
            )),
        }
    }

    /// How the first axle moves from `start` (m): at the constant `speed`, or through the `profile` (knots checked
    /// when the settings are validated; a bad one falls back to the constant speed, never reached after
    /// validation).
    pub fn motion(&self, start: f64) -> Motion {
        if self.profile.is_empty() {
            return Motion::constant(start, self.speed);
        }
        Motion::through(start, &self.profile).unwrap_or_else(|_| Motion::constant(start, self.speed))
    }

    /// The largest speed (m/s) the load reaches: `speed`, or the profile's fastest knot.
    pub fn largest_speed(&self) -> f64 {
        self.profile.iter().fold(self.speed, |v, &(_, knot)| v.max(knot))
    }

    /// The key that sets the speed, for an error about it: the acceleration, the profile or the constant speed.
    pub fn speed_setting(&self) -> Setting {
        match (self.acceleration, self.profile.is_empty()) {
            (Some(_), _) => Setting::Acceleration,
            (None, false) => Setting::SpeedProfile,
            (None, true) => Setting::Speed,
        }
    }

    /// Whether the speed changes during the run.
    pub fn changes_speed(&self) -> bool {
        self.profile.iter().any(|&(_, v)| v != self.speed)
    }

    /// The profile's knots, and `speed` as the profile's speed at x = 0 (to 1e-9 relative).
    pub(crate) fn validate_profile(&self) -> Result<()> {
        if self.profile.is_empty() {
            return Ok(());
        }
        let at_zero = Motion::through(0.0, &self.profile)?.speed(0.0);
        // With an acceleration, `speed` is v at x = 0 even where the travel starts beyond it.
        if self.acceleration.is_none() && (at_zero - self.speed).abs() > 1e-9 * at_zero {
            return Err(invalid(
                Setting::Speed,
                self.speed,
                format!("must be the speed profile's speed at x = 0, {at_zero} m/s (MovingLoadSettings::with_profile)"),
            ));
        }
        Ok(())
    }
}
