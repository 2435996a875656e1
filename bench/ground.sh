#!/bin/sh
# The ground (issue 20): renders the Kagwene example (scenes/examples/kagwene.toml, both
# views) without and with a 100 km x 100 km context grid around it, and with the context and
# detail below the grid's cells ([ground] detail = true), alternately, and prints
# per run the wall time, scene build time, trace time of both views, ground triangles and
# peak resident memory. The context is synthetic (bench/context_grid.cpp: the DEM's own
# heights continued outward with seeded relief; no real regional DEM ships with landsim).
# Run from the repository after a Release build:
#   sh bench/ground.sh [RUNS] [WIDTH]
set -eu
RUNS=${1:-3}
WIDTH=${2:-960}
OUT=${OUT_DIR:-/tmp/landsim-ground}
BIN=build/bin
mkdir -p "$OUT"
[ -f "$OUT/context.tif" ] ||
  "$BIN/context_grid" data/terrain/gorillas_elevation.asc "$OUT/context.tif" 100 90 1 > /dev/null
# The example with absolute paths, and a copy with the context.
ROOT=$(pwd)
sed "s#\"\.\./\.\./#\"$ROOT/#g; s#\"kagwene_classes.toml\"#\"$ROOT/scenes/examples/kagwene_classes.toml\"#" \
  scenes/examples/kagwene.toml > "$OUT/off.toml"
sed "s#^albedo = \(.*\)#albedo = \1\ncontext = [\"$OUT/context.tif\"]#" "$OUT/off.toml" > "$OUT/on.toml"
{ cat "$OUT/on.toml"; printf '\n[ground]\ndetail = true\n'; } > "$OUT/detail.toml"
echo "case run wall_s scene_s trace_s ground_triangles peak_MB"
for run in $(seq 1 "$RUNS"); do
  for case in off on detail; do
    start=$(date +%s.%N)
    json=$("$BIN/landsim" render "$OUT/$case.toml" --width "$WIDTH" --threads 2 --json \
      --out "$OUT/$case" 2> /dev/null)
    end=$(date +%s.%N)
    triangles=$("$BIN/landsim" export-obj "$OUT/$case.toml" --max-trees 0 --out "$OUT/$case.obj" 2>&1 |
      sed -n 's/.*ground (\([0-9]*\) triangles).*/\1/p')
    rm -f "$OUT/$case.obj" "$OUT/$case.instances.csv"
    echo "$json" | python3 -c '
import json, sys
d = json.load(sys.stdin)
trace = sum(i["trace_seconds"] for i in d["images"])
print(sys.argv[1], sys.argv[2], "%.1f" % (float(sys.argv[4]) - float(sys.argv[3])),
      "%.2f" % d["scene_seconds"], "%.1f" % trace, sys.argv[5],
      "%.0f" % (d["peak_memory_bytes"] / 1e6))' "$case" "$run" "$start" "$end" "$triangles"
  done
done
