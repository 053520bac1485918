//! A wheel rolling at constant speed over rigid ground with a rail profile r(x) (docs/theory.md §9, §12): the moving
//! interaction with row e_w (the wheel's DOF), gap g = z_w − r(x_c) and relative velocity U = ż_w − v·r′(x_c), so the
//! rheonomic velocity at t_{k+1} is −v·r′(x_c(t_{k+1})). Off the beam the rail is this rigid ground; on rigid ground
//! alone it is the textbook base excitation of a vehicle.
//!
//! With the rigid law the wheel's positions are projected onto the ground after each step ([`nscd::position`]): a
//! velocity-level constraint alone follows r with the trapezoid's O(h³) error a step, and a drift of nanometres
//! above the ground made Moreau's rule drop the contact for a step (a massless wheel then sank into the ground and
//! rode on 3.5 mm low). A closed contact now stays in the index set and ends every step on the ground.

use friction::{InteractionKind, InteractionRow, Law};
use irregularity::WheelTrack;
use nscd::{MovingInteraction, MovingState};

/// A wheel on rigid ground.
#[derive(Debug, Clone)]
pub struct WheelOnGround {
    /// The wheel's DOF in the system.
    pub dof: usize,
    /// Where the wheel is at t = 0 (m).
    pub start: f64,
    /// Speed (m/s).
    pub speed: f64,
    /// The ground's profile and the wheel's flat.
    pub track: WheelTrack,
    /// The contact law: `Law::Signorini` (rigid, Newton impact) or `Law::Compliant`; its gap field is not used.
    pub law: Law,
}

impl WheelOnGround {
    /// Where the wheel is at `time` (m).
    pub fn position(&self, time: f64) -> f64 {
        self.start + self.speed * time
    }
}

impl MovingInteraction for WheelOnGround {
    fn law(&self) -> Law {
        self.law
    }

    fn kind(&self) -> InteractionKind {
        InteractionKind::Contact
    }

    fn update(&mut self, time: f64, step: f64, q: &[f64], v: &[f64], row: &mut InteractionRow) -> MovingState {
        row.set_entries([(self.dof, 1.0)]);
        let (x, next) = (self.position(time), self.position(time + step));
        let (r, slope) = self.track.height_slope(x, x - self.start);
        MovingState {
            gap: q[self.dof] - r,
            velocity: v[self.dof] - self.speed * slope,
            rheonomic: -self.speed * self.track.height_slope(next, next - self.start).1,
        }
    }

    fn gap(&self, time: f64, q: &[f64], row: &mut InteractionRow) -> f64 {
        row.set_entries([(self.dof, 1.0)]);
        let x = self.position(time);
        q[self.dof] - self.track.height_slope(x, x - self.start).0
    }
}
