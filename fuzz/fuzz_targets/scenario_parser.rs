//! Fuzz the scenario parser and builder: any bytes, read as a scenario file, must give a scenario or an error that
//! names what is wrong — never a panic. Built scenarios are not run (runs are covered by the property tests).
#![no_main]

use libfuzzer_sys::fuzz_target;
use scenario::Scenario;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    match Scenario::from_toml(&text, "fuzz.toml") {
        Ok(scenario) => {
            if let Err(error) = scenario.build() {
                assert!(!error.to_string().is_empty());
            }
        }
        Err(error) => assert!(error.is_invalid_input(), "{error}"),
    }
});
