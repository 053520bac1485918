//! Vehicles in `run` (docs/theory.md §12): a quarter car over a dipped joint with its wheel outputs, a train of quarter
//! cars, and bad vehicle inputs refused with exit code 2 naming the scenario path.

use super::write_file as scenario;
use super::{frictrack, json, temporary_folder};

/// A quarter car at 50 m/s over a 2 mm dipped joint: wheels.csv holds one row per step with the documented columns,
/// the wheel force dips and peaks around the joint, the JSON reports the wheel and the body, the energy closes.
#[test]
fn a_quarter_car_over_a_dipped_joint_writes_its_wheel() {
    let folder = temporary_folder("vehicles");
    let car = scenario(
        &folder,
        "car.toml",
        "[load]\nspeed = 50.0\n[vehicle]\nkind = \"quarter-car\"\n[[rail.irregularities]]\nkind = \"dipped-joint\"\n\
         position = 100.0\ndepth = 2e-3\nlength = 0.5\n[integration]\nload_advance = 0.05\n[output]\n\
         extremes_nodes = [40.0, 160.0]\n",
    );
    let out = folder.join("out");
    let v = json(&frictrack(&["run", &car, "--format", "json", "--out", out.to_str().unwrap(), "--quiet"]));
    let vehicles = &v["vehicles"];
    assert_eq!(vehicles["contact"], "hertz");
    let wheel = &vehicles["wheels"][0];
    let (q0, min, max) = (
        wheel["static_force"].as_f64().unwrap(),
        wheel["min_force"].as_f64().unwrap(),
        wheel["max_force"].as_f64().unwrap(),
    );
    assert!((q0 / (8500.0 * 9.81) - 1.0).abs() < 1e-12 && min < 0.5 * q0 && max > 1.2 * q0, "{q0} {min} {max}");
    assert!(vehicles["bodies"][0]["rms_acceleration"].as_f64().unwrap() > 0.0);
    assert!(v["energy"]["residual"].as_f64().unwrap().abs() < 1e-9 * v["energy"]["load_work"].as_f64().unwrap().abs());
    let csv = std::fs::read_to_string(out.join("wheels.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next().unwrap(), "vehicle,wheel,time,position,force,rail_deflection,moment");
    assert_eq!(lines.count() as u64, v["steps"].as_u64().unwrap());
    assert!(out.join("wheel-forces.png").exists());
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["files"]["wheels.csv"]["columns"][4]["unit"], "N");
    std::fs::remove_dir_all(&folder).unwrap();
}

/// Quarter cars on the axles of a scenario train: one vehicle per axle, each carrying its axle's force as the rail
/// carries it (one rail: half of each axle, the default on a foundation).
#[test]
fn a_train_of_quarter_cars_carries_its_axles() {
    let folder = temporary_folder("vehicle-train");
    let train = scenario(
        &folder,
        "train.toml",
        "[load]\nspeed = 100.0\n[[load.axles]]\noffset = 0.0\nforce = 100e3\n[[load.axles]]\noffset = 2.5\n\
         force = 120e3\n[vehicle]\n",
    );
    let v = json(&frictrack(&["run", &train, "--format", "json"]));
    let wheels = v["vehicles"]["wheels"].as_array().unwrap();
    assert_eq!(wheels.len(), 2);
    assert!((wheels[1]["static_force"].as_f64().unwrap() - 60e3).abs() < 1e-6);
    assert_eq!(v["axle_share"]["carries"], "one-rail");
    assert_eq!(wheels[1]["offset"].as_f64().unwrap(), 2.5);
    // From a static start at 20 m/s the second wheel never leaves the rail: 0 s off it, not "-0.0" (an empty float
    // sum starts at −0).
    let slow = ["run", &train, "--speed", "20", "--load-advance", "0.02", "--static-start", "50", "--format", "json"];
    let out = frictrack(&slow);
    assert!(!String::from_utf8_lossy(&out.stdout).contains("-0.0"), "{}", String::from_utf8_lossy(&out.stdout));
    assert_eq!(json(&out)["vehicles"]["wheels"][1]["time_off_rail"].as_f64(), Some(0.0));
    std::fs::remove_dir_all(&folder).unwrap();
}

/// Bad vehicles exit 2 and name the path, the value and what is allowed.
#[test]
fn bad_vehicles_exit_2_naming_the_path() {
    let folder = temporary_folder("bad-vehicles");
    for (name, text, expected) in [
        ("mass.toml", "[vehicle]\nkind = \"quarter-car\"\nmass = 5.0\n", "vehicle.mass"),
        ("negative.toml", "[vehicle]\nbody_mass = -1.0\n", "vehicle.body_mass"),
        (
            "rail.toml",
            "[[rail.irregularities]]\nkind = \"ramp\"\nstart = 1.0\nlength = 1.0\nheight = 1e-3\n",
            "rail.irregularities",
        ),
        ("coarse.toml", "[load]\nspeed = 20.0\n[vehicle]\n", "integration.load_advance"),
        ("spacing.toml", "[vehicle]\ncount = 3\n", "vehicle.spacing"),
        ("flat.toml", "[vehicle]\n[[vehicle.flats]]\nwheel = 4\nlength = 0.05\n", "vehicle.flats[0].wheel"),
        ("solver.toml", "[vehicle]\n[integration]\nsolver = \"homotopy\"\n", "integration.solver"),
        ("kind.toml", "[vehicle]\nkind = \"bicycle\"\n", "vehicle.kind"),
        (
            "random.toml",
            "[vehicle]\n[[rail.irregularities]]\nkind = \"random\"\nspectrum = \"fra-9\"\n",
            "rail.irregularities[0]",
        ),
        ("matrices.toml", "[vehicle]\nkind = \"matrices\"\n", "vehicle.matrices"),
        ("restitution.toml", "[vehicle]\ncontact = \"rigid\"\nrestitution = 1.5\n", "vehicle.restitution"),
        ("misplaced.toml", "[vehicle]\nrestitution = 0.5\n", "vehicle.restitution"),
        ("stiffness.toml", "[vehicle]\ncontact = \"rigid\"\ncontact_stiffness = 1e9\n", "vehicle.contact_stiffness"),
    ] {
        let path = scenario(&folder, name, text);
        let out = frictrack(&["run", &path]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {stderr}");
        assert!(stderr.contains(expected), "{name}: {stderr}");
    }
    std::fs::remove_dir_all(&folder).unwrap();
}

/// Two rail cars from the scenario: eight wheels, each on a quarter of its car.
#[test]
fn rail_cars_run_from_a_scenario() {
    let folder = temporary_folder("rail-cars");
    let cars = scenario(
        &folder,
        "cars.toml",
        "[load]\nspeed = 60.0\n[vehicle]\nkind = \"rail-car\"\ncount = 2\nspacing = 25.0\n[vehicle.rail_car]\n\
         wheelset_mass = 1100.0\n[integration]\nload_advance = 0.05\n",
    );
    let v = json(&frictrack(&["run", &cars, "--format", "json"]));
    let wheels = v["vehicles"]["wheels"].as_array().unwrap();
    assert_eq!(wheels.len(), 8);
    assert_eq!(wheels[7]["offset"].as_f64().unwrap(), 45.0);
    assert!((wheels[3]["static_force"].as_f64().unwrap() - 61.68e3).abs() < 10.0);
    assert_eq!(v["vehicles"]["bodies"].as_array().unwrap().len(), 2);
    // HSLM-A1's 50 axles are no whole number of four-axle cars; HSLM-A2's 48 are, with a warning (articulated).
    let on_train = scenario(&folder, "train.toml", "[load]\ntrain = \"hslm-a1\"\n[vehicle]\nkind = \"rail-car\"\n");
    let out = frictrack(&["run", &on_train]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("four axles each"));
    let a2 = scenario(&folder, "a2.toml", "[load]\ntrain = \"hslm-a2\"\n[vehicle]\nkind = \"rail-car\"\n");
    let out = frictrack(&["check", &a2]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("articulated"), "{}", String::from_utf8_lossy(&out.stderr));
    // A train file of two cars: each car built from its four axles.
    std::fs::write(
        folder.join("cars.csv"),
        "offset,force\n0,1e5\n2.5,1e5\n15,1e5\n17.5,1e5\n22,1.5e5\n25,1.5e5\n40,1.5e5\n43,1.5e5\n",
    )
    .unwrap();
    let csv = folder.join("cars.csv");
    let text = format!(
        "[load]\nspeed = 40.0\ntrain = {:?}\n[vehicle]\nkind = \"rail-car\"\n[integration]\nload_advance = 0.04\n",
        csv.to_str().unwrap()
    );
    let from_file = scenario(&folder, "from-file.toml", &text);
    let v = json(&frictrack(&["run", &from_file, "--format", "json"]));
    let wheels = v["vehicles"]["wheels"].as_array().unwrap();
    let offsets: Vec<f64> = wheels.iter().map(|w| w["offset"].as_f64().unwrap()).collect();
    assert_eq!(offsets, [0.0, 2.5, 15.0, 17.5, 22.0, 25.0, 40.0, 43.0]);
    // The rail carries half of each axle of the file.
    assert!((wheels[7]["static_force"].as_f64().unwrap() / 0.75e5 - 1.0).abs() < 1e-12);
    std::fs::remove_dir_all(&folder).unwrap();
}

/// The rail-car example as its header says to run it (`--out`, which takes snapshots from the static start on), and
/// again with rigid wheel–rail contact: at θ = ½ a warning names `integration.theta`; at θ = 0.51 none, and the
/// wheel-force envelope over 70–160 m is Hertz's within 0.15 Q₀ (measured on the example's 0.25 m elements:
/// 22.7–99.9 kN against 23.3–105.0 kN, Q₀ = 61.7 kN; both carry step-to-step ringing), the bodies' accelerations
/// within 2 %, and the energy closes with the projection booked. The example's header quotes the Hertz run's
/// envelope and body acceleration: they are checked here.
#[test]
fn the_rail_car_example_runs_with_hertz_and_rigid_contact() {
    let folder = temporary_folder("rigid-cars");
    let example = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/rail-cars-dipped-joint.toml");
    let text = std::fs::read_to_string(&example).unwrap();
    let out = folder.join("cars");
    let hertz =
        json(&frictrack(&["run", example.to_str().unwrap(), "--format", "json", "--out", out.to_str().unwrap()]));
    assert!(out.join("snapshots.csv").exists());
    let v = &hertz["vehicles"];
    let kn = |key: &str| (v[key].as_f64().unwrap() / 1e3).round();
    let body = (v["max_body_acceleration"].as_f64().unwrap() * 100.0).round() / 100.0;
    assert_eq!((kn("min_wheel_force"), kn("max_wheel_force"), body), (23.0, 105.0, 0.13));
    assert!(text.contains("over 70–160 m they range 23–105 kN, the bodies reach 0.13 m/s²"));
    let rigid_text = text.replace("spacing = 25.0", "spacing = 25.0\ncontact = \"rigid\"");
    let rigid = scenario(&folder, "rigid.toml", &rigid_text);
    let warned = frictrack(&["run", &rigid, "--format", "json"]);
    assert_eq!(warned.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&warned.stderr).contains("integration.theta = 0.5"));
    let damped = scenario(
        &folder,
        "damped.toml",
        &rigid_text.replace("load_advance = 0.05", "load_advance = 0.05\ntheta = 0.51"),
    );
    let output = frictrack(&["run", &damped, "--format", "json"]);
    assert!(!String::from_utf8_lossy(&output.stderr).contains("warning"));
    let rigid = json(&output);
    let (h, r) = (&hertz["vehicles"], &rigid["vehicles"]);
    assert_eq!(r["contact"], "rigid");
    let q0 = h["wheels"][0]["static_force"].as_f64().unwrap();
    for key in ["min_wheel_force", "max_wheel_force"] {
        let (a, b) = (h[key].as_f64().unwrap(), r[key].as_f64().unwrap());
        assert!((a - b).abs() < 0.15 * q0, "{key}: Hertz {a} N, rigid {b} N");
    }
    let (a, b) = (h["max_body_acceleration"].as_f64().unwrap(), r["max_body_acceleration"].as_f64().unwrap());
    assert!((a / b - 1.0).abs() < 0.02, "body {a} against {b} m/s²");
    assert!(r["projection_work"].as_f64().unwrap() < 0.0);
    assert!(
        rigid["energy"]["residual"].as_f64().unwrap().abs()
            < 1e-9 * rigid["energy"]["load_work"].as_f64().unwrap().abs()
    );
    std::fs::remove_dir_all(&folder).unwrap();
}

/// Groups of vehicles, each with its own contact law: a rail car with Hertz contact and, 30 m behind it, two quarter
/// cars 10 m apart on rigid wheels, one of them with a flat (counted within its group). The report names the laws
/// `mixed` and lists the six wheels at their offsets, each on its static load; groups' inputs are refused by
/// their own paths.
#[test]
fn groups_of_vehicles_each_with_its_contact() {
    let folder = temporary_folder("groups");
    let base =
        "[load]\nspeed = 40.0\n[integration]\nload_advance = 0.04\ntheta = 0.51\n[vehicle]\nkind = \"rail-car\"\n";
    let groups = "[[vehicle.behind]]\noffset = 30.0\nkind = \"quarter-car\"\ncount = 2\nspacing = 10.0\n\
                  contact = \"rigid\"\n[[vehicle.behind.flats]]\nwheel = 2\nlength = 0.05\n";
    let mixed = scenario(&folder, "mixed.toml", &format!("{base}{groups}"));
    let v = json(&frictrack(&["run", &mixed, "--format", "json"]));
    let vehicles = &v["vehicles"];
    assert_eq!(vehicles["contact"], "mixed");
    let wheels = vehicles["wheels"].as_array().unwrap();
    let offsets: Vec<f64> = wheels.iter().map(|w| w["offset"].as_f64().unwrap()).collect();
    assert_eq!(offsets, [0.0, 2.5, 17.5, 20.0, 30.0, 40.0]);
    assert!((wheels[0]["static_force"].as_f64().unwrap() - 61.68e3).abs() < 10.0);
    assert!((wheels[5]["static_force"].as_f64().unwrap() - 8500.0 * 9.81).abs() < 1e-6 * 8500.0 * 9.81);
    assert_eq!(vehicles["bodies"].as_array().unwrap().len(), 3);
    assert!(v["energy"]["residual"].as_f64().unwrap().abs() < 1e-9 * v["energy"]["load_work"].as_f64().unwrap().abs());
    for (name, text, path) in [
        ("nooffset.toml", format!("{base}[[vehicle.behind]]\nkind = \"moving-mass\"\n"), "vehicle.behind[0].offset"),
        ("first.toml", format!("{base}offset = 3.0\n"), "vehicle.offset"),
        (
            "mass.toml",
            format!("{base}[[vehicle.behind]]\noffset = 5.0\nkind = \"moving-mass\"\nmass = -2.0\n"),
            "vehicle.behind[0].mass",
        ),
        (
            "restitution.toml",
            format!("{base}[[vehicle.behind]]\noffset = 5.0\ncontact = \"rigid\"\nrestitution = 2.0\n"),
            "vehicle.behind[0].restitution",
        ),
        (
            "flat.toml",
            format!("{base}[[vehicle.behind]]\noffset = 30.0\n[[vehicle.behind.flats]]\nwheel = 2\nlength = 0.05\n"),
            "vehicle.behind[0].flats[0].wheel",
        ),
        (
            "nested.toml",
            format!("{base}[[vehicle.behind]]\noffset = 5.0\n[[vehicle.behind.behind]]\noffset = 9.0\n"),
            "vehicle.behind[0].behind",
        ),
        (
            "train.toml",
            "[load]\ntrain = \"hslm-a1\"\n[vehicle]\nkind = \"moving-mass\"\n[[vehicle.behind]]\noffset = 5.0\n".into(),
            "vehicle.behind",
        ),
    ] {
        let path_to = scenario(&folder, name, &text);
        let out = frictrack(&["run", &path_to]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {stderr}");
        assert!(stderr.contains(path), "{name}: {stderr}");
    }
    std::fs::remove_dir_all(&folder).unwrap();
}

/// A quarter car at 100 m/s on the reference track: its wheel force's element ripple falls at least like l_e (2665,
/// 1191, 643, 163 N on 2, 1, 0.5, 0.25 m elements at Δx = 0.05 m — docs/theory.md §12 quotes them), and the run warns
/// above 1 % of Q₀ with the element length that brings it below: 1 m → 0.5 m, where it is below and nothing is said.
#[test]
fn the_element_ripple_of_a_wheel_force_is_measured_and_warned_about() {
    let folder = temporary_folder("ripple");
    let car = scenario(
        &folder,
        "car.toml",
        "[foundation]\ndamping_ratio = 0.05\n[vehicle]\nkind = \"quarter-car\"\n[output]\nextremes_nodes = [60.0, \
         140.0]\n[integration]\nstatic_start = 40.0\nload_advance = 0.05\n[load]\nspeed = 100.0\n",
    );
    let ripple = |elements: &str| {
        let out = frictrack(&["run", &car, "--elements", elements, "--format", "json"]);
        let wheel = &json(&out)["vehicles"]["wheels"][0];
        let said = String::from_utf8_lossy(&out.stderr).into_owned();
        (wheel["element_ripple"].as_f64().unwrap(), wheel["static_force"].as_f64().unwrap(), said)
    };
    let measured: Vec<(f64, f64, String)> = ["100", "200", "400", "800"].into_iter().map(ripple).collect();
    let rounded: Vec<f64> = measured.iter().map(|m| m.0.round()).collect();
    assert_eq!(rounded, [2665.0, 1191.0, 643.0, 163.0]);
    let (_, q0, said) = &measured[1];
    assert!((q0 - 83385.0).abs() < 1.0);
    assert!(
        said.contains("warning: mesh.elements = 200: wheel 1's force carries a ripple of 1191 N (1.4 % of its static")
            && said.contains("elements of 0.5 m (mesh.elements = 400) bring it below"),
        "{said}"
    );
    assert!(measured[2].0 < 0.01 * q0 && !measured[2].2.contains("ripple"), "{}", measured[2].2);
    std::fs::remove_dir_all(&folder).unwrap();
}

/// A quarter car at 10 m/s is refused for its contact mode with the default load advance, and the refusal names the
/// longest step that resolves it; `--max-step` (a row of the one table of overrides) reaches the run: the same file
/// then runs on that step, the load advance kept.
#[test]
fn a_slow_quarter_car_runs_on_the_step_its_refusal_names() {
    let example = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/quarter-car-wheel-flat.toml");
    let refused = frictrack(&["run", example, "--speed", "10", "--format", "json"]);
    assert_eq!(refused.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&refused.stderr);
    let named = stderr.split("integration.max_step ≤ ").nth(1).and_then(|t| t.split(' ').next()).unwrap();
    let h: f64 = named.parse().unwrap();
    let v = json(&frictrack(&["run", example, "--speed", "10", "--max-step", named, "--format", "json", "--quiet"]));
    assert_eq!(v["time_step"].as_f64().unwrap(), h);
    assert!(v["vehicles"]["wheels"][0]["min_force"].as_f64().unwrap() > 0.0);
}
