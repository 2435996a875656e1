#!/usr/bin/env python3
"""A band's reflectance factor from monochromatic runs, weighted by the band's response.

    scripts/band_weighted.py brf.json response.csv [--solar]

brf.json is `landsim brf --wavelength ... --out DIR`'s; response.csv has `wavelength_nm,response`
rows (data/bands/ holds Sentinel-2A's). Each direction's factor (and the BHR's, at the bottom
of the atmosphere) is the integral over wavelength of response x factor over that of the
response, by trapezoids over the run's wavelengths (RAMI4ATM's band-weighted results), the
response linear between its points. With --solar the weight is response x the sun's spectrum
above the atmosphere (data/atmosphere/thuillier_2003.csv): what a band run of landsim gives.
The standard error printed is the weighted sum of the wavelengths' (their runs share a seed,
so their errors are correlated: this bounds the band's). Prints CSV on stdout."""
import csv
import json
import pathlib
import sys


def table(path, x_key, y_key):
    rows = [r for r in csv.reader(line for line in open(path) if not line.startswith("#"))]
    head = rows[0]
    xs = [float(r[head.index(x_key)]) for r in rows[1:]]
    ys = [float(r[head.index(y_key)]) for r in rows[1:]]
    return xs, ys


def linear(xs, ys, x):
    """ys at x, linear between the points, 0 outside them."""
    if x < xs[0] or x > xs[-1]:
        return 0.0
    for i in range(1, len(xs)):
        if x <= xs[i]:
            f = (x - xs[i - 1]) / (xs[i] - xs[i - 1])
            return ys[i - 1] + f * (ys[i] - ys[i - 1])
    return ys[-1]


def weights(wavelengths, response, solar):
    # Trapezoids over the run's wavelengths: each point weighs half of each interval beside it.
    w = []
    for i, nm in enumerate(wavelengths):
        left = wavelengths[i] - wavelengths[i - 1] if i > 0 else 0.0
        right = wavelengths[i + 1] - wavelengths[i] if i + 1 < len(wavelengths) else 0.0
        weight = linear(*response, nm) * 0.5 * (left + right)
        if solar:
            weight *= linear(*solar, nm)
        w.append(weight)
    total = sum(w)
    if total <= 0.0:
        sys.exit("the band's response is zero at every wavelength of the run")
    return [x / total for x in w]


def weighted(values, w, key):
    mean = sum(wi * v[key] for wi, v in zip(w, values))
    se = sum(wi * v[key + "_se"] for wi, v in zip(w, values))
    return mean, se


def main():
    args = [a for a in sys.argv[1:] if a != "--solar"]
    if len(args) != 2:
        sys.exit(__doc__)
    result = json.load(open(args[0]))
    if "wavelengths_nm" not in result:
        sys.exit(args[0] + ": not a monochromatic run (landsim brf --wavelength)")
    names = [f"{nm:g}nm" for nm in result["wavelengths_nm"]]
    solar = None
    if "--solar" in sys.argv:
        here = pathlib.Path(__file__).resolve().parent.parent
        solar = table(here / "data/atmosphere/thuillier_2003.csv", "wavelength_nm",
                      "irradiance_w_m2_nm")
    w = weights(result["wavelengths_nm"], table(args[1], "wavelength_nm", "response"), solar)
    key = "hdrf" if result["level"] == "boa" else "brf"
    out = csv.writer(sys.stdout)
    out.writerow(["view_zenith_deg", "zenith_deg", "azimuth_deg", key, key + "_se"])
    if "bhr" in result:
        bands = result["bhr"]["bands"]
        mean = sum(wi * bands[n]["mean"] for wi, n in zip(w, names))
        se = sum(wi * bands[n]["se"] for wi, n in zip(w, names))
        out.writerow(["bhr", "", "", f"{mean:.6f}", f"{se:.6f}"])
    for d in result["directions"]:
        mean, se = weighted([d["bands"][n] for n in names], w, key)
        out.writerow([d.get("view_zenith_deg", d["zenith_deg"]), d["zenith_deg"], d["azimuth_deg"],
                      f"{mean:.6f}", f"{se:.6f}"])


if __name__ == "__main__":
    main()
