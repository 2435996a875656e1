#!/bin/sh
# landsim brf against Blender Cycles on RAMI-III HET01, side by side and alternating: each
# measures the principal plane's BRFs to the same relative standard error (0.1% by default),
# landsim with its periodic cell and distant measure, Cycles on the cell copied 7 x 7 seen by
# orthographic cameras (bench/cycles_het01.py). Prints each run's wall time, the ratio, and
# the two curves side by side with their difference in combined standard errors.
#
# Usage: bench/rami_vs_cycles.sh [VIEWS] [ROUNDS] [TARGET]
#   VIEWS: signed view zeniths, comma-separated (default: -75 to 75 every 2, RAMI's plane)
#   ROUNDS: alternations (default 2); TARGET: relative standard error (default 0.001)
# Needs a Release build in build/ and Debian's blender (apt install blender).
set -eu
cd "$(dirname "$0")/.."
VIEWS=${1:-$(seq -s, -75 2 75)}
ROUNDS=${2:-2}
TARGET=${3:-0.001}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

# RAMI's signed zenith to landsim's --direction: the sun stands at azimuth 90 (east).
directions=""
for v in $(echo "$VIEWS" | tr , ' '); do
  if [ "$v" -lt 0 ]; then directions="$directions --direction $((-v)),90"
  else directions="$directions --direction $v,270"; fi
done

for round in $(seq "$ROUNDS"); do
  start=$(date +%s.%N)
  # shellcheck disable=SC2086
  build/bin/landsim brf scenes/rami/het01.toml --json --spp 16384 --target-se "$TARGET" \
    --budget-paths 0 $directions > "$OUT/landsim_$round.json"
  landsim=$(echo "$(date +%s.%N) - $start" | bc)
  start=$(date +%s.%N)
  blender -b --factory-startup -P bench/cycles_het01.py -- "$OUT/cycles_$round.json" "$TARGET" \
    "$VIEWS" > "$OUT/cycles_$round.log" 2>&1
  cycles=$(echo "$(date +%s.%N) - $start" | bc)
  echo "round $round: landsim $landsim s, Cycles $cycles s, ratio $(echo "scale=2; $cycles / $landsim" | bc)"
done

python3 - "$OUT" "$ROUNDS" <<'PY'
import json, math, sys
out, rounds = sys.argv[1], int(sys.argv[2])
l = json.load(open(f"{out}/landsim_{rounds}.json"))["directions"]
c = json.load(open(f"{out}/cycles_{rounds}.json"))["directions"]
print("view  landsim BRF +- se (paths)        Cycles BRF +- se (spp)      difference / combined se")
worst = 0.0
for a, b in zip(l, c):
    z = math.hypot(a["brf_se"], b["brf_se"])
    d = (a["brf"] - b["brf"]) / z
    worst = max(worst, abs(d))
    print(f"{b['view_zenith_deg']:+4d}  {a['brf']:.5f} +- {a['brf_se']:.5f} ({a['paths']:>8})"
          f"   {b['brf']:.5f} +- {b['brf_se']:.5f} ({b['samples']:>4})   {d:+.1f}")
print(f"largest difference: {worst:.1f} combined standard errors")
PY
