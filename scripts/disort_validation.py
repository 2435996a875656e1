#!/usr/bin/env python3
"""DISORT's plane-parallel cases through `landsim brf`, against DISORT's own printout.

Reads DISORT 2.0's test output (data/radiative_transfer/disort_test_cases.txt): for every case
shipped as scenes/disort/case_<name>.toml, the incident flux (the direct beam's flux at the
top), the upward diffuse flux at the top, the direct and diffuse downward fluxes at the
bottom, and the upward intensities at the top. Runs landsim brf on the scenario in those
directions and prints a Markdown table: landsim's albedo, soil_direct and soil_diffuse beside
DISORT's fluxes over the light coming in (mu0 FBEAM + pi FISOT; the budgets under the sun
and under the sky weighed by their parts of it), and the top's BRF (pi I / mu0 FBEAM; with
no beam, the radiance over the sky's, I / FISOT) at each polar cosine, with the largest
deviation in standard errors (DISORT's printed precision, five significant digits, added to
landsim's).

Usage: scripts/disort_validation.py [LANDSIM] [--spp N] [--budget-paths N]
"""
import argparse
import json
import math
import pathlib
import re
import subprocess

ROOT = pathlib.Path(__file__).resolve().parent.parent
NUMBER = r"[-+]?\d*\.\d+(?:E[-+]\d+)?"


def parse_cases(text):
    """Each case's fluxes (rows of depth, direct, diffuse down, diffuse up) and top intensities."""
    cases = {}
    for block in re.split(r"DISORT: Test Case No\. ", text)[1:]:
        name = re.match(r"(\w+)", block).group(1)
        azimuths = [float(a) for a in re.search(r"User azimuthal angles :(.*)", block).group(1).split()]
        fluxes_part = block.split("FLUXES")[1].split("I N T E N S I T I E S")[0]
        rows = [
            [float(v) for v in m.groups()]
            for m in re.finditer(rf"^\s+({NUMBER})\s+({NUMBER})\s+({NUMBER})\s+({NUMBER})\s+{NUMBER}\s*$",
                                 fluxes_part, re.M)
        ]
        # Case 11a's printout (a later DISORT) has more columns: depth, layer, direct, diffuse,
        # total down, diffuse up, ...
        rows += [
            [float(m.group(i)) for i in (1, 2, 3, 5)]
            for m in re.finditer(rf"^\s+({NUMBER})\s+\d+\s+({NUMBER})\s+({NUMBER})\s+({NUMBER})\s+({NUMBER})\s",
                                 fluxes_part, re.M)
        ]
        intensities = []
        top = block.split("I N T E N S I T I E S")[1]
        depth = None
        for line in top.splitlines():
            # A depth's first line starts near the margin; its other polar cosines are indented.
            indent = len(line) - len(line.lstrip())
            m = re.match(rf"^\s+({NUMBER})\s+({NUMBER})((?:\s+{NUMBER})+)\s*$", line)
            if m and indent < 8:
                depth = float(m.group(1))
                mu, values = float(m.group(2)), m.group(3).split()
            else:
                m = re.match(rf"^\s+({NUMBER})((?:\s+{NUMBER})+)\s*$", line)
                if not m or depth is None:
                    continue
                mu, values = float(m.group(1)), m.group(2).split()
            if depth == 0.0 and mu > 0.0:
                intensities += [(mu, az, float(v)) for az, v in zip(azimuths, values)]
        fisot = float(re.search(rf"isotropic incident intensity =\s*({NUMBER})", block).group(1))
        cases[name] = {"fluxes": rows, "top": intensities, "fisot": fisot}
    return cases


def uncertainty(se, reference):
    """landsim's standard error and DISORT's printed precision (five significant digits)."""
    return math.hypot(se, 5e-5 * reference)


def measure(landsim, scenario, directions, spp, budget):
    args = [landsim, "brf", str(scenario), "--json", "--spp", str(spp), "--budget-paths", str(budget)]
    for zenith, azimuth in directions:
        args += ["--direction", f"{zenith:.10f},{azimuth:.6f}"]
    return json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("landsim", nargs="?", default=str(ROOT / "build/bin/landsim"))
    p.add_argument("--spp", type=int, default=100000)
    p.add_argument("--budget-paths", type=int, default=200000)
    a = p.parse_args()
    cases = parse_cases((ROOT / "data/radiative_transfer/disort_test_cases.txt").read_text())
    print("| case | albedo: landsim / DISORT | soil direct | soil diffuse | top: landsim / DISORT at mu = ... | worst |")
    print("|---|---|---|---|---|---|")
    for scenario in sorted((ROOT / "scenes/disort").glob("case_*.toml")):
        name = scenario.stem.removeprefix("case_")
        c = cases[name]
        top, bottom = c["fluxes"][0], c["fluxes"][-1]
        beam, sky = top[1], math.pi * c["fisot"]  # mu0 FBEAM, and pi FISOT from the sky
        incident = beam + sky
        # The scenarios' sun stands at azimuth 90; DISORT's azimuth 0 is away from it (270).
        directions = [(math.degrees(math.acos(mu)), (270.0 - az) % 360.0) for mu, az, _ in c["top"]]
        j = measure(a.landsim, scenario, directions, a.spp, a.budget_paths)
        iso = j["budget_isotropic"]
        sun = j.get("budget", {k: {"mean": 0.0, "se": 0.0} for k in iso})

        def mix(sun_share, sky_share):
            """The budgets under each light, weighed by its part of the light coming in."""
            return {"mean": (beam * sun_share["mean"] + sky * sky_share["mean"]) / incident,
                    "se": math.hypot(beam * sun_share["se"], sky * sky_share["se"]) / incident}

        nothing = {"mean": 0.0, "se": 0.0}
        sky_down = {"mean": iso["soil_direct"]["mean"] + iso["soil_diffuse"]["mean"],
                    "se": math.hypot(iso["soil_direct"]["se"], iso["soil_diffuse"]["se"])}
        cells, worst = [], 0.0
        for (want, got) in ((top[3] / incident, mix(sun["albedo"], iso["albedo"])),
                            (bottom[1] / incident, mix(sun["soil_direct"], nothing)),
                            (bottom[2] / incident, mix(sun["soil_diffuse"], sky_down))):
            cells.append(f"{got['mean']:.4f} ± {got['se']:.4f} / {want:.4f}")
            if want > 1e-6:  # DISORT's zeros print as 1e-16 and less
                worst = max(worst, abs(got["mean"] - want) / uncertainty(got["se"], want))
        tops = []
        for (mu, _, value), d in zip(c["top"], j["directions"]):
            # With a beam its BRF, pi I / (mu0 FBEAM); with the sky alone (1000 cd/m2 per unit
            # FISOT) the radiance over the sky's, I / FISOT.
            if beam > 0:
                want, got, se = math.pi * value / beam, d["brf"], d["brf_se"]
            else:
                want, got, se = value / c["fisot"], d["radiance"] / 1000.0, d["radiance_se"] / 1000.0
            tops.append(f"{mu:g}: {got:.4f} / {want:.4f}")
            if want > 1e-6:
                worst = max(worst, abs(got - want) / uncertainty(se, want))
        print(f"| {name} | " + " | ".join(cells) + " | " + "; ".join(tops) + f" | {worst:.1f} se |")


if __name__ == "__main__":
    main()
