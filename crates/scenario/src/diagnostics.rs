//! What a scenario's numbers mean for the model, before anything runs: refusals for inputs that cannot give an
//! answer, and warnings for legitimate but suspicious ones (docs/theory.md §2–§4).
//!
//! - Refused: a mesh with no free deflection DOF (one pinned element: the load has nothing to bend), and a beam
//!   without foundation whose supports leave a rigid-body motion (free–free, pinned–free: a mechanism).
//! - Warned: elements longer than a quarter of the deflection bowl π/β (β = (k_f/4EI)^¼; 10 m for the reference
//!   case, so elements over 2.5 m cannot represent it and the peaks come out wrong), and friction devices that snap
//!   to the same node and merge (their forces add) or sit on a support (dropped); a rigid wheel–rail contact at
//!   θ < 0.51 (its force's period-2 mode undamped, docs/theory.md §9); on sleepers, a bay of fewer than 4 elements and
//!   a step that does not resolve the sleeper passing, rail-on-pad or pinned–pinned frequency (§18); a damping ratio
//!   without a soil (a ratio of a critical damping that is 0).

use crate::error::{Result, invalid};
pub use crate::warning::Warning;
use crate::{Case, Scenario};
use analytic::reference::InfiniteBeam;
use analytic::span::SimplySupportedSpan;
use fem_beam::{BeamModel, Support};
use track::SectionKind;
use track::vehicle::wheel_rail::WheelRail;

/// Refuse models that cannot give an answer (see the module documentation).
pub fn refuse_degenerate(model: &BeamModel) -> Result<()> {
    let mesh = model.mesh();
    let free_deflections = (0..mesh.nodes()).filter(|&i| model.dofs().free_index(2 * i).is_some()).count();
    if free_deflections == 0 {
        return Err(invalid(
            "mesh.elements",
            mesh.elements,
            "leaves no node free to deflect between the supports; use at least 2 elements (and enough to resolve \
             the deflection bowl)",
        ));
    }
    let supports = model.supports();
    if model.foundation().stiffness == 0.0
        && model.sleepers().is_none()
        && supports.left.held() + supports.right.held() < 2
    {
        return Err(invalid(
            "supports",
            format!("{:?}/{:?}", supports.left, supports.right).to_lowercase(),
            "without a foundation (k_f = 0) these supports leave a rigid-body motion (a mechanism); pin both ends, \
             clamp one, or give foundation.stiffness > 0",
        ));
    }
    Ok(())
}

/// The wave error of a foundation fitted to the ground above which a run is warned about: 10 % of the peak, the
/// accuracy the published models of a soft site reach against measurements.
pub const GROUND_FIT_TOLERANCE: f64 = 0.1;

/// The warning a foundation fitted to the ground earns where its wave is off the exact one by more than
/// [`GROUND_FIT_TOLERANCE`].
pub fn ground_fit_warning(fit: &analytic::ground::FittedFoundation) -> Option<Warning> {
    (fit.wave_error > GROUND_FIT_TOLERANCE).then(|| Warning {
        field: "ground".into(),
        value: format!("fitted at {} m/s", fit.speed),
        message: format!(
            "the foundation fitted to the ground gives a steady wave {:.0} % off the exact one at this speed (its \
             deepest point {:+.0} %): near and above the ground's critical speed no local spring, dashpot and mass \
             represents the ground, so this run's numbers are the fitted foundation's; `frictrack stationary` gives \
             the exact linear wave on the ground",
            100.0 * fit.wave_error,
            100.0 * fit.peak_error
        ),
    })
}

