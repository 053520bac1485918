//! Studies for frictrack (not yet implemented).
//!
//! This crate will hold scenarios, speed sweeps, critical-speed search, optimisation, metrics, CSV/JSON output
//! and plots (MODEL.md §7). It is empty until the studies issue lands.
