"""frictrack.run against the command line: the same numbers to the bit, the same scenario however it is given, bad
input named, the GIL released while a run is in flight."""

import json
import os
import re
import subprocess
import tempfile
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import frictrack

ROOT = Path(__file__).resolve().parents[3]
EXAMPLES = ROOT / "examples"


def cli() -> str:
    """The frictrack binary the workspace's tests built (FRICTRACK_BIN overrides)."""
    path = os.environ.get("FRICTRACK_BIN") or str(ROOT / "target" / "debug" / "frictrack")
    if not Path(path).exists():
        pytest.skip(f"no frictrack binary at {path}: run cargo build -p frictrack first")
    return path


def cli_run(args):
    """`frictrack run ARGS --format json --out DIR`: the summary (dict) and the output folder."""
    folder = tempfile.mkdtemp(prefix="frictrack-py-")
    out = subprocess.run([cli(), "run", *args, "--format", "json", "--out", folder], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout), Path(folder)


def without_wall_time(summary):
    """A run's summary without what the clock says (the whole run's and the time loop's wall times)."""
    return {k: v for k, v in summary.items() if k not in ("wall_time", "time_loop")}


def same_table(table, csv_path):
    """Every column of `table` equals the CSV file's, to the bit."""
    expected = np.genfromtxt(csv_path, delimiter=",", names=True)
    assert list(expected.dtype.names) == table.columns
    for name in table.columns:
        assert np.array_equal(np.atleast_1d(expected[name]), table[name], equal_nan=True), name


@pytest.mark.parametrize(
    "args, kwargs",
    [
        ([], {}),
        (["--train", "hslm-a1", "--speed", "80", "--elements", "100"], {"train": "hslm-a1", "speed": 80.0, "elements": 100}),
        (["--speed", "150", "--distributed-friction", "2000"], {"speed": 150.0, "distributed_friction": 2000.0}),
        (["--speed", "288km/h", "--devices", "7", "--device-force", "2e4"], {"speed": "288km/h", "devices": 7, "device_force": 2e4}),
        ([str(EXAMPLES / "quarter-car-wheel-flat.toml")], {}),
        ([str(EXAMPLES / "timoshenko-rail.toml"), "--elements", "400"], {"elements": 400}),
        ([str(EXAMPLES / "voided-sleeper.toml")], {}),
        (["--speed", "240", "--acceleration", "-60"], {"speed": 240.0, "acceleration": -60.0}),
    ],
    ids=["reference", "train", "friction", "km/h", "vehicle", "timoshenko", "voided-sleepers", "braking"],
)
def test_a_run_is_the_command_lines_to_the_bit(args, kwargs):
    scenario = args[0] if args and args[0].endswith(".toml") else None
    run = frictrack.run(scenario, **kwargs)
    summary, folder = cli_run(args)
    assert without_wall_time(run.summary) == without_wall_time(summary)
    same_table(run.histories, folder / "histories.csv")
    same_table(run.snapshots, folder / "snapshots.csv")
    if scenario is not None and "vehicles" in summary:
        same_table(run.wheels, folder / "wheels.csv")
        assert len(run.losses) == summary["vehicles"]["losses_of_contact"]
        assert run.losses.units["impact_force"] == "N"
        if "wheel-flat" in scenario:
            assert len(run.losses) > 10
    else:
        assert run.wheels is None and run.losses is None
    if (folder / "sleepers.csv").exists():
        same_table(run.sleepers, folder / "sleepers.csv")
        assert run.sleepers.units["sleeper_acceleration"] == "m/s²" and run.sleepers.units["pad_force"] == "N"
    else:
        assert run.sleepers is None
    if "timoshenko" in (scenario or ""):
        assert run.summary["rail_theory"].startswith("Timoshenko")
    if "acceleration" in kwargs:
        assert run.summary["speed_change"]["end_speed"] < run.summary["speed_change"]["start_speed"] == 240.0
    if "voided" in (scenario or ""):
        voided = run.summary["sleepers"]["exceptions"]
        assert [e["index"] for e in voided] == [49, 50, 51] and all(e["first_contact"] > 0 for e in voided)
    # The text report is the command line's, by the same library code (but the wall time's line).
    text = subprocess.run([cli(), "run", *args], capture_output=True, text=True).stdout
    assert without_wall_time_line(str(run)) == without_wall_time_line(text)


