#!/bin/sh
# Scene objects (issue 21): renders the vehicles example (scenes/examples/kagwene_vehicles.toml)
# with its two vehicles and without them (the same scenario, [[objects]] removed),
# alternately, and prints per run the wall time, scene build time and trace time. The mesh
# load time is bench/object_load_bench's (build/bin/object_load_bench).
# Run from the repository after a Release build:
#   sh bench/objects.sh [RUNS] [WIDTH]
set -eu
RUNS=${1:-3}
WIDTH=${2:-960}
OUT=${OUT_DIR:-/tmp/landsim-objects}
BIN=build/bin
mkdir -p "$OUT"
ROOT=$(pwd)
sed "s#\"\.\./\.\./#\"$ROOT/#g; s#\"kagwene_classes.toml\"#\"$ROOT/scenes/examples/kagwene_classes.toml\"#" \
  scenes/examples/kagwene_vehicles.toml > "$OUT/with.toml"
# Without: every [[objects]] table dropped (up to the next table).
awk '/^\[\[objects\]\]/ {skip = 1; next} /^\[/ {skip = 0} !skip' "$OUT/with.toml" > "$OUT/without.toml"
echo "case run wall_s scene_s trace_s"
for run in $(seq 1 "$RUNS"); do
  for case in without with; do
    start=$(date +%s.%N)
    json=$("$BIN/landsim" render "$OUT/$case.toml" --width "$WIDTH" --threads 2 --json \
      --out "$OUT/$case" 2> /dev/null)
    end=$(date +%s.%N)
    echo "$json" | python3 -c '
import json, sys
d = json.load(sys.stdin)
trace = sum(i["trace_seconds"] for i in d["images"])
print(sys.argv[1], sys.argv[2], "%.1f" % (float(sys.argv[4]) - float(sys.argv[3])),
      "%.2f" % d["scene_seconds"], "%.1f" % trace)' "$case" "$run" "$start" "$end"
  done
done
