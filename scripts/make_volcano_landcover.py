#!/usr/bin/env python3
"""Writes data/featuremaps/volcano_landcover.asc: a synthetic land-cover class grid for the
Maunga Whau elevation grid (same 61 x 87 cells of 10 m), for the default scene's trees.

Classes from elevation: 2 woodland below 112 m, 3 parkland (scattered trees) to 140 m,
1 grassland above (the cone and its crater). Not survey data; see data/featuremaps/PROVENANCE.md.
"""
import pathlib

root = pathlib.Path(__file__).resolve().parent.parent
lines = (root / "data/terrain/volcano.asc").read_text().splitlines()
header, rows = lines[:6], [list(map(float, l.split())) for l in lines[6:]]


def landcover(h):
    if h < 112:
        return 2
    if h < 140:
        return 3
    return 1


out = header[:5] + ["NODATA_value -9999"]
out += [" ".join(str(landcover(h)) for h in row) for row in rows]
(root / "data/featuremaps/volcano_landcover.asc").write_text("\n".join(out) + "\n")
