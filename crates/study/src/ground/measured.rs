//! A measured record of the track's deflection under a passing train, set beside the computed steady wave: read from
//! a CSV, aligned to the train's frame by the shift (and direction) that fits best, and compared — the peaks of both
//! over the record's span and the root-mean-square misfit (docs/theory.md §19, the Ledsgård check).
//!
//! The record's positions x are its own (a measurement gives time or distance from an arbitrary origin, running
//! either way along the train): s = d·x + c with d = ±1 and the shift c chosen by least squares, c scanned every
//! 5 cm over the train's length either way and refined by golden section to 1 mm. The computed wave is read between
//! its points (0.25 m apart) linearly: that reading errs by ≤ h²/8·|W″| ≈ 3e-4 of the peak for the ≳ 5 m bowls of a
//! track on soft ground, far inside a digitised record's ±0.2 mm.

pub use crate::ground::comparison::Comparison;
use crate::ground::wave::{GroundWave, GroundWaveStudy, WaveWindow};
use analytic::golden::golden_section;
use scenario::error::{Result, invalid};

/// The most rows a record may have.
const MAX_ROWS: usize = 1_000_000;
/// The largest record file (bytes).
const MAX_BYTES: u64 = 64 << 20;
/// The scan's step in the shift (m) and the refined shift's tolerance (m).
const SHIFT_STEP: f64 = 0.05;
const SHIFT_TOLERANCE: f64 = 1e-3;

/// A measured record: positions (m) and deflections (m, upward positive).
#[derive(Debug, Clone, PartialEq)]
pub struct MeasuredRecord {
    /// The file it was read from, as given.
    pub name: String,
    /// x (m), the record's own coordinate.
    pub x: Vec<f64>,
    /// W (m, upward positive).
    pub deflection: Vec<f64>,
}

impl MeasuredRecord {
    /// Read `path`: a header naming the columns — `x` or `x_m` (m), then `deflection` (m) or `displacement_mm` /
    /// `deflection_mm` (mm), upward positive — then one row per point, `#` comments; `field` names the option in
    /// errors.
    pub fn read(path: &std::path::Path, field: &str) -> Result<Self> {
        let name = path.display().to_string();
        let bad = |why: String| invalid(field, &name, why);
        let size = std::fs::metadata(path).map_err(|e| bad(format!("cannot read the record: {e}")))?.len();
        if size > MAX_BYTES {
            return Err(bad("records are at most 64 MiB".into()));
        }
        let text = std::fs::read_to_string(path).map_err(|e| bad(format!("cannot read the record: {e}")))?;
        Self::parse(&name, &text, field)
    }

    /// The record `name` from the text of a record file (as [`Self::read`] takes it).
    pub fn parse(name: &str, text: &str, field: &str) -> Result<Self> {
        let name = name.to_string();
        let bad = |why: String| invalid(field, &name, why);
        let mut lines = text.lines().map(|l| l.split('#').next().unwrap_or("").trim()).filter(|l| !l.is_empty());
        let header = lines.next().unwrap_or("").trim_start_matches('\u{feff}').to_ascii_lowercase();
        let scale = match header.replace(' ', "").as_str() {
            "x,deflection" | "x_m,deflection" | "x,deflection_m" | "x_m,deflection_m" => 1.0,
            "x,displacement_mm" | "x_m,displacement_mm" | "x,deflection_mm" | "x_m,deflection_mm" => 1e-3,
            _ => {
                return Err(bad(format!(
                    "the header `{header}` names no known columns: expected `x_m,deflection_mm` (or x in m, \
                     deflection in m), upward positive"
                )));
            }
        };
        let (mut x, mut deflection) = (Vec::new(), Vec::new());
        for line in lines {
            let cells: Vec<&str> = line.split(',').map(str::trim).collect();
            let number = |i: usize| cells.get(i).and_then(|c| c.parse::<f64>().ok()).filter(|v| v.is_finite());
            let (Some(position), Some(value), 2) = (number(0), number(1), cells.len()) else {
                return Err(bad(format!("the row `{line}` is not two finite numbers")));
            };
            if x.len() == MAX_ROWS {
                return Err(bad(format!("records hold at most {MAX_ROWS} rows")));
            }
            x.push(position);
            deflection.push(value * scale);
        }
        if x.len() < 2 {
            return Err(bad("a record needs at least two rows".into()));
        }
        Ok(Self { name, x, deflection })
    }

