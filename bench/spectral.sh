#!/bin/sh
# Spectral transport against RGB (issue 25): renders the default scene (640 x 360, 2 threads)
# with a landsim built before the spectral renderer (OLD, a folder holding its landsim and
# modules) and with this build, at SPP samples per pixel, each with seeds 1 and 2, alternately
# RUNS times; prints wall time, trace time, peak memory and the relative noise (bench/exr_noise:
# RMS of the two seeds' difference / sqrt 2 over the mean luminance, sky excluded).
# Run from the repository after a Release build:
#   OLD=/path/to/old/bin sh bench/spectral.sh [RUNS] [SPP...]
set -eu
RUNS=${1:-3}
shift || true
SPPS=${*:-16}
OUT=${OUT_DIR:-/tmp/landsim-spectral}
NEW=build/bin
mkdir -p "$OUT"
ROOT=$(pwd)
for spp in $SPPS; do
  for seed in 1 2; do
    sed "s#\"\.\./\.\./#\"$ROOT/#g; s#\"volcano_classes.toml\"#\"$ROOT/scenes/examples/volcano_classes.toml\"#; s#^seed = 1#seed = $seed#; s#^spp = 16#spp = $spp#" \
      scenes/examples/default.toml > "$OUT/s${spp}_$seed.toml"
  done
done
echo "build spp run wall_s trace_s peak_MB noise"
for spp in $SPPS; do
  for run in $(seq 1 "$RUNS"); do
    for build in old new; do
      bin=$NEW
      [ "$build" = old ] && bin=$OLD
      for seed in 1 2; do
        start=$(date +%s.%N)
        json=$("$bin/landsim" render "$OUT/s${spp}_$seed.toml" --threads 2 --json \
                 --out "$OUT/$build$spp-$seed" 2> /dev/null)
        end=$(date +%s.%N)
        echo "$json" > "$OUT/$build$spp-$seed.json"
      done
      noise=$("$NEW/exr_noise" "$OUT/$build$spp-1/crater.exr" "$OUT/$build$spp-2/crater.exr" | head -1 | cut -d' ' -f2)
      python3 -c '
import json, sys
d = json.load(open(sys.argv[4]))
i = d["images"][0]
print(sys.argv[1], sys.argv[2], sys.argv[3], "%.1f" % (float(sys.argv[6]) - float(sys.argv[5])),
      "%.2f" % i["trace_seconds"], "%.0f" % (d["peak_memory_bytes"] / 1e6), sys.argv[7])' \
        "$build" "$spp" "$run" "$OUT/$build$spp-2.json" "$start" "$end" "$noise"
    done
  done
done
