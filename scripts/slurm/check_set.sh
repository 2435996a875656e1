#!/bin/sh
# The final step of an image-set job: every image must be there; then the manifest is written.
#SBATCH --job-name=landsim-check
#SBATCH --output=landsim-check-%j.log
set -eu
: "${LANDSIM:=build/bin/landsim}"
"$LANDSIM" render "$SCENARIO" --out "$OUT" --check
