#!/bin/sh
# The memory estimate against the measured peak (issue 27): for each scenario, the estimate
# of `landsim info` and the peak resident memory of `landsim render --spp 1` (GNU time's
# maximum resident set size). Run from the repository after a Release build:
#   sh bench/memory.sh [SCENARIO...]
# Without arguments: the default scene, the Kagwene example and the 100 k-tree scene.
set -eu
LANDSIM=${LANDSIM:-build/bin/landsim}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
if [ $# -eq 0 ]; then
  set -- scenes/examples/default.toml scenes/examples/kagwene.toml bench/scenarios/forest_100k.toml
fi
printf '%-44s %10s %10s %7s\n' scenario estimate peak ratio
for scenario in "$@"; do
  estimate=$("$LANDSIM" info --json "$scenario" |
    sed 's/.*"memory_estimate_bytes":\([0-9]*\).*/\1/')
  /usr/bin/time -f '%M' -o "$OUT/peak" "$LANDSIM" render "$scenario" --spp 1 \
    --out "$OUT/images" >/dev/null 2>&1
  peak_kb=$(tail -n 1 "$OUT/peak")
  awk -v s="$scenario" -v e="$estimate" -v p="$peak_kb" 'BEGIN {
    printf "%-44s %7.0f MB %7.0f MB %7.2f\n", s, e / 1e6, p * 1024 / 1e6, e / (p * 1024) }'
done
