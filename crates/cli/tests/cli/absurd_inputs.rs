//! Inputs outside the model's validity (docs/theory.md §2–§4, `scenario::plausibility`): refused where no answer can
//! be given (exit 2, the field, the value and the limit named), warned where the model runs but its answer is not
//! the track's (exit 0, a warning naming the value and the limit) — never a confident answer without a word.

use super::{frictrack, temporary_folder};

/// stderr and exit code of `frictrack run SCENARIO --quiet` for a scenario file of `toml`.
fn run_file(name: &str, toml: &str, extra: &[&str]) -> (Option<i32>, String) {
    let dir = temporary_folder(&format!("absurd-{name}"));
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, toml).unwrap();
    let out = frictrack(&[&["run", path.to_str().unwrap(), "--quiet"], extra].concat());
    (out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned())
}

#[test]
fn absurd_inputs_are_refused_or_warned_naming_value_and_limit() {
    // A speed at or above the bar wave speed: refused, the value in its shortest form.
    let out = frictrack(&["run", "--speed", "1e300"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("load.speed = 1e300") && err.contains("bar wave speed √(E/ρ) = 5189 m/s"), "{err}");
    // Beyond 3 v_cr: warned.
    let out = frictrack(&["run", "--speed", "700", "--quiet"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success() && err.contains("warning: load.speed = 700 m/s") && err.contains("3 v_cr"), "{err}");
    // A 1e12 N load: warned before (the load) and after (the deflection beyond 1 % of the length).
    let (code, err) = run_file("force", "[load]\nforce = 1e12\n", &[]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("warning: load.force = load 1.0000e12 N") && err.contains("above 1e6 N"), "{err}");
    assert!(err.contains("warning: result = deflection") && err.contains("above 1 %"), "{err}");
    // A 1e12 kg moving mass: its static wheel load.
    let (code, err) = run_file("mass", "[vehicle]\nkind = \"moving-mass\"\nmass = 1e12\n", &[]);
    assert!(code == Some(0) && err.contains("warning: vehicle = static wheel load 9.8100e12 N"), "{err}");
    // A 0.5 m harmonic irregularity on a 1 m wavelength: slope π.
    let rough = "[vehicle]\n[[rail.irregularities]]\nkind = \"harmonic\"\namplitude = 0.5\nwavelength = 1.0\n";
    let (code, err) = run_file("rough", rough, &[]);
    assert!(code == Some(0) && err.contains("warning: rail.irregularities = slope 3.142"), "{err}");
    // A matrices vehicle whose weight lifts its wheel: refused, named by its real path.
    let upward = "[vehicle]\nkind = \"matrices\"\n[vehicle.matrices]\nmass = [[1000.0]]\ndamping = [[0.0]]\n\
                  stiffness = [[0.0]]\nweight = [9810.0]\nwheels = [{ dof = 0, offset = 0.0 }]\n";
    let (code, err) = run_file("upward", upward, &[]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("vehicle.matrices.weight = -9810") && err.contains("every wheel must press"), "{err}");
    // A rail car's field is named under [vehicle.rail_car].
    let car = "[vehicle]\nkind = \"rail-car\"\n[vehicle.rail_car]\nbogie_half_distance = -1.0\n";
    let (code, err) = run_file("car", car, &[]);
    assert!(code == Some(2) && err.contains("vehicle.rail_car.bogie_half_distance = -1"), "{err}");
    // A beam a million kilometres long: the message names the length, not only the load advance.
    let (code, err) = run_file("long", "[mesh]\nlength = 1e9\n", &[]);
    assert!(code == Some(2) && err.contains("beam length 1.0000e9 m") && err.contains("mesh.length"), "{err}");
    // The reference case itself is plausible: no warning.
    let out = frictrack(&["run", "--quiet"]);
    assert!(!String::from_utf8_lossy(&out.stderr).contains("warning"));
}

/// The first line of standard error starting with `prefix` (None if it ends first), the command killed once read.
fn announced(args: &[&str], prefix: &str) -> Option<String> {
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_frictrack"))
        .args(args)
        .stderr(std::process::Stdio::piped())
        .stdout(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let stderr = std::io::BufReader::new(child.stderr.take().unwrap());
    let line = std::io::BufRead::lines(stderr).map_while(Result::ok).find(|l| l.starts_with(prefix));
    child.kill().unwrap();
    child.wait().unwrap();
    line
}

/// Work of hours says so before it starts (the estimate rule of `runner::cost`), instead of printing nothing: a run,
/// a stationary sweep of 190 000 speeds with friction, and a study at paper resolution (announced per batch, its
/// notes first).
#[test]
fn long_work_announces_its_size_and_estimate() {
    let run = announced(&["run", "--elements", "1000000", "--load-advance", "0.0002"], "this run").unwrap();
    assert!(run.starts_with("this run: 1000000 steps over 2000000 DOFs") && run.contains(" h "), "{run}");
    let args = ["stationary", "--speeds", "10:200:0.001", "--distributed-friction", "5000", "--format", "json"];
    let stationary = announced(&args, "stationary").unwrap();
    assert!(stationary.starts_with("stationary: 190001 stationary solves of 481 nodes, nonsmooth"), "{stationary}");
    assert!(stationary.contains(" min "), "{stationary}");
    let out = std::env::temp_dir().join(format!("frictrack-announce-{}", std::process::id()));
    let out_arg = out.to_string_lossy().into_owned();
    let study = announced(&["study", "discrete-speed", "--resolution", "paper", "--out", &out_arg], "discrete-speed");
    let _ = std::fs::remove_dir_all(&out);
    let study = study.unwrap();
    // 3783 sweep runs and the 156 that refine the 13 curves' critical speeds after them (12 each).
    assert!(
        study.starts_with("discrete-speed: 3939 runs, the largest of 2000 steps over 400 DOFs, 31 friction"),
        "{study}"
    );
}
