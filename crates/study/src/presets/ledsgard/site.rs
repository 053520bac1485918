//! The built-in Ledsgård site: `examples/ledsgard` compiled in — the composite beam, and the two-beam track, on the
//! site's profile, the X2000 and the records measured at 70 and 185 km/h (examples/ledsgard/README.md gives every
//! number's source and where a choice was made).

use crate::ground::measured::MeasuredRecord;
use scenario::Scenario;
use scenario::error::Result;
use scenario::sections::AxleSection;

const SITE: &str = include_str!("../../../../../examples/ledsgard/ledsgard.toml");
const TWO_BEAM_SITE: &str = include_str!("../../../../../examples/ledsgard/ledsgard-two-beam.toml");
const TRAIN: &str = include_str!("../../../../../examples/ledsgard/x2000.csv");
const RECORDS: [(f64, &str, &str); 2] = [
    (70.0, "x2000_70kmh.csv", include_str!("../../../../../examples/ledsgard/x2000_70kmh.csv")),
    (185.0, "x2000_185kmh.csv", include_str!("../../../../../examples/ledsgard/x2000_185kmh.csv")),
];

/// The site with the composite beam.
pub(super) fn site() -> Result<Scenario> {
    with_train(SITE, "ledsgard.toml")
}

/// The site with the two-beam track: one rail on pads, sleepers and ballast over the embankment beam.
pub(super) fn two_beam_site() -> Result<Scenario> {
    with_train(TWO_BEAM_SITE, "ledsgard-two-beam.toml")
}

/// The site `text` (read as `name`) with the X2000's axles in it (the file names its train by path, which a built-in
/// site has none of).
fn with_train(text: &str, name: &str) -> Result<Scenario> {
    let mut site = Scenario::from_toml(text, name)?;
    let train = scenario::trains::parse_csv("x2000", TRAIN, "x2000.csv")?;
    site.load.train = None;
    site.load.axles = train.axles.iter().map(|a| AxleSection { offset: a.offset, force: a.force }).collect();
    Ok(site)
}

/// The measured records with their train speed (km/h).
pub(super) fn records() -> Result<Vec<(f64, MeasuredRecord)>> {
    RECORDS.iter().map(|&(speed, name, text)| Ok((speed, MeasuredRecord::parse(name, text, "ledsgard")?))).collect()
}
