"""Does friction at the bearings keep a 20 m concrete deck within the Eurocode's deck-acceleration limit under the
high-speed load models? HSLM-A1 … A10 over the example bridge (examples/hslm-bridge.toml) at 140–420 km/h, without
friction and with 3 friction devices of 50 kN, each train's largest deck acceleration against the EN 1990 limit
(3.5 m/s² for a ballasted deck, 5 m/s² for direct fastening), plotted with matplotlib.

    pip install ./crates/python matplotlib
    python examples/python/hslm_friction.py [--out hslm-friction.png] [--deck-track ballasted] [--resolution coarse]

The verdicts are frictrack's own (`frictrack.study("hslm", …)`, the same as `frictrack study hslm`): every train's
largest acceleration is refined by fresh runs around its sampled maximum (golden section to 0.4 km/h on the coarse
grid), never read off a sampled curve — a 10 km/h grid misses HSLM-A2's peak by 16 % (3.30 against 3.93 m/s²) and
calls a failing deck safe.
"""

import argparse
from pathlib import Path

import frictrack

BRIDGE = Path(__file__).resolve().parents[1] / "hslm-bridge.toml"
KMH = 3.6


def check(deck_track, resolution):
    """The hslm study on the example bridge: its summary (curves with refined peaks and verdicts) and its table."""
    return frictrack.study("hslm", BRIDGE, resolution=resolution, deck_track=deck_track)


def verdict_lines(summary):
    """One line per train and friction set-up, then one per set-up: how many trains fail."""
    limit = summary["acceleration_limit"]
    lines = []
    for c in summary["curves"]:
        setup = "no friction" if c["friction"] == "none" else summary["friction_setup"]
        verdict = {
            "over": "OVER the limit",
            "within": "within the limit",
            # The largest value is at an end of the speed range, still rising: nothing is known beyond it.
            "within the range only": "within the limit up to the range's end",
        }[c["deck_verdict"]]
        lines.append(
            f"{c['train'].upper():8s} {setup:18s} {c['peak_max_acceleration']:5.2f} m/s² at "
            f"{c['peak_acceleration_speed'] * KMH:5.1f} km/h: {verdict}"
        )
    for e in summary["envelopes"]:
        setup = "no friction" if e["friction"] == "none" else summary["friction_setup"]
        failing = [t.upper() for t in e["trains_over_limit"]]
        lines.append(
            f"{setup}: {len(failing)} of 10 trains over {limit} m/s² ({summary['deck_track']})"
            + (f": {', '.join(failing)}" if failing else "")
            + f"; largest {e['peak_max_acceleration']:.2f} m/s² ({e['acceleration_train'].upper()})"
        )
    return lines


def plot(study, out):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    summary, table = study.summary, study.table
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.5), sharey=True)
    # Ten distinct colours (a qualitative palette): each train is told apart in both panels.
    colors = plt.cm.tab10(np.arange(10))
    limit = summary["acceleration_limit"]
    for ax, friction, title in zip(axes, ["none", "with"], ["without friction", summary["friction_setup"]]):
        for k in range(1, 11):
            rows = table.data[(table.data["train"] == f"hslm-a{k}") & (table.data["friction"] == friction)]
            ax.plot(rows["speed"] * KMH, rows["deck_acceleration"], color=colors[k - 1], label=f"HSLM-A{k}")
        for c in summary["curves"]:
            # A peak refined between grid speeds is marked; a largest value at an end of the range is a bound
            # (the peak may lie beyond it), already on its curve, and not drawn as a peak.
            if c["friction"] == friction and c["peak_acceleration_location"] == "interior":
                k = int(c["train"][len("hslm-a"):])
                ax.plot(c["peak_acceleration_speed"] * KMH, c["peak_max_acceleration"], "v", color=colors[k - 1],
                        markeredgecolor="black", markersize=7)
        ax.axhline(limit, color="black", linewidth=1.2, linestyle="--")
        ax.text(142, limit * 1.02, f"EN 1990 limit {limit} m/s² ({summary['deck_track']} deck)", fontsize=9)
        ax.set_title(title, fontsize=11)
        ax.set_xlabel("train speed (km/h)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("largest deck acceleration (m/s²)")
    axes[0].legend(ncol=2, fontsize=8, loc="upper left")
    f1 = summary["natural_frequencies"][0]
    fig.suptitle(f"20 m deck (f₁ = {f1:.1f} Hz, 1 % damping) under HSLM-A1 … A10: sampled curves, peaks refined between grid speeds (▼)",
                 fontsize=12)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="hslm-friction.png")
    parser.add_argument("--deck-track", default="ballasted", choices=["ballasted", "direct-fastening"])
    parser.add_argument("--resolution", default="coarse", choices=["coarse", "paper"])
    args = parser.parse_args()
    study = check(args.deck_track, args.resolution)
    for line in verdict_lines(study.summary):
        print(line)
    plot(study, args.out)
    print(f"wrote {args.out}")
