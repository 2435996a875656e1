#!/bin/sh
# Wind (issue 22): renders the default scene (scenes/examples/default.toml, 640 x 360, 16 spp)
# as an image set of FRAMES frames without wind (the scene built once) and with wind (speed 3,
# gust 2: the scene, its variants' phase groups and their BVHs rebuilt for every frame),
# alternately, and prints per run the wall time, scene build time summed over frames, BVH
# build and trace time summed over images, and peak memory.
# Run from the repository after a Release build:
#   sh bench/wind.sh [RUNS] [FRAMES]
set -eu
RUNS=${1:-3}
FRAMES=${2:-3}
OUT=${OUT_DIR:-/tmp/landsim-wind}
BIN=build/bin
mkdir -p "$OUT"
ROOT=$(pwd)
LIST=$(python3 -c "import sys; print(', '.join(str(float(f)) for f in range(int(sys.argv[1]))))" "$FRAMES")
sed "s#\"\.\./\.\./#\"$ROOT/#g; s#\"volcano_classes.toml\"#\"$ROOT/scenes/examples/volcano_classes.toml\"#; s#^seed = 1#seed = 1\nframes = [$LIST]#" \
  scenes/examples/default.toml > "$OUT/calm.toml"
{ cat "$OUT/calm.toml"; printf '\n[wind]\nspeed = 3.0\ngust = 2.0\n'; } > "$OUT/wind.toml"
echo "case run wall_s scene_s bvh_s trace_s peak_MB"
for run in $(seq 1 "$RUNS"); do
  for case in calm wind; do
    start=$(date +%s.%N)
    json=$("$BIN/landsim" render "$OUT/$case.toml" --threads 2 --json --out "$OUT/$case" 2> /dev/null)
    end=$(date +%s.%N)
    echo "$json" | python3 -c '
import json, sys
d = json.load(sys.stdin)
bvh = sum(i["bvh_seconds"] for i in d["images"])
trace = sum(i["trace_seconds"] for i in d["images"])
print(sys.argv[1], sys.argv[2], "%.1f" % (float(sys.argv[4]) - float(sys.argv[3])),
      "%.2f" % d["scene_seconds"], "%.2f" % bvh, "%.1f" % trace,
      "%.0f" % (d["peak_memory_bytes"] / 1e6))' "$case" "$run" "$start" "$end"
  done
done
