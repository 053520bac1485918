"""The track's point receptance with an Euler–Bernoulli rail and with a Timoshenko rail, drawn as the literature
draws it: |α| (m/N) on log–log axes, the phase below.

    python examples/python/receptance_plot.py            # writes receptance-rails.png beside where it is run

The scenario is examples/receptance.toml (the reference track, its soil damped, absorbing zones, 0.0625 m elements);
the Euler–Bernoulli curve is the same track with the rail's shear keys removed. On this continuous soil both show one
resonance, the rail on its soil near 10 Hz; above a few hundred hertz the Timoshenko rail, softer in shear, gives
more. Needs matplotlib."""

import pathlib
import sys

import numpy as np

import frictrack

EXAMPLE = pathlib.Path(__file__).resolve().parents[1] / "receptance.toml"


def curves(frequencies):
    """(label, Receptance) for both rails on the example's track."""
    timoshenko = frictrack.receptance(EXAMPLE, frequencies)
    text = EXAMPLE.read_text()
    for key in ("theory", "shear_modulus", "shear_coefficient"):
        text = "\n".join(line for line in text.splitlines() if not line.startswith(key))
    euler = frictrack.receptance(text, frequencies)
    return [("Euler–Bernoulli rail", euler), ("Timoshenko rail (G = 81 GPa, κ = 0.4)", timoshenko)]


def draw(results, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 6))
    for label, result in results:
        table = result.table
        top.loglog(table["frequency"], table["magnitude"], label=label)
        bottom.semilogx(table["frequency"], table["phase"], label=label)
    top.set_ylabel("|α| (m/N)")
    bottom.set_ylabel("phase (°)")
    bottom.set_xlabel("frequency (Hz)")
    top.set_title("Point receptance of the reference track at mid-track")
    top.legend()
    for axis in (top, bottom):
        axis.grid(True, which="both", alpha=0.3)
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def main(argv):
    frequencies = np.arange(2.0, 2001.0, 2.0)
    results = curves(frequencies)
    draw(results, pathlib.Path("receptance-rails.png"))
    for label, result in results:
        top = result.table["magnitude"][-1]
        print(f"{label}: resonance {result.resonances[0]['frequency']:.2f} Hz, |α| at 2 kHz {top:.3e} m/N")


if __name__ == "__main__":
    main(sys.argv[1:])