def test_a_recorded_sleeper_is_the_command_lines_table(tmp_path):
    """A section over a sleeper (30.3 m, voided sleeper 50) records it: `Run.sleepers` is `sleepers.csv` to the
    bit, with units; a section between sleepers records none."""
    text = (EXAMPLES / "voided-sleeper.toml").read_text().replace("[output]", "[output]\nsections = [30.3]")
    scenario = tmp_path / "recorded.toml"
    scenario.write_text(text)
    run = frictrack.run(text, progress=False)
    _, folder = cli_run([str(scenario)])
    same_table(run.sleepers, folder / "sleepers.csv")
    assert set(run.sleepers["sleeper"]) == {50.0} and run.sleepers.units["sleeper_ballast_force"] == "N"
    # The void closes: the ballast under it carries nothing until the wheel has pushed the gap shut.
    assert run.sleepers["sleeper_ballast_force"][0] == 0.0 < run.sleepers["sleeper_ballast_force"].max()
    assert frictrack.run(EXAMPLES / "voided-sleeper.toml", progress=False).sleepers is None


def without_wall_time_line(text):
    return [line for line in text.splitlines() if "wall time" not in line]


def test_the_run_folder_is_the_command_lines(tmp_path):
    """`out=` writes the folder `frictrack run --out` writes, by the same library code: every file of the command
    line's folder is there, the CSVs byte for byte and summary.json but its wall time; bad folders are refused before
    the run."""
    example = str(EXAMPLES / "quarter-car-wheel-flat.toml")
    frictrack.run(example, out=tmp_path / "py", progress=False)
    _, cli_folder = cli_run([example])
    names = sorted(p.name for p in cli_folder.iterdir())
    assert {"summary.json", "wheels.csv", "wheel-forces.png", "histories-deflection.svg"} <= set(names), names
    assert sorted(p.name for p in (tmp_path / "py").iterdir()) == names
    for name in names:
        if name.endswith(".csv"):
            assert (tmp_path / "py" / name).read_bytes() == (cli_folder / name).read_bytes(), name
    summaries = [json.loads((folder / "summary.json").read_text()) for folder in (tmp_path / "py", cli_folder)]
    # Where each came from: the call, then the command line; both at this build's commit, today.
    assert summaries[0]["command"] == f"frictrack.run({example!r}, out={str(tmp_path / 'py')!r}) (Python)"
    assert summaries[1]["command"].split()[1:3] == ["run", example]
    assert summaries[0]["git_revision"] == summaries[1]["git_revision"]
    for summary in summaries:
        summary["report"].pop("wall_time")
        summary["report"].pop("time_loop")
        summary["text"] = summary["text"][: summary["text"].index("  wall time")]
        assert summary.pop("date")[:10] == time.strftime("%Y-%m-%d", time.gmtime())
        summary.pop("command")
    assert summaries[0] == summaries[1]
    (tmp_path / "file").write_text("")
    with pytest.raises(frictrack.InputError, match="out"):
        frictrack.run(out=tmp_path / "file", progress=False)


def test_a_dict_a_toml_string_and_a_file_are_the_same_run(tmp_path):
    toml = '[mesh]\nelements = 100\n[load]\nspeed = 120.0\n[friction.devices]\ncount = 7\nforce = 20e3\n'
    file = tmp_path / "case.toml"
    file.write_text(toml)
    as_dict = {"mesh": {"elements": 100}, "load": {"speed": 120.0}, "friction": {"devices": {"count": 7, "force": 20e3}}}
    runs = [frictrack.run(toml), frictrack.run(str(file)), frictrack.run(file), frictrack.run(as_dict)]
    first = without_wall_time(runs[0].summary)
    assert first["devices"] == 7
    for other in runs[1:]:
        assert without_wall_time(other.summary) == first
        assert np.array_equal(other.histories["deflection"], runs[0].histories["deflection"])


