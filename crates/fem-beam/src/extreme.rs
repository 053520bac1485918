//! The words every response is reported in (docs/theory.md §6, §13, §14): an [`Extreme`] — a value, where and when
//! — its downward and upward pair ([`DeflectionExtremes`]) and a [`LiftOffZone`] — neighbouring sections where the beam left a unilateral soil. A time-domain run, a sweep
//! of runs, the co-moving window and the stationary wave all report through these two types, so that a deflection's
//! peak has one shape in every JSON file: `{"value": …, "position": …, "time": …}`.
//!
//! Positions are x along the beam (m) in a run, s = x − vt (m, positive ahead of the load) in the load's moving frame,
//! where a steady state has no time. Deflection extremes are magnitudes (m, ≥ 0); an extreme of value 0 never
//! happened (no step deflected that way), and has neither place nor time.

/// An extreme of a response: its value, where and when it happened.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(deny_unknown_fields))]
pub struct Extreme {
    /// The value: a magnitude (m, ≥ 0) for deflections and gaps, m/s² for accelerations, N·m for moments.
    pub value: f64,
    /// Where (m): the node in a run, s in the moving frame; None if it never happened.
    pub position: Option<f64>,
    /// When (s); None if it never happened, or in the moving frame of a steady state.
    pub time: Option<f64>,
}

impl Extreme {
    /// `value` at node `position` (m), time `time` (s) of a run.
    pub fn at(value: f64, position: f64, time: f64) -> Self {
        Self { value, position: Some(position), time: Some(time) }
    }

    /// `value` at s (m) of a steady state in the load's moving frame, which has no time.
    pub fn in_frame(value: f64, s: f64) -> Self {
        Self { value, position: Some(s), time: None }
    }

    /// Keep the larger of this extreme and `value` at `position` and `time` — the running maximum of a run's
    /// observers, which leaves a value of 0 (never happened) without place or time.
    pub fn raise(&mut self, value: f64, position: f64, time: f64) {
        if value > self.value {
            *self = Self::at(value, position, time);
        }
    }

    /// Where and when, if it happened in a run (a steady state's extreme has no time).
    pub fn place(&self) -> Option<(f64, f64)> {
        self.position.zip(self.time)
    }

    /// This extreme if it happened (a value above 0).
    pub fn happened(&self) -> Option<&Extreme> {
        (self.value > 0.0).then_some(self)
    }
}

/// The largest downward and upward deflections of a response (magnitudes, with where and when): a run's over its
/// nodes and steps, a window's while the load was inside it, a steady wave's over s. `T` is how each is told: an
/// [`Extreme`] (the default), a bare magnitude (m), or a wrapper that adds what a report needs (an `Option` where it
/// may be undefined). Every (downward, upward) pair frictrack reports is this type; in JSON it is written flat into
/// its holder (`#[serde(flatten)]`) as `max_downward_deflection` and `max_upward_deflection`, or — through
/// [`in_window`] — as `window_max_downward_deflection` and `window_max_upward_deflection`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct DeflectionExtremes<T = Extreme> {
    /// Largest downward deflection (m, magnitude), where and when.
    #[cfg_attr(feature = "serde", serde(rename = "max_downward_deflection"))]
    pub max_downward: T,
    /// Largest upward deflection (m, magnitude; 0 if the beam never rose), where and when.
    #[cfg_attr(feature = "serde", serde(rename = "max_upward_deflection"))]
    pub max_upward: T,
}

impl<T> DeflectionExtremes<T> {
    /// Each of the pair told another way: `tell(max_downward)`, `tell(max_upward)`.
    pub fn map<U>(self, mut tell: impl FnMut(T) -> U) -> DeflectionExtremes<U> {
        DeflectionExtremes { max_downward: tell(self.max_downward), max_upward: tell(self.max_upward) }
    }
}

/// The JSON names of a window's pair, `window_max_downward_deflection` and `window_max_upward_deflection`: a serde
/// `with` module for a flattened [`DeflectionExtremes`] (`#[serde(flatten, with = "fem_beam::extreme::in_window")]`).
#[cfg(feature = "serde")]
pub mod in_window {
    use super::DeflectionExtremes;
    use serde::ser::SerializeMap;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    /// The pair's two entries under their window names.
    pub fn serialize<T: Serialize, S: Serializer>(pair: &DeflectionExtremes<T>, to: S) -> Result<S::Ok, S::Error> {
        let mut map = to.serialize_map(Some(2))?;
        map.serialize_entry("window_max_downward_deflection", &pair.max_downward)?;
        map.serialize_entry("window_max_upward_deflection", &pair.max_upward)?;
        map.end()
    }

