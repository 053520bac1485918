"""The installed wheel, in an environment without Rust (scripts/wheel-check): the package and the `frictrack`
command come from the wheel, and give the numbers they should — the run the command line's JSON to the bit, a
receptance its closed form, a stationary wave the closed-form steady state."""

import json
import math
import shutil
import subprocess
import sys
from pathlib import Path

import frictrack

# Installed, not the source tree; no Rust toolchain reachable.
assert Path(frictrack.__file__).resolve().is_relative_to(Path(sys.prefix).resolve()), frictrack.__file__
for tool in ("cargo", "rustc"):
    assert shutil.which(tool) is None, f"{tool} is on PATH: {shutil.which(tool)}"
command = shutil.which("frictrack")
assert command is not None and Path(command).resolve().is_relative_to(Path(sys.prefix).resolve()), command

# The console script is the command line: its version, and the reference run's JSON equal to frictrack.run()'s
# but for the clock.
version = subprocess.run([command, "--version"], capture_output=True, text=True, check=True).stdout.split()
assert version == ["frictrack", frictrack.__version__], version
out = subprocess.run([command, "run", "--format", "json"], capture_output=True, text=True, check=True)
clock = ("wall_time", "time_loop")
by_command = {k: v for k, v in json.loads(out.stdout).items() if k not in clock}
by_python = {k: v for k, v in frictrack.run(progress=False).summary.items() if k not in clock}
assert by_command == by_python
bad = subprocess.run([command, "run", "--speed", "-3"], capture_output=True, text=True)
assert bad.returncode == 2 and "speed" in bad.stderr, (bad.returncode, bad.stderr)

# The receptance of the reference track (a UIC60 rail on a Winkler soil, 200 m of 1 m elements) at low frequency
# is the infinite beam's, α = λ/(2(k − mω²)), λ⁴ = (k − mω²)/(4EI): the ends are e^(−31) away, 1e-3 covers the
# mesh's 1 m cubic elements under a point force.
ei, k, m = 210e9 * 3.055e-5, 250e3, 7800.0 * 7.684e-3
receptance = frictrack.receptance(frequencies=[0.5, 1.0, 2.0])
for f, alpha in zip(receptance.table["frequency"], receptance.table["magnitude"]):
    dynamic = k - m * (2 * math.pi * f) ** 2
    exact = (dynamic / (4 * ei)) ** 0.25 / (2 * dynamic)
    assert abs(alpha / exact - 1) < 1e-3, (f, alpha, exact)

# The stationary wave at 150 m/s against the closed-form steady state: 1e-6, five times the wave's own
# discretisation error estimate (2e-7 of the peak, one halving of its 0.25 m elements).
wave = frictrack.stationary(speeds=[150.0], progress=False).points[0]
closed = frictrack.analytic(speeds=[150.0])[0]
assert wave["status"] == "converged"
peak, exact = wave["max_downward_deflection"]["value"], closed["max_downward_deflection"]["value"]
assert abs(peak / exact - 1) < 1e-6, (peak, exact)
print(f"wheel smoke test passed: frictrack {frictrack.__version__} from {Path(frictrack.__file__).parent}")
