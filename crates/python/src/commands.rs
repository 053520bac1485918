//! The command line's other commands for Python, each returning what the command prints or writes: `analytic`
//! (the closed-form steady state, JSON points), `stationary` (the stationary wave's points as JSON, its text report
//! and each wave's CSV), `study` (a preset's summary, CSV, headline and lines), `train` (a train's axles) and `track_profile` (a
//! random rail's sample and periodogram as CSV, its summary as JSON).

use crate::errors::to_python;
use crate::interruptible;
use crate::scenario_input::{Source, overrides};
use pyo3::prelude::*;
use report::output::Output;
use runner::Runner;
use scenario::error::StudyError;
use study::ground::measured::MeasuredRecord;
use study::presets::{Preset, Resolution, run_preset};
use study::stationary::output::{ErrorEstimate, StationaryStudy, wave_csv};
use study::stationary::text::StationaryReport;
use study::steady_response::SteadyResponse;

fn json<T: serde::Serialize>(value: &T) -> PyResult<String> {
    serde_json::to_string_pretty(value).map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))
}

/// `frictrack analytic`: the steady state of the scenario's beam on its soil (optionally at another damping ratio,
/// under a train) at `speeds` (m/s): the JSON points and the command line's warnings.
#[pyfunction]
#[pyo3(signature = (kind, text, speeds, damping_ratio, train))]
pub(crate) fn analytic(
    kind: &str,
    text: Option<String>,
    speeds: Vec<f64>,
    damping_ratio: Option<f64>,
    train: Option<String>,
) -> PyResult<(String, Vec<String>)> {
    scenario::speeds::check_count("speeds", speeds.len()).map_err(to_python)?;
    let scenario = Source::of(kind, text)?.read()?;
    let train = train
        .map(|name| scenario::trains::named_or_file(&name, scenario.load.force, "train"))
        .transpose()
        .map_err(to_python)?;
    let response = SteadyResponse::of(&scenario, damping_ratio, train, &speeds).map_err(to_python)?;
    Ok((json(&response.points)?, response.warnings()))
}

/// `frictrack stationary`: the stationary wave at `speeds` (m/s, by continuation) on the domain `behind`:`ahead` (m)
/// of `element_length` (m): the points as JSON, each found wave's CSV (speed, text) and the warnings; `progress`, if
/// given, is called with the fraction of speeds done.
#[pyfunction]
#[pyo3(name = "stationary", signature = (kind, text, speeds, domain, keywords, progress=None, measured=None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn stationary_wave(
    py: Python<'_>,
    kind: &str,
    text: Option<String>,
    speeds: Vec<f64>,
    domain: DomainArgument,
    keywords: Vec<(String, Bound<'_, PyAny>)>,
    progress: Option<Bound<'_, PyAny>>,
    measured: Option<std::path::PathBuf>,
) -> PyResult<StationaryTexts> {
    scenario::speeds::check_count("speeds", speeds.len()).map_err(to_python)?;
    let scenario = overrides(&keywords)?.apply(Source::of(kind, text)?.read()?).map_err(to_python)?;
    if scenario.ground.is_some() {
        return on_the_ground(py, &scenario, speeds, domain, progress, measured);
    }
    if let Some(path) = measured {
        let why = "a measured record is compared with the steady wave on a [ground] only";
        return Err(to_python(scenario::error::invalid("measured", path.display(), why)));
    }
    let title = scenario.title.clone();
    // What Python leaves out is the library's default domain, not a copy of it.
    let default = stationary::Domain::default();
    let domain = stationary::Domain {
        behind: domain.0.unwrap_or(default.behind),
        ahead: domain.1.unwrap_or(default.ahead),
        element_length: domain.2.unwrap_or(default.element_length),
    };
    let total = speeds.len() as f64;
    let solve = move |stop: &_, told: &interruptible::Progress| {
        let first = scenario.stationary_problem(speeds.first().copied().unwrap_or(0.0), domain)?;
        told.announce("frictrack.stationary", &runner::cost::Estimate::stationary(&first, &speeds, true));
        let done = |n: usize| told.set(n as f64 / total);
        StationaryStudy::of_until(&scenario, &speeds, domain, ErrorEstimate::Halving, Some(stop), &done)
    };
    let study = interruptible::run_reporting(py, progress, solve)?.map_err(to_python)?;
    let waves = study.waves.iter().flatten().map(|w| (w.speed, wave_csv(w))).collect();
    let text = StationaryReport { title: &title, study: &study }.text();
    Ok((json(&study.points)?, text, waves, study.warnings(), "stationary_wave", None))
}

