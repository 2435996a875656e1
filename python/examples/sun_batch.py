"""Twenty variations of the default scene (sun elevation x visibility x season) rendered
from Python, and the mean canopy radiance plotted against sun elevation (docs/PYTHON.md).

    python3 python/examples/sun_batch.py --out sun_batch.png
"""
import argparse
import json

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import landsim

ELEVATIONS = [10, 25, 40, 55, 70]
VISIBILITIES = [5000, 30000]  # m
SEASONS = ["summer", "autumn"]


def canopy_luminance(image):
    """Mean luminance (cd/m2) of the pixels whose first hit is a leaf or bark."""
    classes = json.loads(image.metadata["legend"])["object"]["values"]
    tree = [int(k) for k, name in classes.items() if name in ("leaf", "bark")]
    mask = np.isin(image.object, tree)
    return float(image.luminance[mask].mean())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="sun_batch.png")
    parser.add_argument("--spp", type=int, default=16)
    parser.add_argument("--width", type=int, default=320)
    args = parser.parse_args()

    base = landsim.Scenario.default()
    rows = []
    for season in SEASONS:
        for visibility in VISIBILITIES:
            for elevation in ELEVATIONS:
                s = base.copy()
                s.set("render.season", season).set("atmosphere.aerosol.visibility", visibility)
                s.set("sun.elevation", elevation)
                image = landsim.render(s, spp=args.spp, width=args.width)
                rows.append((season, visibility, elevation, canopy_luminance(image)))
                print(f"{season:7s} {visibility:6d} m {elevation:3d} deg: "
                      f"canopy {rows[-1][3]:8.1f} cd/m2", flush=True)

    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    for season in SEASONS:
        for visibility, style in zip(VISIBILITIES, ["--", "-"]):
            ys = [r[3] for r in rows if r[0] == season and r[1] == visibility]
            ax.plot(ELEVATIONS, ys, style, marker="o",
                    label=f"{season}, visibility {visibility // 1000} km")
    ax.set_xlabel("sun elevation (degrees)")
    ax.set_ylabel("mean canopy luminance (cd/m$^2$)")
    ax.set_title("Default scene, 20 variations rendered from Python")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