/// Warnings for `scenario` built into `case`.
pub fn warnings(scenario: &Scenario, case: &Case) -> Vec<Warning> {
    let mut out = Vec::new();
    let model = &case.model;
    out.extend(case.ground_fit.as_ref().and_then(ground_fit_warning));
    // β of the infinite beam on this foundation (none without one: k_f = 0 has no deflection bowl).
    if let Ok(infinite) = InfiniteBeam::new(model.beam(), model.foundation()) {
        let bowl = std::f64::consts::PI / infinite.beta();
        let l = model.mesh().element_length();
        if l > 0.25 * bowl {
            let needed = (4.0 * model.mesh().length / bowl).ceil();
            out.push(Warning {
                field: "mesh.elements".into(),
                value: model.mesh().elements.to_string(),
                message: format!(
                    "elements of {l:.3} m are longer than a quarter of the deflection bowl π/β = {bowl:.3} m (limit \
                     {:.3} m): the deflection under the load is not resolved; use at least {needed} elements",
                    0.25 * bowl
                ),
            });
        }
    }
    if let Some(devices) = &scenario.friction.devices {
        let requested = devices.requested();
        let placed = case.interactions.count(SectionKind::Device);
        if placed < requested {
            out.push(Warning {
                field: "friction.devices".into(),
                value: format!("{requested} devices"),
                message: format!(
                    "they occupy only {placed} distinct free node(s) of the {} m mesh: devices snapped to one node \
                     merge (their forces add) and devices on a support are dropped; refine the mesh or space them \
                     at least one element ({:.3} m) apart",
                    model.mesh().length,
                    model.mesh().element_length()
                ),
            });
        }
    }
    out.extend(deck_resolution(case));
    out.extend(sleeper_resolution(case));
    out.extend(damping_without_soil(scenario));
    out.extend(embankment_on_the_default_soil(scenario));
    out.extend(soil_of_no_stiffness(scenario));
    out.extend(scenario.ground_warnings());
    out.extend(rigid_contact_damping(case));
    out.extend(timoshenko_sawtooth(case));
    out.extend(articulated_cars(scenario, case));
    out.extend(crate::plausibility::input_warnings(scenario, case));
    out
}

/// The warnings of a sweep of `scenario` over `speeds` (m/s): those of its runs at the lowest and at the highest
/// speed — every speed-dependent check (the step h = Δx/v resolving a frequency, the speed against v_cr) is worst at
/// one of them — each once, so that a sweep warns of what any of its runs would (the scenario's own speed alone
/// would miss a "load advance too coarse" at a swept speed).
pub fn sweep_warnings(scenario: &Scenario, speeds: &[f64]) -> Result<Vec<Warning>> {
    let (low, high) = speeds.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
    let mut out: Vec<Warning> = Vec::new();
    for v in [low, high].into_iter().filter(|v| v.is_finite()) {
        let at = Scenario { load: crate::LoadSection { speed: v, ..scenario.load.clone() }, ..scenario.clone() };
        for w in warnings(&at, &at.build()?) {
            if !out.contains(&w) {
                out.push(w);
            }
        }
    }
    Ok(out)
}

/// Rail cars on an HSLM train's axles: the HSLM coaches are articulated (neighbours share a bogie), which cars of
/// two bogies of their own, four axles each, are not.
fn articulated_cars(scenario: &Scenario, case: &Case) -> Vec<Warning> {
    let cars = scenario.vehicle.as_ref().is_some_and(|v| v.kind == crate::vehicle::VehicleKind::RailCar);
    match case.settings.moving.load.axles() {
        Some(train) if cars && train.name.starts_with("hslm") => vec![Warning {
            field: "vehicle.kind".into(),
            value: "rail-car".into(),
            message: format!(
                "{} is articulated (its coaches share bogies): rail cars on its axles read every four consecutive \
                 axles as an independent car with two bogies of its own — a different train; quarter cars or \
                 moving masses keep its axle layout",
                train.name
            ),
        }],
        _ => Vec::new(),
    }
}

/// θ from which a rigid wheel–rail contact's force keeps still: at θ = ½ the trapezoidal rule leaves the
/// velocity-level constraint's period-2 mode undamped (as for any index-2 constraint), and every node a wheel
/// crosses adds to it. Measured on the example of two rail cars at 60 m/s (`examples/rail-cars-dipped-joint.toml`
/// with contact = "rigid"): step-to-step alternation of the wheel forces up to 0.54 Q₀ at θ = 0.5, growing along
/// the run; 0.047 Q₀ at 0.51 (Hertz at 0.5: 0.12 Q₀), for 1.4 % of the viscous dissipation in numerical damping.
pub const RIGID_CONTACT_THETA: f64 = 0.51;

