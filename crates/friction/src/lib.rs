//! # friction: the nonsmooth laws and the friction interactions (docs/theory.md §4, §9)
//!
//! A friction device with maximal force F_u on a section of velocity u applies r ∈ −F_u·Sign(u): stuck while
//! |r| ≤ F_u, slipping with |r| = F_u against the motion. Discrete devices and friction distributed in the ballast
//! both reduce to an [`InteractionSet`]: rows H_α (the relative velocity U_α = H_α q̇ over the free DOFs) with a
//! [`Law`] each — Coulomb friction, rigid (Signorini) contact with Newton impact, or a compliant unilateral stop;
//! the generalised force is Hᵀr.
//!
//! - [`law`]: the laws, each with its behaviour in the step, and the one form they all take (an impulse in
//!   [lo, hi] against its velocity) as a projection, and its natural residual.
//! - `drift`: the drift of the compliant laws' rows; `step`: what a law reads of the step — the scheme's weights,
//!   the row's start (both re-exported by [`law`]).
//! - [`hertz`]: Hertz's law linearised within the step (its Newton iterations' state).
//! - [`interaction`]: interaction sets, their sparse rows, laws and kinds.
//!
//! The crate knows no beam: what places devices and ballast sections on a beam mesh lives in `track`.

mod drift;
pub mod hertz;
pub mod interaction;
pub mod law;
mod step;

pub use interaction::{InteractionKind, InteractionRow, InteractionSet};
pub use law::Law;
