"""The command line's other commands from Python: the same numbers as the command prints or writes, to the bit."""

import json
import subprocess

import numpy as np
import pytest

import frictrack
from test_run import cli


def cli_json(*args):
    out = subprocess.run([cli(), *args, "--format", "json"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def test_analytic_and_stationary_are_the_command_lines(tmp_path):
    assert frictrack.analytic(None, [80.0, 120.0], damping_ratio=0.05) == cli_json(
        "analytic", "--speeds", "80:120:40", "--damping-ratio", "0.05"
    )
    case = tmp_path / "ballast.toml"
    case.write_text("[foundation]\ndamping_ratio = 0.05\n[friction.distributed]\nforce_per_length = 2000.0\n")
    wave = frictrack.stationary(case, [100.0, 200.0])
    expected = cli_json("stationary", str(case), "--speeds", "100:200:100")
    assert wave.points == expected
    # The same as a dict with overrides: the scenario's keys, or the command line's names.
    assert frictrack.stationary({"foundation": {"damping_ratio": 0.05}}, [100.0, 200.0],
                                distributed_friction=2000.0).points == expected
    # A domain of its own, as --domain gives it; left out, the command line's default (not a copy of it).
    assert frictrack.stationary(case, [100.0], domain=(80.0, 70.0), element_length=0.5).points == [cli_json(
        "stationary", str(case), "--speed", "100", "--domain", "80:70", "--element-length", "0.5"
    )]
    assert sorted(wave.waves) == [100.0, 200.0]
    # Its text report is the command line's table, by the same library code.
    table_text = subprocess.run([cli(), "stationary", str(case), "--speeds", "100:200:100"], capture_output=True,
                                text=True).stdout
    assert str(wave) == table_text and "speed (m/s)" in str(wave)
    table = wave.waves[100.0]
    assert np.max(np.abs(table["friction_force"])) <= 2000.0 * (1 + 1e-12)
    # The units convention of every table: plain names, units beside them.
    assert table.columns[:2] == ["s", "deflection"] and table.units["moment"] == "N·m"
    # The peak is refined between nodes: the nodes' lowest is a little above it.
    lowest, peak = -table["deflection"].min(), expected[0]["max_downward_deflection"]["value"]
    assert lowest <= peak and lowest >= 0.99 * peak


def test_a_study_is_the_command_lines(tmp_path):
    study = frictrack.study("amplification", jobs=2)
    out = subprocess.run([cli(), "study", "amplification", "--out", str(tmp_path), "--quiet"], capture_output=True,
                         text=True)
    assert out.returncode == 0, out.stderr
    written = json.loads((tmp_path / "amplification.json").read_text())
    assert study.summary == written["summary"]
    expected = np.genfromtxt(tmp_path / "amplification.csv", delimiter=",", names=True)
    for name in study.table.columns:
        assert np.array_equal(expected[name], study.table[name]), name
    assert len(study.headline) == 2 and study.table.units["speed"] == "m/s"
    with __import__("pytest").raises(frictrack.InputError, match="resolution = fine: must be one of coarse, paper"):
        frictrack.study("amplification", resolution="fine")


def test_trains_and_rails():
    a1 = frictrack.train("hslm-a1")
    assert a1["name"] == "hslm-a1" and a1["axles"] == len(a1["axles_table"]) > 40
    assert a1["total_force"] == a1["axles_table"]["force"].sum()
    profile, psd, summary = frictrack.track_profile("german-low", length=200.0, spacing=0.25, seed=3)
    assert len(profile) == 800 and profile.columns == ["x", "r"]
    assert abs(np.std(profile["r"]) - summary["sample_std"]) <= 1e-12 * summary["sample_std"] + 1e-15
    with __import__("pytest").raises(frictrack.InputError, match="spectrum"):
        frictrack.track_profile("german-medium")


def test_receptance_is_the_command_lines(tmp_path):
    """frictrack.receptance gives the command line's JSON to the bit, its CSV as a table with units, its text as
    str(); the undamped reference track's warnings arrive as UserWarning; bad input names the field."""
    case = tmp_path / "track.toml"
    case.write_text("[mesh]\nelements = 800\n[foundation]\ndamping_ratio = 0.1\nloss_factor = 0.2\n"
                    "[foundation.absorbing_zones]\nlength = 40.0\n")
    result = frictrack.receptance(case, np.arange(1.0, 51.0), at=100.0, out=tmp_path / "out")
    expected = cli_json("receptance", str(case), "--frequencies", "1:50:1", "--at", "100")
    assert result.summary == expected
    assert result.table.units["magnitude"] == "m/N" and len(result.table) == 50
    assert np.array_equal(result.table["magnitude"], [p["magnitude"] for p in expected["points"]])
    assert 9.5 < result.resonances[0]["frequency"] < 10.5
    text = subprocess.run([cli(), "receptance", str(case), "--frequencies", "1:50:1", "--at", "100"],
                          capture_output=True, text=True).stdout
    assert str(result) == text
    assert (tmp_path / "out" / "receptance.png").is_file()
    with pytest.warns(UserWarning, match="come back"):
        frictrack.receptance(None, [5.0, 10.0, 20.0])
    with pytest.raises(frictrack.InputError, match="at = 500"):
        frictrack.receptance(None, [10.0], at=500.0)
    # A new user's arguments (they raised TypeError, ValueError, OverflowError or went unused): each names itself.
    for arguments, named in [
        (dict(frequencies="10:100:1"), "frequencies"),
        (dict(frequencies=None), "frequencies"),
        (dict(frequencies=[10.0], at="middle"), "at"),
        (dict(frequencies=[10.0], excite=[1, 2]), "excite"),
        (dict(frequencies=[10.0], jobs=-1), "jobs"),
        (dict(frequencies=[10.0], speed=100), "speed"),
    ]:
        with pytest.raises(frictrack.InputError, match=f"invalid {named} = "):
            frictrack.receptance(None, **arguments)
    # One frequency, as the command line takes A:A:STEP.
    assert len(frictrack.receptance(None, 50.0).table) == 1


def test_a_timoshenko_rail_in_the_stationary_wave_and_the_closed_form():
    """The stationary wave's Timoshenko elements and the Timoshenko closed form agree (as on the command line:
    measured 2.8e-6 at 150 m/s) and each is the command line's."""
    rail = {"beam": {"theory": "timoshenko", "shear_modulus": 81e9, "shear_coefficient": 0.4},
            "foundation": {"damping_ratio": 0.05}}
    wave = frictrack.stationary(rail, [150.0])
    closed = frictrack.analytic(rail, [150.0])
    peak = wave.points[0]["max_downward_deflection"]["value"]
    assert abs(peak / closed[0]["max_downward_deflection"]["value"] - 1) < 1e-4
    assert "Timoshenko" in str(wave)
