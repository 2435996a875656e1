#!/bin/sh
# Range degradation at forest scale, on against off side by side (issue 16). Run from the
# repository after a Release build:  sh bench/degradation.sh [RUNS] [OUT_DIR]
# Each mode runs RUNS times in its own process (peak memory is per process); then the
# images are compared, a seed change gives the sampling-noise floor, and the fly-through
# measures popping with and without blending.
set -eu
RUNS=${1:-3}
OUT=${2:-/tmp/landsim-degradation}
BENCH=build/bin/degradation_bench
mkdir -p "$OUT"
for run in $(seq 1 "$RUNS"); do
  for mode in off on; do
    "$BENCH" forest --mode "$mode" --spp 4 --out "$OUT/forest_$mode.exr"
  done
done
"$BENCH" forest --mode off --spp 4 --seed 2 --out "$OUT/forest_off_seed2.exr"
echo "on against off:"
"$BENCH" compare "$OUT/forest_on.exr" "$OUT/forest_off.exr"
echo "noise floor (off, seed 2 against seed 1):"
"$BENCH" compare "$OUT/forest_off_seed2.exr" "$OUT/forest_off.exr"
"$BENCH" flythrough --frames 24
echo "a million trees, 1 spp:"
for run in $(seq 1 "$RUNS"); do
  for mode in off on; do
    "$BENCH" forest --mode "$mode" --trees 1000000 --spp 1 --out "$OUT/million_$mode.exr"
  done
done
echo "one tree, cost of each level (4 spp, 512 x 512):"
"$BENCH" tree --mode off
for r2 in 30 60 100 150 250 400 700 1200; do "$BENCH" tree --r2 "$r2"; done