    /// The pair read back from its window names.
    pub fn deserialize<'de, T: Deserialize<'de>, D: Deserializer<'de>>(
        from: D,
    ) -> Result<DeflectionExtremes<T>, D::Error> {
        #[derive(Deserialize)]
        struct Window<T> {
            window_max_downward_deflection: T,
            window_max_upward_deflection: T,
        }
        let window = Window::deserialize(from)?;
        Ok(DeflectionExtremes {
            max_downward: window.window_max_downward_deflection,
            max_upward: window.window_max_upward_deflection,
        })
    }
}

/// Neighbouring sections of a unilateral soil where the beam was above the soil's undeformed surface: in a run, at
/// some time of it; in a steady state, in the moving frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(deny_unknown_fields))]
pub struct LiftOffZone {
    /// The first section's position (m; s in the moving frame).
    pub from: f64,
    /// The last section's position (m).
    pub to: f64,
    /// Sections in the zone.
    pub sections: usize,
    /// The largest gap between the beam and the soil's surface (m), where and when.
    pub largest_gap: Extreme,
    /// When the first of the sections lifted (s); None in the moving frame.
    pub first_time: Option<f64>,
    /// When the last of them was last lifted (s); None in the moving frame.
    pub last_time: Option<f64>,
}

impl LiftOffZone {
    /// Widen this zone by its neighbour `next` (further along x): the union of the sections, the earlier start, the
    /// later end and the larger gap.
    pub fn absorb(&mut self, next: &LiftOffZone) {
        let earlier = |a: Option<f64>, b: Option<f64>| a.zip(b).map(|(a, b)| a.min(b)).or(a).or(b);
        let later = |a: Option<f64>, b: Option<f64>| a.zip(b).map(|(a, b)| a.max(b)).or(a).or(b);
        self.to = next.to;
        self.first_time = earlier(self.first_time, next.first_time);
        self.last_time = later(self.last_time, next.last_time);
        if next.largest_gap.value > self.largest_gap.value {
            self.largest_gap = next.largest_gap;
        }
        self.sections += next.sections;
    }
}

/// The zone with the largest gap among `zones`, if any.
pub fn largest_zone(zones: &[LiftOffZone]) -> Option<&LiftOffZone> {
    zones.iter().max_by(|a, b| a.largest_gap.value.total_cmp(&b.largest_gap.value))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_extreme_that_never_rose_above_zero_has_no_place_or_time() {
        let mut e = Extreme::default();
        e.raise(0.0, 3.0, 1.0);
        e.raise(-1.0, 3.0, 1.0);
        assert_eq!(e.happened(), None);
        assert_eq!((e.position, e.time), (None, None));
        e.raise(2.0, 4.0, 0.5);
        e.raise(1.0, 5.0, 0.7);
        assert_eq!(e, Extreme::at(2.0, 4.0, 0.5));
    }

    #[test]
    fn absorbing_a_neighbour_keeps_the_larger_gap_and_the_widest_times() {
        let zone = |from, gap, t0, t1| LiftOffZone {
            from,
            to: from,
            sections: 1,
            largest_gap: Extreme::at(gap, from, t0),
            first_time: Some(t0),
            last_time: Some(t1),
        };
        let mut a = zone(1.0, 1e-3, 0.2, 0.3);
        a.absorb(&zone(1.5, 2e-3, 0.1, 0.25));
        assert_eq!((a.from, a.to, a.sections), (1.0, 1.5, 2));
        assert_eq!(a.largest_gap, Extreme::at(2e-3, 1.5, 0.1));
        assert_eq!((a.first_time, a.last_time), (Some(0.1), Some(0.3)));
        let mut framed = LiftOffZone { largest_gap: Extreme::in_frame(1e-3, -2.0), ..LiftOffZone::default() };
        framed.absorb(&LiftOffZone { to: 1.0, largest_gap: Extreme::in_frame(5e-4, 1.0), ..LiftOffZone::default() });
        assert_eq!((framed.first_time, framed.largest_gap.position), (None, Some(-2.0)));
    }
}