/// A rigid wheel–rail contact integrated with θ below [`RIGID_CONTACT_THETA`].
fn rigid_contact_damping(case: &Case) -> Vec<Warning> {
    let settings = &case.settings;
    let Some(vehicles) = settings.moving.load.vehicles() else {
        return Vec::new();
    };
    let rigid = vehicles.vehicles.iter().any(|p| matches!(vehicles.contact_of(p), WheelRail::Rigid { .. }));
    let theta = settings.integration.theta;
    if !rigid || theta >= RIGID_CONTACT_THETA {
        return Vec::new();
    }
    vec![Warning {
        field: "integration.theta".into(),
        value: format!("{theta}"),
        message: format!(
            "rigid wheel–rail contact at θ < {RIGID_CONTACT_THETA}: the trapezoidal rule leaves the contact force's \
             step-to-step (period-2) oscillation undamped, and the wheel forces can swing by half their static load \
             (rail cars at 60 m/s); theta = {RIGID_CONTACT_THETA} damps it for about 1 % of the dissipation"
        ),
    }]
}

/// A Timoshenko rail integrated by the θ-method at θ = ½: its shear modes sit far above any step the load advance
/// gives, and the trapezoidal rule keeps their energy — the velocity jump under a passing load (F/(κGA − ρAv²) in
/// the slope) becomes a step-to-step sawtooth of the velocities, the accelerations and the dashpot forces that does
/// not converge. Measured on UIC60 (κ = 0.4) on sleepers at 50 m/s (docs/theory.md §5.4): the largest pad force
/// +1.7 % at 64 elements a bay where the generalized-α of ρ∞ = ½ stays within 0.2 % from 4 to 64.
fn timoshenko_sawtooth(case: &Case) -> Vec<Warning> {
    let integration = &case.settings.integration;
    let timoshenko = matches!(case.model.beam().theory, fem_beam::BeamTheory::Timoshenko { .. });
    if !timoshenko || integration.spectral_radius.is_some() || integration.theta > 0.5 {
        return Vec::new();
    }
    vec![Warning {
        field: "integration.theta".into(),
        value: format!("{}", integration.theta),
        message: "a Timoshenko rail at θ = 0.5 keeps its unresolved shear modes as a step-to-step sawtooth of the \
                  velocities, accelerations and dashpot (pad) forces that does not go away under refinement; \
                  integration.spectral_radius = 0.5 (--spectral-radius 0.5) damps them and stays second order"
            .into(),
    }]
}

/// The highest frequency a deck-acceleration check needs, f_max = max(30 Hz, 1.5 f₁, f₃) (EN 1990 A2, docs/theory.md
/// §10), with the span it was taken from; None unless the model is a span (no foundation, both ends pinned).
pub fn deck_frequency(model: &BeamModel) -> Option<(f64, SimplySupportedSpan)> {
    let sleepers = model.sleepers().is_some();
    let span = span_of(model.beam(), &model.supports(), model.foundation().stiffness, sleepers, model.mesh().length)?;
    Some((deck_band(&span), span))
}

/// The simply supported span a beam of `length` (m) is — None unless both ends are pinned, without a foundation
/// (`foundation_stiffness` 0) and without `sleepers`: a bridge deck, whose accelerations EN 1990 A2 checks.
pub fn span_of(
    beam: &fem_beam::Beam,
    supports: &fem_beam::Supports,
    foundation_stiffness: f64,
    sleepers: bool,
    length: f64,
) -> Option<SimplySupportedSpan> {
    let pinned = supports.left == Support::Pinned && supports.right == Support::Pinned;
    if !(pinned && foundation_stiffness == 0.0 && !sleepers) {
        return None;
    }
    SimplySupportedSpan::new(beam, 0.0, length).ok()
}

