"""The ``frictrack`` command installed with the wheel: the same command line as the Rust binary, run by the package's
compiled module in this process (``frictrack --help``)."""

import sys


def main() -> None:
    """Run ``frictrack`` with this process's arguments and exit with its code (0 done, 1 failed, 2 invalid input,
    130 interrupted)."""
    from . import _native

    sys.exit(_native.command_line(["frictrack", *sys.argv[1:]]))
