//! Rail profiles r(x) (m, upward positive) and their slopes r′(x), the input of a wheel–rail contact's gap and drift
//! (docs/theory.md §11): deterministic shapes, a measured profile, a random profile, and sums of them. Wheel flats
//! belong to a wheel, not to the rail: [`WheelFlat`].

use crate::error::{Result, invalid};
use crate::random::RandomProfile;
use std::f64::consts::{PI, TAU};

/// A rail profile.
#[derive(Debug, Clone, PartialEq)]
pub enum Profile {
    /// r = 0.
    Smooth,
    /// r = a·sin(2π(x − x₀)/λ): a corrugation (λ = 30–1000 mm) or a long wave.
    Harmonic {
        /// a (m).
        amplitude: f64,
        /// λ (m) > 0.
        wavelength: f64,
        /// x₀ (m).
        start: f64,
    },
    /// A rise of `height` over [start, start + length], r = 0 before and `height` after (linear: a settlement step).
    Ramp {
        /// Where it begins (m).
        start: f64,
        /// Its length (m) > 0.
        length: f64,
        /// Total rise (m; negative for a drop).
        height: f64,
    },
    /// A dipped joint: r = −(d/2)(1 + cos(2π(x − x_j)/ℓ)) for |x − x_j| ≤ ℓ/2, else 0 (a cosine dip of depth d).
    DippedJoint {
        /// x_j, the middle of the dip (m).
        position: f64,
        /// d (m) > 0, e.g. 3 mm.
        depth: f64,
        /// ℓ (m) > 0, e.g. 1 m.
        length: f64,
    },
    /// A measured profile: points (x, r) with x strictly rising, linear in between, r = the end values beyond.
    Table {
        /// (x m, r m).
        points: Vec<(f64, f64)>,
    },
    /// A random profile from a spectrum.
    Random(RandomProfile),
    /// The sum of several.
    Sum(Vec<Profile>),
}

impl Profile {
    /// Check the parameters (`path` names the profile in errors, e.g. `irregularity`).
    pub fn validate(&self, path: &str) -> Result<()> {
        let positive = |field: &str, v: f64| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(invalid(&format!("{path}.{field}"), v, "must be finite and > 0 (m)"))
            }
        };
        let finite = |field: &str, v: f64| {
            if v.is_finite() { Ok(()) } else { Err(invalid(&format!("{path}.{field}"), v, "must be finite (m)")) }
        };
        match self {
            Profile::Smooth => Ok(()),
            Profile::Harmonic { amplitude, wavelength, start } => {
                finite("amplitude", *amplitude)?;
                positive("wavelength", *wavelength)?;
                finite("start", *start)
            }
            Profile::Ramp { start, length, height } => {
                finite("start", *start)?;
                positive("length", *length)?;
                finite("height", *height)
            }
            Profile::DippedJoint { position, depth, length } => {
                finite("position", *position)?;
                positive("depth", *depth)?;
                positive("length", *length)
            }
            Profile::Table { points } => {
                if points.len() < 2 {
                    return Err(invalid(&format!("{path}.points"), points.len(), "needs at least 2 points"));
                }
                for (i, w) in points.windows(2).enumerate() {
                    let ((x0, r0), (x1, r1)) = (w[0], w[1]);
                    if !(x0.is_finite() && x1.is_finite() && r0.is_finite() && r1.is_finite() && x1 > x0) {
                        return Err(invalid(
                            &format!("{path}.points[{}]", i + 1),
                            format!("({x1}, {r1})"),
                            format!("x must rise strictly and every value be finite (after x = {x0} m)"),
                        ));
                    }
                }
                Ok(())
            }
            Profile::Random(random) => random.settings.validate(),
            Profile::Sum(parts) => parts.iter().enumerate().try_for_each(|(i, p)| p.validate(&format!("{path}[{i}]"))),
        }
    }

    /// (r(x), r′(x)): height (m) and slope (m/m) at x (m). At a kink (ramp ends, table points) the slope is the one
    /// on the right.
    pub fn height_slope(&self, x: f64) -> (f64, f64) {
        match self {
            Profile::Smooth => (0.0, 0.0),
            Profile::Harmonic { amplitude, wavelength, start } => {
                let k = TAU / wavelength;
                let (s, c) = crate::trig::sin_cos(k * (x - start));
                (amplitude * s, amplitude * k * c)
            }
            Profile::Ramp { start, length, height } => {
                let t = (x - start) / length;
                if t < 0.0 {
                    (0.0, 0.0)
                } else if t < 1.0 {
                    (height * t, height / length)
                } else {
                    (*height, 0.0)
                }
            }
            Profile::DippedJoint { position, depth, length } => {
                let u = x - position;
                if u.abs() > 0.5 * length {
                    return (0.0, 0.0);
                }
                let k = TAU / length;
                let (s, c) = crate::trig::sin_cos(k * u);
                (-0.5 * depth * (1.0 + c), 0.5 * depth * k * s)
            }
            Profile::Table { points } => table(points, x),
            Profile::Random(random) => random.height_slope(x),
            Profile::Sum(parts) => parts.iter().fold((0.0, 0.0), |(r, s), p| {
                let (dr, ds) = p.height_slope(x);
                (r + dr, s + ds)
            }),
        }
    }

    /// An upper bound of |r′(x)| over every x (m/m), from the shapes' own slopes: a|2π/λ| for a harmonic, rise over
    /// length for a ramp, dπ/ℓ for a dipped joint, the steepest segment of a table, Σ|A_k|Ω_k for a random profile
    /// (the triangle inequality over its harmonics), the sum of the parts' for a sum. Exact for a single shape but a
    /// random profile, whose harmonics never all peak at once.
    pub fn slope_bound(&self) -> f64 {
        match self {
            Profile::Smooth => 0.0,
            Profile::Harmonic { amplitude, wavelength, .. } => amplitude.abs() * TAU / wavelength,
            Profile::Ramp { length, height, .. } => height.abs() / length,
            Profile::DippedJoint { depth, length, .. } => depth * std::f64::consts::PI / length,
            Profile::Table { points } => {
                points.windows(2).map(|w| ((w[1].1 - w[0].1) / (w[1].0 - w[0].0)).abs()).fold(0.0, f64::max)
            }
            Profile::Random(random) => random.harmonics.iter().map(|h| h.amplitude.abs() * h.wavenumber).sum(),
            Profile::Sum(parts) => parts.iter().map(Profile::slope_bound).sum(),
        }
    }

    /// r at `count` points x₀ + i·`spacing` (m).
    pub fn sample(&self, start: f64, spacing: f64, count: usize) -> Vec<(f64, f64)> {
        (0..count)
            .map(|i| {
                let x = start + i as f64 * spacing;
                (x, self.height_slope(x).0)
            })
            .collect()
    }
}

