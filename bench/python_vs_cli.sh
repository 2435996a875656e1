#!/bin/sh
# The same image set rendered by `landsim render` and by the Python module's render_set and
# render (docs/PERFORMANCE.md "Python"), alternating, RUNS times each: wall time of the whole
# process (scene building, tracing, writing) and the trace time each reports; then the
# medians. Optionally a second program (an older build) for the program's own cost.
#   sh bench/python_vs_cli.sh [BUILD_DIR] [RUNS] [OTHER_LANDSIM]
set -eu
BUILD=${1:-build}
RUNS=${2:-5}
OTHER=${3:-}
LANDSIM="$BUILD/bin/landsim"
PY=/usr/bin/python3
OUT=$(mktemp -d)
TIMES=$(mktemp)
trap 'rm -rf "$OUT" "$TIMES"' EXIT
ARGS="--spp 16 --width 640"
wall() {  # command...: prints the wall seconds
  start=$(date +%s.%N)
  "$@" > /dev/null 2>&1
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}
for i in $(seq "$RUNS"); do
  rm -rf "$OUT"/*
  echo "cli $(wall "$LANDSIM" render $ARGS --out "$OUT/cli")"
  echo "python_set $(wall env PYTHONPATH="$BUILD/python" $PY -c "
import landsim
landsim.render_set(landsim.Scenario.default(), '$OUT/py', spp=16, width=640)")"
  echo "python_render $(wall env PYTHONPATH="$BUILD/python" $PY -c "
import landsim
landsim.render(landsim.Scenario.default(), spp=16, width=640)")"
  if [ -n "$OTHER" ]; then echo "other_cli $(wall "$OTHER" render $ARGS --out "$OUT/other")"; fi
done | tee "$TIMES"
echo "medians of $RUNS runs (s):"
for name in cli python_set python_render other_cli; do
  grep "^$name " "$TIMES" | cut -d' ' -f2 | sort -n |
    awk -v n="$name" '{v[NR]=$1} END {if (NR) printf "  %-14s %.2f\n", n, v[int((NR+1)/2)]}'
done
