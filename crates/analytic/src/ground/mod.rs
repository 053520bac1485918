//! The ground under the track (docs/theory.md §19): horizontal visco-elastic layers over a half-space, and their
//! surface response to a vertical load e^{i(ωt − kx)} in the frequency–wavenumber domain — the exact stiffness
//! method of Kausel & Roësset (1981, BSSA 71): each layer a 4 × 4 dynamic stiffness between its top and bottom
//! (u, w), the half-space a 2 × 2 one, condensed from the bottom up to the surface.
//!
//! - `profile`: [`GroundProfile`] — the layers and the half-space, their complex moduli, the checks of a profile.
//! - `half_space`: the half-space's stiffness, in a closed form that stays finite as ω/k → 0.
//! - `layer`: a layer's stiffness from the transfer matrix exp(A h) of its first-order system, on sublayers thin
//!   enough (|k|h, ωh/|C_s| ≤ 1) that neither the static limit nor thick layers lose digits.
//! - `filon`: the Fourier integral of a piecewise cubic, exact at any s (the moving wave's last step).
//! - `fitted`: [`FittedFoundation`] — a spring, dashpot and co-vibrating mass fitted to a line support along a
//!   moving load's line ω = kv, with its wave's error: what a run in time takes for the ground.
//! - `fitted_embankment`: the same fit of the ground under the two-beam track's embankment, to what the rail feels.
//! - `flexibility`: the surface flexibility F_zz(k, ω) of the profile, to the depth a wave reaches.
//! - `rayleigh_modes`: the trapped Rayleigh modes' phase velocities at a frequency (det K = 0 of the free surface).
//! - `line_support`: [`LineSupport`], a beam's support per wave: a Winkler foundation or the strip's k_eq.
//! - `moving_load`: [`GroundedBeam`] — a beam on a line support under a moving force, its steady wave by one
//!   Fourier integral over an adaptively sampled spectrum.
//! - `receptance`: the beam's point receptance α(ω) on a line support (the ground's strip, or a spring).
//! - `thin_layer`: the same modes by the thin-layer method (finite elements in depth), the independent check.
//! - `track_on_embankment`: [`TrackOnEmbankment`] — a rail on pads, sleepers and ballast over an embankment beam on
//!   a support (the two-beam track), as the rail's line support.
//! - `track_interface`: [`InterfaceSpectra`] — the two-beam track's sleepers-less-embankment deflection and the
//!   waves of a pair of forces across the ballast: what a tensionless ballast on the ground needs.
//! - `strip`: [`StripGround`] — the track's strip on the ground and its equivalent stiffness k_eq(k_x, ω).

mod filon;
mod fitted;
mod fitted_embankment;
mod flexibility;
mod half_space;
mod layer;
mod line_support;
mod moving_load;
mod profile;
mod rayleigh_modes;
mod receptance;
mod strip;
mod thin_layer;
mod track_interface;
mod track_on_embankment;

pub use fitted::FittedFoundation;
pub use flexibility::{surface_flexibility, surface_stiffness};
pub use half_space::half_space_stiffness;
pub use layer::layer_stiffness;
pub use line_support::LineSupport;
pub use moving_load::{GroundedBeam, MovingSpectrum, SPECTRUM_TOLERANCE};
pub use profile::{GroundProfile, HalfSpace, MAX_LAYERS, SoilLayer, SoilMaterial};
pub use rayleigh_modes::rayleigh_phase_velocities;
pub use receptance::RECEPTANCE_TOLERANCE;
pub use strip::{STRIP_TOLERANCE, StripGround};
pub use thin_layer::{ThinLayerMesh, thin_layer_phase_velocity};
pub use track_interface::InterfaceSpectra;
pub use track_on_embankment::{Embankment, TrackOnEmbankment};
