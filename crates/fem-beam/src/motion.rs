//! How the loads move along the track (docs/theory.md §10.5): the first axle's position s(t) (m) from its start s(0),
//! at a constant speed or through a speed profile over position — knots (x_i, v_i), the speed changing at constant
//! acceleration a_i = (v_{i+1}² − v_i²)/(2(x_{i+1} − x_i)) between them (v² linear in x) and held outside them. A
//! train's axles follow at their offsets, all at the same speed. Over each piece
//!
//! ```text
//! s(t) = x_j + v_j τ + ½ a_j τ²,   ṡ(t) = v_j + a_j τ,   τ = t − t_j,
//! t_{j+1} − t_j = 2(x_{j+1} − x_j)/(v_j + v_{j+1}),
//! ```
//!
//! so the time at which the load reaches x is τ = 2Δ/(v_j + √(v_j² + 2a_jΔ)), Δ = x − x_j (no cancellation when
//! a_j < 0). At constant speed s(t) = s(0) + vt to the bit.

use crate::error::{FemError, Result};

/// One piece of the motion: from `time` (s) at `position` (m) with `speed` (m/s), at `acceleration` (m/s²).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Piece {
    time: f64,
    position: f64,
    speed: f64,
    acceleration: f64,
}

impl Piece {
    fn position(&self, t: f64) -> f64 {
        let tau = t - self.time;
        self.position + self.speed * tau + 0.5 * self.acceleration * tau * tau
    }

    fn speed(&self, t: f64) -> f64 {
        self.speed + self.acceleration * (t - self.time)
    }

    /// τ at which the piece reaches `x` (m) from its start.
    fn duration_to(&self, x: f64) -> f64 {
        let delta = x - self.position;
        if self.acceleration == 0.0 {
            return delta / self.speed;
        }
        let end = (self.speed * self.speed + 2.0 * self.acceleration * delta).max(0.0).sqrt();
        2.0 * delta / (self.speed + end)
    }
}

/// The first axle's motion s(t), t ≥ 0 (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Motion {
    pieces: Vec<Piece>,
}

impl Motion {
    /// s(t) = `start` + `speed`·t (m, m/s).
    pub fn constant(start: f64, speed: f64) -> Self {
        Self { pieces: vec![Piece { time: 0.0, position: start, speed, acceleration: 0.0 }] }
    }

    /// The motion from `start` (m) through `knots` (x_i m, v_i m/s): x strictly increasing, v finite and > 0; the
    /// speed held at v_0 before x_0 and at v_n after x_n. Empty knots: refused (use [`Motion::constant`]). Knots of
    /// one speed are [`Motion::constant`].
    pub fn through(start: f64, knots: &[(f64, f64)]) -> Result<Self> {
        check_knots(knots)?;
        if knots.iter().all(|k| k.1 == knots[0].1) {
            // A profile that never changes the speed is the constant speed, to the bit.
            return Ok(Self::constant(start, knots[0].1));
        }
        // v(x): held outside the knots, v² linear in x between them.
        let speed_at = |x: f64| {
            let i = knots.partition_point(|k| k.0 <= x);
            match i {
                0 => knots[0].1,
                i if i == knots.len() => knots[i - 1].1,
                i => {
                    let ((xa, va), (xb, vb)) = (knots[i - 1], knots[i]);
                    (va * va + (vb * vb - va * va) * (x - xa) / (xb - xa)).sqrt()
                }
            }
        };
        let mut bounds = vec![start];
        bounds.extend(knots.iter().map(|k| k.0).filter(|&x| x > start));
        let mut pieces: Vec<Piece> = Vec::with_capacity(bounds.len());
        for (i, &position) in bounds.iter().enumerate() {
            let speed = speed_at(position);
            let acceleration = bounds.get(i + 1).map_or(0.0, |&next| {
                let v = speed_at(next);
                (v * v - speed * speed) / (2.0 * (next - position))
            });
            let time = pieces.last().map_or(0.0, |p| p.time + p.duration_to(position));
            pieces.push(Piece { time, position, speed, acceleration });
        }
        Ok(Self { pieces })
    }

    fn piece_at_time(&self, t: f64) -> &Piece {
        let i = self.pieces.partition_point(|p| p.time <= t).max(1);
        &self.pieces[i - 1]
    }

    /// s(t) (m).
    pub fn position(&self, t: f64) -> f64 {
        self.piece_at_time(t).position(t)
    }

    /// ṡ(t) (m/s).
    pub fn speed(&self, t: f64) -> f64 {
        self.piece_at_time(t).speed(t)
    }

    /// The time t ≥ 0 (s) at which the first axle reaches `x` (m; 0 for x at or behind its start).
    pub fn time_at(&self, x: f64) -> f64 {
        let i = self.pieces.partition_point(|p| p.position <= x).max(1);
        let piece = &self.pieces[i - 1];
        (piece.time + piece.duration_to(x)).max(0.0)
    }

