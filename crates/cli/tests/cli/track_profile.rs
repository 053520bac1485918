//! `frictrack track-profile` (docs/theory.md §11): a random rail profile as CSV with its PSD, the same bits for the
//! same seed, and bad settings refused with exit code 2 naming the field.

use super::{frictrack, is_png, is_svg, json, temporary_folder};

/// FRA class 4 over 600 m sampled every 0.25 m (a whole period, 2400 samples): the sample's σ equals the target
/// √∫_band S dΩ to 1e-9 (the harmonics are orthogonal over the period); the PSD file's periodogram equals the
/// target within 2 % from the 10th harmonic on (the mean of S over a bin of 2π/600 rad/m against its centre); a
/// second run with the same seed writes the same bytes, another seed other heights.
#[test]
fn a_profile_is_written_with_its_spectrum_and_reproduced_by_its_seed() {
    let dir = temporary_folder("track-profile");
    let out = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let args = |seed: &str, folder: &str| {
        vec![
            "track-profile".to_string(),
            "fra-4".into(),
            "--length".into(),
            "600".into(),
            "--spacing".into(),
            "0.25".into(),
            "--seed".into(),
            seed.into(),
            "--out".into(),
            folder.into(),
            "--format".into(),
            "json".into(),
        ]
    };
    let run = |a: Vec<String>| frictrack(&a.iter().map(String::as_str).collect::<Vec<_>>());
    let summary = json(&run(args("7", &out("a"))));
    let (sample, target) = (summary["sample_std"].as_f64().unwrap(), summary["target_std"].as_f64().unwrap());
    assert!((sample / target - 1.0).abs() < 1e-9, "σ {sample} vs {target}");
    // Harmonics k·2π/600 for k = 2 … 400: from 300 m to 1.5 m.
    assert_eq!(summary["harmonics"], 399);
    let profile = std::fs::read_to_string(dir.join("a/track-profile.csv")).unwrap();
    assert_eq!(profile.lines().count(), 1 + 2400);
    assert!(profile.starts_with("x,r\n0,"));
    let psd = std::fs::read_to_string(dir.join("a/track-profile-psd.csv")).unwrap();
    assert!(psd.starts_with("wavenumber,wavelength,periodogram,target\n"));
    // Harmonics k = 10 … 399 (the last bin is clipped by the band's edge). The bin mean of S ∝ Ω⁻² differs from its
    // centre value by about (ΔΩ/Ω)²/4 = 1/(4k²): 0.25 % from k = 10 on, 2.8 % at k = 3.
    for line in psd.lines().skip(9).take(390) {
        let v: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        assert!((v[2] / v[3] - 1.0).abs() < 0.02, "{line}");
    }
    for figure in ["track-profile", "track-profile-psd"] {
        assert!(is_png(&dir.join(format!("a/{figure}.png"))) && is_svg(&dir.join(format!("a/{figure}.svg"))));
    }
    run(args("7", &out("b")));
    assert_eq!(std::fs::read(dir.join("b/track-profile.csv")).unwrap(), profile.as_bytes());
    run(args("8", &out("c")));
    assert_ne!(std::fs::read(dir.join("c/track-profile.csv")).unwrap(), profile.as_bytes());

    for (bad, field) in [
        (vec!["track-profile", "fra-7"], "spectrum"),
        (vec!["track-profile", "--spacing", "0.5"], "spacing"),
        (vec!["track-profile", "--band", "2:1"], "band"),
        (vec!["track-profile", "--band", "2"], "--band"),
        (vec!["track-profile", "--length", "50"], "length"),
    ] {
        let mut bad = bad;
        let folder = out("bad");
        bad.extend(["--out", folder.as_str()]);
        let result = frictrack(&bad);
        assert_eq!(result.status.code(), Some(2), "{bad:?}");
        assert!(String::from_utf8_lossy(&result.stderr).contains(&format!("invalid {field} =")), "{bad:?}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
