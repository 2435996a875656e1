#!/bin/sh
# The memory estimate against the measured peak (issue 27): for each scenario, the estimate
# of `landsim info` and the peak resident memory of `landsim render --spp 1` (GNU time's
# maximum resident set size). Run from the repository after a Release build:
#   sh bench/memory.sh [SCENARIO...]
# Without arguments: the three calibration scenes (the default scene, the Kagwene example,
# the 100 k-tree scene), then four variations the constants were not fitted on (degradation
# off twice, a 3840 x 2160 image, Kagwene at ten times the density).
set -eu
LANDSIM=${LANDSIM:-build/bin/landsim}
REPO=$(pwd)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
if [ $# -eq 0 ]; then
  absolute() {  # a scenario's relative paths made absolute, so that it can live in $OUT
    sed "s|\"\.\./\.\./|\"$REPO/|; s|\"\([a-z]*_classes\.toml\)\"|\"$REPO/scenes/examples/\1\"|" "$1"
  }
  absolute scenes/examples/default.toml |
    sed 's|^\[render\]|[render]\ndegradation = false|' > "$OUT/default_degradation_off.toml"
  absolute scenes/examples/default.toml |
    sed 's|width = 640|width = 3840|; s|height = 360|height = 2160|' > "$OUT/default_3840x2160.toml"
  absolute bench/scenarios/forest_100k.toml |
    sed 's|^\[render\]|[render]\ndegradation = false|' > "$OUT/forest_100k_degradation_off.toml"
  absolute scenes/examples/kagwene.toml |
    sed 's|density_per_ha = \([0-9]*\)|density_per_ha = \10|; s|min_spacing = .*|min_spacing = 0.0|' \
      > "$OUT/kagwene_density_x10.toml"
  absolute scenes/examples/kagwene.toml |
    sed 's|density_per_ha = [0-9]*|density_per_ha = 99000|; s|min_spacing = .*|min_spacing = 0.0|' \
      > "$OUT/kagwene_99000_per_ha.toml"
  set -- scenes/examples/default.toml scenes/examples/kagwene.toml \
    bench/scenarios/forest_100k.toml "$OUT"/default_degradation_off.toml \
    "$OUT"/default_3840x2160.toml "$OUT"/forest_100k_degradation_off.toml \
    "$OUT"/kagwene_density_x10.toml
fi
printf '%-36s %6s %10s %10s %7s\n' scenario trees estimate peak ratio
for scenario in "$@"; do
  info=$("$LANDSIM" info --json "$scenario")
  estimate=$(echo "$info" | sed 's/.*"memory_estimate_bytes":\([0-9]*\).*/\1/')
  trees=$(echo "$info" | sed 's/.*"instances":\([0-9]*\).*/\1/')
  /usr/bin/time -f '%M' -o "$OUT/peak" "$LANDSIM" render "$scenario" --spp 1 \
    --out "$OUT/images" >/dev/null 2>&1
  peak_kb=$(tail -n 1 "$OUT/peak")
  awk -v s="$(basename "$scenario")" -v n="$trees" -v e="$estimate" -v p="$peak_kb" 'BEGIN {
    printf "%-36s %6d %7.0f MB %7.0f MB %7.2f\n", s, n, e / 1e6, p * 1024 / 1e6, e / (p * 1024) }'
done
# A scene that cannot fit (about ninety million trees): how long `info` and the refusal take.
if [ -f "$OUT/kagwene_99000_per_ha.toml" ]; then
  /usr/bin/time -f '%e %M' -o "$OUT/info" "$LANDSIM" info "$OUT/kagwene_99000_per_ha.toml" >/dev/null
  set +e
  /usr/bin/time -f '%e %M' -o "$OUT/refused" "$LANDSIM" render "$OUT/kagwene_99000_per_ha.toml" \
    --out "$OUT/refused_images" >/dev/null 2>&1
  code=$?
  set -e
  awk -v i="$(tail -n 1 "$OUT/info")" -v r="$(tail -n 1 "$OUT/refused")" -v c="$code" 'BEGIN {
    split(i, a, " "); split(r, b, " ")
    printf "Kagwene at 99000 trees/ha: info %.2f s, %.0f MB; render refused (exit %d) in %.2f s, %.0f MB\n",
      a[1], a[2] * 1024 / 1e6, c, b[1], b[2] * 1024 / 1e6 }'
fi
