#!/bin/sh
# Issue 57's cost read against the light itself (docs/PERFORMANCE.md "Conserved light",
# the last table): each build's error against one converged render of conserved light (this
# build, bench/reference_render.sh: REF_SPP samples, another sampling seed), rather than
# against its own image as bench/haze_cost.sh measures it. The error is bench/image_error's
# relative MSE of luminance. The build before issue 57 converges to another image (paths cut
# at 4 bounces, a haze that scatters no light down): its error falls to that difference and no
# further, where this build's falls as 1 / samples. SCENE (default
# scenes/examples/default.toml), 320 x 180, the builds alternating at each sample count of
# SPPS, the whole process timed.
#   sh bench/haze_truth.sh OLD_BUILD NEW_BUILD
set -eu
OLD=$1
BUILD=$2
SCENE=${SCENE:-scenes/examples/default.toml}
SPPS=${SPPS:-"4 16 64 256"}
. "$(dirname "$0")/reference_render.sh"
VIEW=$(basename "$(ls "$OUT"/ref/*.exr | grep -v checkpoint | head -n 1)")
for spp in $SPPS; do
  for build in "$OLD" "$BUILD"; do
    rm -rf "$OUT/img"
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    "$build/bin/landsim" render "$SCENE" $SIZE --spp "$spp" --set render.seed=1 \
      --set render.sampling_seed=1 --out "$OUT/img" > /dev/null 2>&1
    end=$(date +%s.%N)
    printf "%-16s %4s spp wall %7.2f s  %s\n" "$(basename "$(dirname "$build")")/$(basename "$build")" \
      "$spp" "$(echo "$end - $start" | bc)" \
      "$("$ERROR" "$OUT/img/$VIEW" "$OUT/ref/$VIEW" | head -n 1 | tr '\n' ' ')"
  done
done
