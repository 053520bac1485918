//! What a run on sleepers must resolve (docs/theory.md §18), warned about where it does not: the mesh the
//! pinned–pinned wave (half a wavelength per bay: at least 4 elements a bay, the rule a span's modes follow), the
//! step the frequencies the sleepers add — the sleeper passing frequency v/a the load excites, the rail bouncing on
//! its pads and the pinned–pinned resonance — each with 20 steps per period
//! ([`crate::diagnostics::resolving_step`]).

use crate::Case;
use crate::diagnostics::{resolving_advance, resolving_step};
use crate::warning::Warning;

/// Elements a bay the pinned–pinned wave needs (its half wavelength is the spacing).
pub const ELEMENTS_PER_BAY: usize = 4;

/// The warnings of a run of `case` on sleepers (none on a continuous track).
pub fn sleeper_resolution(case: &Case) -> Vec<Warning> {
    let model = &case.model;
    let Some((sleepers, _)) = model.sleepers() else { return Vec::new() };
    let mut out = Vec::new();
    let mesh = model.mesh();
    let per_bay = sleepers.spacing / mesh.element_length();
    if per_bay < ELEMENTS_PER_BAY as f64 - 1e-9 {
        let needed = (mesh.length / sleepers.spacing * ELEMENTS_PER_BAY as f64).round();
        out.push(Warning {
            field: "mesh.elements".into(),
            value: mesh.elements.to_string(),
            message: format!(
                "{per_bay:.0} element(s) a bay of {} m: the pinned–pinned wave (half a wavelength a bay) needs at least \
                 {ELEMENTS_PER_BAY}; use {needed} elements",
                sleepers.spacing
            ),
        });
    }
    let speed = case.settings.moving.speed;
    let lumped = sleepers.bay_resonances(model.beam().mass_per_length());
    let frequencies = [
        ("the sleeper passing frequency v/a", speed / sleepers.spacing),
        ("the rail on its pads (a bay lumped)", lumped.rail_on_pads),
        ("the pinned–pinned resonance", sleepers.pinned_pinned(model.beam())),
    ];
    let h = case.settings.time_step();
    let missed: Vec<String> = frequencies
        .iter()
        .filter(|(_, f)| h > resolving_step(*f) * (1.0 + 1e-9))
        .map(|(what, f)| {
            format!(
                "{what} {f:.0} Hz (load advance ≤ {:.4} m, or max_step ≤ {:.3e} s)",
                resolving_advance(*f, speed),
                resolving_step(*f)
            )
        })
        .collect();
    if !missed.is_empty() {
        out.push(Warning {
            field: "integration.load_advance".into(),
            value: case.settings.integration.load_advance.to_string(),
            message: format!(
                "the step h = {h:.3e} s resolves {:.1} Hz with 20 steps per period; not resolved on these sleepers: {}",
                1.0 / (20.0 * h),
                missed.join("; ")
            ),
        });
    }
    out
}
