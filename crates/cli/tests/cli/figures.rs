//! Figures of outputs: `sweep --out FILE.csv` draws the swept metrics beside the CSV, and `frictrack plot` draws
//! them again from the files alone — a sweep's CSV, or a run folder, to the same bytes as the run drew them.

use super::{frictrack, is_svg, temporary_folder};

#[test]
fn a_sweep_draws_its_figures_and_plot_draws_them_again() {
    let dir = temporary_folder("sweep-figures");
    let csv = dir.join("dist.csv");
    let out = frictrack(&[
        "sweep",
        "--distributed-friction",
        "2000",
        "--speeds",
        "150:250:25",
        "--critical",
        "--out",
        csv.to_str().unwrap(),
        "--quiet",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let figures = ["dist-deflection", "dist-acceleration", "dist-energy"];
    for f in figures {
        assert!(is_svg(&dir.join(format!("{f}.svg"))), "{f}");
    }
    // The refined critical speed's runs are drawn: the deflection curve has more points than the 5 speeds.
    let svg = std::fs::read_to_string(dir.join("dist-deflection.svg")).unwrap();
    assert!(svg.contains("max deflection vs speed") && svg.contains("critical speed 2"));
    // Titled as a sweep, not by the file's stem, and the case named under the title: the figure reads alone.
    assert!(svg.contains("speed sweep: max deflection") && !svg.contains("dist:"), "title");
    assert!(svg.contains("F = 83.4 kN; k_f = 250 kN/m², undamped; friction: fᵤ = 2 kN/m"), "subtitle");
    let drawn = std::fs::read(dir.join("dist-acceleration.svg")).unwrap();
    let deflection = std::fs::read(dir.join("dist-deflection.svg")).unwrap();
    for f in figures {
        std::fs::remove_file(dir.join(format!("{f}.svg"))).unwrap();
    }
    let out = frictrack(&["plot", csv.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stdout).contains("dist-energy.png/.svg"));
    assert_eq!(std::fs::read(dir.join("dist-acceleration.svg")).unwrap(), drawn, "the same figure from the CSV");
    // The refined critical speed, its runs and the case come back from the JSON beside the CSV: the same figure.
    assert_eq!(std::fs::read(dir.join("dist-deflection.svg")).unwrap(), deflection, "critical speed redrawn");

    // A run folder: the histories and snapshots figures again, to the byte.
    let run = dir.join("run");
    let out = frictrack(&["run", "--speed", "150", "--out", run.to_str().unwrap(), "--quiet"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let before = std::fs::read(run.join("snapshots-moment.svg")).unwrap();
    std::fs::remove_file(run.join("snapshots-moment.svg")).unwrap();
    assert!(frictrack(&["plot", run.to_str().unwrap()]).status.success());
    assert_eq!(std::fs::read(run.join("snapshots-moment.svg")).unwrap(), before);
    // Nothing to read: exit 2 naming the file.
    let out = frictrack(&["plot", dir.join("missing.csv").to_str().unwrap()]);
    assert_ne!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stderr).contains("missing.csv"));
}
