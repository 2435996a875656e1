#!/bin/sh
# Time to E64 (issue 46's measure, docs/PERFORMANCE.md "Time to E64"): SCENE (default
# bench/scenarios/kagwene_1m.toml, the million-tree view) at 480 x 270 against a converged
# reference, the whole process timed for each render, the error by bench/image_error
# (relative MSE on luminance, R, G, B). E64 is the old build's error at 64 spp. RUNS rounds,
# the builds alternating within each round:
#   old build, independent samples, 64 spp (E64)
#   new build, independent samples, 64 spp
#   new build, Sobol samples at 32, 48 and 64 spp
#   new build, Sobol samples, adaptive (noise_threshold 0.04, min 16, max 256 spp)
# The new build's renders of each round draw their own samples (render.sampling_seed = the
# round), so their errors vary from round to round as an image's does; the old build knows no
# sampling seed (another seed would move the trees) and renders the same image each round.
# The reference (REF_SPP samples, another sampling seed) is rendered once into REF and
# reused while REF/done exists: about 15 minutes of both cores at 4096 spp.
# With FULL_SPP set (the Sobol sample count that reached E64 at 480 x 270), one more round
# at the view's own 1920 x 1080: the old build at 64 spp against Sobol at FULL_SPP.
#   sh bench/forest_error.sh OLD_BUILD NEW_BUILD [RUNS]
#   FULL_SPP=48 sh bench/forest_error.sh OLD_BUILD NEW_BUILD 0
set -eu
OLD=$1
NEW=$2
RUNS=${3:-3}
SCENE=${SCENE:-bench/scenarios/kagwene_1m.toml}
SIZE="--width 480"
REF=${REF:-${TMPDIR:-/tmp}/landsim-$(basename "$SCENE" .toml)-ref}
REF_SPP=${REF_SPP:-4096}
ERROR="$NEW/bin/image_error"
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
if [ ! -f "$REF/done" ]; then
  rm -rf "$REF"
  "$NEW/bin/landsim" render "$SCENE" $SIZE --spp "$REF_SPP" --set render.sampling_seed=99 \
    --out "$REF" > /dev/null 2>&1
  touch "$REF/done"
fi
VIEW=$(basename "$(ls "$REF"/*.exr | head -n 1)")
run() {  # label, build, extra arguments
  label=$1 build=$2
  shift 2
  rm -rf "$OUT/img"
  start=$(date +%s.%N)
  [ "$build" = "$NEW" ] && set -- --set render.sampling_seed="$round" "$@"
  "$build/bin/landsim" render "$SCENE" $SIZE "$@" --out "$OUT/img" > /dev/null 2>&1
  end=$(date +%s.%N)
  printf "%-28s wall %6.2f s %s\n" "$label" "$(echo "$end - $start" | bc)" \
    "$("$ERROR" "$OUT/img/$VIEW" "$REF/$VIEW")"
}
for round in $(seq "$RUNS"); do
  run "old independent 64" "$OLD" --spp 64
  run "new independent 64" "$NEW" --spp 64 --set render.sampler=independent
  for spp in 32 48 64; do run "new sobol $spp" "$NEW" --spp $spp --set render.sampler=sobol; done
  run "new sobol adaptive 0.04" "$NEW" --spp 256 --set render.sampler=sobol \
    --set render.noise_threshold=0.04 --set render.min_spp=16
done
if [ -n "${FULL_SPP:-}" ]; then
  for build in "$OLD" "$NEW"; do
    rm -rf "$OUT/img"
    set -- --spp 64
    [ "$build" = "$NEW" ] && set -- --spp "$FULL_SPP" --set render.sampler=sobol
    start=$(date +%s.%N)
    "$build/bin/landsim" render "$SCENE" "$@" --out "$OUT/img" > /dev/null 2>&1
    end=$(date +%s.%N)
    printf "1920 x 1080 %-16s %s wall %6.2f s\n" "$build" "$*" "$(echo "$end - $start" | bc)"
  done
fi
