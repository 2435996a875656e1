#!/bin/sh
# Independent samples against padded Owen-scrambled Sobol (docs/PERFORMANCE.md "Sampler"):
# the default scene at 320 x 180, its converged reference (1024 spp, another sampling seed,
# independent samples), then each sampler at 16, 32 and 64 spp with its wall time and relative
# MSE against the reference (bench/image_error: luminance and the mean of R, G, B), for
# SEEDS sampling seeds each (the error of one image is itself noisy).
#   sh bench/sampler.sh [BUILD_DIR] [SEEDS]
set -eu
BUILD=${1:-build}
SEEDS=${2:-3}
. "$(dirname "$0")/reference_render.sh"
for spp in 16 32 64; do
  for seed in $(seq "$SEEDS"); do
    for sampler in independent sobol; do
      start=$(date +%s.%N)
      "$LANDSIM" render $SIZE --spp "$spp" --set render.sampler=$sampler \
        --set render.sampling_seed=$((seed + 1)) --out "$OUT/img" > /dev/null 2>&1
      end=$(date +%s.%N)
      printf "%s %3d spp seed %d wall %.2f s %s\n" "$sampler" "$spp" "$seed" \
        "$(echo "$end - $start" | bc)" "$("$ERROR" "$OUT/img/crater.exr" "$OUT/ref/crater.exr")"
    done
  done
done
