//! The moving-load spectra of one site at each speed, kept for the curves that share them: curves that differ only
//! in the ballast's friction (the `ledsgard` study's four on each track) need the same spectra at every speed — under
//! the composite beam its spectrum on the line support, on the two-beam track the four interface spectra (~1.2 s a speed at Ledsgård,
//! most of a friction wave's cost) — so each is sampled once a speed, not once a curve. The site is kept with them:
//! a scenario that differs from it in anything but its friction gets spectra of its own
//! ([`SiteSpectra::fits`]), never another site's.

use analytic::ground::{InterfaceSpectra, MovingSpectrum};
use scenario::Scenario;
use scenario::error::Result;
use std::sync::{Arc, Mutex};

/// The spectra of a site, by speed (m/s, to the bit).
#[derive(Debug)]
pub struct SiteSpectra {
    /// The site without ballast friction.
    site: Scenario,
    line: Mutex<Vec<(u64, Arc<MovingSpectrum>)>>,
    interface: Mutex<Vec<(u64, Arc<InterfaceSpectra>)>>,
}

impl SiteSpectra {
    /// An empty store for `site` (its friction, if any, is not part of what the spectra depend on).
    pub fn new(site: &Scenario) -> Self {
        Self { site: without_friction(site), line: Mutex::default(), interface: Mutex::default() }
    }

    /// Whether `scenario` is this site, but for its ballast friction.
    pub fn fits(&self, scenario: &Scenario) -> bool {
        without_friction(scenario) == self.site
    }

    /// The beam's spectrum on its line support at `speed` (the composite beam's, or the rail's on the two-beam
    /// track): the kept one, or `sample`'s, kept.
    pub(crate) fn line(
        &self,
        speed: f64,
        sample: impl FnOnce() -> Result<MovingSpectrum>,
    ) -> Result<Arc<MovingSpectrum>> {
        kept(&self.line, speed, sample)
    }

    /// The two-beam track's interface spectra at `speed`: the kept ones, or `sample`'s, kept.
    pub(crate) fn interface(
        &self,
        speed: f64,
        sample: impl FnOnce() -> Result<InterfaceSpectra>,
    ) -> Result<Arc<InterfaceSpectra>> {
        kept(&self.interface, speed, sample)
    }
}

fn without_friction(scenario: &Scenario) -> Scenario {
    let mut site = scenario.clone();
    site.friction.distributed = None;
    site
}

/// The entry of `store` at `speed`, sampled (outside the lock: two speeds sample at once) and kept if missing.
fn kept<T>(store: &Mutex<Vec<(u64, Arc<T>)>>, speed: f64, sample: impl FnOnce() -> Result<T>) -> Result<Arc<T>> {
    let key = speed.to_bits();
    let find = |store: &[(u64, Arc<T>)]| store.iter().find(|(k, _)| *k == key).map(|(_, s)| Arc::clone(s));
    if let Some(found) = find(&store.lock().unwrap_or_else(|e| e.into_inner())) {
        return Ok(found);
    }
    let sampled = Arc::new(sample()?);
    let mut store = store.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(found) = find(&store) {
        return Ok(found);
    }
    store.push((key, Arc::clone(&sampled)));
    Ok(sampled)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    /// A site at another friction fits; another beam does not (it gets spectra of its own).
    #[test]
    fn a_site_fits_itself_at_any_friction_only() {
        let site = Scenario::default();
        let spectra = SiteSpectra::new(&site);
        let mut rubbing = site.clone();
        rubbing.friction.distributed =
            Some(scenario::DistributedSection { force_per_length: 2e3, ..Default::default() });
        assert!(spectra.fits(&site) && spectra.fits(&rubbing));
        let mut stiffer = site.clone();
        stiffer.beam.youngs_modulus *= 2.0;
        assert!(!spectra.fits(&stiffer));
    }

    /// Each speed is sampled once, whatever the number of curves asking; a failed sample is not kept.
    #[test]
    fn each_speed_is_sampled_once() {
        let store = Mutex::default();
        let calls = Cell::new(0);
        let sample = |value: i32| {
            calls.set(calls.get() + 1);
            Ok(value)
        };
        for _curve in 0..4 {
            for (speed, value) in [(50.0, 1), (60.0, 2), (70.0, 3)] {
                assert_eq!(*kept(&store, speed, || sample(value)).unwrap(), value);
            }
        }
        assert_eq!(calls.get(), 3);
        let failed = kept(&store, 80.0, || Err(scenario::error::invalid("speed", 80.0, "a test")));
        assert!(failed.is_err());
        assert_eq!(*kept(&store, 80.0, || sample(4)).unwrap(), 4);
        assert_eq!(calls.get(), 4);
    }
}
