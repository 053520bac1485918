//! The resonances of a receptance curve and the doubts about it (docs/theory.md §17): local peaks of |α| refined
//! between the grid's frequencies; a mesh that does not resolve the bending waves at the top frequency; waves that
//! reach the track's ends and come back.

use analytic::dispersion::wavenumbers;
use analytic::golden::refine_peak;
use fem_beam::BeamModel;
use num_complex::Complex64;
use scenario::error::Result;
use serde::Serialize;
use std::f64::consts::TAU;

/// Elements per bending wavelength below which the mesh is said not to resolve a frequency: 10 (Hermite's error is
/// then below 1e-4 of |α|, the Timoshenko element's below 1 %; docs/theory.md §17).
pub const ELEMENTS_PER_WAVELENGTH: f64 = 10.0;

/// Elements per bending wavelength below which a peak is the mesh's and not listed as a resonance: 4 (two a
/// half-wave). Between 4 and [`ELEMENTS_PER_WAVELENGTH`] a peak is the track's, its height a little off: the
/// pinned–pinned peak at four elements a 0.6 m bay (eight a wavelength) lies 0.4 % high; the spurious 17.8 kHz peak of
/// 0.0625 m elements had 1.6.
pub const LISTED_ELEMENTS_PER_WAVELENGTH: f64 = 4.0;

/// Reflections from the ends above this share of the outgoing wave are warned about (1 %).
pub const REFLECTION_LIMIT: f64 = 0.01;

/// A resonance: a local peak of |α|, its frequency refined between the grid's neighbours (golden section, to 1e-6 of
/// the frequency).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Resonance {
    /// f (Hz).
    pub frequency: f64,
    /// |α| there (m/N).
    pub magnitude: f64,
    /// Peak over the higher of its two bases — the least |α| on each side before the curve climbs above the peak —
    /// (≥ 1.05: smaller bumps are not listed).
    pub prominence: f64,
    /// What resonates, where an estimate of the track's names it ([`name_resonances`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<&'static str>,
}

/// A peak must stand this much above the larger minimum beside it to be listed (5 %).
const PROMINENCE: f64 = 1.05;

/// The local peaks of a curve of (frequency Hz, |α|), each refined by golden section on `magnitude` between its
/// neighbours' frequencies (to 1e-6 of the frequency: the peak's value is flat there, its place is what is refined).
pub fn resonances(points: &[(f64, f64)], magnitude: impl Fn(f64) -> Result<f64>) -> Result<Vec<Resonance>> {
    let mut out = Vec::new();
    for i in 1..points.len().saturating_sub(1) {
        let (before, here, after) = (points[i - 1].1, points[i].1, points[i + 1].1);
        if !(here > before && here >= after) {
            continue;
        }
        // The bases on either side (down to where the curve climbs higher than this peak): a resonance stands 5 %
        // above the higher of them, a ripple does not.
        let floor = lowest_before(points, i).max(lowest_after(points, i));
        if here < PROMINENCE * floor {
            continue;
        }
        let (a, b) = (points[i - 1].0, points[i + 1].0);
        let (frequency, magnitude) = refine_peak(&mut |f| magnitude(f), (a, b), points[i], 1e-6 * b)?;
        out.push(Resonance { frequency, magnitude, prominence: magnitude / floor, name: None });
    }
    Ok(out)
}

/// The resonances a track is known for, by name, with their estimates (Hz) and how far (as a ratio) a peak may lie
/// from the estimate to take its name: the rail bouncing on a continuous foundation, √(k_f/ρA)/2π; on sleepers the
/// bay's lumped resonances ([`fem_beam::Sleepers::bay_resonances`]: the track on the ballast (on the subgrade, with
/// the sleeper on the ballast above it, where the ballast is a body), the rail on its pads — lumped, they miss the rail's bending by up to ~20 %: a factor 1.5) and the pinned–pinned one
/// ([`analytic::dispersion::pinned_pinned`], within 1 % at mid-span: 10 %, so that the peak beside the dip above a
/// sleeper, ~20 % higher, is not taken for it).
pub fn known_resonances(model: &BeamModel) -> Vec<(&'static str, f64, f64)> {
    let rho_a = model.beam().mass_per_length();
    let mut out = Vec::new();
    let k_f = model.foundation().stiffness;
    if k_f > 0.0 && model.sleepers().is_none() {
        out.push(("rail on its foundation", (k_f / rho_a).sqrt() / TAU, 1.5));
    }
    if let Some((s, _)) = model.sleepers() {
        let bay = s.bay_resonances(rho_a);
        match bay.sleeper_on_ballast {
            None => out.push(("track on the ballast", bay.track, 1.5)),
            Some(middle) => {
                out.push(("track on the subgrade", bay.track, 1.5));
                out.push(("sleeper on the ballast", middle, 1.5));
            }
        }
        out.push(("rail on its pads", bay.rail_on_pads, 1.5));
        out.push(("pinned–pinned", analytic::dispersion::pinned_pinned(model.beam(), s.spacing), 1.1));
    }
    out
}