def test_bad_input_raises_input_error_naming_it():
    with pytest.raises(frictrack.InputError, match="sped") as bad_keyword:
        frictrack.run(sped=100.0)
    assert isinstance(bad_keyword.value, ValueError)
    with pytest.raises(frictrack.InputError, match=r"mesh\.lenght.*did you mean `length`"):
        frictrack.run({"mesh": {"lenght": 100.0}})
    with pytest.raises(frictrack.InputError, match="needs shear_coefficient"):
        frictrack.run({"beam": {"theory": "timoshenko", "shear_modulus": 81e9}})
    with pytest.raises(frictrack.InputError, match="speed"):
        frictrack.run(speed=-5.0)
    with pytest.raises(frictrack.InputError, match='invalid speed = "fast": must be a speed: m/s .* or km/h'):
        frictrack.run(speed="fast")
    with pytest.raises(frictrack.InputError, match='invalid theta = "0.5": must be a number'):
        frictrack.run(theta="0.5")
    with pytest.raises(frictrack.InputError, match="devices"):
        frictrack.run(devices=2.5)
    with pytest.raises(frictrack.InputError, match="solver"):
        frictrack.run(solver="fastest")
    with pytest.raises(frictrack.InputError, match="scenario file"):
        frictrack.run("no/such/file.toml")


def test_the_gil_is_released_while_a_run_is_in_flight():
    """Another Python thread counts while a run of about a second is in flight: with the GIL held it could not."""
    done = threading.Event()
    result = {}

    def work():
        result["run"] = frictrack.run(speed=150.0, distributed_friction=2000.0, elements=400)
        done.set()

    worker = threading.Thread(target=work)
    counts = 0
    started = time.perf_counter()
    worker.start()
    while not done.is_set():
        counts += 1
    elapsed = time.perf_counter() - started
    worker.join()
    assert elapsed > 0.2, f"the run took {elapsed} s: too short to show anything"
    # A held GIL would let this thread run only between the run's polls (none: the run never returns to Python).
    assert counts > 10_000, f"{counts} iterations in {elapsed:.2f} s"
    assert result["run"].summary["steps"] > 0


def test_tables_carry_their_units_and_become_data_frames():
    run = frictrack.run(elements=50)
    assert run.histories.units["moment"] == "N·m" and run.snapshots.units["x"] == "m"
    pandas = pytest.importorskip("pandas")
    frame = run.histories.to_pandas()
    assert isinstance(frame, pandas.DataFrame) and frame.attrs["units"]["deflection"] == "m"
    assert list(frame.columns) == run.histories.columns


def test_the_catalogue_and_the_keywords():
    assert frictrack.trains()[:2] == ["single", "hslm-a1"] and len(frictrack.trains()) == 11
    assert "distributed_friction" in frictrack.override_names()


def test_the_docs_and_stubs_follow_the_table_of_overrides():
    """`run`'s keywords in the type stubs, its docstring's units and the command line's help all come from one table:
    a keyword added, renamed, retyped or given a unit there fails here until the docs say it too."""
    table = frictrack.override_table()
    assert [row[0] for row in table] == frictrack.override_names()
    stubs = (Path(frictrack.__file__).parent / "__init__.pyi").read_text()
    signature = stubs.split("def run(", 1)[1].split(") -> Run:", 1)[0]
    keywords = re.findall(r"^    (\w+): ([^=]+) = \.\.\.,$", signature.split("*,", 1)[1], re.M)
    assert keywords == [(name, python_type) for name, python_type, _, _ in table]
    doc = " ".join(frictrack.run.__doc__.split())
    for name, _, unit, _ in table:
        assert f"``{name}``" in doc, name
        if unit:
            said = re.search(rf"``{name}`` \(([^)]*)\)", doc)
            assert said and unit in said.group(1), f"{name}: the docstring must give its unit {unit}"
    help_text = " ".join(subprocess.run([cli(), "run", "--help"], capture_output=True, text=True, check=True).stdout.split())
    for name, _, _, what in table:
        assert " ".join(what.split()) in help_text, name


@pytest.fixture
def python_handles_ctrl_c():
    """Python's own SIGINT handler for the test: a process started in the background by a shell without job control
    inherits SIGINT ignored, and then `_thread.interrupt_main` does nothing (CI launched that way failed both Ctrl-C
    tests with "DID NOT RAISE")."""
    import signal

    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


