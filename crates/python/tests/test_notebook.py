"""scripts/run_notebook.py, the check the notebook tour passes in scripts/wheel-check: a notebook stored with outputs
is refused before it runs, a cell that warns or fails fails the run, a clean one passes — and the tour itself is
stored clean."""

import importlib.util
from pathlib import Path

import pytest

from test_run import ROOT

nbformat = pytest.importorskip("nbformat")
pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

spec = importlib.util.spec_from_file_location("run_notebook", ROOT / "scripts" / "run_notebook.py")
run_notebook = importlib.util.module_from_spec(spec)
spec.loader.exec_module(run_notebook)


def notebook(tmp_path: Path, *sources: str, outputs: bool = False) -> Path:
    cells = [nbformat.v4.new_code_cell(source) for source in sources]
    if outputs:
        cells[0].outputs = [nbformat.v4.new_output("stream", name="stdout", text="kept\n")]
    path = tmp_path / "check.ipynb"
    nbformat.write(nbformat.v4.new_notebook(cells=cells), path)
    return path


def test_the_tour_is_stored_without_outputs():
    tour = nbformat.read(ROOT / "examples" / "notebooks" / "tour.ipynb", as_version=4)
    code = [c for c in tour.cells if c.cell_type == "code"]
    assert len(code) >= 9 and all(not c.outputs and c.execution_count is None for c in code)


def test_outputs_warnings_and_errors_fail_a_clean_notebook_passes(tmp_path, capsys):
    assert run_notebook.main(notebook(tmp_path, "print(1)", outputs=True), None) == 1
    assert "stored with outputs" in capsys.readouterr().err
    assert run_notebook.main(notebook(tmp_path, "import warnings\nwarnings.warn('too coarse')"), None) == 1
    assert "UserWarning: too coarse" in capsys.readouterr().err
    with pytest.raises(Exception, match="ZeroDivisionError"):
        run_notebook.main(notebook(tmp_path, "1 / 0"), None)
    assert run_notebook.main(notebook(tmp_path, "x = 2 + 2", "print(x)"), None) == 0