/// f_max = max(30 Hz, 1.5 f₁, f₃) of `span` (Hz): the band of its deck-acceleration check (EN 1990 A2.4.4.2.1(4)).
pub fn deck_band(span: &SimplySupportedSpan) -> f64 {
    fem_beam::modal_band::deck_band(span.frequency(1), span.frequency(3))
}

/// The longest step h (s) that resolves `frequency` (Hz) with 20 steps per period: θ = ½ then has a phase error
/// below 2 % per period.
pub fn resolving_step(frequency: f64) -> f64 {
    1.0 / (20.0 * frequency)
}

/// The largest load advance (m) whose step h = Δx/v is the [`resolving_step`] of `frequency` (Hz) at `speed` (m/s).
pub fn resolving_advance(frequency: f64, speed: f64) -> f64 {
    speed * resolving_step(frequency)
}

/// A span must resolve accelerations up to f_max of [`deck_frequency`]: the mesh resolves the pinned mode n whose
/// f_n first reaches f_max with at least 4 elements per half-wave (L/(4n)), and the time step resolves f_max with at
/// least 20 steps per period ([`resolving_advance`]).
pub fn deck_resolution(case: &Case) -> Vec<Warning> {
    let model = &case.model;
    let Some((f_max, span)) = deck_frequency(model) else {
        return Vec::new();
    };
    let mesh = model.mesh();
    let mode = (1..=100_000).find(|&n| span.frequency(n) >= f_max).unwrap_or(100_000);
    let mut out = Vec::new();
    let longest = mesh.length / (4.0 * mode as f64);
    if mesh.element_length() > longest {
        out.push(Warning {
            field: "mesh.elements".into(),
            value: mesh.elements.to_string(),
            message: format!(
                "deck accelerations need frequencies up to {f_max:.1} Hz (max of 30 Hz, 1.5 f₁ = {:.1} Hz, f₃ = \
                 {:.1} Hz): mode {mode} reaches it and needs elements of at most {longest:.3} m; use at least {} \
                 elements",
                1.5 * span.frequency(1),
                span.frequency(3),
                4 * mode
            ),
        });
    }
    let h = case.settings.time_step();
    if h > resolving_step(f_max) {
        out.push(Warning {
            field: "integration.load_advance".into(),
            value: case.settings.integration.load_advance.to_string(),
            message: format!(
                "the step h = {h:.3e} s resolves {:.1} Hz with 20 steps per period, below the {f_max:.1} Hz deck \
                 accelerations need: use a load advance of at most {:.4} m at {} m/s, or integration.max_step = \
                 {:.4e} s for every speed",
                1.0 / (20.0 * h),
                resolving_advance(f_max, case.settings.moving.speed),
                case.settings.moving.speed,
                resolving_step(f_max)
            ),
        });
    }
    out
}

/// Elements a bay the pinned–pinned wave needs (its half wavelength is the spacing).
pub const ELEMENTS_PER_BAY: usize = 4;

/// How far the mesh's pinned–pinned frequency may lie from the rail's (relative) before it is warned about.
pub const PINNED_PINNED_TOLERANCE: f64 = 0.01;