/// Name each of `resonances` by the known resonance of `model` nearest to it (in ratio), each name given once, to
/// the resonance nearest to it, within that name's factor ([`known_resonances`]).
pub fn name_resonances(model: &BeamModel, resonances: &mut [Resonance]) {
    for (name, estimate, factor) in known_resonances(model) {
        let distance = |r: &Resonance| (r.frequency / estimate).ln().abs();
        let nearest = resonances
            .iter_mut()
            .filter(|r| r.name.is_none() && distance(r) <= factor.ln())
            .min_by(|a, b| distance(a).total_cmp(&distance(b)));
        if let Some(r) = nearest {
            r.name = Some(name);
        }
    }
}

/// The least |α| to the left of peak `i` before the curve rises above it (or the grid ends): the topographic
/// prominence's left base, blind to ripples on the flank.
fn lowest_before(points: &[(f64, f64)], i: usize) -> f64 {
    let peak = points[i].1;
    points[..i].iter().rev().map(|p| p.1).take_while(|&m| m <= peak).fold(peak, f64::min)
}

/// The least |α| to the right of peak `i` before the curve rises above it (or the grid ends).
fn lowest_after(points: &[(f64, f64)], i: usize) -> f64 {
    let peak = points[i].1;
    points[i + 1..].iter().map(|p| p.1).take_while(|&m| m <= peak).fold(peak, f64::min)
}

/// The wavenumbers (rad/m) of the track of `model` at `f` (Hz): the rail on its soil and the sleepers' dynamic
/// stiffness spread over their spacing (the long waves' view of them, [`fem_beam::Sleepers::dynamic_stiffness_per_metre`]).
fn track_waves(model: &BeamModel, f: f64) -> [Complex64; 2] {
    let (beam, foundation) = (model.beam(), model.foundation());
    let omega = TAU * f;
    let sleepers = model.sleepers().map_or(Complex64::new(0.0, 0.0), |(s, _)| s.dynamic_stiffness_per_metre(omega));
    wavenumbers(beam, foundation.dynamic_stiffness(omega) + sleepers, beam.loss_factor, omega)
}

/// The shortest bending wavelength (m) of the track of `model` at `f` (Hz).
fn shortest_wavelength(model: &BeamModel, f: f64) -> f64 {
    TAU / track_waves(model, f).iter().map(|k| k.re.abs()).fold(0.0, f64::max)
}

/// Whether the mesh of `model` has at least `per_wavelength` elements a bending wavelength of the track at `f` (Hz).
pub fn resolves(model: &BeamModel, f: f64, per_wavelength: f64) -> bool {
    shortest_wavelength(model, f) / model.mesh().element_length() >= per_wavelength
}

/// Drop the `resonances` that are the mesh's — fewer than [`LISTED_ELEMENTS_PER_WAVELENGTH`] elements a wavelength —
/// returning how many went.
pub fn keep_resolved(model: &BeamModel, resonances: &mut Vec<Resonance>) -> usize {
    let before = resonances.len();
    resonances.retain(|r| resolves(model, r.frequency, LISTED_ELEMENTS_PER_WAVELENGTH));
    before - resonances.len()
}

/// The doubts about a receptance of `model` at `frequencies` (Hz, increasing) for a force at `excite` (m):
/// elements too long for the bending waves at the top frequencies, and waves from the force that come back from the
/// ends (on a track without absorbing zones).
pub fn warnings(model: &BeamModel, frequencies: &[f64], excite: f64) -> Vec<String> {
    let (foundation, mesh) = (model.foundation(), model.mesh());
    let l = mesh.element_length();
    let waves = |f: f64| track_waves(model, f);
    let shortest = |f: f64| shortest_wavelength(model, f);
    let mut out = Vec::new();
    let resolved = |f: &&f64| resolves(model, **f, ELEMENTS_PER_WAVELENGTH);
    let top = *frequencies.last().expect("validated: at least one");
    if !resolved(&&top) {
        let needed = shortest(top) / ELEMENTS_PER_WAVELENGTH;
        let up_to =
            frequencies.iter().rev().find(resolved).map_or("none of them".to_string(), |f| format!("up to {f} Hz"));
        out.push(format!(
            "the mesh's {l} m elements resolve the bending waves ({ELEMENTS_PER_WAVELENGTH} elements a wavelength) {up_to}; \
             at {top} Hz the wavelength is {:.3} m: elements of {needed:.4} m or shorter resolve it",
            shortest(top)
        ));
    }
    if model.element_damping().iter().all(|&c| c == foundation.damping) {
        let distance = excite.min(mesh.length - excite);
        let (f, back) = frequencies
            .iter()
            .map(|&f| (f, (-2.0 * distance * waves(f).iter().map(|k| k.im).fold(f64::INFINITY, f64::min)).exp()))
            .fold((0.0, 0.0), |best, this| if this.1 > best.1 { this } else { best });
        if back > REFLECTION_LIMIT {
            out.push(format!(
                "waves from the force reach the track's ends {distance:.1} m away and come back at up to {:.1} % of \
                 their size (at {f} Hz): give the foundation damping or a loss factor, [foundation.absorbing_zones], \
                 or a longer track",
                100.0 * back
            ));
        }
    }
    out
}
