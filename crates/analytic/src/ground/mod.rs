//! The ground under the track (docs/theory.md §19): horizontal visco-elastic layers over a half-space, and their
//! surface response to a vertical load e^{i(ωt − kx)} in the frequency–wavenumber domain — the exact stiffness
//! method of Kausel & Roësset (1981, BSSA 71): each layer a 4 × 4 dynamic stiffness between its top and bottom
//! (u, w), the half-space a 2 × 2 one, condensed from the bottom up to the surface.
//!
//! - `profile`: [`GroundProfile`] — the layers and the half-space, their complex moduli, the checks of a profile.
//! - `half_space`: the half-space's stiffness, in a closed form that stays finite as ω/k → 0.
//! - `layer`: a layer's stiffness from the transfer matrix exp(A h) of its first-order system, on sublayers thin
//!   enough (|k|h, ωh/|C_s| ≤ 1) that neither the static limit nor thick layers lose digits.
//! - `flexibility`: the surface flexibility F_zz(k, ω) of the profile.

mod flexibility;
mod half_space;
mod layer;
mod profile;

pub use flexibility::surface_flexibility;
pub use half_space::half_space_stiffness;
pub use layer::layer_stiffness;
pub use profile::{GroundProfile, HalfSpace, MAX_LAYERS, SoilLayer, SoilMaterial};
