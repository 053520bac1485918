"""Progress of a long call: a callable of the fraction done, or a tqdm bar — in a terminal as on the command line, in a
notebook as a widget (or a text bar redrawn in place without ipywidgets)."""

from __future__ import annotations

import sys
from typing import Any, Callable, Optional, Union

from . import _native

InputError = _native.InputError

ProgressLike = Union[None, bool, Callable[[float], Any]]


def _in_notebook() -> bool:
    """True in a Jupyter kernel (where standard error is not a terminal, but a bar is still drawn in place)."""
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None and hasattr(ipython, "get_ipython") else None
    return getattr(shell, "kernel", None) is not None


def _tqdm() -> Any:
    """tqdm's class for here: the notebook widget where ipywidgets is installed in a kernel, else the text bar (which a
    notebook also redraws in place). ImportError without tqdm."""
    if _in_notebook():
        try:
            import ipywidgets  # noqa: F401  (tqdm.notebook needs it; without it tqdm.auto warns)
            from tqdm.notebook import tqdm
            return tqdm
        except ImportError:
            pass
    from tqdm import tqdm
    return tqdm


class _Reporter:
    """What ``progress=`` asks for: a callable of the fraction done (0–1), a tqdm bar (``True``; by default when tqdm is
    installed and standard error is a terminal, as the command line's bar, or in a Jupyter notebook), or nothing
    (``False``)."""

    def __init__(self, progress: ProgressLike, what: str) -> None:
        self.bar = None
        self.callback: Optional[Callable[[float], Any]] = None
        if callable(progress):
            self.callback = progress
            return
        if progress is False:
            return
        terminal = hasattr(sys.stderr, "isatty") and sys.stderr.isatty()
        if progress is None and not (terminal or _in_notebook()):
            return
        try:
            tqdm = _tqdm()
        except ImportError:
            if progress is True:
                raise InputError("invalid progress = True: needs tqdm (pip install tqdm), or pass a callable "
                                 "f(fraction)") from None
            return
        self.bar = tqdm(total=1.0, desc=what, bar_format="{desc}: {percentage:3.0f}%|{bar}| {elapsed}<{remaining}")
        self.callback = self._update

    def _update(self, fraction: float) -> None:
        self.bar.n = fraction
        self.bar.refresh()

    def __enter__(self) -> "Optional[Callable[[float], Any]]":
        return self.callback

    def __exit__(self, *_: Any) -> None:
        if self.bar is not None:
            self.bar.close()
