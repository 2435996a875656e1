#!/usr/bin/env python3
"""Plots principal-plane BRF curves from `landsim brf --out DIR` results (brf.csv).

    scripts/plot_brf.py OUT.png LABEL=DIR [LABEL=DIR ...]

Each curve is the BRF against RAMI's signed view zenith (negative on the sun's side) with its
standard error as a band. Needs matplotlib (Debian's python3-matplotlib)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=100)
    for item in sys.argv[2:]:
        label, folder = item.split("=", 1)
        with open(folder + "/brf.csv") as f:
            rows = sorted(csv.DictReader(f), key=lambda r: float(r["view_zenith_deg"]))
        z = [float(r["view_zenith_deg"]) for r in rows]
        brf = [float(r["brf"]) for r in rows]
        se = [float(r["brf_se"]) for r in rows]
        ax.plot(z, brf, label=label)
        ax.fill_between(z, [b - s for b, s in zip(brf, se)], [b + s for b, s in zip(brf, se)],
                        alpha=0.3)
    ax.set_xlabel("view zenith (degrees; negative: the sun's side)")
    ax.set_ylabel("BRF")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(sys.argv[1])


if __name__ == "__main__":
    main()