    /// The speed (m/s) where the first axle is at `x` (m).
    pub fn speed_at(&self, x: f64) -> f64 {
        self.speed(self.time_at(x))
    }

    /// The largest and smallest speeds (m/s) from the start to where the first axle is at `end` (m): the extremes
    /// are at the pieces' ends (speed monotone over each).
    pub fn speed_range(&self, end: f64) -> (f64, f64) {
        let mut speeds = vec![self.speed(0.0), self.speed_at(end)];
        speeds.extend(self.pieces.iter().filter(|p| p.position <= end).map(|p| p.speed));
        speeds.iter().fold((f64::NEG_INFINITY, f64::INFINITY), |(hi, lo), &v| (hi.max(v), lo.min(v)))
    }

    /// The same motion `distance` (m) further back at every time (a co-moving window's shift).
    pub fn shift_back(&mut self, distance: f64) {
        for piece in &mut self.pieces {
            piece.position -= distance;
        }
    }
}

/// The knots of a speed profile: at least one, positions finite and strictly increasing, speeds finite and > 0.
pub fn check_knots(knots: &[(f64, f64)]) -> Result<()> {
    let field = "load.speed_profile";
    if knots.is_empty() {
        return Err(FemError::InvalidField { field, value: 0.0, allowed: "needs one [x, v] knot at least" });
    }
    for (i, &(x, v)) in knots.iter().enumerate() {
        if !x.is_finite() {
            return Err(FemError::InvalidField { field, value: x, allowed: "positions must be finite (m)" });
        }
        if !(v.is_finite() && v > 0.0) {
            return Err(FemError::InvalidField { field, value: v, allowed: "speeds must be finite and > 0 (m/s)" });
        }
        if i > 0 && x <= knots[i - 1].0 {
            return Err(FemError::InvalidField {
                field,
                value: x,
                allowed: "positions must increase from knot to knot",
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constant_speed_is_start_plus_speed_times_time_to_the_bit() {
        let m = Motion::constant(-3.7, 61.3);
        for t in [0.0, 1e-3, 0.123456, 2.5] {
            assert_eq!(m.position(t), -3.7 + 61.3 * t);
            let x = -3.7 + 61.3 * t;
            assert_eq!(m.time_at(x), (x - -3.7) / 61.3);
        }
    }

    /// Uniform acceleration from 20 to 40 m/s over 0 … 300 m (a = 2 m/s²) started 10 m before the first knot: the
    /// closed forms of constant acceleration, the times inverting the positions, the speed held after the last knot.
    #[test]
    fn a_profile_follows_constant_acceleration_between_its_knots() {
        let m = Motion::through(-10.0, &[(0.0, 20.0), (300.0, 40.0)]).unwrap();
        let a = (40.0f64.powi(2) - 20.0f64.powi(2)) / 600.0;
        assert!((a - 2.0).abs() < 1e-15);
        let t0 = 0.5; // 10 m at 20 m/s
        assert!((m.time_at(0.0) - t0).abs() < 1e-15);
        for tau in [0.0, 1.0, 5.0, 9.999] {
            let t = t0 + tau;
            assert!((m.position(t) - (20.0 * tau + 0.5 * a * tau * tau)).abs() < 1e-11);
            assert!((m.speed(t) - (20.0 + a * tau)).abs() < 1e-12);
            assert!((m.time_at(m.position(t)) - t).abs() < 1e-12);
        }
        // 300 m at a mean speed of 30 m/s: 10 s; then 40 m/s.
        assert!((m.time_at(300.0) - 10.5).abs() < 1e-12);
        assert!((m.position(12.5) - 380.0).abs() < 1e-11);
        assert_eq!(m.speed_range(300.0), (40.0, 20.0));
        // Braking the same way is the reverse, and a run started inside a piece takes its speed there.
        let braking = Motion::through(50.0, &[(0.0, 40.0), (300.0, 20.0)]).unwrap();
        let v = (1600.0f64 - 2.0 * 2.0 * 50.0).sqrt();
        assert!((braking.speed(0.0) - v).abs() < 1e-12);
        assert!((braking.time_at(300.0) - 250.0 / (0.5 * (v + 20.0))).abs() < 1e-12);
    }

    #[test]
    fn bad_knots_are_refused_by_key() {
        for knots in [vec![], vec![(0.0, 0.0)], vec![(0.0, 10.0), (0.0, 20.0)], vec![(f64::NAN, 1.0)]] {
            let error = Motion::through(0.0, &knots).unwrap_err().to_string();
            assert!(error.contains("load.speed_profile"), "{error}");
        }
    }
}
