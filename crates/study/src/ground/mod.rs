//! The ground under the track (`frictrack ground`, `frictrack.ground` in Python; docs/theory.md §19): the
//! scenario's composite beam on its `[ground]` — the soil's Rayleigh modes and their least phase velocity ([`phase_minimum`]), the static
//! strip stiffness and the Winkler control, the crossing of the beam's and the soil's dispersion curves, the critical
//! speed of the track on the ground ([`numbers`]); the steady response over speeds and its peak ([`speeds`]); the
//! report, tables and figures ([`text`]); a train's steady wave on the ground (`frictrack stationary`, [`wave`]; one speed's in [`wave_point`]) and
//! its report, tables and figures ([`wave_text`]); what the beam stands on, the strip or the two-beam track
//! ([`support`]); ballast friction under the composite beam or between the sleepers and the embankment
//! (`friction`), the spectra the curves of one site share ([`shared_spectra`]); the sleepers lifting off the ballast of the two-beam track ([`lift_off`]); a measured record set beside it ([`measured`], its numbers in [`comparison`]).

pub mod comparison;
pub(crate) mod friction;
pub mod lift_off;
pub mod measured;
pub mod numbers;
pub mod phase_minimum;
pub mod shared_spectra;
pub mod speeds;
pub mod support;
pub mod text;
pub mod wave;
pub mod wave_point;
pub mod wave_text;

pub use numbers::{DispersionPoint, GroundRequest, GroundStudy, ModesPoint, StiffnessPoint, TrackKind};
pub use shared_spectra::SiteSpectra;
pub use speeds::SpeedPoint;
pub use wave::{GroundWave, GroundWavePoint, GroundWaveStudy, WaveWindow};
