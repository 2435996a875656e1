#!/bin/sh
# The cost of conserved light (issue 57, docs/PERFORMANCE.md "Conserved light"): for each
# scene, the build before and this one alternating, RUNS rounds, two renders per build and
# round that differ only in their sampling seed. Each render's whole process is timed; the
# noise is bench/exr_noise's (the RMS of the two renders' luminance difference over sqrt(2),
# relative to the mean, sky excluded; band layers too). The cost at equal error of a build
# is time x noise^2 (noise falls as 1 / sqrt(samples)); each build's noise is measured against
# its own image, since the two converge to different ones (that is the issue's point).
#   sh bench/haze_cost.sh OLD_BUILD NEW_BUILD [RUNS]
# SCENES (default: the default scene, ndvi.toml, the million-tree view), SIZE, SPP override.
# EXTRA adds arguments to the new build's renders (e.g. "--set haze.multiple_scattering=paths").
set -eu
OLD=$1
NEW=$2
RUNS=${3:-3}
SCENES=${SCENES:-"scenes/examples/default.toml scenes/examples/ndvi.toml bench/scenarios/kagwene_1m.toml"}
SIZE=${SIZE:-"--width 320 --height 180"}
SPP=${SPP:-16}
EXTRA=${EXTRA:-}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
render() {  # build, seed, folder, extra...
  build=$1 seed=$2 folder=$3
  shift 3
  start=$(date +%s.%N)
  "$build/bin/landsim" render "$scene" $SIZE --spp "$SPP" --threads 2 \
    --set render.sampling_seed="$seed" --out "$folder" "$@" > /dev/null 2>&1
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}
for scene in $SCENES; do
  for round in $(seq "$RUNS"); do
    for which in old new; do
      build=$OLD
      [ "$which" = new ] && build=$NEW
      rm -rf "$OUT/a" "$OUT/b"
      # shellcheck disable=SC2086
      if [ "$which" = new ]; then
        t1=$(render "$build" $((2 * round)) "$OUT/a" $EXTRA)
        t2=$(render "$build" $((2 * round + 1)) "$OUT/b" $EXTRA)
      else
        t1=$(render "$build" $((2 * round)) "$OUT/a")
        t2=$(render "$build" $((2 * round + 1)) "$OUT/b")
      fi
      image=$(basename "$(ls "$OUT"/a/*.exr | grep -v checkpoint | head -n 1)")
      noise=$("$NEW/bin/exr_noise" "$OUT/a/$image" "$OUT/b/$image" | tr '\n' ' ')
      printf "%-40s %s round %s wall %6.2f %6.2f s  %s\n" "$(basename "$scene")" "$which" \
        "$round" "$t1" "$t2" "$noise"
    done
  done
done
