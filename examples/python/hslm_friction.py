"""Does friction at the bearings keep a 20 m concrete deck within the Eurocode's deck-acceleration limit under the
high-speed load models? HSLM-A1 … A10 over the example bridge (examples/hslm-bridge.toml) at 140–420 km/h, without
friction and with friction devices, the largest deck acceleration of each against the EN 1990 limit for a ballasted
deck (3.5 m/s²), plotted with matplotlib.

    pip install ./crates/python matplotlib
    python examples/python/hslm_friction.py [--out hslm-friction.png] [--step 10] [--trains 10]

Each train's speeds run on all cores (`frictrack.sweep`); the figure and one line per train tell which trains break
the limit and whether friction brings them back under it.
"""

import argparse
from pathlib import Path

import numpy as np

import frictrack

BRIDGE = Path(__file__).resolve().parents[1] / "hslm-bridge.toml"
LIMIT = 3.5  # m/s², EN 1990 A2.4.4.2.1 for a ballasted deck
KMH = 3.6
#: Friction devices at the deck: 3 devices of 50 kN (a set the hslm study also uses, scaled to a 20 m span).
DEVICES = {"devices": 3, "device_force": 50e3}


def worst_accelerations(trains, speeds):
    """For each train: the largest deck acceleration (m/s²) over `speeds` (m/s), without and with the devices."""
    rows = []
    for train in trains:
        bare = frictrack.sweep(BRIDGE, speeds, train=train)
        rubbed = frictrack.sweep(BRIDGE, speeds, train=train, **DEVICES)
        rows.append((train, bare["speed"], bare["max_acceleration"], rubbed["max_acceleration"]))
    return rows


def plot(rows, out):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(9, 5.5))
    colors = plt.cm.viridis(np.linspace(0, 0.9, len(rows)))
    for (train, speeds, bare, rubbed), color in zip(rows, colors):
        ax.plot(speeds * KMH, bare, color=color, label=train.upper())
        ax.plot(speeds * KMH, rubbed, color=color, linestyle="--")
    ax.axhline(LIMIT, color="black", linewidth=1)
    ax.text(speeds[0] * KMH, LIMIT * 1.03, "EN 1990 limit, ballasted deck (3.5 m/s²)", fontsize=9)
    ax.set_xlabel("train speed (km/h)")
    ax.set_ylabel("largest deck acceleration (m/s²)")
    ax.set_title("20 m deck under HSLM: solid without friction, dashed with 3 × 50 kN devices")
    ax.legend(ncol=2, fontsize=8, loc="upper left")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="hslm-friction.png")
    parser.add_argument("--step", type=float, default=10.0, help="speed step (km/h)")
    parser.add_argument("--trains", type=int, default=10, help="HSLM-A1 … A<trains>")
    args = parser.parse_args()
    speeds = np.arange(140.0, 420.0 + 1e-9, args.step) / KMH
    trains = [f"hslm-a{k}" for k in range(1, args.trains + 1)]
    rows = worst_accelerations(trains, speeds)
    for train, s, bare, rubbed in rows:
        i, j = int(np.nanargmax(bare)), int(np.nanargmax(rubbed))
        verdict = "over the limit" if bare[i] > LIMIT else "within the limit"
        fixed = "; with the devices within it" if bare[i] > LIMIT and rubbed[j] <= LIMIT else ""
        print(f"{train.upper():8s} {bare[i]:6.2f} m/s² at {s[i] * KMH:5.0f} km/h ({verdict}){fixed}; with devices "
              f"{rubbed[j]:6.2f} m/s² at {s[j] * KMH:5.0f} km/h")
    plot(rows, args.out)
    print(f"wrote {args.out}")
