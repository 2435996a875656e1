#!/bin/sh
# Adaptive sampling against equal samples (docs/PERFORMANCE.md "Adaptive sampling"): the
# default scene at 320 x 180, its converged reference (1024 spp), uniform renders at 16, 32
# and 64 spp and adaptive ones (noise_threshold, min_spp 16, at most 256), each with its wall
# time, relative MSE against the reference and mean samples per pixel.
#   sh bench/adaptive.sh [BUILD_DIR]
set -eu
BUILD=${1:-build}
. "$(dirname "$0")/reference_render.sh"
run() {  # name, extra arguments
  start=$(date +%s.%N)
  "$LANDSIM" render $SIZE "$@" --out "$OUT/img" > /dev/null 2>&1
  end=$(date +%s.%N)
  printf "%s wall %.2f s %s\n" "$name" "$(echo "$end - $start" | bc)" \
    "$("$ERROR" "$OUT/img/crater.exr" "$OUT/ref/crater.exr")"
}
for spp in 16 32 64; do name="uniform $spp spp"; run --spp "$spp"; done
for t in 0.1 0.05 0.03 0.02; do
  name="adaptive $t"; run --spp 256 --set render.noise_threshold=$t --set render.min_spp=16
done
