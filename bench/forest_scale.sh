#!/bin/sh
# Forest scale (issue 18): renders the million-tree benchmark (bench/scenarios/kagwene_1m.toml:
# about 1 M trees over the Kagwene DEM, 1920 x 1080, 64 spp, haze) or its day-to-day variant
# (kagwene_100k.toml: 100 k trees, 480 x 270) and prints, per run, the scene build, BVH build
# and trace times, rays per second, peak resident memory and the whole process's wall time.
# Run from the repository after a Release build:
#   sh bench/forest_scale.sh [small|large|scale] [RUNS] [BINARY ...]
# `scale` renders the million- and the ten-million-tree scenes (kagwene_1m, kagwene_10m) at
# 240 x 135, 16 spp (issue 46's scale measure: BVH build and trace at 10x the trees).
# Several binaries (e.g. an old build and a new one) run alternately, RUNS times each, so
# their ratios are measured side by side; the last image of each is kept in OUT_DIR
# (default /tmp/landsim-forest-scale) for degradation_bench compare.
set -eu
SIZE=${1:-small}
RUNS=${2:-3}
shift 2 2> /dev/null || shift $#
BINARIES=${*:-build/bin/landsim}
ARGS=""
case "$SIZE" in
  small) SCENARIOS=bench/scenarios/kagwene_100k.toml ;;
  large) SCENARIOS=bench/scenarios/kagwene_1m.toml ;;
  scale) SCENARIOS="bench/scenarios/kagwene_1m.toml bench/scenarios/kagwene_10m.toml"
         ARGS="--width 240 --height 135 --spp 16" ;;
  *) echo "usage: sh bench/forest_scale.sh [small|large|scale] [RUNS] [BINARY ...]" >&2; exit 2 ;;
esac
OUT=${OUT_DIR:-/tmp/landsim-forest-scale}
mkdir -p "$OUT"
echo "scenario binary run wall_s scene_s bvh_s trace_s Mrays_per_s peak_MB"
for run in $(seq 1 "$RUNS"); do
  n=0
  for SCENARIO in $SCENARIOS; do
  for bin in $BINARIES; do
    n=$((n + 1))
    start=$(date +%s.%N)
    json=$("$bin" render "$SCENARIO" $ARGS --threads 2 --json --out "$OUT/$n" 2> /dev/null)
    end=$(date +%s.%N)
    echo "$json" | python3 -c '
import json, sys
d = json.load(sys.stdin); i = d["images"][0]
print(sys.argv[5], sys.argv[1], sys.argv[2], "%.1f" % (float(sys.argv[4]) - float(sys.argv[3])),
      "%.2f" % d["scene_seconds"], "%.2f" % i["bvh_seconds"], "%.1f" % i["trace_seconds"],
      "%.3f" % (i["rays_per_second"] / 1e6), "%.0f" % (d["peak_memory_bytes"] / 1e6))' \
      "$bin" "$run" "$start" "$end" "$(basename "$SCENARIO" .toml)"
  done
  done
done