/// The pinned–pinned resonance as `per_bay` elements of `beam` give it — the first mode of one bay `spacing` m long
/// pinned at both ends, against the rail's own ([`analytic::dispersion::pinned_pinned`]) — warned about beyond
/// [`PINNED_PINNED_TOLERANCE`]. Hermite elements converge as O(h⁴) (UIC60 at a = 0.6 m: +0.39 % at two a bay, +0.03 %
/// at four); the Timoshenko element as O(h²) (κ = 0.4: +4.1 % at two, +1.0 % at four, +0.25 % at eight), so the
/// elements it needs are estimated as per_bay·√(error/tolerance).
fn meshed_pinned_pinned(beam: &fem_beam::Beam, spacing: f64, per_bay: usize, mesh: &fem_beam::Mesh) -> Option<Warning> {
    use fem_beam::{BeamModel, Foundation, Mesh, Support, Supports};
    let bay = Mesh::new(spacing, per_bay.max(1)).ok()?;
    let model = BeamModel::new(*beam, Foundation::linear(0.0, 0.0), bay, Supports::both(Support::Pinned)).ok()?;
    let meshed = model.natural_frequencies(1).ok()?.first()? / std::f64::consts::TAU;
    let exact = analytic::dispersion::pinned_pinned(beam, spacing);
    let error = meshed / exact - 1.0;
    if error.abs() <= PINNED_PINNED_TOLERANCE {
        return None;
    }
    let per_bay_needed = (per_bay as f64 * (error.abs() / PINNED_PINNED_TOLERANCE).sqrt()).ceil();
    Some(Warning {
        field: "mesh.elements".into(),
        value: mesh.elements.to_string(),
        message: format!(
            "{per_bay} elements a bay give this {} rail's pinned–pinned resonance at {meshed:.0} Hz against its \
             {exact:.0} Hz ({:+.1} %); about {per_bay_needed} a bay bring it within {} % — use {} elements",
            beam.theory.describe(),
            100.0 * error,
            100.0 * PINNED_PINNED_TOLERANCE,
            (mesh.length / spacing * per_bay_needed).round()
        ),
    })
}

/// What a run of `case` on sleepers must resolve (docs/theory.md §18), warned about where it does not (none on a
/// continuous track): the mesh the pinned–pinned wave ([`ELEMENTS_PER_BAY`], the rule a span's modes follow), the
/// step the frequencies the sleepers add — the sleeper passing frequency v/a the load excites, the rail bouncing on
/// its pads and the pinned–pinned resonance — each with 20 steps per period ([`resolving_step`]).
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
    if per_bay >= ELEMENTS_PER_BAY as f64 - 1e-9 {
        out.extend(meshed_pinned_pinned(model.beam(), sleepers.spacing, per_bay.round() as usize, mesh));
    }
    let speed = case.settings.moving.speed;
    let lumped = sleepers.bay_resonances(model.beam().mass_per_length());
    let body = lumped.sleeper_on_ballast.map(|f| ("the sleeper on the ballast body (a bay lumped)", f));
    let frequencies: Vec<(&str, f64)> = [
        ("the sleeper passing frequency v/a", speed / sleepers.spacing),
        ("the rail on its pads (a bay lumped)", lumped.rail_on_pads),
        ("the pinned–pinned resonance", analytic::dispersion::pinned_pinned(model.beam(), sleepers.spacing)),
    ]
    .into_iter()
    .chain(body)
    .collect();
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

/// A damping ratio given without a soil: ζ is a ratio of c_cr = 2√(k_f ρA), which is 0 at k_f = 0, so it damps
/// nothing — on sleepers their pads and ballast carry the damping (`[sleepers.pad]`, `[sleepers.ballast]` damping).
fn damping_without_soil(scenario: &Scenario) -> Option<Warning> {
    let ratio = scenario.foundation.damping_ratio.filter(|&r| r > 0.0)?;
    if scenario.foundation.stiffness > 0.0 {
        return None;
    }
    let instead = match scenario.sleepers {
        Some(_) => {
            "the sleepers' pads and ballast carry their own dashpots ([sleepers.pad] and [sleepers.ballast] damping)"
        }
        None => "give foundation.damping in N·s/m², or [damping] rayleigh for a deck",
    };
    Some(Warning {
        field: "foundation.damping_ratio".into(),
        value: crate::number::number(ratio),
        message: format!(
            "is a ratio of the soil's critical damping 2√(k_f ρA), which is 0 with foundation.stiffness = 0: it damps \
             nothing; {instead}"
        ),
    })
}

