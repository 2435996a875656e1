#!/bin/sh
# Usage: scripts/slurm/submit.sh SCENARIO OUT_DIR [extra sbatch options]
# Queues one array task per image of the set and, after all of them succeed, the check that
# writes manifest.json. The image count comes from `landsim info --json`.
set -eu
SCENARIO=$1
OUT=$2
shift 2
: "${LANDSIM:=build/bin/landsim}"
IMAGES=$("$LANDSIM" info "$SCENARIO" --json | sed -n 's/.*"images": *\([0-9]*\).*/\1/p')
if [ -z "$IMAGES" ] || [ "$IMAGES" -lt 1 ]; then
  echo "submit.sh: could not count the images of $SCENARIO" >&2
  exit 2
fi
export SCENARIO OUT LANDSIM
DIR=$(dirname "$0")
ARRAY=$(sbatch --parsable --array=0-$((IMAGES - 1)) --export=ALL "$@" "$DIR/render_array.sh")
sbatch --parsable --dependency=afterok:"$ARRAY" --export=ALL "$DIR/check_set.sh"
echo "submitted $IMAGES images as job $ARRAY" >&2