@pytest.mark.usefixtures("python_handles_ctrl_c")
def test_ctrl_c_stops_a_run_within_a_step():
    """KeyboardInterrupt (what Ctrl-C raises) arrives while a long run is in flight: the run stops at its next step
    and the interrupt is raised — within a fraction of a second, not at the run's end (several seconds)."""
    import _thread

    timer = threading.Timer(0.3, _thread.interrupt_main)
    started = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        frictrack.run(speed=150.0, distributed_friction=2000.0, elements=1600, load_advance=0.025)
    stopped = time.perf_counter() - started
    timer.cancel()
    assert stopped < 1.5, f"stopped after {stopped:.2f} s"
    # The package still works afterwards.
    assert frictrack.run(elements=50).summary["steps"] > 0


@pytest.mark.usefixtures("python_handles_ctrl_c")
def test_ctrl_c_stops_a_stationary_sweep_within_a_speed():
    """Ctrl-C during a long stationary sweep (2000 speeds with ballast friction, tens of seconds) stops it before its
    next speed — it used to be ignored until the sweep ended (> 30 s seen)."""
    import _thread

    timer = threading.Timer(0.3, _thread.interrupt_main)
    started = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        frictrack.stationary({"foundation": {"damping_ratio": 0.05}}, [20.0 + 0.1 * i for i in range(2000)],
                             distributed_friction=2000.0)
    stopped = time.perf_counter() - started
    timer.cancel()
    assert stopped < 1.3, f"stopped after {stopped:.2f} s"


def test_one_cap_on_the_speeds_of_every_entry_point():
    """More than a million speeds are refused before anything runs, by Python as by the command line."""
    too_many = [100.0] * 1_000_001
    for call in (lambda: frictrack.sweep(None, too_many), lambda: frictrack.stationary(None, too_many),
                 lambda: frictrack.analytic(None, too_many)):
        with pytest.raises(frictrack.InputError, match="at most 1000000"):
            call()


def test_a_sweep_warns_what_a_run_at_its_speeds_warns():
    bridge = ROOT / "examples" / "hslm-bridge.toml"
    sweep = frictrack.sweep(bridge, [20.0, 100.0])
    run = frictrack.run(bridge, speed=20.0)
    coarse = [w for w in run.warnings if "load_advance" in w]
    assert coarse and coarse[0] in sweep.warnings, (run.warnings, sweep.warnings)


def test_every_sweep_column_has_its_unit_on_sleepers_too():
    """The sleepers' columns (pad and ballast forces, the voided sleeper's lowest point) came without units: the
    Python sweep listed only the base and vehicle columns."""
    sweep = frictrack.sweep(EXAMPLES / "voided-sleeper.toml", [40.0], jobs=1)
    assert {"max_pad_force", "max_ballast_force", "exception_lowest"} <= set(sweep.columns), sweep.columns
    assert (sweep.units["max_pad_force"], sweep.units["max_ballast_force"]) == ("N", "N"), sweep.units
    assert sweep.units["exception_lowest"] == "m", sweep.units
    assert all(sweep.units[c] for c in sweep.columns), sweep.units


def test_speeds_may_be_one_number_and_bad_speeds_name_themselves():
    """`stationary(speeds=200)` raised a bare TypeError ('int' object is not iterable)."""
    one = frictrack.stationary(None, speeds=200)
    assert [p["speed"] for p in one.points] == [200.0]
    assert [p["speed"] for p in frictrack.analytic(None, 150)] == [150.0]
    with pytest.raises(frictrack.InputError, match='invalid speeds = "fast": `fast` is not a speed'):
        frictrack.sweep(None, "fast")
    # Speeds with their unit, as run(speed="540km/h") takes one (stationary(speeds="144km/h") was refused).
    assert [p["speed"] for p in frictrack.analytic(None, "720km/h")] == [200.0]
    assert [p["speed"] for p in frictrack.analytic(None, ["360km/h", 150.0])] == [100.0, 150.0]


