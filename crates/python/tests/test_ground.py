"""frictrack.ground on examples/soft-ground.toml: the composite beam on a layered ground from Python — the critical
speeds with their units, the tables, the files it writes (the same numbers as its JSON), and a bad profile refused
by key."""

import json

import pytest

import frictrack
from test_run import ROOT

SITE = (ROOT / "examples" / "soft-ground.toml").read_text()


def test_the_ground_from_python(tmp_path):
    site = tmp_path / "site.toml"
    site.write_text(SITE)
    out = tmp_path / "out"
    with pytest.warns(UserWarning):  # this site's fundamental mode falls to the end of the range: no least value
        ground = frictrack.ground(site, frequencies=range(1, 31), out=out)
    assert ground.critical_speed < ground.winkler_critical_speed
    assert ground.dispersion.units == {"frequency": "Hz", "phase_velocity": "m/s"}
    assert len(ground.dispersion["frequency"]) == 30
    assert ground.stiffness.units["stiffness_real"] == "N/m²"
    # The critical speed is refined between the sampled peak's neighbours, never below the sample.
    speeds, down = ground.speeds["speed"], ground.speeds["max_downward_deflection"]
    best, step = int(down.argmax()), speeds[1] - speeds[0]
    assert down[best] <= ground.summary["critical_deflection"]
    assert abs(ground.critical_speed - speeds[best]) <= step
    written = json.loads((out / "ground.json").read_text())
    assert written["critical_speed"] == ground.critical_speed
    assert (out / "ground-dispersion.svg").stat().st_size > 10_000
    assert "critical speed on the ground" in str(ground)
    bad = SITE.replace("thickness = 4.0", "thickness = -4.0")
    with pytest.raises(frictrack.InputError, match=r"ground.layers\[1\].thickness = -4"):
        frictrack.ground(bad)


def test_a_train_on_the_ground_from_python():
    """The X2000 at Ledsgård at 70 km/h: `frictrack.stationary` on a `[ground]` gives the command line's wave — its
    points (the deepest 6.09 mm, 12.17 m behind the first axle), the wave as a table with its units and the measured
    record beside it (RMS misfit 0.62 mm, as `--measured`); an element length (a mesh) is refused by name."""
    site = ROOT / "examples" / "ledsgard" / "ledsgard.toml"
    record = ROOT / "examples" / "ledsgard" / "x2000_70kmh.csv"
    result = frictrack.stationary(site, speeds=[70 / 3.6], measured=record)
    assert result.measured["direction"] == -1.0
    assert abs(result.measured["rms_misfit"] - 0.62e-3) < 5e-6
    point = result.points[0]
    assert point["status"] == "converged"
    assert abs(point["max_downward_deflection"]["value"] - 6.089e-3) < 1e-6
    assert abs(point["max_downward_deflection"]["position"] + 12.17) < 0.01
    wave = result.waves[70 / 3.6]
    assert wave.units == {"s": "m", "deflection": "m"}
    assert abs(wave["deflection"].min() + 6.089e-3) < 2e-5  # the points 0.25 m apart, the peak refined between
    assert "stationary on the ground" in str(result)
    with pytest.raises(frictrack.InputError, match="element_length = 0.1"):
        frictrack.stationary(site, speeds=[20.0], element_length=0.1)


def test_ballast_friction_on_the_ground_from_python(tmp_path):
    """The X2000 at Ledsgård at 185 km/h with ballast friction of 2 kN/m under the composite beam: the command line's
    8.54 mm (8.78 without friction), the friction's own numbers with the point; on the two-beam track with a
    tensionless ballast (friction and lift-off at one interface) refused by name."""
    site = ROOT / "examples" / "ledsgard" / "ledsgard.toml"
    point = frictrack.stationary(site, speeds=[185 / 3.6], distributed_friction=2000.0).points[0]
    assert point["status"] == "converged"
    assert abs(point["max_downward_deflection"]["value"] - 8.543e-3) < 1e-6
    assert point["friction"]["slipping_length"] > 100.0 and point["friction"]["friction_power"] > 0.0
    folder = ROOT / "examples" / "ledsgard"
    (tmp_path / "x2000.csv").write_text((folder / "x2000.csv").read_text())
    text = (folder / "ledsgard-two-beam.toml").read_text()
    lifting = tmp_path / "lifting.toml"
    lifting.write_text(text.replace("[embankment]", '[embankment]\ninterface = "tensionless"', 1))
    with pytest.raises(frictrack.InputError, match="embankment.interface"):
        frictrack.stationary(lifting, speeds=[20.0], distributed_friction=2000.0)


