//! `[rail]`: the rail's irregularities under the vehicles' wheels (docs/theory.md §11), summed — the schema and its
//! translation into an [`irregularity::Profile`], errors named by their path in the scenario file.

use crate::error::{Result, StudyError, invalid};
use irregularity::{Profile, RandomProfile, RandomSettings, Spectrum};
use serde::{Deserialize, Serialize};

/// `[rail]`: the rail's irregularities, summed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(default, deny_unknown_fields)]
pub struct RailSection {
    /// `[[rail.irregularities]]`, each with a `kind`.
    pub irregularities: Vec<IrregularitySection>,
}

impl RailSection {
    /// Whether the rail is smooth.
    pub fn is_empty(&self) -> bool {
        self.irregularities.is_empty()
    }
}

/// One irregularity of the rail (m, upward positive).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum IrregularitySection {
    /// a·sin(2π(x − start)/λ).
    Harmonic {
        /// a (m).
        amplitude: f64,
        /// λ (m).
        wavelength: f64,
        /// x₀ (m).
        #[serde(default)]
        start: f64,
    },
    /// A linear rise of `height` over [start, start + length].
    Ramp {
        /// Start (m).
        start: f64,
        /// Length (m).
        length: f64,
        /// Rise (m).
        height: f64,
    },
    /// A cosine dip of `depth` over `length` centred at `position`.
    DippedJoint {
        /// Centre (m).
        position: f64,
        /// Depth (m).
        depth: f64,
        /// Length (m).
        length: f64,
    },
    /// A measured profile: a CSV file of `x,r` lines (m).
    Table {
        /// The file.
        file: String,
    },
    /// A random profile from a spectrum (`german-low`, `german-high`, `fra-1` … `fra-6`).
    Random {
        /// The spectrum's name.
        spectrum: String,
        /// Wavelength band [shortest, longest] (m); default the spectrum's usual band.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        band: Option<[f64; 2]>,
        /// Seed of the phases. Default 1.
        #[serde(default = "default_seed")]
        seed: u64,
        /// Period of the profile (m); default the beam's length plus the vehicles' (at least the longest
        /// wavelength).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        length: Option<f64>,
    },
}

fn default_seed() -> u64 {
    1
}

/// An irregularity error renamed to its path in the scenario file.
fn rail_path(index: usize, error: irregularity::IrregularityError) -> StudyError {
    let irregularity::IrregularityError::InvalidField { field, value, allowed } = error;
    let field = field.rsplit('.').next().unwrap_or(&field).to_string();
    invalid(&format!("rail.irregularities[{index}].{field}"), value, allowed)
}

impl RailSection {
    /// The rail's profile over a run covering `reach` m of track (the beam and the vehicles behind it).
    pub fn profile(&self, reach: f64) -> Result<Profile> {
        let mut parts = Vec::with_capacity(self.irregularities.len());
        for (i, item) in self.irregularities.iter().enumerate() {
            let profile = match item {
                IrregularitySection::Harmonic { amplitude, wavelength, start } => {
                    Profile::Harmonic { amplitude: *amplitude, wavelength: *wavelength, start: *start }
                }
                IrregularitySection::Ramp { start, length, height } => {
                    Profile::Ramp { start: *start, length: *length, height: *height }
                }
                IrregularitySection::DippedJoint { position, depth, length } => {
                    Profile::DippedJoint { position: *position, depth: *depth, length: *length }
                }
                IrregularitySection::Table { file } => Profile::Table { points: read_profile(file, i)? },
                IrregularitySection::Random { spectrum, band, seed, length } => {
                    let spectrum = Spectrum::from_name(spectrum).map_err(|e| rail_path(i, e))?;
                    let band = band.map_or(spectrum.default_band(), |[a, b]| (a, b));
                    let given = *length;
                    let length = given.unwrap_or(reach.max(band.1));
                    let settings = RandomSettings { spectrum, band, length, seed: *seed };
                    Profile::Random(RandomProfile::new(settings).map_err(|e| match (given, e) {
                        // The period was not given: it follows the band's longest wavelength (or the run's reach),
                        // and the error belongs to what set it.
                        (None, irregularity::IrregularityError::InvalidField { field, allowed, .. })
                            if field == "length" =>
                        {
                            invalid(
                                &format!("rail.irregularities[{i}].band"),
                                format!("[{}, {}]", band.0, band.1),
                                format!(
                                    "sets the profile's period (length, not given) to {length} m, which {allowed}; \
                                     narrow the band or give a shorter length"
                                ),
                            )
                        }
                        (_, e) => rail_path(i, e),
                    })?)
                }
            };
            profile.validate("rail").map_err(|e| rail_path(i, e))?;
            parts.push(profile);
        }
        Ok(match parts.len() {
            0 => Profile::Smooth,
            1 => parts.pop().expect("one part"),
            _ => Profile::Sum(parts),
        })
    }
}

/// Largest profile file read (bytes): 100 000 points of two numbers fit.
const MAX_PROFILE_BYTES: u64 = 8 << 20;

/// Points (x, r) (m) from a CSV file of `x,r` lines, an optional header line, `#` comments.
fn read_profile(file: &str, index: usize) -> Result<Vec<(f64, f64)>> {
    let path = format!("rail.irregularities[{index}].file");
    let io = |e: std::io::Error| invalid(&path, file, format!("cannot read the profile file: {e}"));
    let size = std::fs::metadata(file).map_err(io)?.len();
    if size > MAX_PROFILE_BYTES {
        return Err(invalid(&path, file, format!("is {size} bytes; at most {MAX_PROFILE_BYTES} are read")));
    }
    let text = std::fs::read_to_string(file).map_err(io)?;
    // Spreadsheets write a UTF-8 byte-order mark first: it is no part of the header.
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let mut points = Vec::new();
    let mut header = false;
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let values: Vec<&str> = line.split(',').map(str::trim).collect();
        match values.as_slice() {
            [x, r] => match (x.parse::<f64>(), r.parse::<f64>()) {
                (Ok(x), Ok(r)) => points.push((x, r)),
                // One header line before the first point (after comments, if any).
                _ if points.is_empty() && !header => header = true,
                _ => return Err(invalid(&path, file, format!("line {}: expected two numbers x,r (m)", n + 1))),
            },
            _ => return Err(invalid(&path, file, format!("line {}: expected two values x,r (m)", n + 1))),
        }
    }
    Ok(points)
}
