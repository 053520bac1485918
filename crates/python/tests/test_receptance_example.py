"""examples/python/receptance_plot.py: both rails give one resonance on the continuous soil at the same frequency,
the Timoshenko rail more receptance at kHz, and the figure is written."""

import importlib.util

import numpy as np

from test_run import ROOT

EXAMPLE = ROOT / "examples" / "python" / "receptance_plot.py"


def test_both_rails_and_the_figure(tmp_path, monkeypatch):
    spec = importlib.util.spec_from_file_location("receptance_plot", EXAMPLE)
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    results = example.curves(np.array([5.0, 8.0, 10.0, 12.0, 15.0, 1000.0, 2000.0]))
    (_, euler), (_, timoshenko) = results
    # The one resonance is the rail on its soil, where shear does not matter (long waves): the same to 1 %.
    assert len(euler.resonances) == len(timoshenko.resonances) == 1
    assert abs(euler.resonances[0]["frequency"] / timoshenko.resonances[0]["frequency"] - 1) < 1e-2
    # At 2 kHz the bending waves are short and the Timoshenko rail, softer in shear, answers more.
    assert timoshenko.table["magnitude"][-1] > 1.1 * euler.table["magnitude"][-1]
    path = tmp_path / "rails.png"
    example.draw(results, path)
    assert path.stat().st_size > 10_000
