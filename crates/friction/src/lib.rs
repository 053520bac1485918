//! Coulomb friction for frictrack (not yet implemented).
//!
//! This crate will hold the set-valued Coulomb law r ∈ −F_u·Sign(u), discrete friction devices, distributed
//! (ballast) friction and the `ContactSet` (rows H_j, bounds F_j) that both reduce to; see MODEL.md §4.
//! It is empty until the time-stepping issue lands.