/// `frictrack stationary` on a `[ground]`: the train's steady wave at `speeds` on the window `domain` (behind the
/// last axle, ahead of the first; an element length is refused: the wave has no mesh), with the `measured` record
/// beside it where given.
fn on_the_ground(
    py: Python<'_>,
    scenario: &scenario::Scenario,
    speeds: Vec<f64>,
    domain: DomainArgument,
    progress: Option<Bound<'_, PyAny>>,
    measured: Option<std::path::PathBuf>,
) -> PyResult<StationaryTexts> {
    if let Some(length) = domain.2 {
        let why = "leave it out: on a [ground] the wave is a Fourier integral, with no mesh";
        return Err(to_python(scenario::error::invalid("element_length", length, why)));
    }
    let default = study::ground::WaveWindow::default();
    let mut window = study::ground::WaveWindow {
        behind: domain.0.unwrap_or(default.behind),
        ahead: domain.1.unwrap_or(default.ahead),
    };
    let record = measured.map(|path| MeasuredRecord::read(&path, "measured")).transpose().map_err(to_python)?;
    if let Some(record) = &record {
        record.check_speeds(speeds.len(), "measured").map_err(to_python)?;
        window = record.widened(window);
    }
    let total = speeds.len() as f64;
    let scenario = scenario.clone();
    let solve = move |stop: &_, told: &interruptible::Progress| {
        let threads = std::thread::available_parallelism().map_or(1, usize::from);
        told.announce("frictrack.stationary", &study::ground::wave::cost(&scenario, speeds.len(), threads));
        let done = |n: usize| told.set(n as f64 / total);
        study::ground::GroundWaveStudy::of(&scenario, &speeds, window, Some(stop), &done)
    };
    let mut study = interruptible::run_reporting(py, progress, solve)?.map_err(to_python)?;
    if let Some(record) = &record {
        study.compare_with(record, "measured").map_err(to_python)?;
    }
    let waves = study.waves.iter().map(|w| (w.speed, w.csv())).collect();
    let comparison = study.comparison.as_ref().map(json).transpose()?;
    Ok((json(&study.points)?, report::output::Output::text(&study), waves, Vec::new(), "ground_wave", comparison))
}

/// `domain` as Python gives it: behind, ahead (m) and the element length (m), each None for the default.
type DomainArgument = (Option<f64>, Option<f64>, Option<f64>);

/// The stationary points (JSON, a list even for one speed), the text report, each found wave's CSV by speed, the
/// warnings, the name of the waves' columns in `columns()` and, on a ground, the measured record's comparison (JSON).
type StationaryTexts = (String, String, Vec<(f64, String)>, Vec<String>, &'static str, Option<String>);

/// A study's summary (JSON), CSV, headline, lines and CSV columns with their units.
type StudyTexts = (String, String, Vec<String>, Vec<String>, Vec<(String, String)>);

/// `frictrack study NAME`: the preset on the scenario (its `[output] deck_track` set to `deck_track` if given) at
/// `resolution` ("coarse" or "paper") on `jobs` threads: (summary JSON, CSV, headline, lines, columns with units).
#[pyfunction]
#[pyo3(name = "study", signature = (name, kind, text, resolution, jobs, deck_track, keywords))]
pub(crate) fn preset(
    py: Python<'_>,
    name: &str,
    kind: &str,
    text: Option<String>,
    resolution: &str,
    jobs: usize,
    deck_track: Option<String>,
    keywords: Vec<(String, Bound<'_, PyAny>)>,
) -> PyResult<StudyTexts> {
    let preset = Preset::from_name(name).map_err(to_python)?;
    let resolution = Resolution::from_name(resolution).map_err(to_python)?;
    let mut base = overrides(&keywords)?.apply(Source::of(kind, text)?.read()?).map_err(to_python)?;
    if let Some(track) = deck_track {
        base.output.deck_track = track.parse().map_err(to_python)?;
    }
    let runner = Runner::new(jobs).map_err(to_python)?;
    let what = format!("frictrack.study({name:?})");
    let work = move |stop: &_, told: &interruptible::Progress| {
        let announce = |estimate: &runner::cost::Estimate| told.announce(&what, estimate);
        run_preset(preset, resolution, &base, &runner.with_stop(stop).with_estimate(&announce))
    };
    let data = interruptible::run_reporting(py, None, work)?.map_err(to_python)?;
    let columns = data.columns.iter().map(|(c, u)| (c.clone(), u.to_string())).collect();
    Ok((json(&data.summary)?, data.csv, data.headline, data.lines, columns))
}

/// `frictrack trains` for one: the train `name` (a catalogue name or a CSV file) as its summary (JSON) and axles
/// (offset m behind the first, force N).
#[pyfunction]
pub(crate) fn train(name: &str) -> PyResult<(String, Vec<(f64, f64)>)> {
    let train =
        scenario::trains::named_or_file(name, scenario::Scenario::default().load.force, "name").map_err(to_python)?;
    let axles = train.axles.iter().map(|a| (a.offset, a.force)).collect();
    Ok((json(&scenario::trains::TrainSummary::of(&train))?, axles))
}

/// `frictrack track-profile`: a random rail of `spectrum` over `band` (m, shortest and longest wavelength; None: the
/// spectrum's) and `length` (m) sampled every `spacing` (m) with `seed`: (profile CSV, periodogram CSV, summary JSON).
#[pyfunction]
#[pyo3(signature = (spectrum, length, spacing, seed, band))]
pub(crate) fn track_profile(
    spectrum: &str,
    length: f64,
    spacing: f64,
    seed: u64,
    band: Option<(f64, f64)>,
) -> PyResult<(String, String, String)> {
    let spectrum = irregularity::Spectrum::from_name(spectrum).map_err(|e| to_python(StudyError::from(e)))?;
    let mut settings = irregularity::RandomSettings::new(spectrum, length, seed);
    if let Some(band) = band {
        settings.band = band;
    }
    let request = report::track_profile::ProfileRequest { settings, spacing };
    request.validate().map_err(to_python)?;
    let sample = report::track_profile::sample_profile(request).map_err(to_python)?;
    Ok((sample.profile_csv(), sample.psd_csv(), json(&sample.summary())?))
}
