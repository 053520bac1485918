"""The cluster examples (examples/cluster): the Dask sweep on a real LocalCluster of two worker processes equals the
command line's sweep, and the Slurm script's dry run — its shard and merge commands run in order here, no Slurm —
writes the file one unsharded sweep writes."""

import importlib.util
import io
import os
import subprocess

import numpy as np
import pytest

from test_run import ROOT, cli

CLUSTER = ROOT / "examples" / "cluster"


def test_the_dask_sweep_equals_the_command_lines():
    pytest.importorskip("distributed")
    spec = importlib.util.spec_from_file_location("dask_sweep", CLUSTER / "dask_sweep.py")
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    speeds = example.speeds_of("100:250:50")
    text = example.csv(example.sweep(None, speeds, workers=2))
    out = subprocess.run([cli(), "sweep", "--speeds", "100:250:50", "--quiet"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    expected = np.genfromtxt(io.StringIO(out.stdout), delimiter=",", names=True)
    got = np.genfromtxt(io.StringIO(text), delimiter=",", names=True)
    for name in example.COLUMNS:
        assert np.array_equal(expected[name], got[name]), name


def test_the_slurm_dry_run_shards_and_merges_to_the_unsharded_sweep(tmp_path):
    scenario = tmp_path / "case.toml"
    scenario.write_text("[mesh]\nelements = 60\nlength = 60.0\n[friction.devices]\ncount = 5\nforce = 20e3\n")
    env = dict(os.environ, FRICTRACK=cli())
    out = tmp_path / "out"
    dry = subprocess.run(
        ["bash", str(CLUSTER / "slurm-sweep.sh"), str(scenario), "40:200:20", "3", str(out), "--dry-run"],
        capture_output=True, text=True, env=env,
    )
    assert dry.returncode == 0, dry.stderr
    commands = dry.stdout.strip().splitlines()
    assert len(commands) == 1 + 3 + 1, commands  # the folder, three array tasks, the merge
    assert all("--shard" in c and "--resume" in c for c in commands[1:4]) and " merge " in commands[4]
    for command in commands:
        done = subprocess.run(["bash", "-c", command], capture_output=True, text=True, env=env)
        assert done.returncode == 0, f"{command}: {done.stderr}"
    whole = tmp_path / "whole.csv"
    done = subprocess.run([cli(), "sweep", str(scenario), "--speeds", "40:200:20", "--out", str(whole), "--quiet"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert (out / "sweep.csv").read_text() == whole.read_text()