    /// The record against `wave` of a train `length` m long, aligned as the module says; refused (`field`) where
    /// no alignment keeps the whole record inside the wave's window.
    pub fn compare(&self, wave: &GroundWave, length: f64, field: &str) -> Result<Comparison> {
        let mut best: Option<(f64, f64, f64)> = None;
        for direction in [1.0, -1.0] {
            let misfit = |shift: f64| self.misfit(wave, direction, shift);
            let reach = length + (self.span().1 - self.span().0);
            let steps = (2.0 * reach / SHIFT_STEP).ceil() as usize;
            let scanned = (0..=steps).map(|i| -reach + i as f64 * SHIFT_STEP).filter_map(|c| Some((c, misfit(c)?)));
            let Some((c, _)) = scanned.min_by(|a, b| a.1.total_cmp(&b.1)) else { continue };
            let mut objective = |c: f64| Ok::<_, std::convert::Infallible>(misfit(c).unwrap_or(f64::INFINITY));
            let Ok((shift, value)) =
                golden_section(&mut objective, c - SHIFT_STEP, c + SHIFT_STEP, SHIFT_TOLERANCE, false);
            if best.is_none_or(|b| value < b.2) {
                best = Some((direction, shift, value));
            }
        }
        let Some((direction, shift, rms_misfit)) = best.filter(|b| b.2.is_finite()) else {
            return Err(invalid(
                field,
                &self.name,
                "the record is longer than the computed wave's window: widen --domain behind the train or ahead of it",
            ));
        };
        let computed: Vec<f64> = self.x.iter().filter_map(|&x| read(wave, direction * x + shift)).collect();
        let largest = |values: &[f64], sign: f64| values.iter().map(|w| sign * w).fold(0.0, f64::max);
        Ok(Comparison {
            record: self.name.clone(),
            direction,
            shift,
            rms_misfit,
            rms_measured: (self.deflection.iter().map(|w| w * w).sum::<f64>() / self.x.len() as f64).sqrt(),
            measured_max_downward: largest(&self.deflection, -1.0),
            measured_max_upward: largest(&self.deflection, 1.0),
            computed_max_downward: largest(&computed, -1.0),
            computed_max_upward: largest(&computed, 1.0),
        })
    }

    /// `window` grown so that the record, however long, fits inside it wherever it lies along the train: each side at
    /// least the record's length.
    pub fn widened(&self, window: WaveWindow) -> WaveWindow {
        let length = self.span().1 - self.span().0;
        WaveWindow { behind: window.behind.max(length), ahead: window.ahead.max(length) }
    }

    /// The least and largest x (m).
    fn span(&self) -> (f64, f64) {
        self.x.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)))
    }

    /// The RMS misfit with the record placed at s = d·x + c; None where a point falls outside the wave.
    fn misfit(&self, wave: &GroundWave, direction: f64, shift: f64) -> Option<f64> {
        let mut sum = 0.0;
        for (&x, &measured) in self.x.iter().zip(&self.deflection) {
            sum += (read(wave, direction * x + shift)? - measured).powi(2);
        }
        Some((sum / self.x.len() as f64).sqrt())
    }
}

/// W(s) read linearly between the wave's points; None outside them.
fn read(wave: &GroundWave, s: f64) -> Option<f64> {
    let (first, last) = (*wave.s.first()?, *wave.s.last()?);
    if !(first..=last).contains(&s) {
        return None;
    }
    let step = (last - first) / (wave.s.len() - 1) as f64;
    let i = (((s - first) / step) as usize).min(wave.s.len() - 2);
    let t = (s - wave.s[i]) / step;
    Some(wave.deflection[i] * (1.0 - t) + wave.deflection[i + 1] * t)
}

impl GroundWaveStudy {
    /// Set `record` beside the wave ([`MeasuredRecord::compare`]); `field` (the option that gave it) names the
    /// refusal where the study has more than one speed (a record is one train's passage at one speed).
    pub fn compare_with(&mut self, record: &MeasuredRecord, field: &str) -> Result<()> {
        record.check_speeds(self.waves.len(), field)?;
        if let [wave] = self.waves.as_slice() {
            self.comparison = Some(record.compare(wave, self.train.length(), field)?);
        }
        Ok(())
    }
}

impl MeasuredRecord {
    /// Refuse, by `field`, a comparison over `speeds` speeds other than one: a record is one passage at one speed.
    /// Checked before the waves are computed, and again by [`GroundWaveStudy::compare_with`].
    pub fn check_speeds(&self, speeds: usize, field: &str) -> Result<()> {
        match speeds {
            1 => Ok(()),
            n => Err(invalid(
                field,
                &self.name,
                format!("a record is one passage at one speed: give one speed, not {n}"),
            )),
        }
    }
}
