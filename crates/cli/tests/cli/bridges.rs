//! A simply supported span (a railway bridge) from a scenario: no foundation, pinned ends, Rayleigh damping.

use super::{frictrack, json};

#[test]
fn a_damped_span_runs_and_bad_damping_is_refused() {
    let folder = std::env::temp_dir().join(format!("frictrack-bridges-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let write = |name: &str, damping: &str| {
        let path = folder.join(name);
        let text = format!(
            "[mesh]\nlength = 20.0\nelements = 40\n[foundation]\nstiffness = 0.0\n{damping}\n[load]\nspeed = 30.0\n\
             [integration]\nload_advance = 0.05\nend_time = 2.0\n"
        );
        std::fs::write(&path, text).unwrap();
        path
    };
    let bare = write("bare.toml", "");
    let damped = write("damped.toml", "[damping]\nrayleigh = { ratio = 0.05, frequencies = [1.285, 11.57] }");
    let by_coefficients =
        write("coefficients.toml", "[damping]\nrayleigh = { alpha = 0.7266818, beta = 1.2380781e-3 }");
    let run = |path: &std::path::Path| json(&frictrack(&["run", path.to_str().unwrap(), "--format", "json"]));
    let (b, d, c) = (run(&bare), run(&damped), run(&by_coefficients));
    // Damping dissipates energy and lowers the free vibration after the load has left (end_time 2 s).
    assert_eq!(b["viscous_dissipation"].as_f64().unwrap(), 0.0);
    assert!(d["viscous_dissipation"].as_f64().unwrap() > 0.0);
    assert!(d["max_upward_deflection"].as_f64().unwrap() < b["max_upward_deflection"].as_f64().unwrap());
    // ζ = 5 % at 1.285 and 11.57 Hz is α = 0.7266818 1/s, β = 1.2380781e-3 s (7 digits): the same run to 1e-6.
    let (dd, cd) = (d["max_downward_deflection"].as_f64().unwrap(), c["max_downward_deflection"].as_f64().unwrap());
    assert!((dd - cd).abs() <= 1e-6 * dd, "{dd} vs {cd}");
    let mixed = write("mixed.toml", "[damping]\nrayleigh = { ratio = 0.05, alpha = 0.1 }");
    let reversed = write("reversed.toml", "[damping]\nrayleigh = { ratio = 0.05, frequencies = [10.0, 1.0] }");
    for (path, needle) in [(mixed, "damping.rayleigh"), (reversed, "frequencies[1]")] {
        let out = frictrack(&["run", path.to_str().unwrap()]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains(needle), "{stderr}");
    }
    std::fs::remove_dir_all(&folder).unwrap();
}
