//! Nonsmooth contact dynamics for frictrack (not yet implemented).
//!
//! This crate will hold the Moreau–Jean θ-method stepper, the per-step friction solvers and the energy
//! bookkeeping of MODEL.md §5–§6. It is empty until the time-stepping issue lands.