def test_wrong_arguments_name_themselves(tmp_path):
    """Each raised a bare TypeError with no argument named, or (acceleration=None) promised text and pairs it then
    refused."""
    folder = tmp_path / "run"
    frictrack.run(None, speed=150.0, elements=50, out=folder)
    for call, named in [
        (lambda: frictrack.report(None), "folder = None"),
        (lambda: frictrack.report(42), "folder = 42"),
        (lambda: frictrack.report(folder, out=123), "out = 123"),
        (lambda: frictrack.ground(None, out=123), "out = 123"),
        (lambda: frictrack.stationary(None, 100.0, domain="ab"), "domain = 'ab'"),
        (lambda: frictrack.stationary(None, 100.0, domain=(10, 20, 30)), r"domain = \(10, 20, 30\)"),
        (lambda: frictrack.run(None, out=123), "out = 123"),
        (lambda: frictrack.run(None, acceleration=[1, 2]), r"acceleration = .*must be a number in m/s²"),
    ]:
        with pytest.raises(frictrack.InputError, match=f"invalid {named}"):
            call()
    # None leaves the scenario's value, as an absent keyword does; an acceleration may carry its unit.
    assert frictrack.run(None, speed=150.0, elements=50, acceleration=None).summary.get("speed_change") is None
    braking = frictrack.run(None, speed=150.0, elements=50, acceleration="-20m/s2").summary["speed_change"]
    assert braking["acceleration"] == -20.0


def test_progress_is_told_to_a_callback():
    """A callable `progress` hears the fraction done as the work goes (polled every 50 ms) and 1.0 at the end, for a
    run, a sweep and a stationary sweep (each ~1 s: several polls); the results are those without it."""
    for call in (
        lambda p: frictrack.run(speed=150.0, distributed_friction=2000.0, elements=400, load_advance=0.05,
                                progress=p),
        lambda p: frictrack.sweep(None, [100.0, 150.0, 200.0], jobs=1, distributed_friction=2000.0, progress=p),
        lambda p: frictrack.stationary({"foundation": {"damping_ratio": 0.05}}, [20.0 + i for i in range(200)],
                                       distributed_friction=2000.0, progress=p),
    ):
        heard = []
        call(heard.append)
        assert heard[-1] == 1.0 and len(heard) >= 2, heard
        assert all(0.0 <= a <= b <= 1.0 for a, b in zip(heard, heard[1:])), heard
    quiet = frictrack.sweep(None, [100.0, 150.0], jobs=1, progress=False)
    told = frictrack.sweep(None, [100.0, 150.0], jobs=1, progress=lambda f: None)
    assert np.array_equal(quiet["max_downward_deflection"], told["max_downward_deflection"])


def test_an_exception_in_the_progress_callback_stops_the_work():
    def fail(fraction):
        if fraction > 0.0:
            raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        frictrack.stationary({"foundation": {"damping_ratio": 0.05}}, [20.0 + 0.1 * i for i in range(2000)],
                             distributed_friction=2000.0, progress=fail)


def test_long_work_is_announced_before_it_starts(capsys):
    """Work estimated above 10 s says so on stderr before it starts, as the command line does (the estimate rule of
    study.cost): a stationary sweep of 20 000 speeds with friction (~8 min) and a sweep of 3000 runs with ballast
    friction (~12 min on 2 threads), each stopped by its progress callback at the first poll; short work says nothing."""
    def stop(fraction):
        raise RuntimeError("enough")

    for name, call in (
        ("frictrack.stationary: 20000 stationary solves of 481 nodes, nonsmooth",
         lambda: frictrack.stationary(None, [10.0 + 0.01 * i for i in range(20000)], distributed_friction=5000.0,
                                      progress=stop)),
        ("frictrack.sweep: 3000 runs, the largest of 2000 steps over 400 DOFs, 799 friction sections",
         lambda: frictrack.sweep(None, [10.0 + 0.1 * i for i in range(3000)], jobs=2, distributed_friction=5000.0,
                                 progress=stop)),
    ):
        with pytest.raises(RuntimeError, match="enough"):
            call()
        said = capsys.readouterr().err
        assert said.startswith(name) and "estimated" in said, said
    frictrack.sweep(None, [100.0, 150.0], jobs=1, progress=False)
    assert capsys.readouterr().err == ""


def test_a_keyword_that_is_no_override_is_named_as_such():
    """`co_moving=True` was told its value must be a number; the name is what is wrong."""
    with pytest.raises(frictrack.InputError, match="invalid override = co_moving: is not one of speed"):
        frictrack.run(co_moving=True)