def test_sleepers_lifting_off_the_ballast_from_python(tmp_path):
    """The two-beam track at Ledsgård with a ballast that cannot pull (`[embankment] interface = "tensionless"`): at
    185 km/h the command line's lift between the locomotive and the first car, 3.58 µm against the weight's 11.49 µm
    compression, with its unit, and the opening and the ballast's push along the wave."""
    folder = ROOT / "examples" / "ledsgard"
    (tmp_path / "x2000.csv").write_text((folder / "x2000.csv").read_text())
    text = (folder / "ledsgard-two-beam.toml").read_text()
    site = tmp_path / "site.toml"
    site.write_text(text.replace("[embankment]", '[embankment]\ninterface = "tensionless"', 1))
    result = frictrack.stationary(site, speeds=[185 / 3.6])
    lift = result.points[0]["lift_off"]
    assert abs(lift["largest_gap"]["value"] - 3.58e-6) < 1e-8
    assert -16.5 < lift["largest_gap"]["position"] < -12.4
    assert abs(lift["preload"] + 11.49e-6) < 1e-8
    wave = result.waves[185 / 3.6]
    assert wave.units == {"s": "m", "deflection": "m", "gap": "m", "ballast_force": "N/m"}
    assert 0.0 < wave["gap"].max() <= lift["largest_gap"]["value"]
    assert "lift off the ballast" in str(result)


def test_a_run_in_time_on_the_ground_from_python():
    """`frictrack.run` on a `[ground]` takes the foundation fitted at its speed, as the command line does: the fit and
    its wave error in the summary, and at the ground's critical speed the warning the command line prints."""
    run = frictrack.run(SITE, speed=40.0)
    fit = run.summary["ground_fit"]
    assert fit["speed"] == 40.0 and fit["wave_error"] < 0.06
    assert run.summary["critical_speed"] is None
    near = frictrack.run(SITE, speed=61.4)
    assert any(w.startswith("ground = fitted at 61.4 m/s") for w in near.warnings), near.warnings


def test_a_voided_sleeper_over_the_embankment_from_python(tmp_path):
    """`frictrack.run` on the two-beam track at Ledsgård (one 90 kN wheel at 185 km/h) with sleeper 200 voided by
    1.5 mm, as the command line runs it: the fit is the rail's (6.3 % from the exact wave), the void never closes on
    this soft site (no first contact, no ballast force) and the sleeper's own numbers come with the run."""
    text = (ROOT / "examples" / "ledsgard" / "ledsgard-two-beam.toml").read_text()
    text = text.replace('train = "x2000.csv"', "force = 90000.0", 1)
    text = text.replace("[mesh]", "[[sleepers.exceptions]]\nindex = 200\ngap = 0.0015\n\n[mesh]", 1)
    site = tmp_path / "voided.toml"
    site.write_text(text)
    run = frictrack.run(site, speed="185km/h")
    fit = run.summary["ground_fit"]
    assert abs(fit["wave_error"] - 0.063) < 0.001
    voided = run.summary["sleepers"]["exceptions"][0]
    assert voided["what"] == "void 1.5 mm" and abs(voided["x"] - 130.325) < 1e-9
    assert "first_contact" not in voided and voided["ballast_force"] == 0.0
    assert voided["largest_gap"] > 1.5e-3