/// The two-beam track with neither a `[ground]` nor a `[foundation]` of its own: its embankment rests on the reference
/// case's soil (k_f = 250 kN/m², undamped), a default that sets the track's stiffness and critical speed, said as
/// every such default is.
fn embankment_on_the_default_soil(scenario: &Scenario) -> Option<Warning> {
    if scenario.embankment.is_none() || scenario.ground.is_some() {
        return None;
    }
    let soil = &scenario.foundation;
    if *soil != crate::FoundationSection::default() {
        return None;
    }
    Some(Warning {
        field: "foundation".into(),
        value: "not given".into(),
        message: format!(
            "the [embankment] rests on the reference case's soil, k_f = {} N/m² with no damping: give the soil under \
             it as a [foundation] (k_f, damping) or a layered [ground]",
            crate::number::number(soil.stiffness)
        ),
    })
}

/// A tensionless or bilinear soil of zero stiffness: no soil at all (a span with no soil under it), so its law acts
/// on nothing — run as such, and said.
fn soil_of_no_stiffness(scenario: &Scenario) -> Option<Warning> {
    let soil = &scenario.foundation;
    if !soil.is_nonlinear_without_soil() || scenario.ground.is_some() {
        return None;
    }
    Some(Warning {
        field: "foundation.law".into(),
        value: format!("{:?}", soil.law).to_lowercase(),
        message: "acts on no soil with foundation.stiffness = 0: the beam rests on its supports (and sleepers) alone"
            .into(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A damping ratio without a soil is said to damp nothing (on sleepers, pointing at their dashpots); with a soil
    /// it is not warned about.
    #[test]
    fn a_damping_ratio_without_a_soil_is_warned_about() {
        let text = "[foundation]\nstiffness = 0.0\ndamping_ratio = 0.05\n[sleepers]\n[mesh]\nlength = 60.0\n\
                    elements = 400\n[integration]\nload_advance = 0.03\n";
        let scenario = Scenario::from_toml(text, "t.toml").unwrap();
        let said = warnings(&scenario, &scenario.build().unwrap());
        let damping = said.iter().find(|w| w.field == "foundation.damping_ratio").expect("warned");
        assert!(damping.message.contains("damps nothing") && damping.message.contains("[sleepers.pad]"), "{damping}");
        let soil = Scenario::from_toml("[foundation]\ndamping_ratio = 0.05\n", "t.toml").unwrap();
        assert!(warnings(&soil, &soil.build().unwrap()).iter().all(|w| w.field != "foundation.damping_ratio"));
    }

    /// A Timoshenko rail of soft shear (κ = 0.1) on four elements a bay: its pinned–pinned resonance comes out more
    /// than 1 % high and the warning says by how much and how many elements bring it within 1 %; with that many it
    /// is not warned about, nor is UIC60 (κ = 0.4: +1.0 %) or an Euler–Bernoulli rail (+0.03 %) on four a bay.
    #[test]
    fn a_timoshenko_bay_too_coarse_for_the_pinned_pinned_resonance_is_warned_about() {
        let said = |kappa: Option<f64>, elements: usize| {
            let beam = kappa.map_or(String::new(), |k| {
                format!("[beam]\ntheory = \"timoshenko\"\nshear_modulus = 81e9\nshear_coefficient = {k}\n")
            });
            let text = format!(
                "{beam}[foundation]\nstiffness = 0.0\n[sleepers]\n[mesh]\nlength = 60.0\nelements = {elements}\n"
            );
            let scenario = Scenario::from_toml(&text, "t.toml").unwrap();
            sleeper_resolution(&scenario.build().unwrap()).into_iter().find(|w| w.message.contains("resonance at"))
        };
        let coarse = said(Some(0.1), 400).expect("warned");
        assert!(coarse.message.contains("4 elements a bay") && coarse.message.contains("within 1 %"), "{coarse}");
        let needed: usize = coarse.message.rsplit("use ").next().unwrap().split(' ').next().unwrap().parse().unwrap();
        assert!(said(Some(0.1), needed).is_none(), "{needed} elements still warned: {coarse}");
        assert!(said(Some(0.4), 400).is_none() && said(None, 400).is_none());
    }
}
