"""Run a notebook top to bottom as a reader would (scripts/wheel-check): it must be stored without outputs (a
notebook saved with its results would hide what the code gives today), every cell must run without error, and no
cell may print a warning. Prints each cell's time and the whole run's.

    python scripts/run_notebook.py examples/notebooks/tour.ipynb [--save executed.ipynb]

``--save`` keeps the executed notebook (with its outputs) elsewhere, to look at its figures.
"""

import re
import sys
import time
from pathlib import Path

import nbformat
from nbclient import NotebookClient

# How Python shows a warning (warnings.showwarning): "file:line: SomethingWarning: message".
WARNING = re.compile(r"\b[A-Z]\w*Warning\b: ")


def main(path: Path, save: "Path | None") -> int:
    notebook = nbformat.read(path, as_version=4)
    stored = [i for i, c in enumerate(notebook.cells) if c.cell_type == "code" and (c.outputs or c.execution_count)]
    if stored:
        print(f"{path}: cells {stored} are stored with outputs; clear them (Jupyter: Edit > Clear Outputs of All "
              f"Cells) before committing", file=sys.stderr)
        return 1
    start = time.monotonic()
    # The notebook's own folder is its working directory, as when a reader opens it there.
    # (The kernel listens on loopback only; its "running over TCP without encryption" line is its own log.)
    client = NotebookClient(notebook, timeout=900, kernel_name="python3", resources={"metadata": {"path": str(path.parent)}})
    client.execute()
    if save is not None:
        nbformat.write(notebook, save)
    failures = []
    for i, cell in enumerate(notebook.cells):
        for output in cell.get("outputs", []):
            text = output.get("text", "") if output.get("output_type") == "stream" else ""
            if output.get("name") == "stderr" and WARNING.search(text):
                failures.append(f"cell {i}: {text.strip()}")
    for failure in failures:
        print(f"{path}: warning in {failure}", file=sys.stderr)
    for i, cell in enumerate(notebook.cells):
        timing = cell.get("metadata", {}).get("execution", {})
        began, ended = timing.get("iopub.execute_input"), timing.get("shell.execute_reply")
        if began and ended:
            from datetime import datetime

            seconds = (datetime.fromisoformat(ended.rstrip("Z")) - datetime.fromisoformat(began.rstrip("Z"))).total_seconds()
            print(f"  cell {i}: {seconds:.1f} s")
    figures = sum(1 for c in notebook.cells for o in c.get("outputs", []) if "image/png" in o.get("data", {}))
    print(f"{path}: {len(notebook.cells)} cells, {figures} figures, ran in {time.monotonic() - start:.1f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    arguments = sys.argv[1:]
    saved = Path(arguments[arguments.index("--save") + 1]) if "--save" in arguments else None
    sys.exit(main(Path(arguments[0]), saved))
