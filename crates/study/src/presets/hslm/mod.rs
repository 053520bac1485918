//! Study 7 (docs/theory.md §10): the Eurocode HSLM-A1 … A10 trains over a bridge deck or a track, with and without
//! friction — the run (`study`), the resonance speeds f·D/i (`resonances`), the typed results and their summary
//! (`results`, `summary`), the deck's EN 1990 check (`verdict`), the figures and the report's headline.

mod figures;
mod headline;
mod resonances;
mod results;
mod study;
mod summary;
pub mod verdict;

pub(super) use study::{fallback_devices, friction_setups, overrides, study};