/// Linear interpolation in a table of rising x, constant beyond its ends.
fn table(points: &[(f64, f64)], x: f64) -> (f64, f64) {
    let i = points.partition_point(|p| p.0 <= x);
    if i == 0 {
        return (points[0].1, 0.0);
    }
    if i == points.len() {
        return (points[points.len() - 1].1, 0.0);
    }
    let ((x0, r0), (x1, r1)) = (points[i - 1], points[i]);
    let slope = (r1 - r0) / (x1 - x0);
    (r0 + slope * (x - x0), slope)
}

/// A wheel flat: a chord of length ℓ cut into a wheel of diameter D, depth d = D/2 − √(D²/4 − ℓ²/4) ≈ ℓ²/(4D), met
/// once per revolution (every πD of the wheel's travel s). Seen from the wheel centre as a haversine dip (the rounded
/// flat of Newton & Clark 1979, J. Mech. Eng. Sci. 21:287–297): r(s) = −(d/2)(1 − cos(2π s′/ℓ)) for
/// s′ = (s − s₀) mod πD < ℓ, else 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelFlat {
    /// ℓ (m) > 0.
    pub length: f64,
    /// D (m), larger than ℓ.
    pub diameter: f64,
    /// s₀: travel (m) at which the flat first meets the rail.
    pub first_contact: f64,
}

impl WheelFlat {
    /// Check ℓ, D and s₀ (`path` names the flat in errors).
    pub fn validate(&self, path: &str) -> Result<()> {
        let (l, d) = (self.length, self.diameter);
        if !(d.is_finite() && d > 0.0) {
            return Err(invalid(&format!("{path}.diameter"), d, "must be finite and > 0 (m)"));
        }
        if !(l.is_finite() && l > 0.0 && l < d) {
            return Err(invalid(&format!("{path}.length"), l, format!("must lie in (0, D = {d}) m")));
        }
        if !self.first_contact.is_finite() {
            return Err(invalid(&format!("{path}.first_contact"), self.first_contact, "must be finite (m)"));
        }
        Ok(())
    }

    /// d (m): the exact chord depth.
    pub fn depth(&self) -> f64 {
        let r = 0.5 * self.diameter;
        r - (r * r - 0.25 * self.length * self.length).sqrt()
    }

    /// (r, dr/ds) at the wheel's travel `s` (m).
    pub fn height_slope(&self, s: f64) -> (f64, f64) {
        let u = (s - self.first_contact).rem_euclid(PI * self.diameter);
        if u >= self.length {
            return (0.0, 0.0);
        }
        let k = TAU / self.length;
        let (sin, cos) = crate::trig::sin_cos(k * u);
        let d = self.depth();
        (-0.5 * d * (1.0 - cos), -0.5 * d * k * sin)
    }
}

/// What a wheel's centre follows: the rail's profile at the wheel's place x and the wheel's own flat, if any, at its
/// travel s (both m; d/ds = d/dx for a wheel rolling along x).
#[derive(Debug, Clone, PartialEq)]
pub struct WheelTrack {
    /// The rail.
    pub rail: Profile,
    /// The wheel's flat.
    pub flat: Option<WheelFlat>,
}

impl WheelTrack {
    /// A smooth wheel over `rail`.
    pub fn rail(rail: Profile) -> Self {
        Self { rail, flat: None }
    }

    /// (height m, slope) under the wheel at `x` after a travel of `travel` (m).
    pub fn height_slope(&self, x: f64, travel: f64) -> (f64, f64) {
        let (r, s) = self.rail.height_slope(x);
        match &self.flat {
            Some(flat) => {
                let (f, fs) = flat.height_slope(travel);
                (r + f, s + fs)
            }
            None => (r, s),
        }
    }
}
