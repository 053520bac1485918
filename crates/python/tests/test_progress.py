"""Progress where the user works: a tqdm bar in a terminal and in a Jupyter notebook (where standard error is not a
terminal), nothing in a script whose output is captured, and the fraction reaching a callable."""

import sys
import types

import pytest

import frictrack
from frictrack._progress import _Reporter


def test_a_notebook_kernel_gets_a_bar_and_a_captured_script_does_not(monkeypatch):
    pytest.importorskip("tqdm")
    # Under pytest standard error is captured, not a terminal: no bar unless asked.
    with _Reporter(None, "run") as told:
        assert told is None
    # In a Jupyter kernel (IPython's shell has a kernel): a bar — the text one, redrawn in place, without ipywidgets.
    ipython = types.ModuleType("IPython")
    ipython.get_ipython = lambda: types.SimpleNamespace(kernel=object())
    monkeypatch.setitem(sys.modules, "IPython", ipython)
    monkeypatch.setitem(sys.modules, "ipywidgets", None)
    reporter = _Reporter(None, "run")
    assert type(reporter.bar).__module__ == "tqdm.std"
    with reporter as told:
        told(0.5)
        assert reporter.bar.n == 0.5
    # A shell without a kernel (a terminal IPython) is left to the terminal test.
    ipython.get_ipython = lambda: types.SimpleNamespace()
    with _Reporter(None, "run") as told:
        assert told is None


def test_a_callable_hears_the_run_to_its_end():
    fractions = []
    frictrack.run(elements=50, progress=fractions.append)
    assert fractions and fractions[-1] == pytest.approx(1.0) and fractions == sorted(fractions)