def test_check_resolution_estimates_each_outcomes_error_from_twins_at_other_resolutions():
    """`check_resolution=True` is `run --check-resolution`: the summary holds the three resolutions (the run's among
    them) and every outcome's values there, with the run's error or None where the values do not converge."""
    run = frictrack.run(elements=60, load_advance=0.4, speed=150, check_resolution=True, progress=False)
    check = run.summary["resolution_check"]
    assert [r["elements"] for r in check["resolutions"]] == [30, 60, 120]
    assert check["run"] == 1 and check["resolutions"][1]["load_advance"] == 0.4
    by_name = {o["name"]: o for o in check["outcomes"]}
    window = by_name["window_max_downward_deflection"]
    assert window["values"][1] == run.summary["window_max_downward_deflection"]["value"]
    assert window["convergence"]["kind"] in {"settled", "monotone", "alternating", "not_contracting", "scattered"}
    assert all((o["error"] is None) == (o["convergence"]["kind"] == "not_contracting") for o in check["outcomes"])
    assert "resolution check" in run.report
    assert "resolution_check" not in frictrack.run(elements=60, load_advance=0.4, speed=150, progress=False).summary


@pytest.mark.parametrize("bad", [1, "yes", None, 0.5])
def test_check_resolution_takes_only_a_bool(bad):
    with pytest.raises(frictrack.InputError, match=r"check_resolution = .*True or False"):
        frictrack.run(check_resolution=bad, progress=False)


def test_accuracy_refines_until_every_outcome_is_within_it():
    """`accuracy=0.05` is `run --accuracy 0.05`: the finest run's summary, its check over the last three
    resolutions and whether the tolerance was reached."""
    run = frictrack.run(elements=50, load_advance=0.8, accuracy=0.05, progress=False)
    accuracy = run.summary["accuracy"]
    assert accuracy["status"]["kind"] == "reached" and accuracy["tolerance"] == 0.05
    check = run.summary["resolution_check"]
    assert check["run"] == 2 and check["resolutions"][2]["elements"] == accuracy["resolutions"][-1]["elements"]
    assert all(o["error"] <= 0.05 * abs(o["values"][2]) for o in check["outcomes"])
    assert "accuracy 5 %: reached" in run.report


@pytest.mark.parametrize("bad", [0, -0.01, float("nan"), 1, 1.5, "1%", True])
def test_a_bad_accuracy_is_refused_naming_it(bad):
    with pytest.raises(frictrack.InputError, match=r"invalid accuracy = .*relative error in \(0, 1\)"):
        frictrack.run(accuracy=bad, progress=False)


def test_accuracy_and_check_resolution_are_not_given_together():
    with pytest.raises(frictrack.InputError, match="check_resolution"):
        frictrack.run(accuracy=0.01, check_resolution=True, progress=False)


def test_a_scenario_s_accuracy_refines_its_run_and_a_sweep_refuses_it_by_name():
    """`[integration] accuracy` is a single run's `accuracy=`; a sweep keeps the resolution given and refuses it."""
    text = "[mesh]\nelements = 50\n[integration]\nload_advance = 0.8\naccuracy = 0.05\n"
    run = frictrack.run(text, progress=False)
    assert run.summary["accuracy"]["tolerance"] == 0.05
    assert frictrack.run(text, accuracy=0.1, progress=False).summary["accuracy"]["tolerance"] == 0.1
    with pytest.raises(frictrack.InputError, match=r"invalid integration.accuracy = 0.05"):
        frictrack.sweep(text, speeds=[150, 200], progress=False)
    with pytest.raises(frictrack.InputError, match=r"integration.accuracy.*check_resolution"):
        frictrack.run(text, check_resolution=True, progress=False)


def test_a_sweep_checks_the_run_at_its_peak():
    sweep = frictrack.sweep(speeds=[150, 200, 250], elements=100, load_advance=0.2, check_resolution=True,
                            progress=False)
    assert sweep.resolution_check["speed"] == 200.0
    assert sweep.resolution_check["point"] == "the speed of the largest max downward deflection"
    assert sweep.resolution_check["check"]["outcomes"][0]["name"] == "max_downward_deflection"
    assert frictrack.sweep(speeds=[150, 200], elements=100, load_advance=0.2, progress=False).resolution_check is None
