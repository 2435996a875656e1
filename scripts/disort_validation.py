#!/usr/bin/env python3
"""DISORT's plane-parallel cases through `landsim brf`, against DISORT's own printout.

Reads DISORT 2.0's test output (data/radiative_transfer/disort_test_cases.txt): for every case
shipped as scenes/disort/case_<name>.toml, the incident flux (the direct beam's flux at the
top), the upward diffuse flux at the top, the direct and diffuse downward fluxes at the
bottom, and the upward intensities at the top. Runs landsim brf on the scenario in those
directions and prints a Markdown table: landsim's albedo, soil_direct and soil_diffuse beside
DISORT's fluxes over the incident one, and the top's BRF (pi I / incident flux) at each
polar cosine, with the largest deviation in standard errors (DISORT's printed precision,
five significant digits, added to landsim's).

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
        intensities = []
        top = block.split("I N T E N S I T I E S")[1]
        depth = None
        for line in top.splitlines():
            m = re.match(rf"^\s+({NUMBER})\s+({NUMBER})((?:\s+{NUMBER})+)\s*$", line)
            if m:
                depth = float(m.group(1))
                mu, values = float(m.group(2)), m.group(3).split()
            else:
                m = re.match(rf"^\s+({NUMBER})((?:\s+{NUMBER})+)\s*$", line)
                if not m or depth is None:
                    continue
                mu, values = float(m.group(1)), m.group(2).split()
            if depth == 0.0 and mu > 0.0:
                intensities += [(mu, az, float(v)) for az, v in zip(azimuths, values)]
        cases[name] = {"fluxes": rows, "top": intensities}
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
    print("| case | albedo: landsim / DISORT | soil direct | soil diffuse | top BRF: landsim / DISORT at mu = ... | worst |")
    print("|---|---|---|---|---|---|")
    for scenario in sorted((ROOT / "scenes/disort").glob("case_*.toml")):
        c = cases[scenario.stem.removeprefix("case_")]
        top, bottom = c["fluxes"][0], c["fluxes"][-1]
        incident = top[1]  # the beam's flux through the top: mu0 FBEAM
        # The scenarios' sun stands at azimuth 90; DISORT's azimuth 0 is away from it (270).
        directions = [(math.degrees(math.acos(mu)), (270.0 - az) % 360.0) for mu, az, _ in c["top"]]
        j = measure(a.landsim, scenario, directions, a.spp, a.budget_paths)
        b = j["budget"]
        cells, worst = [], 0.0
        for (want, got) in ((top[3] / incident, b["albedo"]), (bottom[1] / incident, b["soil_direct"]),
                            (bottom[2] / incident, b["soil_diffuse"])):
            cells.append(f"{got['mean']:.4f} ± {got['se']:.4f} / {want:.4f}")
            if want > 1e-6:  # DISORT's zeros print as 1e-16 and less
                worst = max(worst, abs(got["mean"] - want) / uncertainty(got["se"], want))
        brfs = []
        for (mu, _, value), d in zip(c["top"], j["directions"]):
            want = math.pi * value / incident
            brfs.append(f"{mu:g}: {d['brf']:.4f} / {want:.4f}")
            if want > 1e-6:
                worst = max(worst, abs(d["brf"] - want) / uncertainty(d["brf_se"], want))
        print(f"| {scenario.stem.removeprefix('case_')} | " + " | ".join(cells) + " | " + "; ".join(brfs)
              + f" | {worst:.1f} se |")


if __name__ == "__main__":
    main()
