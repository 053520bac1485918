//! # stationary: the wave of a load moving on an infinite track
//!
//! In coordinates that move with the load, s = x − vt, a load crossing an endless uniform track at constant speed
//! leaves a wave W(s) that does not change (docs/theory.md §14): no time stepping, no entry transient, no
//! reflections. This crate solves for it directly on a finite domain closed by exact transparent ends
//! ([`far_field`]): the moving-frame operator ([`operator`]), a semismooth Newton iteration on the soil's contact for
//! tensionless and bilinear soils ([`solve()`]), and the wave's peaks, lift-off zones and power balance ([`wave`]).
//! On the ground ([`ground`], [`ground_contact`]) the ground is a non-local linear operator applied by FFT and the
//! ballast's friction or its lift-off stays local.
//! Continuation in speed ([`solve::solve_from`]) starts each speed from the last one's contact set.

pub mod continuation;
pub mod control;
pub mod error;
pub mod far_field;
pub mod friction;
pub mod ground;
pub mod ground_contact;
pub mod krylov;
pub mod newton;
pub mod operator;
pub mod path_search;
pub mod problem;
mod reading;
pub mod refine;
mod rows;
mod sets;
pub mod solve;
mod status;
pub mod toeplitz;
pub mod wave;

pub use control::Control;
pub use error::{Result, StationaryError};
pub use ground::{FrictionTrack, GroundFrictionProblem, GroundFrictionWave, GroundWindow, solve_on_ground};
pub use ground_contact::{GroundContactProblem, GroundContactWave, solve_with_lift_off};
pub use problem::{Domain, StationaryProblem};
pub use refine::solve_halved;
pub use solve::{ContactGuess, Convergence, solve, solve_from, solve_within};
pub use wave::{PowerBalance, SlipZone, StationaryWave};
